// Tests for the recording format (docs/recording-format.md): round trips, tolerant parsing and
// every documented error with its line and column.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <system_error>

#include "core/io/Recording.h"

#ifdef __linux__
#include <sys/resource.h>
#include <csignal>
#endif

namespace armtrack {
namespace {

namespace fs = std::filesystem;

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

template <typename A, typename B>
void expectBitwiseEqual(const A& a, const B& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    EXPECT_EQ(bits(a(i)), bits(b(i))) << what << "[" << i << "]: " << a(i) << " vs " << b(i);
  }
}

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class RecordingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() /
           ("armtrack_test_recording_" + name + "_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  /// Writes text byte for byte (no newline translation).
  fs::path writeText(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
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
    for (const auto& e : fs::directory_iterator(dir_)) names.insert(e.path().filename().string());
    return names;
  }

  fs::path dir_;
};

/// The RecordingError thrown by f, or a failure when none is thrown.
RecordingError errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const RecordingError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a RecordingError";
  return RecordingError("", -1, -1, "(no error)");
}

RecordingError readError(const fs::path& p) {
  return errorOf([&] { readRecording(p); });
}

void expectError(const RecordingError& e, const fs::path& file, int line, int column,
                 const std::string& messagePart) {
  EXPECT_EQ(e.file(), file.string());
  EXPECT_EQ(e.line(), line) << e.what();
  EXPECT_EQ(e.column(), column) << e.what();
  EXPECT_NE(e.message().find(messagePart), std::string::npos)
      << "message: " << e.message() << "\nexpected to contain: " << messagePart;
}

const std::string kImuHeader = "t,ua_gx,ua_gy,ua_gz,ua_ax,ua_ay,ua_az\n";

// ---------------------------------------------------------------------------------------------

TEST(RecordingErrorTest, WhatHasFileLineColumnAndMessage) {
  const RecordingError e("dir/rec.csv", 12, 3, "bad number \"x\" in column \"ua_gz\"");
  EXPECT_STREQ(e.what(), "dir/rec.csv:12:3: bad number \"x\" in column \"ua_gz\"");
  EXPECT_EQ(e.file(), "dir/rec.csv");
  EXPECT_EQ(e.line(), 12);
  EXPECT_EQ(e.column(), 3);
  EXPECT_EQ(e.message(), "bad number \"x\" in column \"ua_gz\"");
}

TEST(SidecarPathTest, ReplacesTheExtension) {
  EXPECT_EQ(sidecarPath("a/b/session.csv"), fs::path("a/b/session.json"));
  EXPECT_EQ(sidecarPath("session"), fs::path("session.json"));
  EXPECT_EQ(sidecarPath("x.y.csv"), fs::path("x.y.json"));
}

// ---------------------------------------------------------------------------------------------
// Round trips

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

