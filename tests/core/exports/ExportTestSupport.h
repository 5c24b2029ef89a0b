// Shared by the export tests: a temporary folder, a simulated session with known angles, and
// small readers for the files the exports write.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/Recording.h"
#include "core/kinematics/ClinicalAngles.h"
#include "core/metrics/RangeOfMotion.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack::exporttest {

namespace fs = std::filesystem;

/// A fresh folder under the system's temporary folder, removed with its contents afterwards.
class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    m_path = fs::temp_directory_path() / ("armtrack-exports-" + std::to_string(rd()));
    fs::create_directories(m_path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(m_path, ec);
  }
  const fs::path& path() const { return m_path; }
  fs::path operator/(const std::string& name) const { return m_path / name; }

 private:
  fs::path m_path;
};

/// Every entry below a folder (relative paths, sorted), to show nothing else was left behind.
inline std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    out.push_back(fs::relative(e.path(), dir).string());
  std::sort(out.begin(), out.end());
  return out;
}

inline std::vector<std::string> readLines(const fs::path& p) {
  std::ifstream in(p);
  EXPECT_TRUE(in.good()) << p;
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

inline std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Splits on every separator; empty fields are kept.
inline std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

/// A known movement: every joint a sinusoid around a mid-range posture (rad, Hz).
inline SinusoidTrajectory knownMovement() {
  SinusoidTrajectory tr;
  tr.offset << 0.6, 0.4, -0.2, -0.9, 0.3;  // flexion, abduction, -IR, -elbow, -pronation
  tr.amplitude << 0.5, 0.3, 0.35, 0.6, 0.5;
  tr.frequency << 0.5, 0.5, 0.4, 0.5, 0.3;
  tr.phase << 0.0, 1.0, 0.5, 2.0, 0.3;
  return tr;
}

/// The true clinical angles (deg, clinicalAngleInfo() order) at time t.
inline std::array<double, 5> trueClinicalDeg(const Trajectory& tr, double t) {
  return asArray(toClinical(tr.at(t).th));
}

/// A simulated session of the known movement: IMUs at imuRate, Kinect at 30 Hz (no noise, so
/// the raw channels are exactly what the simulation computed).
inline Recording simulatedSession(const Trajectory& tr, double seconds, double imuRate,
                                  Side side = Side::Right) {
  SimulationParams p = defaultSimulation();
  p.duration = seconds;
  p.upperArm.rateHz = imuRate;
  p.forearm.rateHz = imuRate;
  p.side = side;
  return simulateRecording(tr, p);
}

/// The session's angle series: the true angles of every IMU row (what a perfect estimator gives).
inline AngleSeries truthSeries(const Recording& rec) {
  std::vector<double> t;
  std::vector<JointVector> th;
  for (const ArmSample& s : rec.samples)
    if (s.trueAngles) {
      t.push_back(s.t);
      th.push_back(*s.trueAngles);
    }
  return angleSeriesFromJoints(t, th);
}

}  // namespace armtrack::exporttest
