// What the recording-format tests share (test_recording.cpp reads, test_recording_writer.cpp
// writes): bit-exact comparisons, a per-test folder, error checks and a recording that uses every
// column with awkward values.
#pragma once

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "core/io/Recording.h"
#include "tests/support/TempDirTest.h"

namespace armtrack::recording_test {

namespace fs = std::filesystem;

inline std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}
template <typename A, typename B>
void expectBitwiseEqual(const A& a, const B& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    EXPECT_EQ(bits(a(i)), bits(b(i))) << what << "[" << i << "]: " << a(i) << " vs " << b(i);
  }
}

inline std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class RecordingTest : public armtrack::test::TempDirTest {
 protected:
  RecordingTest() : TempDirTest("armtrack_test_recording_") {}

  /// Writes text byte for byte (no newline translation).
  fs::path writeText(const std::string& name, const std::string& text) {
    const fs::path p = m_dir / name;
    std::ofstream out(p, std::ios::binary);
    out << text;
    return p;
  }

  /// Writes a CSV and a minimal valid sidecar next to it.
  fs::path writeCsv(const std::string& text) {
    writeText("rec.json", R"({"format": "armtrack-recording", "version": 1})");
    return writeText("rec.csv", text);
  }

  std::set<std::string> dirEntries() const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(m_dir)) names.insert(e.path().filename().string());
    return names;
  }
};

/// The RecordingError thrown by f, or a failure when none is thrown.
inline RecordingError errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const RecordingError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a RecordingError";
  return RecordingError("", -1, -1, "(no error)");
}

inline RecordingError readError(const fs::path& p) {
  return errorOf([&] { readRecording(p); });
}

inline void expectError(const RecordingError& e, const fs::path& file, int line, int column,
                        const std::string& messagePart) {
  EXPECT_EQ(e.file(), file.string());
  EXPECT_EQ(e.line(), line) << e.what();
  EXPECT_EQ(e.column(), column) << e.what();
  EXPECT_NE(e.message().find(messagePart), std::string::npos)
      << "message: " << e.message() << "\nexpected to contain: " << messagePart;
}

inline const std::string kImuHeader = "t,ua_gx,ua_gy,ua_gz,ua_ax,ua_ay,ua_az\n";

/// Random finite doubles over the whole range (subnormals, huge, tiny, negative zero).
class AwkwardDoubles {
 public:
  double operator()() {
    for (;;) {
      const double x = std::bit_cast<double>(m_rng());
      if (std::isfinite(x)) return x;
    }
  }

 private:
  std::mt19937_64 m_rng{20240611};
};

inline Recording mixedRecording() {
  AwkwardDoubles r;
  auto v3 = [&] { return Eigen::Vector3d(r(), r(), r()); };
  auto v2 = [&] { return Eigen::Vector2d(r(), r()); };
  Recording rec;
  rec.meta.geometry = {0.31, 0.27, 0.123456789, 1.4, 0.025, 0.19, 1.7000000000000002, 0.015};
  rec.meta.up = Eigen::Vector3d(0.0, -1.0, 0.0);
  rec.meta.g = 9.80665;
  CameraParams cam;
  cam.fx = 612.3456;
  cam.fy = 611.9;
  cam.cx = 319.5;
  cam.cy = 241.25;
  cam.dist = {0.1, -0.25, 1e-4, -2e-4, 0.03};
  cam.R << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  cam.t = Eigen::Vector3d(0.05, -0.1, 1.75);
  rec.meta.camera = cam;

  double t = 0.0;
  for (int i = 0; i < 200; ++i) {
    ArmSample s;
    s.t = t;
    t += 0.001;  // accumulates values like 0.30000000000000004
    switch (i % 5) {
      case 0:  // both IMUs
        s.upperArm = ImuReading{v3(), v3()};
        s.forearm = ImuReading{v3(), v3()};
        break;
      case 1:  // upper-arm IMU only, with truth
        s.upperArm = ImuReading{v3(), v3()};
        s.trueAngles = JointVector::NullaryExpr([&] { return r(); });
        break;
      case 2:  // optical positions only
        s.elbow = v3();
        s.wrist = v3();
        break;
      case 3:  // camera pixels, one marker only on some rows
        s.camWrist = v2();
        if (i % 2 == 0) s.camElbow = v2();
        break;
      default:  // time only
        break;
    }
    rec.samples.push_back(s);
  }
  rec.samples[3].forearm = ImuReading{Eigen::Vector3d(-0.0, 0.0, 5e-324), v3()};
  return rec;
}