Recording mixedRecording() {
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

void expectSameSamples(const std::vector<ArmSample>& a, const std::vector<ArmSample>& b) {
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

void expectSameMeta(const RecordingMeta& a, const RecordingMeta& b) {
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

TEST_F(RecordingTest, RoundTripIsBitExact) {
  const Recording rec = mixedRecording();
  const fs::path p = dir_ / "session.csv";
  writeRecording(p, rec);
  ASSERT_TRUE(fs::exists(dir_ / "session.json"));
  const Recording back = readRecording(p);
  EXPECT_TRUE(back.warnings.empty());
  expectSameMeta(rec.meta, back.meta);
  expectSameSamples(rec.samples, back.samples);
  // Only the final files remain: no temporary files left behind.
  EXPECT_EQ(dirEntries(), (std::set<std::string>{"session.csv", "session.json"}));
}

TEST_F(RecordingTest, RoundTripWithoutCameraAndWithDefaults) {
  Recording rec;
  rec.samples.resize(3);
  rec.samples[0].t = 0.0;
  rec.samples[1].t = 0.0;  // equal times are allowed
  rec.samples[2].t = 1.5;
  rec.samples[1].elbow = Eigen::Vector3d(0.1, 0.2, 0.3);
  const fs::path p = dir_ / "r.csv";
  writeRecording(p, rec);
  const Recording back = readRecording(p);
  expectSameMeta(rec.meta, back.meta);
  expectSameSamples(rec.samples, back.samples);
}

TEST_F(RecordingTest, WrittenTextHasCommentHeaderInFixedOrderAndEmptyCells) {
  Recording rec;
  ArmSample a;
  a.t = 0;
  a.forearm = ImuReading{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6.5)};
  ArmSample b;
  b.t = 0.5;
  JointVector th;
  th << 0.1, 0.2, 0.3, 0.4, -0.5;
  b.trueAngles = th;
  b.camElbow = Eigen::Vector2d(320, 240.25);
  rec.samples = {a, b};
  const fs::path p = dir_ / "r.csv";
  writeRecording(p, rec);
  EXPECT_EQ(readText(p),
            "# ArmTrack recording, format version 1\n"
            "t,fa_gx,fa_gy,fa_gz,fa_ax,fa_ay,fa_az,cam_elbow_u,cam_elbow_v,"
            "true_th0,true_th1,true_th2,true_th4,true_th5\n"
            "0,1,2,3,4,5,6.5,,,,,,,\n"
            "0.5,,,,,,,320,240.25,0.1,0.2,0.3,0.4,-0.5\n");
  const std::string json = readText(dir_ / "r.json");
  EXPECT_NE(json.find("\"format\": \"armtrack-recording\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"version\": 1"), std::string::npos) << json;
  EXPECT_NE(json.find("\n  \"geometry\": {"), std::string::npos) << "pretty-printed: " << json;
}

TEST_F(RecordingTest, EmptyRecordingHasOnlyTimeColumn) {
  const fs::path p = dir_ / "r.csv";
  writeRecording(p, Recording{});
  EXPECT_EQ(readText(p), "# ArmTrack recording, format version 1\nt\n");
  EXPECT_TRUE(readRecording(p).samples.empty());
}

TEST_F(RecordingTest, OverwritesAnExistingRecording) {
  const fs::path p = dir_ / "r.csv";
  writeRecording(p, mixedRecording());
  Recording second;
  second.samples.resize(1);
  second.samples[0].t = 7.0;
  writeRecording(p, second);
  const Recording back = readRecording(p);
  expectSameSamples(second.samples, back.samples);
  EXPECT_FALSE(back.meta.camera.has_value());
  EXPECT_EQ(dirEntries(), (std::set<std::string>{"r.csv", "r.json"}));
}

// ---------------------------------------------------------------------------------------------
// Tolerant reading

TEST_F(RecordingTest, ColumnsInAnyOrderAndUnknownColumnsIgnored) {
  const fs::path p = writeCsv(
      "note,wrist_z,ua_az,ua_gx,t,wrist_x,ua_ay,ua_gz,wrist_y,ua_gy,ua_ax,extra\n"
      "hello,0.3,9.81,0.5,0.25,0.1,0.02,-1.5,0.2,2,0.01,\n"
      "any text,,,,0.5,,,,,,,42\n");
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 2u);
  const ArmSample& s = rec.samples[0];
  EXPECT_EQ(s.t, 0.25);
  ASSERT_TRUE(s.upperArm.has_value());
  EXPECT_EQ(s.upperArm->gyr, Eigen::Vector3d(0.5, 2, -1.5));
  EXPECT_EQ(s.upperArm->acc, Eigen::Vector3d(0.01, 0.02, 9.81));
  ASSERT_TRUE(s.wrist.has_value());
  EXPECT_EQ(*s.wrist, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_FALSE(s.forearm || s.elbow || s.camWrist || s.camElbow || s.trueAngles);
  const ArmSample& s2 = rec.samples[1];
  EXPECT_EQ(s2.t, 0.5);
  EXPECT_FALSE(s2.upperArm || s2.forearm || s2.elbow || s2.wrist || s2.camWrist || s2.camElbow ||
               s2.trueAngles);
}

TEST_F(RecordingTest, CommentsBlankLinesCrlfAndBomAccepted) {
  const fs::path p = writeCsv(
      "\xEF\xBB\xBF# exported by hand\r\n"
      "\r\n"
      "#another comment\r\n"
      "t,elbow_x,elbow_y,elbow_z,true_th0,true_th1,true_th2,true_th4,true_th5\r\n"
      "0,1,2,3,,,,,\r\n"
      "# a comment between rows\r\n"
      "   \r\n"
      "\r\n"
      "0.01,,,,0.1,0.2,0.3,0.4,0.5\r\n"
      "0.02,4,5,6,,,,,");  // last line without newline
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 3u);
  EXPECT_EQ(rec.samples[0].t, 0.0);
  ASSERT_TRUE(rec.samples[0].elbow.has_value());
  EXPECT_EQ(*rec.samples[0].elbow, Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(rec.samples[0].trueAngles.has_value());
  ASSERT_TRUE(rec.samples[1].trueAngles.has_value());
  JointVector th;
  th << 0.1, 0.2, 0.3, 0.4, 0.5;
  EXPECT_EQ(*rec.samples[1].trueAngles, th);
  EXPECT_FALSE(rec.samples[1].elbow.has_value());
  EXPECT_EQ(rec.samples[2].t, 0.02);
  EXPECT_EQ(*rec.samples[2].elbow, Eigen::Vector3d(4, 5, 6));
}

TEST_F(RecordingTest, SensorsAtDifferentRates) {
  const fs::path p = writeCsv(
      "t,ua_gx,ua_gy,ua_gz,ua_ax,ua_ay,ua_az,fa_gx,fa_gy,fa_gz,fa_ax,fa_ay,fa_az,"
      "cam_wrist_u,cam_wrist_v,cam_elbow_u,cam_elbow_v\n"
      "0.000,1,1,1,0,0,9.8,2,2,2,0,0,9.8,100,200,,\n"
      "0.001,1,1,1,0,0,9.8,,,,,,,,,300,400\n"
      "0.002,,,,,,,2,2,2,0,0,9.8,,,,\n");
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 3u);
  EXPECT_TRUE(rec.samples[0].upperArm && rec.samples[0].forearm);
  EXPECT_EQ(*rec.samples[0].camWrist, Eigen::Vector2d(100, 200));
  EXPECT_FALSE(rec.samples[0].camElbow);
  EXPECT_TRUE(rec.samples[1].upperArm && !rec.samples[1].forearm);
  EXPECT_EQ(*rec.samples[1].camElbow, Eigen::Vector2d(300, 400));
  EXPECT_FALSE(rec.samples[1].camWrist);
  EXPECT_TRUE(!rec.samples[2].upperArm && rec.samples[2].forearm);
  EXPECT_EQ(rec.samples[2].forearm->gyr, Eigen::Vector3d(2, 2, 2));
  EXPECT_EQ(rec.samples[2].forearm->acc, Eigen::Vector3d(0, 0, 9.8));
}

TEST_F(RecordingTest, SpacesAroundCellsAndLeadingPlusAccepted) {
  const fs::path p = writeCsv(" t , elbow_x,elbow_y ,elbow_z\n 1.5 ,+2, 3e-1 ,\t-4\n2,  , ,\n");
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 2u);
  EXPECT_EQ(rec.samples[0].t, 1.5);
  EXPECT_EQ(*rec.samples[0].elbow, Eigen::Vector3d(2, 0.3, -4));
  EXPECT_FALSE(rec.samples[1].elbow.has_value());
}

// ---------------------------------------------------------------------------------------------
// CSV errors: message, line and column

TEST_F(RecordingTest, BadNumber) {
  const fs::path p = writeCsv("# comment\n" + kImuHeader + "0,1,2,3,4,5,6\n0.1,1.2.3,2,3,4,5,6\n");
  const RecordingError e = readError(p);
  expectError(e, p, 4, 2, "bad number \"1.2.3\" in column \"ua_gx\"");
  EXPECT_EQ(std::string(e.what()), p.string() + ":4:2: " + e.message());

  for (const std::string bad : {"abc", "1e", "0x10", "1;5", "--1", "+-1", "\"1\"", "1 2"}) {
    const fs::path q = writeCsv(kImuHeader + "0,1,2,3,4,5," + bad + "\n");
    expectError(readError(q), q, 2, 7, "bad number \"" + bad + "\" in column \"ua_az\"");
  }
}

