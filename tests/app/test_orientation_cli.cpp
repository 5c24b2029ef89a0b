// armtrack-cli orientation driven in-process through runCli with hostile input: absurd but
// finite gyroscope rows and a gap in time. Every input row gets an output row, none is NaN, and
// what was rejected is counted and placed.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/Cli.h"
#include "tests/app/CliRun.h"
#include "tests/support/TempDirTest.h"

namespace fs = std::filesystem;

namespace {

constexpr double kG = 9.81;
constexpr double kToRad = std::numbers::pi / 180.0;

using armtrack::test::cli;
using armtrack::test::CliResult;

std::vector<std::vector<std::string>> readCsv(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

class OrientationCliTest : public armtrack::test::TempDirTest {
 protected:
  OrientationCliTest() : TempDirTest("armtrack_orient_cli_") {}
};

// 200 Hz, a sensor turning about x at 0.5 rad/s from level; rows `spikes` get gyr_x = value, and
// no rows are written for t in (gapFrom, gapTo]. Returns the true tilt (rad) at the last row.
double writeImu(const fs::path& p, const std::vector<std::pair<int, std::string>>& spikes,
                double gapFrom, double gapTo, int rows, int* written) {
  std::ofstream f(p);
  f << "t,gyr_x,gyr_y,gyr_z,acc_x,acc_y,acc_z\n";
  const double dt = 0.005, rate = 0.5;
  *written = 0;
  double angle = 0.0;
  for (int k = 0; k < rows; ++k) {
    const double t = k * dt;
    angle = 0.6 * std::sin(rate * t);  // tilt about x, rad
    const double w = 0.6 * rate * std::cos(rate * t);
    if (t > gapFrom && t <= gapTo) continue;
    const Eigen::Vector3d acc =
        Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()).inverse() * Eigen::Vector3d(0, 0, kG);
    std::string gx = std::to_string(w);
    for (const auto& [row, value] : spikes)
      if (row == k) gx = value;
    f << t << "," << gx << ",0,0," << acc.x() << "," << acc.y() << "," << acc.z() << "\n";
    ++*written;
  }
  return angle;
}

TEST_F(OrientationCliTest, AbsurdGyroscopeRowsAreRejectedFlaggedAndReported) {
  const fs::path in = path("imu.csv"), out = path("quat.csv");
  int written = 0;
  const double tilt =
      writeImu(in, {{400, "1e308"}, {800, "1e38"}, {1200, "1e6"}}, 1e9, 1e9, 3000, &written);
  const CliResult r = cli({"orientation", in.string(), "--out", out.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = readCsv(out);
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(written) + 1);  // a row for every input row
  EXPECT_EQ(rows[0], (std::vector<std::string>{"t", "qw", "qx", "qy", "qz", "flag"}));
  int flagged = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 6u) << i;
    for (const std::string& c : rows[i]) {
      ASSERT_TRUE(std::isfinite(std::stod(c))) << "row " << i << ": " << c;
    }
    if (rows[i][5] == "1") ++flagged;
  }
  EXPECT_EQ(flagged, 3);
  // Row 400 is line 402 (header first).
  EXPECT_NE(r.err.find("3 row(s) rejected"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("3 at or beyond"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("line 402 (t = 2 s), line 802 (t = 4 s), line 1202 (t = 6 s)"),
            std::string::npos)
      << r.err;
  // The last orientation still has the true tilt.
  const auto& last = rows.back();
  const Eigen::Quaterniond q(std::stod(last[1]), std::stod(last[2]), std::stod(last[3]),
                             std::stod(last[4]));
  const Eigen::Vector3d up = q.conjugate() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d upTrue =
      Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()).inverse() * Eigen::Vector3d::UnitZ();
  EXPECT_LT(std::acos(std::min(1.0, up.dot(upTrue))), 1.0 * kToRad);
}

TEST_F(OrientationCliTest, NonFiniteSensorCellsRejectTheRowNotTheFile) {
  const fs::path in = path("imu.csv"), out = path("quat.csv");
  int written = 0;
  writeImu(in, {{300, "nan"}, {301, "-inf"}, {302, "1e999"}}, 1e9, 1e9, 1000, &written);
  const CliResult r = cli({"orientation", in.string(), "--out", out.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = readCsv(out);
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(written) + 1);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 6u) << i;
    EXPECT_EQ(rows[i][5], i >= 301 && i <= 303 ? "1" : "0") << i;
    for (const std::string& c : rows[i]) ASSERT_TRUE(std::isfinite(std::stod(c))) << i;
  }
  EXPECT_NE(r.err.find("3 not finite"), std::string::npos) << r.err;
  // A time that is not a number still cannot be placed: that is an error with line and column.
  std::ofstream(in, std::ios::app) << "nan,0,0,0,0,0,9.81\n";
  const CliResult bad = cli({"orientation", in.string(), "--out", out.string(), "--overwrite"});
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find(":1002:1:"), std::string::npos) << bad.err;
}

TEST_F(OrientationCliTest, GapIsReportedAndMarkedAndTheTiltRecovers) {
  const fs::path in = path("imu.csv"), out = path("quat.csv");
  int written = 0;
  const double tilt = writeImu(in, {}, 5.0, 10.0, 2800, &written);  // ends 4 s after the gap
  const CliResult r = cli({"orientation", in.string(), "--out", out.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = readCsv(out);
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(written) + 1);
  int afterGap = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 6u) << i;
    afterGap += rows[i][5] == "2";
  }
  EXPECT_EQ(afterGap, 1);
  EXPECT_NE(r.err.find("1 gap(s) in time longer than 0.1 s"), std::string::npos) << r.err;
  const auto& last = rows.back();
  const Eigen::Quaterniond q(std::stod(last[1]), std::stod(last[2]), std::stod(last[3]),
                             std::stod(last[4]));
  const Eigen::Vector3d up = q.conjugate() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d upTrue =
      Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()).inverse() * Eigen::Vector3d::UnitZ();
  EXPECT_LT(std::acos(std::min(1.0, up.dot(upTrue))), 2.0 * kToRad);
}

}  // namespace
