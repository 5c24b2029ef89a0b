// armtrack-cli calibrate, driven in-process: a simulated protocol recording with misaligned,
// biased IMUs is calibrated, the file is applied to a recording, and bad input gets exit 1 or 2
// with a clear message. calibrateCommand throws like the other commands; cli() maps the
// exceptions to exit codes the way runCli does.
#include <gtest/gtest.h>

#include <unistd.h>

#include <Eigen/Geometry>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/Args.h"
#include "app/cli/Calibrate.h"
#include "app/cli/Cli.h"
#include "core/calibration/Calibration.h"
#include "core/io/Recording.h"

namespace fs = std::filesystem;

namespace armtrack {
namespace {

struct CliResult {
  int code;
  std::string out, err;
};

CliResult calibrateCli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  int code = 0;
  try {
    code = cli::calibrateCommand(args, out, err);
  } catch (const cli::UsageError& e) {
    err << "armtrack-cli: error: " << e.what() << "\n";
    code = 2;
  } catch (const std::exception& e) {
    err << "armtrack-cli: error: " << e.what() << "\n";
    code = 1;
  }
  return {code, out.str(), err.str()};
}

CliResult runCli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = cli::runCli(args, out, err);
  return {code, out.str(), err.str()};
}

class CalibrateCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = fs::temp_directory_path() /
            ("armtrack_calib_cli_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(m_dir);
    fs::create_directories(m_dir);
  }
  void TearDown() override { fs::remove_all(m_dir); }
  fs::path path(const std::string& name) const { return m_dir / name; }

  fs::path m_dir;
};