TEST_F(RecordingTest, NumberOutOfRange) {
  const fs::path p = writeCsv(kImuHeader + "0,1,2,1e999,4,5,6\n");
  expectError(readError(p), p, 2, 4, "out of range \"1e999\" in column \"ua_gz\"");
}

TEST_F(RecordingTest, NanAndInfinityInAnySpellingAreErrors) {
  for (const std::string v :
       {"nan", "NaN", "-nan", "NAN", "nan(0x1)", "inf", "-Inf", "INF", "infinity", "-Infinity"}) {
    const fs::path p =
        writeCsv("t,fa_gx,fa_gy,fa_gz,fa_ax,fa_ay,fa_az\n0,0,0,0,0,0,9.8\n1,0,0,0,0,0," + v + "\n");
    expectError(readError(p), p, 3, 7, "not a finite number \"" + v + "\" in column \"fa_az\"");
  }
  const fs::path p = writeCsv("t,elbow_x,elbow_y,elbow_z\nnan,1,2,3\n");
  expectError(readError(p), p, 2, 1, "not a finite number \"nan\" in column \"t\"");
}

TEST_F(RecordingTest, MissingHeaderInEmptyFile) {
  const fs::path p = writeCsv("");
  expectError(readError(p), p, 0, 0, "missing header");
}

TEST_F(RecordingTest, MissingHeaderInCommentOnlyFile) {
  const fs::path p = writeCsv("\xEF\xBB\xBF# just a comment\r\n\r\n  \n# another\n");
  expectError(readError(p), p, 0, 0, "missing header");
}

TEST_F(RecordingTest, TimeGoingBackwards) {
  const fs::path p = writeCsv(
      "elbow_x,elbow_y,t,elbow_z\n"
      "1,2,0.5,3\n"
      "# comment\n"
      "1,2,0.6,3\n"
      "1,2,0.6,3\n"
      "\n"
      "1,2,0.5,3\n");
  expectError(readError(p), p, 7, 3, "time goes backwards: 0.5 after 0.6");
}

TEST_F(RecordingTest, EmptyTimeCell) {
  const fs::path p = writeCsv("t,elbow_x,elbow_y,elbow_z\n0,1,2,3\n,1,2,3\n");
  expectError(readError(p), p, 3, 1, "\"t\"");
}

TEST_F(RecordingTest, WrongFieldCount) {
  const fs::path few = writeCsv(kImuHeader + "0,1,2,3,4,5,6\n0.1,1,2,3,4\n");
  expectError(readError(few), few, 3, 6, "row has 5 fields, header has 7");
  const fs::path many = writeCsv(kImuHeader + "0,1,2,3,4,5,6,7\n");
  expectError(readError(many), many, 2, 8, "row has 8 fields, header has 7");
}

TEST_F(RecordingTest, PartiallyFilledGroup) {
  const fs::path p = writeCsv(kImuHeader + "0,1,,3,4,5,6\n");
  expectError(readError(p), p, 2, 3, "\"ua_gy\"");
  const fs::path q = writeCsv("t,cam_wrist_v,cam_wrist_u\n0,,5\n");
  expectError(readError(q), q, 2, 2, "\"cam_wrist_v\"");
}

TEST_F(RecordingTest, ImuNeedsBothGyroAndAccel) {
  const fs::path p = writeCsv(kImuHeader + "0,1,2,3,,,\n");
  expectError(readError(p), p, 2, 5, "no upper-arm accelerometer values");
  const fs::path q = writeCsv(kImuHeader + "0,,,,4,5,6\n");
  expectError(readError(q), q, 2, 2, "no upper-arm gyroscope values");
  // Gyroscope columns without accelerometer columns in the header: rows with gyro data fail.
  const fs::path r = writeCsv("t,fa_gx,fa_gy,fa_gz\n0,,,\n1,1,2,3\n");
  expectError(readError(r), r, 3, 2, "no forearm accelerometer values");
}

TEST_F(RecordingTest, GroupPartlyInHeader) {
  const fs::path p = writeCsv("# c\nt,elbow_x,elbow_y\n0,1,2\n");
  expectError(readError(p), p, 2, 2, "\"elbow_z\"");
}

TEST_F(RecordingTest, MissingTimeColumn) {
  const fs::path p = writeCsv("# c\n\nelbow_x,elbow_y,elbow_z\n1,2,3\n");
  expectError(readError(p), p, 3, 0, "no \"t\" column in header");
}

TEST_F(RecordingTest, DuplicateColumn) {
  const fs::path p = writeCsv("t,elbow_x,elbow_y,elbow_z,t\n0,1,2,3,0\n");
  expectError(readError(p), p, 1, 5, "duplicate column \"t\"");
}

TEST_F(RecordingTest, UnopenableFile) {
  const fs::path p = dir_ / "does_not_exist.csv";
  expectError(readError(p), p, 0, 0,
              "cannot open file: " + std::generic_category().message(ENOENT));
  const fs::path d = dir_ / "a_directory.csv";
  fs::create_directory(d);
  expectError(readError(d), d, 0, 0, "cannot open file");
}

// ---------------------------------------------------------------------------------------------
// Sidecar

TEST_F(RecordingTest, MissingSidecarGivesWarningAndDefaults) {
  const fs::path p = writeText("rec.csv", "t\n0\n");
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_NE(rec.warnings[0].find((dir_ / "rec.json").string()), std::string::npos)
      << rec.warnings[0];
  EXPECT_EQ(rec.meta.geometry.l3, 0.22);
  EXPECT_EQ(rec.meta.geometry.lf8, 0.01);
  EXPECT_EQ(rec.meta.up, Eigen::Vector3d(-1, 0, 0));
  EXPECT_EQ(rec.meta.g, 9.81);
  EXPECT_FALSE(rec.meta.camera.has_value());
  EXPECT_EQ(rec.samples.size(), 1u);
}

