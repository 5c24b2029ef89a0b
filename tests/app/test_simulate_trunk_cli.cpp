// simulate's trunk options (app/cli/SimulateTrunk.h): what they set in the simulation, the
// values they refuse, their help, and the recording they write.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/Args.h"
#include "app/cli/SimulateTrunk.h"
#include "core/io/Recording.h"
#include "tests/app/CliRun.h"
#include "tests/support/TempDirTest.h"

namespace fs = std::filesystem;

namespace armtrack::cli {
namespace {

using armtrack::test::cli;
using armtrack::test::CliResult;

constexpr double kDeg = std::numbers::pi / 180.0;

SimulationParams applied(const std::vector<std::string>& args, std::string* warnings = nullptr) {
  SimulationParams sim = defaultSimulation();
  sim.seed = 9;
  sim.upperArm.rateHz = 200.0;
  sim.upperArm.gyroBias.setConstant(0.01);
  const Args a("simulate", args, trunkOptionSpecs());
  std::ostringstream err;
  applyTrunkOptions(a, sim, 0.0, err);
  if (warnings) *warnings = err.str();
  return sim;
}

TEST(SimulateTrunkCli, WithoutTheOptionsTheTrunkIsStillAndUnseen) {
  std::string warnings;
  const SimulationParams sim = applied({}, &warnings);
  EXPECT_FALSE(sim.trunk.enabled);
  EXPECT_FALSE(sim.trunkImu.enabled);
  EXPECT_FALSE(sim.kinect.shoulder.has_value());
  EXPECT_TRUE(warnings.empty()) << warnings;
}

TEST(SimulateTrunkCli, OptionsSetTheTrunkTheSternumAndTheShoulder) {
  const SimulationParams sim =
      applied({"--trunk-lean", "12", "--trunk-lateral", "-0.3", "--trunk-rotation", "0.75",
               "--trunk-sway", "0.5", "--trunk-imu", "--no-kinect-shoulder"});
  EXPECT_TRUE(sim.trunk.enabled);
  EXPECT_EQ(sim.trunk.leanDeg, 12.0);
  EXPECT_EQ(sim.trunk.lateralRatio, 0.3);
  EXPECT_EQ(sim.trunk.lateralSign, -1.0);  // towards the patient's left
  EXPECT_EQ(sim.trunk.rotationRatio, 0.75);
  EXPECT_EQ(sim.trunk.rotationSign, 1.0);
  EXPECT_EQ(sim.trunk.swayDeg, 0.5);
  EXPECT_EQ(sim.trunk.swaySeed, 9u);
  // The sternum IMU: the arm IMUs' rate, noise and bias.
  EXPECT_TRUE(sim.trunkImu.enabled);
  EXPECT_EQ(sim.trunkImu.rateHz, 200.0);
  EXPECT_EQ(sim.trunkImu.gyroNoiseStd, Table5::gyroStd());
  EXPECT_EQ(sim.trunkImu.gyroBias, Eigen::Vector3d::Constant(0.01));
  ASSERT_TRUE(sim.kinect.shoulder.has_value());
  EXPECT_FALSE(*sim.kinect.shoulder);
  const SimulationParams on = applied({"--kinect-shoulder"});
  EXPECT_TRUE(on.kinect.shoulder.value_or(false));
  EXPECT_FALSE(on.trunk.enabled);
}

TEST(SimulateTrunkCli, OptionsWithoutALeanAreIgnoredWithAWarning) {
  std::string warnings;
  const SimulationParams sim = applied({"--trunk-sway", "2"}, &warnings);
  EXPECT_FALSE(sim.trunk.enabled);
  EXPECT_NE(warnings.find("--trunk-sway only applies with --trunk-lean"), std::string::npos)
      << warnings;
}

TEST(SimulateTrunkCli, RefusesValuesOutOfRange) {
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"--trunk-lean", "90"}, "--trunk-lean: must be between 0 and 45, got 90"},
      {{"--trunk-lean", "-5"}, "--trunk-lean: must be between 0 and 45"},
      {{"--trunk-lean", "abc"}, "--trunk-lean: expected a number"},
      {{"--trunk-lean", "nan"}, "--trunk-lean: expected a number"},
      {{"--trunk-lean", "10", "--trunk-lateral", "3"}, "--trunk-lateral: must be between -2 and 2"},
      {{"--trunk-lean", "10", "--trunk-sway", "1e9"}, "--trunk-sway: must be between 0 and 5"},
      {{"--kinect-shoulder", "--no-kinect-shoulder"}, "contradict each other"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"simulate", "--trajectory", "reaching", "--out",
                                     "unused-trunk-cli.csv"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const CliResult r = cli(args);
    EXPECT_EQ(r.code, 2) << c.message;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists("unused-trunk-cli.csv"));
  }
}

TEST(SimulateTrunkCli, HelpListsTheOptions) {
  const CliResult r = cli({"simulate", "--help"});
  EXPECT_EQ(r.code, 0);
  for (const char* o :
       {"--trunk-lean DEG", "--trunk-lateral R", "--trunk-rotation R", "--trunk-sway DEG",
        "--trunk-imu", "--kinect-shoulder", "--no-kinect-shoulder"})
    EXPECT_NE(r.out.find(o), std::string::npos) << o;
}

class SimulateTrunkFile : public armtrack::test::TempDirTest {
 protected:
  SimulateTrunkFile() : TempDirTest("armtrack_trunk_cli_") {}
};

// Needs the recording format's trunk columns and sidecar block (core/io, issue 26).
TEST_F(SimulateTrunkFile, TheRecordingCarriesTheSternumTheShoulderAndTheTruth) {
  const fs::path rec = path("leaning.csv");
  const CliResult r = cli({"simulate", "--trajectory", "reaching", "--peak-rate", "120",
                           "--peak-accel", "600", "--duration", "8", "--imu-rate", "200",
                           "--trunk-lean", "15", "--trunk-imu", "--out", rec.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const Recording back = readRecording(rec);
  ASSERT_TRUE(back.meta.trunk.has_value());
  EXPECT_TRUE(
      back.meta.trunk->imuRotation.isApprox(defaultSimulatedTrunkMount(Side::Right).imuRotation));
  EXPECT_TRUE(
      back.meta.trunk->imuPosition.isApprox(defaultSimulatedTrunkMount(Side::Right).imuPosition));
  int imuRows = 0, sternum = 0, truth = 0, shoulders = 0;
  double largestLean = 0.0;
  for (const ArmSample& s : back.samples) {
    imuRows += s.upperArm.has_value();
    sternum += s.trunk.has_value();
    shoulders += s.shoulder.has_value();
    if (s.trueTrunk) {
      ++truth;
      largestLean = std::max(largestLean, s.trueTrunk->x());
      EXPECT_LE(s.trueTrunk->x(), 15.0 * kDeg + 1e-9);
    }
    if (s.trunk) {
      EXPECT_NEAR(s.trunk->acc.norm(), 9.81, 3.0);  // gravity plus a slow lean
    }
  }
  EXPECT_EQ(imuRows, 1601);
  EXPECT_EQ(sternum, imuRows);
  EXPECT_EQ(truth, imuRows);
  EXPECT_EQ(shoulders, 241);  // 30 Hz over 8 s: the Kinect reports the moving trunk's shoulder
  EXPECT_GT(largestLean, 5.0 * kDeg);
}

}  // namespace
}  // namespace armtrack::cli