template <typename T>
void expectSameOptional(const std::optional<T>& a, const std::optional<T>& b,
                        const std::string& what) {
  ASSERT_EQ(a.has_value(), b.has_value()) << what;
  if (a) expectBitwiseEqual(*a, *b, what);
}

inline void expectSameSamples(const std::vector<ArmSample>& a, const std::vector<ArmSample>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string row = "sample " + std::to_string(i) + " ";
    EXPECT_EQ(bits(a[i].t), bits(b[i].t)) << row << "t";
    ASSERT_EQ(a[i].upperArm.has_value(), b[i].upperArm.has_value()) << row;
    if (a[i].upperArm) {
      expectBitwiseEqual(a[i].upperArm->gyr, b[i].upperArm->gyr, row + "ua gyr");
      expectBitwiseEqual(a[i].upperArm->acc, b[i].upperArm->acc, row + "ua acc");
    }
    ASSERT_EQ(a[i].forearm.has_value(), b[i].forearm.has_value()) << row;
    if (a[i].forearm) {
      expectBitwiseEqual(a[i].forearm->gyr, b[i].forearm->gyr, row + "fa gyr");
      expectBitwiseEqual(a[i].forearm->acc, b[i].forearm->acc, row + "fa acc");
    }
    expectSameOptional(a[i].elbow, b[i].elbow, row + "elbow");
    expectSameOptional(a[i].wrist, b[i].wrist, row + "wrist");
    expectSameOptional(a[i].camWrist, b[i].camWrist, row + "camWrist");
    expectSameOptional(a[i].camElbow, b[i].camElbow, row + "camElbow");
    expectSameOptional(a[i].trueAngles, b[i].trueAngles, row + "trueAngles");
  }
}

inline void expectSameMeta(const RecordingMeta& a, const RecordingMeta& b) {
  const ArmGeometry& ga = a.geometry;
  const ArmGeometry& gb = b.geometry;
  EXPECT_EQ(bits(ga.l3), bits(gb.l3));
  EXPECT_EQ(bits(ga.l6), bits(gb.l6));
  EXPECT_EQ(bits(ga.lu3), bits(gb.lu3));
  EXPECT_EQ(bits(ga.thu4), bits(gb.thu4));
  EXPECT_EQ(bits(ga.lu5), bits(gb.lu5));
  EXPECT_EQ(bits(ga.lf6), bits(gb.lf6));
  EXPECT_EQ(bits(ga.thf7), bits(gb.thf7));
  EXPECT_EQ(bits(ga.lf8), bits(gb.lf8));
  expectBitwiseEqual(a.up, b.up, "up");
  EXPECT_EQ(bits(a.g), bits(b.g));
  ASSERT_EQ(a.camera.has_value(), b.camera.has_value());
  if (a.camera) {
    EXPECT_EQ(bits(a.camera->fx), bits(b.camera->fx));
    EXPECT_EQ(bits(a.camera->fy), bits(b.camera->fy));
    EXPECT_EQ(bits(a.camera->cx), bits(b.camera->cx));
    EXPECT_EQ(bits(a.camera->cy), bits(b.camera->cy));
    for (int i = 0; i < 5; ++i) EXPECT_EQ(bits(a.camera->dist[i]), bits(b.camera->dist[i]));
    expectBitwiseEqual(a.camera->R.reshaped(), b.camera->R.reshaped(), "R");
    expectBitwiseEqual(a.camera->t, b.camera->t, "t");
  }
}

}  // namespace armtrack::recording_test