TEST_F(RecordingTest, CorruptSidecarJsonIsAnError) {
  writeText("rec.csv", "t\n0\n");
  const std::string text = "{\"format\": \"armtrack-recording\",\n  \"version\": 1,,\n}\n";
  const fs::path j = writeText("rec.json", text);
  const std::size_t byte = text.find(",,") + 2;  // 1-based position of the second comma
  const RecordingError e = readError(dir_ / "rec.csv");
  expectError(e, j, 2, 16, "bad JSON at byte " + std::to_string(byte));
}

TEST_F(RecordingTest, TruncatedSidecarJsonIsAnError) {
  const fs::path j = writeText("rec.json", "{\"format\": \"armtrack-re");
  expectError(errorOf([&] { readSidecar(j); }), j, 1, 24, "bad JSON at byte");
}

TEST_F(RecordingTest, WrongVersionOrFormatIsAnError) {
  const fs::path j = dir_ / "m.json";
  auto sidecarError = [&](const std::string& text) {
    writeText("m.json", text);
    return errorOf([&] { readSidecar(j); });
  };
  expectError(sidecarError(R"({"format": "armtrack-recording", "version": 2})"), j, 0, 0,
              "\"version\" 2");
  expectError(sidecarError(R"({"format": "armtrack-recording", "version": "1"})"), j, 0, 0,
              "\"version\"");
  expectError(sidecarError(R"({"format": "armtrack-recording"})"), j, 0, 0, "\"version\"");
  expectError(sidecarError(R"({"format": "something-else", "version": 1})"), j, 0, 0, "\"format\"");
  expectError(sidecarError(R"({"version": 1})"), j, 0, 0, "\"format\"");
  expectError(sidecarError(R"([1, 2])"), j, 0, 0, "object");
}

TEST_F(RecordingTest, SidecarFieldsAndDefaults) {
  const fs::path j = writeText("m.json", R"({
    "format": "armtrack-recording", "version": 1, "side": "left", "comment": "unknown key",
    "geometry": {"l3": 0.3, "thf7": 1.0},
    "up": [0, 0, 1.25], "g": 9.8,
    "camera": {"fx": 600, "fy": 601, "cx": 320, "cy": 240,
               "R": [0, -1, 0, 0, 0, -1, 1, 0, 0], "t": [0.1, 0.2, 1.5]}})");
  const RecordingMeta m = readSidecar(j);
  EXPECT_EQ(m.geometry.l3, 0.3);
  EXPECT_EQ(m.geometry.thf7, 1.0);
  EXPECT_EQ(m.geometry.l6, 0.20);  // missing keys keep the defaults
  EXPECT_EQ(m.geometry.lu3, 0.11);
  EXPECT_EQ(m.geometry.thu4, std::numbers::pi / 2);
  EXPECT_EQ(m.geometry.lu5, 0.02);
  EXPECT_EQ(m.geometry.lf6, 0.20);
  EXPECT_EQ(m.geometry.lf8, 0.01);
  EXPECT_EQ(m.up, Eigen::Vector3d(0, 0, 1));  // normalised
  EXPECT_EQ(m.g, 9.8);
  EXPECT_EQ(m.gUp(), Eigen::Vector3d(0, 0, 9.8));
  ASSERT_TRUE(m.camera.has_value());
  EXPECT_EQ(m.camera->fx, 600);
  EXPECT_EQ(m.camera->cy, 240);
  EXPECT_EQ(m.camera->dist, (std::array<double, 5>{0, 0, 0, 0, 0}));
  // Row-major R: the shoulder's z axis maps to camera -y, x to camera z.
  EXPECT_EQ(m.camera->R(0, 1), -1);
  EXPECT_EQ(m.camera->R(1, 2), -1);
  EXPECT_EQ(m.camera->R(2, 0), 1);
  const Eigen::Vector3d pCam = m.camera->R * Eigen::Vector3d(1, 0, 0) + m.camera->t;
  EXPECT_EQ(pCam, Eigen::Vector3d(0.1, 0.2, 2.5));

  writeText("m.json", R"({"format": "armtrack-recording", "version": 1, "side": "right"})");
  EXPECT_NO_THROW(readSidecar(j));
}

TEST_F(RecordingTest, UpMustBeAUnitVectorOfThreeNumbers) {
  const fs::path j = dir_ / "m.json";
  auto withUp = [&](const std::string& up) {
    writeText("m.json", R"({"format": "armtrack-recording", "version": 1, "up": )" + up + "}");
  };
  withUp("[0.6, 0, -0.9]");
  const RecordingMeta m = readSidecar(j);
  EXPECT_NEAR(m.up.norm(), 1.0, 1e-15);
  EXPECT_NEAR(m.up.x() / m.up.z(), 0.6 / -0.9, 1e-15);
  for (const std::string bad : {"[0, 0, 3]", "[0, 0, 0.4]", "[0, 0, 0]"}) {
    withUp(bad);
    expectError(errorOf([&] { readSidecar(j); }), j, 0, 0, "unit vector");
  }
  for (const std::string bad :
       {"[1, 0]", "[1, 0, 0, 0]", "[1, \"0\", 0]", "\"up\"", "[1, 0, null]"}) {
    withUp(bad);
    expectError(errorOf([&] { readSidecar(j); }), j, 0, 0, "\"up");
  }
}

TEST_F(RecordingTest, BadSidecarValues) {
  const fs::path j = dir_ / "m.json";
  auto sidecarError = [&](const std::string& rest) {
    writeText("m.json", R"({"format": "armtrack-recording", "version": 1, )" + rest + "}");
    return errorOf([&] { readSidecar(j); });
  };
  expectError(sidecarError(R"("geometry": {"l3": "long"})"), j, 0, 0, "\"geometry.l3\"");
  expectError(sidecarError(R"("g": -9.81)"), j, 0, 0, "\"g\"");
  expectError(sidecarError(R"("camera": {"fx": 1, "fy": 1, "cx": 1})"), j, 0, 0, "camera.cy");
  expectError(sidecarError(R"("camera": {"fx": 1, "fy": 1, "cx": 1, "cy": 1, "R": [1, 0, 0]})"), j,
              0, 0, "\"camera.R\"");
}

// ---------------------------------------------------------------------------------------------
// Write failures

