// armtrack-cli simulate --pendulum, baseline and study baseline, in-process through runCli: the
// pendulum's recording reads back with its truth, the baseline writes estimate's column names for
// its angles and reports its error, and hostile input gets a clear error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/io/Recording.h"
#include "core/kinematics/ArmModel.h"
#include "tests/app/CliRun.h"
#include "tests/support/TempDirTest.h"

namespace fs = std::filesystem;

namespace {

using armtrack::test::cli;
using armtrack::test::CliResult;

class BaselineCliTest : public armtrack::test::TempDirTest {
 protected:
  BaselineCliTest() : TempDirTest("armtrack_baseline_cli_") {}
};

std::vector<std::string> lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST_F(BaselineCliTest, PendulumRecordingRunsThroughTheBaseline) {
  const fs::path rec = path("pendulum.csv"), est = path("baseline.csv");
  CliResult r = cli({"simulate", "--pendulum", "--out", rec.string(), "--duration", "8", "--rate",
                     "90", "--gyro-rate", "50", "--accel-rate", "25", "--zero", "35"});
  ASSERT_EQ(r.code, 0) << r.err;
  const armtrack::Recording read = armtrack::readRecording(rec);
  ASSERT_EQ(read.samples.size(), 721u);
  ASSERT_TRUE(read.samples.back().trueAngles.has_value());

  r = cli({"baseline", rec.string(), "--out", est.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto out = lines(est);
  ASSERT_EQ(out.size(), 722u);
  EXPECT_EQ(out[0], "t,th4,th5,elevation");
  EXPECT_NE(r.out.find("th4 elbow flexion/extension"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("humerus elevation"), std::string::npos) << r.out;

  // The output exists now: refused without --overwrite.
  r = cli({"baseline", rec.string(), "--out", est.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--overwrite"), std::string::npos) << r.err;
}

TEST_F(BaselineCliTest, HostileInputGetsClearErrors) {
  const fs::path rec = path("r.csv");
  CliResult r = cli({"simulate", "--pendulum", "--out", rec.string(), "--rate", "0"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--rate"), std::string::npos) << r.err;
  r = cli({"simulate", "--pendulum", "--out", rec.string(), "--swing", "nan"});
  EXPECT_EQ(r.code, 2) << r.err;
  r = cli({"simulate", "--pendulum", "--out", rec.string(), "--zero", "1e9"});
  EXPECT_EQ(r.code, 2) << r.err;
  r = cli({"baseline", path("missing.csv").string()});
  EXPECT_EQ(r.code, 1);
  r = cli({"baseline"});
  EXPECT_EQ(r.code, 2);
  r = cli({"baseline", rec.string(), "--time-constant", "0"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--time-constant"), std::string::npos) << r.err;
  r = cli({"study", "baseline", "--duration", "1"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--duration"), std::string::npos) << r.err;

  // A recording without an upper-arm IMU: nothing the baseline can estimate, said so.
  {
    std::ofstream f(path("forearm.csv"));
    f << "t,fa_gx,fa_gy,fa_gz,fa_ax,fa_ay,fa_az\n0,0,0,0,-9.81,0,0\n0.01,0,0,0,-9.81,0,0\n";
  }
  r = cli({"baseline", path("forearm.csv").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("upper-arm IMU"), std::string::npos) << r.err;

  // A NaN cell: the reader refuses the file, naming the line.
  {
    std::ofstream f(path("nan.csv"));
    f << "t,ua_gx,ua_gy,ua_gz,ua_ax,ua_ay,ua_az\n0,0,0,0,-9.81,0,0\n0.01,nan,0,0,-9.81,0,0\n";
  }
  r = cli({"baseline", path("nan.csv").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("nan.csv:3"), std::string::npos) << r.err;

  // Without a forearm IMU: the elevation only, with a warning. The arm hangs (the model's reading
  // at the zero pose), so the elevation is 0.
  const armtrack::ArmPrediction hanging = armtrack::predictSensors(
      armtrack::ArmGeometry{}, armtrack::JointVector::Zero(), armtrack::JointVector::Zero(),
      armtrack::JointVector::Zero(), Eigen::Vector3d(-9.81, 0, 0));
  {
    std::ofstream f(path("upper.csv"));
    f.precision(17);
    f << "t,ua_gx,ua_gy,ua_gz,ua_ax,ua_ay,ua_az\n";
    for (double t : {0.0, 0.01, 0.02})
      f << t << ",0,0,0," << hanging.upper.acc.x() << "," << hanging.upper.acc.y() << ","
        << hanging.upper.acc.z() << "\n";
  }
  r = cli({"baseline", path("upper.csv").string(), "--out", path("u.csv").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("no forearm IMU"), std::string::npos) << r.err;
  const auto out = lines(path("u.csv"));
  ASSERT_EQ(out.size(), 4u);
  ASSERT_EQ(out[3].substr(0, 7), "0.02,,,") << out[3];            // th4 and th5 empty
  EXPECT_NEAR(std::stod(out[3].substr(7)), 0.0, 1e-9) << out[3];  // the elevation
}

}  // namespace
