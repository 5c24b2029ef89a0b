// simulate --sensors (core/simulation/ImuErrors.h): the realistic preset writes a recording that
// estimate reads, on the logger's 90 Hz clock with held samples and the truth of the ideal run;
// an unknown model is refused with a message naming the option.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/io/Recording.h"
#include "tests/app/CliRun.h"
#include "tests/support/TempDirTest.h"

namespace fs = std::filesystem;

namespace armtrack {
namespace {

using armtrack::test::cli;
using armtrack::test::CliResult;

class SimulateSensors : public armtrack::test::TempDirTest {
 protected:
  SimulateSensors() : TempDirTest("armtrack_sensors_cli_") {}
};

TEST_F(SimulateSensors, RealisticWritesARecordingThatEstimateReads) {
  const fs::path real = path("real.csv"), ideal = path("ideal.csv");
  const std::vector<std::string> common = {
      "simulate", "--trajectory", "multi-joint", "--duration", "12", "--seed", "3"};
  std::vector<std::string> args = common;
  args.insert(args.end(), {"--sensors", "realistic", "--out", real.string()});
  CliResult r = cli(args);
  ASSERT_EQ(r.code, 0) << r.err;
  args = common;
  args.insert(args.end(), {"--sensors", "ideal", "--imu-rate", "90", "--out", ideal.string()});
  r = cli(args);
  ASSERT_EQ(r.code, 0) << r.err;

  const Recording a = readRecording(real), b = readRecording(ideal);
  ASSERT_EQ(a.samples.size(), b.samples.size());  // the same 90 Hz clock and Kinect rows
  int imuRows = 0, repeats = 0;
  const ArmSample* last = nullptr;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    const ArmSample &x = a.samples[i], &y = b.samples[i];
    EXPECT_EQ(x.t, y.t);
    ASSERT_EQ(x.trueAngles.has_value(), y.trueAngles.has_value());
    if (x.trueAngles) {
      // The truth is the segments' angles, the same as with ideal sensors (to the CSV's digits).
      EXPECT_LT((*x.trueAngles - *y.trueAngles).cwiseAbs().maxCoeff(), 1e-12);
    }
    if (!x.upperArm) continue;
    if (last && x.forearm->acc == last->forearm->acc) ++repeats;
    last = &x;
    ++imuRows;
  }
  EXPECT_EQ(imuRows, 12 * 90 + 1);
  EXPECT_GT(repeats, imuRows / 2);  // the 25 Hz accelerometer held on the 90 Hz clock

  r = cli({"estimate", real.string(), "--out", path("angles.csv").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("elbow flexion"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(path("angles.csv")));
}

TEST_F(SimulateSensors, UnknownModelIsRefusedNamingTheOption) {
  const fs::path out = path("never.csv");
  const CliResult r =
      cli({"simulate", "--trajectory", "multi-joint", "--sensors", "bogus", "--out", out.string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--sensors"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'bogus'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ideal or realistic"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(SimulateSensorsHelp, ListsTheOption) {
  const CliResult r = cli({"simulate", "--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--sensors MODEL"), std::string::npos);
}

}  // namespace
}  // namespace armtrack