TEST_F(RecordingTest, WritingIntoMissingDirectoryThrowsAndLeavesNoFile) {
  const fs::path p = dir_ / "no_such_dir" / "rec.csv";
  const RecordingError e = errorOf([&] { writeRecording(p, mixedRecording()); });
  EXPECT_EQ(e.file(), p.string());
  EXPECT_NE(e.message().find(std::generic_category().message(ENOENT)), std::string::npos)
      << e.message();
  EXPECT_FALSE(fs::exists(p));
  EXPECT_FALSE(fs::exists(dir_ / "no_such_dir"));
  EXPECT_TRUE(dirEntries().empty());
}

TEST_F(RecordingTest, NonFiniteOrDecreasingDataIsNotWritten) {
  const fs::path p = dir_ / "rec.csv";
  Recording rec;
  rec.samples.resize(2);
  rec.samples[1].t = 1.0;
  rec.samples[1].wrist = Eigen::Vector3d(0, std::nan(""), 0);
  expectError(errorOf([&] { writeRecording(p, rec); }), p, 4, 3, "\"wrist_y\"");
  rec.samples[1].wrist.reset();
  rec.samples[1].t = -1.0;
  expectError(errorOf([&] { writeRecording(p, rec); }), p, 4, 1, "decreasing time");
  EXPECT_TRUE(dirEntries().empty());
}

#ifdef __linux__
// A write that fails half-way (here: the file size limit, standing in for a full disk) must throw
// and leave the previous file untouched, with no temporary file behind.
TEST_F(RecordingTest, FailedWriteKeepsTheOldFile) {
  const fs::path p = dir_ / "rec.csv";
  Recording small;
  small.samples.resize(1);
  writeRecording(p, small);
  const std::string before = readText(p);

  Recording big;
  for (int i = 0; i < 20000; ++i) {
    ArmSample s;
    s.t = i * 1e-3;
    s.upperArm = ImuReading{Eigen::Vector3d::Constant(0.123456789), Eigen::Vector3d::Constant(9.8)};
    big.samples.push_back(s);
  }

  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit limited = old;
  limited.rlim_cur = 100 * 1024;
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  const RecordingError e = errorOf([&] { writeRecording(p, big); });
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldHandler);

  EXPECT_EQ(e.file(), p.string());
  EXPECT_NE(e.message().find("write failed"), std::string::npos) << e.message();
  EXPECT_EQ(readText(p), before);
  EXPECT_EQ(dirEntries(), (std::set<std::string>{"rec.csv", "rec.json"}));
}
#endif

// ---------------------------------------------------------------------------------------------
// RecordingWriter (live sessions)

namespace {
ArmSample liveRow(int i) {
  ArmSample s;
  s.t = 0.001 * i + 1e-7 / 3.0;  // not a short decimal: the round trip must be exact
  s.upperArm =
      ImuReading{Eigen::Vector3d(0.1 / 3, -0.2, 0.3 * i), Eigen::Vector3d(9.81, 0.1, -0.2)};
  if (i % 3 == 0) s.wrist = Eigen::Vector3d(0.2, 0.3 / 7, -0.1);
  JointVector th;
  th << 0.1, -0.2 / 3, 0.3, 1.0 / 7, -0.5;
  s.trueAngles = th;
  if (i > 0) s.estimate = th * 1.0001;
  return s;
}
RecordingColumns liveColumns() {
  RecordingColumns c;
  c.upperArm = c.wrist = c.truth = c.estimate = true;
  return c;
}
}  // namespace

TEST_F(RecordingTest, WriterRowsReadBackBitExactWithEstimates) {
  const fs::path p = dir_ / "live.csv";
  RecordingMeta meta;
  meta.g = 9.80665;
  {
    RecordingWriter w(p, meta, liveColumns());
    for (int i = 0; i < 500; ++i) w.append(liveRow(i));
    w.close();
    EXPECT_EQ(w.rows(), 500u);
  }
  const Recording rec = readRecording(p);
  EXPECT_TRUE(rec.warnings.empty());
  EXPECT_EQ(rec.meta.g, 9.80665);
  ASSERT_EQ(rec.samples.size(), 500u);
  for (int i = 0; i < 500; ++i) {
    const ArmSample want = liveRow(i);
    const ArmSample& got = rec.samples[static_cast<std::size_t>(i)];
    EXPECT_EQ(got.t, want.t);
    EXPECT_EQ(got.upperArm->gyr, want.upperArm->gyr);
    EXPECT_EQ(got.wrist.has_value(), want.wrist.has_value());
    EXPECT_EQ(*got.trueAngles, *want.trueAngles);
    ASSERT_EQ(got.estimate.has_value(), i > 0);
    if (i > 0) {
      EXPECT_EQ(*got.estimate, *want.estimate);
    }
    EXPECT_FALSE(got.forearm.has_value());
  }
}

TEST_F(RecordingTest, WriterRefusesBadRowsAndStaysUsable) {
  const fs::path p = dir_ / "live.csv";
  RecordingWriter w(p, RecordingMeta{}, liveColumns());
  w.append(liveRow(1));
  ArmSample extra = liveRow(2);
  extra.forearm = ImuReading{};  // no forearm columns
  EXPECT_NE(errorOf([&] { w.append(extra); }).message().find("forearm"), std::string::npos);
  ArmSample nan = liveRow(2);
  nan.upperArm->acc.x() = std::nan("");
  EXPECT_NE(errorOf([&] { w.append(nan); }).message().find("non-finite"), std::string::npos);
  EXPECT_NE(errorOf([&] { w.append(liveRow(0)); }).message().find("decreasing"), std::string::npos);
  w.append(liveRow(2));
  w.close();
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 2u);
  EXPECT_EQ(rec.samples[1].t, liveRow(2).t);
}

TEST_F(RecordingTest, InterruptedRecordingReadsUpToTheCutLine) {
  // What a killed session leaves: flushed rows, then part of a row and no final newline.
  const fs::path p = dir_ / "live.csv";
  {
    RecordingWriter w(p, RecordingMeta{}, liveColumns());
    for (int i = 0; i < 10; ++i) w.append(liveRow(i));
    w.close();
  }
  std::string text = readText(p);
  text.resize(text.size() - 20);  // cut into the last row
  writeText(p, text);
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 9u);
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_NE(rec.warnings[0].find("line 12 was cut short"), std::string::npos) << rec.warnings[0];
  // A bad row that is not the cut-short last line is still an error.
  writeText(p, text + "\n");
  EXPECT_THROW(readRecording(p), RecordingError);
}

