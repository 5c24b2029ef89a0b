// "armtrack-cli record" fits the straps from the movement as the session goes (no calibration
// file is given to a live session; docs/cli.md, "record"): a patient whose straps are turned
// 25 deg, replayed at 10x, gets a fit that is applied and told, and kept beside the recording;
// "estimate --calibration" with the kept file reproduces the fitted estimate offline, far better
// than the sidecar's mounting. --no-auto-calibration switches it off.
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/CliRun.h"

namespace armtrack {
namespace {

namespace fs = std::filesystem;
using armtrack::test::CliResult;
using armtrack::test::reportedRmse;

CliResult run(std::vector<std::string> args, bool plugins) {
  if (plugins) {
    args.push_back("--plugins");
    args.push_back(ARMTRACK_PLUGIN_DIR);
  }
  return armtrack::test::cli(args);
}

class RecordAutoCalibration : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    turned_ = path("turned.csv");
    const CliResult sim =
        run({"simulate", "--trajectory", "session", "--duration", "110", "--seed", "31",
             "--misalignment", "25", "--imu-rate", "100", "--no-kinect", "--out", turned_.string()},
            false);
    ASSERT_EQ(sim.code, 0) << sim.err;
  }
  fs::path path(const std::string& name) const {
    return fs::path(dir_.path().toStdString()) / name;
  }
  CliResult record(const fs::path& out, bool automatic) {
    std::vector<std::string> args = {
        "record", "--device",  "replay:speed=10,file=" + turned_.string(), "--duration", "200",
        "--out",  out.string()};
    if (!automatic) args.push_back("--no-auto-calibration");
    return run(args, true);
  }
  QTemporaryDir dir_;
  fs::path turned_;
};

double worstOfFour(const std::vector<double>& rmse) {
  double worst = 0.0;
  for (std::size_t j = 0; j < 4 && j < rmse.size(); ++j) worst = std::max(worst, rmse[j]);
  return worst;
}

TEST_F(RecordAutoCalibration, FittedStrapsAreToldKeptAndReproducedOffline) {
  const fs::path live = path("live.csv");
  const CliResult r = record(live, true);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("calibration from movement: upper-arm sensor turned"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("; applied"), std::string::npos) << r.err;
  const fs::path kept = path("live.movement-calibration.json");
  ASSERT_TRUE(fs::exists(kept)) << r.err;
  // Offline with the kept straps, and with the sidecar's (the old path).
  const CliResult with = run({"estimate", live.string(), "--calibration", kept.string()}, false);
  ASSERT_EQ(with.code, 0) << with.err;
  const CliResult without = run({"estimate", live.string(), "--no-auto-calibration"}, false);
  ASSERT_EQ(without.code, 0) << without.err;
  const std::vector<double> a = reportedRmse(with.out), b = reportedRmse(without.out);
  ASSERT_EQ(a.size(), 5u) << with.out;
  ASSERT_EQ(b.size(), 5u) << without.out;
  std::printf("[ figures  ] worst RMSE of th0-th4: %.2f deg with the kept straps, %.2f without\n",
              worstOfFour(a), worstOfFour(b));
  EXPECT_LT(worstOfFour(a), 3.0) << with.out;
  EXPECT_GT(worstOfFour(b), 3.0 * worstOfFour(a)) << without.out;
}

TEST_F(RecordAutoCalibration, SwitchedOffNothingIsFittedOrKept) {
  const fs::path live = path("off.csv");
  const CliResult r = record(live, false);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("calibration from movement"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("off.movement-calibration.json")));
}

}  // namespace
}  // namespace armtrack