TEST_F(CalibrateCliTest, CalibratesASimulatedProtocolRecording) {
  const fs::path rec = path("protocol.csv");
  // "simulate --trajectory calibration" is registered in core (makeTrajectory).
  const CliResult sim =
      runCli({"simulate", "--trajectory", "calibration", "--duration", "57", "--seed", "4",
              "--misalignment", "10", "--gyro-bias", "0.0087", "--out", rec.string()});
  ASSERT_EQ(sim.code, 0) << sim.err;

  const fs::path calib = path("calib.json");
  const CliResult r = calibrateCli({rec.string(), "--out", calib.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("calibrate: iteration"), std::string::npos) << r.err;  // progress
  EXPECT_NE(r.out.find("| thu4 upper-arm strap angle (deg) |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("optical positions"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("rests on the start-pose"), std::string::npos) << r.out;

  const Calibration c = readCalibration(calib);
  EXPECT_TRUE(c.opticalUsed);
  EXPECT_FALSE(c.headingFromStartPoseOnly);
  // The simulator's bias was 0.0087 rad/s on every axis of both IMUs.
  EXPECT_LT((c.upperArm.gyroBias - Eigen::Vector3d::Constant(0.0087)).norm(), 5e-4);
  EXPECT_LT((c.forearm.gyroBias - Eigen::Vector3d::Constant(0.0087)).norm(), 5e-4);

  // Applying it to a recording: readings corrected, geometry in the sidecar metadata.
  Recording recording = readRecording(rec);
  const ArmSample before = recording.samples.front();
  std::ostringstream err;
  cli::applyCalibrationFile(calib, recording, err);
  EXPECT_EQ(recording.meta.geometry.thu4, c.geometry.thu4);
  EXPECT_TRUE(recording.samples.front().upperArm->gyr.isApprox(
      c.upperArm.rotation * (before.upperArm->gyr - c.upperArm.gyroBias)));
  EstimatorParams params;
  cli::applyCalibrationToParams(c, params);
  EXPECT_EQ(params.geometry.lf6, c.geometry.lf6);

  // A right-arm calibration refuses a left-arm recording.
  recording.meta.side = Side::Left;
  EXPECT_THROW(cli::applyCalibrationFile(calib, recording, err), std::runtime_error);
}

TEST_F(CalibrateCliTest, WithoutOpticalDataSaysTheHeadingRestsOnTheStartPose) {
  const fs::path rec = path("protocol.csv");
  ASSERT_EQ(runCli({"simulate", "--trajectory", "calibration", "--duration", "57", "--seed", "5",
                    "--no-kinect", "--out", rec.string()})
                .code,
            0);
  const fs::path calib = path("calib.json");
  const CliResult r = calibrateCli({rec.string(), "--out", calib.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rests on the start-pose assumption alone"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("held (needs optical data)"), std::string::npos) << r.out;
  const Calibration c = readCalibration(calib);
  EXPECT_TRUE(c.headingFromStartPoseOnly);
  Recording recording = readRecording(rec);
  std::ostringstream err;
  cli::applyCalibrationFile(calib, recording, err);
  EXPECT_NE(err.str().find("start-pose assumption"), std::string::npos) << err.str();
}

TEST_F(CalibrateCliTest, UsageAndInputErrors) {
  CliResult r = calibrateCli({"--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("Usage: armtrack-cli calibrate"), std::string::npos);

  r = calibrateCli({});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("missing the recording"), std::string::npos) << r.err;

  r = calibrateCli({"rec.csv"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--out is required"), std::string::npos) << r.err;

  r = calibrateCli({"rec.csv", "--out", "c.json", "--bogus"});
  EXPECT_EQ(r.code, 2);

  r = calibrateCli({path("missing.csv").string(), "--out", path("c.json").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("missing.csv: no such file"), std::string::npos) << r.err;

  // Too short for a calibration.
  const fs::path shortRec = path("short.csv");
  ASSERT_EQ(runCli({"simulate", "--trajectory", "multi-joint", "--duration", "3", "--out",
                    shortRec.string()})
                .code,
            0);
  r = calibrateCli({shortRec.string(), "--out", path("c.json").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("at least 10 s"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("c.json")));

  // Malformed calibration files name the file and the problem.
  const fs::path bad = path("bad.json");
  std::ofstream(bad) << "{\"format\": \"armtrack-recording\", \"version\": 1}";
  Recording recording = readRecording(shortRec);
  std::ostringstream err;
  try {
    cli::applyCalibrationFile(bad, recording, err);
    FAIL() << "no exception";
  } catch (const CalibrationError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(bad.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find("\"format\" must be \"armtrack-calibration\""), std::string::npos) << msg;
  }
}

// ---------------------------------------------------------------------------------------------
// The whole workflow through the dispatcher: calibrate on the protocol, then "estimate
// --calibration" on a session with the same mounting errors comes within 0.5 deg of a perfectly
// mounted session, where "estimate" without it is off by degrees.

// Per-joint RMSE (deg) from estimate's report table.
std::vector<double> reportedRmse(const std::string& report) {
  std::vector<double> rmse;
  std::istringstream in(report);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| th", 0) != 0) continue;
    const auto a = line.find('|', 1), b = line.find('|', a + 1);
    rmse.push_back(std::stod(line.substr(a + 1, b - a - 1)));
  }
  return rmse;
}

TEST_F(CalibrateCliTest, EstimateWithTheCalibrationMatchesPerfectMounting) {
  const std::vector<std::string> errors = {"--misalignment", "10", "--gyro-bias", "0.0087"};
  auto simulate = [&](const std::string& name, const std::string& trajectory, bool mounted) {
    std::vector<std::string> args = {"simulate", "--trajectory", trajectory,         "--seed",
                                     "5",        "--out",        path(name).string()};
    if (trajectory == "multi-joint") args.insert(args.end(), {"--duration", "20"});
    if (!mounted) args.insert(args.end(), errors.begin(), errors.end());
    const CliResult r = runCli(args);
    ASSERT_EQ(r.code, 0) << r.err;
  };
  simulate("protocol.csv", "calibration", false);
  simulate("session.csv", "multi-joint", false);
  simulate("perfect.csv", "multi-joint", true);

  const CliResult cal =
      runCli({"calibrate", path("protocol.csv").string(), "--out", path("calib.json").string()});
  ASSERT_EQ(cal.code, 0) << cal.err;
  EXPECT_EQ(cal.err.find("warning: the recording covers"), std::string::npos) << cal.err;

  auto estimate = [&](const std::string& name, bool calibrated) {
    std::vector<std::string> args = {"estimate", path(name).string(), "--joint-accel-std", "10"};
    if (calibrated) args.insert(args.end(), {"--calibration", path("calib.json").string()});
    const CliResult r = runCli(args);
    EXPECT_EQ(r.code, 0) << r.err;
    if (calibrated) EXPECT_NE(r.err.find("calibration: applied"), std::string::npos) << r.err;
    return reportedRmse(r.out);
  };
  const std::vector<double> perfect = estimate("perfect.csv", false);
  const std::vector<double> raw = estimate("session.csv", false);
  const std::vector<double> fixed = estimate("session.csv", true);
  ASSERT_EQ(perfect.size(), 5u);
  ASSERT_EQ(raw.size(), 5u);
  ASSERT_EQ(fixed.size(), 5u);
  double worstRaw = 0.0;
  for (int j = 0; j < 5; ++j) {
    EXPECT_LE(fixed[j], perfect[j] + 0.5) << "joint " << j;
    worstRaw = std::max(worstRaw, raw[j] - perfect[j]);
  }
  EXPECT_GT(worstRaw, 3.0);  // the mounting errors really matter
}

TEST_F(CalibrateCliTest, EstimateRefusesAMissingOrCorruptCalibration) {
  const CliResult sim = runCli({"simulate", "--trajectory", "multi-joint", "--duration", "2",
                                "--out", path("s.csv").string()});
  ASSERT_EQ(sim.code, 0) << sim.err;
  const CliResult missing =
      runCli({"estimate", path("s.csv").string(), "--calibration", path("nope.json").string()});
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.err.find("nope.json"), std::string::npos) << missing.err;
  std::ofstream(path("bad.json")) << "{ not json";
  const CliResult bad =
      runCli({"estimate", path("s.csv").string(), "--calibration", path("bad.json").string()});
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("bad.json"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace armtrack