#ifdef __linux__
TEST_F(RecordingTest, WriterFullDiskKeepsWrittenRowsAndRetries) {
  const fs::path p = dir_ / "live.csv";
  RecordingWriter w(p, RecordingMeta{}, liveColumns());
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit limited = old;
  limited.rlim_cur = 64 * 1024;
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  int i = 0;
  std::string message;
  for (; i < 5000 && message.empty(); ++i) {
    w.append(liveRow(i));
    if (i % 100 == 99) {
      try {
        w.flush();
      } catch (const RecordingError& e) {
        message = e.message();
      }
    }
  }
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldHandler);
  ASSERT_FALSE(message.empty()) << "the size limit never hit";
  EXPECT_NE(message.find("free some disk space"), std::string::npos) << message;
  // Space is back: the next flush completes the file, nothing lost or doubled.
  w.close();
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), static_cast<std::size_t>(i));
  for (int k = 0; k < i; ++k) EXPECT_EQ(rec.samples[static_cast<std::size_t>(k)].t, liveRow(k).t);
}
#endif

// ---------------------------------------------------------------------------------------------
// Hostile sidecars (issue 9, item 7): impossible geometry and camera blocks are refused naming the
// file and the key; every JSON error names the file.

TEST_F(RecordingTest, SidecarRefusesImpossibleGeometryNamingFileAndKey) {
  const fs::path j = dir_ / "m.json";
  auto geometryError = [&](const std::string& geometry) {
    writeText("m.json", R"({"format": "armtrack-recording", "version": 1, "geometry": )" +
                            geometry + "}");
    return errorOf([&] { readSidecar(j); });
  };
  // Each of these was accepted before and gave 14-172 deg errors (or no estimates at all).
  const std::pair<std::string, std::string> cases[] = {
      {R"({"l3": 0})", "geometry.l3"},        {R"({"l3": -0.3})", "geometry.l3"},
      {R"({"l3": 1e300})", "geometry.l3"},    {R"({"l3": 0.05})", "geometry.l3"},
      {R"({"l3": 0.61})", "geometry.l3"},     {R"({"l6": 0})", "geometry.l6"},
      {R"({"l6": -0.2})", "geometry.l6"},     {R"({"l6": 2.5})", "geometry.l6"},
      {R"({"lu3": -0.01})", "geometry.lu3"},  {R"({"l3": 0.22, "lu3": 0.33})", "geometry.lu3"},
      {R"({"lf6": -0.05})", "geometry.lf6"},  {R"({"l6": 0.2, "lf6": 0.31})", "geometry.lf6"},
      {R"({"lu5": 0.2})", "geometry.lu5"},    {R"({"lf8": -1e6})", "geometry.lf8"},
      {R"({"thu4": 1e300})", "geometry.thu4"}, {R"({"thf7": -7})", "geometry.thf7"}};
  for (const auto& [geometry, key] : cases) {
    SCOPED_TRACE(geometry);
    expectError(geometryError(geometry), j, 0, 0, "\"" + key + "\"");
  }
  // The limits themselves, and the paper's strap at the shoulder (lu3 = lu5 = 0), are possible.
  for (const std::string ok :
       {R"({"l3": 0.1, "l6": 0.6})", R"({"l3": 0.6, "l6": 0.1, "lu3": 0.7, "lf6": 0.2})",
        R"({"lu3": 0, "lu5": 0, "lf6": 0, "lf8": 0})", R"({"lu5": -0.15, "thu4": -6.28})"}) {
    writeText("m.json", R"({"format": "armtrack-recording", "version": 1, "geometry": )" + ok +
                            "}");
    EXPECT_NO_THROW(readSidecar(j)) << ok;
  }
  writeText("m.json", R"({"format": "armtrack-recording", "version": 1, "g": 1e300})");
  expectError(errorOf([&] { readSidecar(j); }), j, 0, 0, "\"g\"");
  writeText("m.json", R"({"format": "armtrack-recording", "version": 1, "g": 1})");
  expectError(errorOf([&] { readSidecar(j); }), j, 0, 0, "\"g\"");
}

TEST_F(RecordingTest, SidecarWithAHugeNumberNamesFileLineAndColumn) {
  const fs::path j = writeText("m.json", "{\"format\": \"armtrack-recording\", \"version\": 1,\n"
                                         "  \"geometry\": {\"l3\": 1e999}}\n");
  // Before: nlohmann's out_of_range escaped with "number overflow parsing '1e999'" and no file.
  const RecordingError e = errorOf([&] { readSidecar(j); });
  expectError(e, j, 2, 22, "1e999");
  // Through the CSV reader too.
  writeText("rec.csv", kImuHeader + "0,0,0,0,0,0,9.81\n");
  writeText("rec.json", "{\"format\": \"armtrack-recording\", \"version\": 1, \"g\": -1e999}");
  expectError(readError(dir_ / "rec.csv"), dir_ / "rec.json", 1, 53, "-1e999");
}

TEST_F(RecordingTest, SidecarCameraWithZeroFocalOrBadRotationNamesFileAndKey) {
  const fs::path j = dir_ / "m.json";
  auto cameraError = [&](const std::string& camera) {
    writeText("m.json",
              R"({"format": "armtrack-recording", "version": 1, "camera": )" + camera + "}");
    return errorOf([&] { readSidecar(j); });
  };
  expectError(cameraError(R"({"fx": 0, "fy": 600, "cx": 320, "cy": 240})"), j, 0, 0,
              "\"camera.fx\"");
  expectError(cameraError(R"({"fx": 600, "fy": -600, "cx": 320, "cy": 240})"), j, 0, 0,
              "\"camera.fy\"");
  expectError(cameraError(R"({"fx": 600, "fy": 600, "cx": 1e300, "cy": 240})"), j, 0, 0,
              "\"camera.cx\"");
  // Scaled, sheared and mirrored matrices are not rotations.
  for (const std::string r : {"[2, 0, 0, 0, 2, 0, 0, 0, 2]", "[1, 0, 0, 0, 1, 0, 0, 0, -1]",
                              "[1, 0.1, 0, 0, 1, 0, 0, 0, 1]", "[0, 0, 0, 0, 0, 0, 0, 0, 0]"}) {
    expectError(cameraError(R"({"fx": 600, "fy": 600, "cx": 320, "cy": 240, "R": )" + r + "}"), j,
                0, 0, "\"camera.R\" is not a rotation");
  }
  expectError(cameraError(R"({"fx": 600, "fy": 600, "cx": 320, "cy": 240, "t": [0, 0, 1e9]})"), j,
              0, 0, "\"camera.t\"");
}

TEST_F(RecordingTest, SidecarWithAnInvalidUtf8StringNamesTheFile) {
  const fs::path j = writeText("m.json", "{\"format\": \"\xff\xfe\", \"version\": 1}");
  const RecordingError e = errorOf([&] { readSidecar(j); });
  EXPECT_EQ(e.file(), j.string()) << e.what();
}

TEST_F(RecordingTest, ImpossibleMetaIsNeverWritten) {
  Recording rec = mixedRecording();
  rec.meta.geometry.l3 = 0.0;
  const RecordingError e = errorOf([&] { writeRecording(dir_ / "r.csv", rec); });
  EXPECT_EQ(e.file(), (dir_ / "r.json").string());
  EXPECT_NE(e.message().find("\"geometry.l3\""), std::string::npos) << e.message();
  rec = mixedRecording();
  rec.meta.camera->fx = 0.0;
  EXPECT_THROW(writeRecording(dir_ / "r.csv", rec), RecordingError);
  EXPECT_THROW(RecordingWriter(dir_ / "live.csv", rec.meta, liveColumns()), RecordingError);
  EXPECT_TRUE(dirEntries().empty());
}

// ---------------------------------------------------------------------------------------------
// Item 12: a NUL byte in a cell must not cut the message short.

TEST_F(RecordingTest, NonPrintableBytesInACellAreShownEscaped) {
  const fs::path p = writeCsv(kImuHeader + "0,0,0,0,0,0,9.81\n" + std::string("0.1,1\0x\x01", 8) +
                              ",0,0,0,0,9.81\n");
  const RecordingError e = readError(p);
  expectError(e, p, 3, 2, "bad number \"1\\x00x\\x01\" in column \"ua_gx\"");
  const std::string what = e.what();
  EXPECT_EQ(what.find('\0'), std::string::npos);
  EXPECT_EQ(std::strlen(e.what()), what.size());  // what a C string consumer sees is all of it
  // A long cell is shown in part.
  const fs::path q =
      writeCsv(kImuHeader + "0," + std::string(5000, '7') + "z,0,0,0,0,9.81\n");
  const RecordingError l = readError(q);
  EXPECT_LT(l.message().size(), 200u) << l.message();
  EXPECT_NE(l.message().find("5001 bytes, first 40 shown"), std::string::npos) << l.message();
}

// ---------------------------------------------------------------------------------------------
// Item 8: one writer per file, nothing created for an unusable path.

TEST_F(RecordingTest, SecondWriterOnTheSameFileIsRefusedAndTheFirstRecordingSurvives) {
  const fs::path p = dir_ / "live.csv";
  RecordingMeta meta;
  meta.g = 9.80665;
  RecordingWriter first(p, meta, liveColumns());
  for (int i = 0; i < 100; ++i) first.append(liveRow(i));
  first.flush();
  RecordingMeta other;
  other.geometry.l3 = 0.3;
  RecordingColumns otherColumns;
  otherColumns.forearm = true;
  const RecordingError e = errorOf([&] { RecordingWriter second(p, other, otherColumns); });
  EXPECT_EQ(e.file(), p.string());
  EXPECT_NE(e.message().find("another recording is being written to this file"), std::string::npos)
      << e.message();
  for (int i = 100; i < 200; ++i) first.append(liveRow(i));
  first.close();
  const Recording rec = readRecording(p);
  EXPECT_TRUE(rec.warnings.empty());
  EXPECT_EQ(rec.meta.g, 9.80665);  // the sidecar is the first writer's
  EXPECT_EQ(rec.meta.geometry.l3, ArmGeometry{}.l3);
  ASSERT_EQ(rec.samples.size(), 200u);
  for (int i = 0; i < 200; ++i) EXPECT_EQ(rec.samples[static_cast<std::size_t>(i)].t, liveRow(i).t);
  // Once the first is closed, the file can be written again (the caller decides on replacing).
  RecordingWriter third(p, other, otherColumns);
  third.close();
  EXPECT_EQ(readRecording(p).samples.size(), 0u);
}

TEST_F(RecordingTest, WriterOnADirectoryOrJsonNameCreatesNothing) {
  fs::create_directory(dir_ / "d");
  RecordingError e = errorOf([&] { RecordingWriter w(dir_ / "d", RecordingMeta{}, liveColumns()); });
  EXPECT_EQ(e.file(), (dir_ / "d").string());
  EXPECT_NE(e.message().find("directory"), std::string::npos) << e.message();
  fs::create_directory(dir_ / "s.json");
  e = errorOf([&] { RecordingWriter w(dir_ / "s.csv", RecordingMeta{}, liveColumns()); });
  EXPECT_EQ(e.file(), (dir_ / "s.json").string());
  e = errorOf([&] { RecordingWriter w(dir_ / "x.json", RecordingMeta{}, liveColumns()); });
  EXPECT_NE(e.message().find(".json"), std::string::npos) << e.message();
  EXPECT_EQ(dirEntries(), (std::set<std::string>{"d", "s.json"}));  // no d.json, s.csv, x.json
  EXPECT_TRUE(fs::is_empty(dir_ / "d"));
}

#ifdef __linux__
// Item 9: the writer's own account of what reached the file.
TEST_F(RecordingTest, WriterCountsTheRowsThatReachedTheFile) {
  const fs::path p = dir_ / "live.csv";
  RecordingWriter w(p, RecordingMeta{}, liveColumns());
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit limited = old;
  limited.rlim_cur = 32 * 1024;
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  bool failed = false;
  for (int i = 0; i < 3000; ++i) {
    w.append(liveRow(i));
    if (i % 100 == 99) {
      try {
        w.flush();
      } catch (const RecordingError&) {
        failed = true;
      }
    }
  }
  std::uint64_t writtenWhileFull = w.rowsWritten();
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldHandler);
  ASSERT_TRUE(failed) << "the size limit never hit";
  EXPECT_EQ(w.rows(), 3000u);
  // Independent truth: the complete lines in the file, less the comment and the header.
  std::string text = readText(p);
  const auto lines = static_cast<std::uint64_t>(std::count(text.begin(), text.end(), '\n'));
  EXPECT_EQ(writtenWhileFull, lines - 2);
  EXPECT_LT(writtenWhileFull, 3000u);
  w.close();
  EXPECT_EQ(w.rowsWritten(), 3000u);
  EXPECT_EQ(readRecording(p).samples.size(), 3000u);
}
#endif

// ---------------------------------------------------------------------------------------------
// Timing (run by hand: --gtest_also_run_disabled_tests --gtest_filter=*Timing*)

TEST_F(RecordingTest, DISABLED_Timing600kRows) {
  Recording rec;
  std::mt19937_64 rng(1);
  std::normal_distribution<double> n(0.0, 1.0);
  rec.samples.reserve(600000);
  for (int i = 0; i < 600000; ++i) {
    ArmSample s;
    s.t = i * 1e-3;
    s.upperArm = ImuReading{Eigen::Vector3d(n(rng), n(rng), n(rng)),
                            Eigen::Vector3d(n(rng), n(rng), 9.81 + n(rng))};
    s.forearm = ImuReading{Eigen::Vector3d(n(rng), n(rng), n(rng)),
                           Eigen::Vector3d(n(rng), n(rng), 9.81 + n(rng))};
    rec.samples.push_back(s);
  }
  const fs::path p = dir_ / "big.csv";
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  writeRecording(p, rec);
  const auto t1 = Clock::now();
  const Recording back = readRecording(p);
  const auto t2 = Clock::now();
  const double ws = std::chrono::duration<double>(t1 - t0).count();
  const double rs = std::chrono::duration<double>(t2 - t1).count();
  std::cout << "600k rows, " << fs::file_size(p) / 1e6 << " MB: write " << ws << " s, read " << rs
            << " s\n";
  ASSERT_EQ(back.samples.size(), rec.samples.size());
  EXPECT_EQ(bits(back.samples.back().forearm->acc.z()), bits(rec.samples.back().forearm->acc.z()));
  EXPECT_LT(rs, 3.0);
}

// ---------------------------------------------------------------------------------------------
// RecordingReader (row by row, for replays of long recordings)

TEST_F(RecordingTest, ReaderStreamsRowsAcrossChunkBoundariesBitExact) {
  // 40,000 rows (about 9 MB, several of the reader's 1 MiB chunks): rows cross chunk edges.
  const fs::path p = dir_ / "long.csv";
  constexpr int kRows = 40000;
  std::vector<ArmSample> written;
  written.reserve(kRows);
  {
    RecordingWriter w(p, RecordingMeta{}, liveColumns());
    for (int i = 0; i < kRows; ++i) {
      written.push_back(liveRow(i));
      w.append(written.back());
    }
    w.close();
  }
  const auto size = fs::file_size(p);
  ASSERT_GT(size, 4u << 20);

  RecordingReader reader(p);
  EXPECT_TRUE(reader.warnings().empty());
  const RecordingColumns& c = reader.columns();
  EXPECT_TRUE(c.upperArm && c.wrist && c.truth && c.estimate);
  EXPECT_FALSE(c.forearm || c.elbow || c.camWrist || c.camElbow);
  EXPECT_EQ(reader.fileSize(), size);
  std::vector<ArmSample> read;
  ArmSample s;
  std::uint64_t lastBytes = reader.bytesRead();
  while (reader.next(s)) {
    read.push_back(s);
    EXPECT_GE(reader.bytesRead(), lastBytes);
    lastBytes = reader.bytesRead();
  }
  EXPECT_FALSE(reader.next(s));  // stays at the end
  EXPECT_EQ(reader.rows(), static_cast<std::uint64_t>(kRows));
  EXPECT_EQ(reader.bytesRead(), size);
  expectSameSamples(read, written);
  for (std::size_t i = 0; i < read.size(); i += 997)
    EXPECT_EQ(read[i].estimate.has_value(), written[i].estimate.has_value()) << i;
}

TEST_F(RecordingTest, ReaderReportsTheRightLineFarIntoAFileAndCutShortLastLine) {
  const fs::path p = dir_ / "long.csv";
  {
    RecordingWriter w(p, RecordingMeta{}, liveColumns());
    for (int i = 0; i < 20000; ++i) w.append(liveRow(i));
    w.close();
  }
  std::string text = readText(p);
  // Lines: 1 comment, 2 header, 3.. rows. Break row 15000 (line 15002) with a letter.
  std::size_t at = 0;
  for (int line = 1; line < 15002; ++line) at = text.find('\n', at) + 1;
  std::string broken = text;
  broken.insert(at, "x");
  writeText(p, broken);
  {
    RecordingReader reader(p);
    ArmSample s;
    int rows = 0;
    try {
      while (reader.next(s)) ++rows;
      ADD_FAILURE() << "no error";
    } catch (const RecordingError& e) {
      EXPECT_EQ(e.line(), 15002) << e.what();
      EXPECT_EQ(e.column(), 1) << e.what();
    }
    EXPECT_EQ(rows, 14999);
  }
  // Killed mid-row: the rows before the cut line are read, then a warning, no error.
  writeText(p, text.substr(0, text.size() - 25));
  RecordingReader reader(p);
  ArmSample s;
  int rows = 0;
  while (reader.next(s)) ++rows;
  EXPECT_EQ(rows, 19999);
  ASSERT_EQ(reader.warnings().size(), 1u);
  EXPECT_NE(reader.warnings()[0].find("line 20002 was cut short"), std::string::npos)
      << reader.warnings()[0];
}

}  // namespace
}  // namespace armtrack
