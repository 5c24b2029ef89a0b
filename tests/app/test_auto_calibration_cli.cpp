// "armtrack-cli estimate" without --calibration tries the calibration from movement on the first
// 60 s (app/cli/AutoCalibration.h): a recording with straps turned 25 deg estimates far better
// than the old path (--no-auto-calibration), a recording the sidecar already describes keeps its
// output byte for byte, a recording with no rest or too short says "not tried" and why, and
// hostile readings (not numbers, saturated) do not break it.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
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
using armtrack::test::reportedRmse;

class AutoCalibrationCli : public armtrack::test::TempDirTest {
 protected:
  AutoCalibrationCli() : TempDirTest("armtrack_autocal_cli_") {}

  fs::path simulate(const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = {"simulate", "--out", path(name).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliResult r = cli(args);
    EXPECT_EQ(r.code, 0) << r.err;
    return path(name);
  }
};

std::string fileText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string movementLine(const std::string& err) {
  const auto at = err.find("calibration from movement: ");
  if (at == std::string::npos) return {};
  return err.substr(at, err.find('\n', at) - at);
}

TEST_F(AutoCalibrationCli, MisalignedStrapsEstimateFarBetterThanTheOldPath) {
  // The protocol's movements (rests included) with real MEMS errors and both straps turned
  // 25 deg about a random axis.
  const fs::path rec = simulate("mis.csv", {"--trajectory", "calibration", "--seed", "21",
                                            "--misalignment", "25", "--sensors", "realistic"});
  for (const bool kinect : {true, false}) {
    std::vector<std::string> args = {"estimate", rec.string()};
    if (!kinect) args.push_back("--no-kinect");
    const CliResult now = cli(args);
    ASSERT_EQ(now.code, 0) << now.err;
    args.push_back("--no-auto-calibration");
    const CliResult old = cli(args);
    ASSERT_EQ(old.code, 0) << old.err;
    const std::string line = movementLine(now.err);
    EXPECT_NE(line.find("; applied"), std::string::npos) << now.err;
    // The simulator turned each sensor by 25 deg: the line says about that much.
    const auto at = line.find("upper-arm sensor turned ");
    ASSERT_NE(at, std::string::npos) << line;
    const double upperDeg = std::stod(line.substr(at + 24));
    EXPECT_NEAR(upperDeg, 25.0, 4.0) << line;
    const auto fa = line.find(", forearm sensor ");
    ASSERT_NE(fa, std::string::npos) << line;
    EXPECT_NEAR(std::stod(line.substr(fa + 17)), 25.0, 4.0) << line;
    EXPECT_TRUE(movementLine(old.err).empty()) << old.err;
    const std::vector<double> a = reportedRmse(now.out), b = reportedRmse(old.out);
    ASSERT_EQ(a.size(), 5u) << now.out;
    ASSERT_EQ(b.size(), 5u) << old.out;
    double sumA = 0.0, sumB = 0.0;
    for (int j = 0; j < 5; ++j) {
      sumA += a[j];
      sumB += b[j];
    }
    // The whole arm is clearly better, and the elbow, which the calibration fixes best, is.
    EXPECT_LT(sumA, 0.5 * sumB) << "kinect " << kinect << "\n" << now.out << old.out;
    EXPECT_LT(a[3], 0.5 * b[3]) << now.out << old.out;
  }
}

// The fitted mounting is judged with Method A's filter whatever --method says: judged with
// Method B's or C's own, whose angles explain the readings roughly with any mounting, a patient's
// session with straps turned 30 deg kept the sidecar's mounting without optics ("not applied",
// then errors of 40-80 deg; issue 27, acceptance 3).
TEST_F(AutoCalibrationCli, MethodsBAndCApplyTheFitToo) {
  const fs::path rec = simulate(
      "bc.csv", {"--trajectory", "session", "--seed", "921", "--duration", "60", "--peak-rate",
                 "150", "--misalignment", "30", "--sensors", "realistic", "--no-kinect"});
  for (const char* method : {"B", "C"}) {
    const CliResult r = cli({"estimate", rec.string(), "--method", method});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(movementLine(r.err).find("; applied"), std::string::npos)
        << "Method " << method << ": " << r.err;
  }
}

TEST_F(AutoCalibrationCli, AlignedRecordingKeepsItsOutputByteForByte) {
  const fs::path rec =
      simulate("ok.csv", {"--trajectory", "calibration", "--seed", "22", "--imu-rate", "200"});
  const fs::path a = path("a.csv"), b = path("b.csv");
  const CliResult now = cli({"estimate", rec.string(), "--out", a.string()});
  ASSERT_EQ(now.code, 0) << now.err;
  const CliResult old =
      cli({"estimate", rec.string(), "--out", b.string(), "--no-auto-calibration"});
  ASSERT_EQ(old.code, 0) << old.err;
  EXPECT_NE(movementLine(now.err).find("not applied"), std::string::npos) << now.err;
  const std::string x = fileText(a), y = fileText(b);
  EXPECT_GT(x.size(), 1000u);
  EXPECT_TRUE(x == y) << "the outputs differ";
  EXPECT_EQ(now.out, old.out);
}

TEST_F(AutoCalibrationCli, NoRestOrTooShortIsNotTriedAndSaysWhy) {
  const fs::path moving = simulate("moving.csv", {"--trajectory", "reaching", "--duration", "20",
                                                  "--seed", "23", "--imu-rate", "100"});
  CliResult r = cli({"estimate", moving.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  std::string line = movementLine(r.err);
  EXPECT_NE(line.find("not tried"), std::string::npos) << r.err;
  EXPECT_NE(line.find("no moment of rest"), std::string::npos) << line;

  const fs::path brief = simulate("short.csv", {"--trajectory", "calibration", "--duration", "5",
                                                "--seed", "23", "--imu-rate", "100"});
  r = cli({"estimate", brief.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  line = movementLine(r.err);
  EXPECT_NE(line.find("not tried"), std::string::npos) << r.err;
  EXPECT_NE(line.find("only 5"), std::string::npos) << line;

  // The expert's flag: no attempt, no line.
  r = cli({"estimate", brief.string(), "--no-auto-calibration"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(movementLine(r.err).empty()) << r.err;
}

TEST_F(AutoCalibrationCli, HostileReadingsDoNotBreakIt) {
  const fs::path rec = simulate("mis.csv", {"--trajectory", "calibration", "--seed", "24",
                                            "--misalignment", "25", "--sensors", "realistic"});
  Recording r = readRecording(rec);
  int k = 0;
  for (ArmSample& s : r.samples) {
    if (!s.upperArm) continue;
    ++k;
    if (k % 11 == 0) s.forearm->acc = {1e6, -1e6, 1e6};      // far beyond any range
    if (k % 13 == 0) s.upperArm->gyr = {500.0, 500.0, 0.0};  // saturated
    if (k % 17 == 0) s.upperArm.reset();                     // a sensor missing a row
  }
  const fs::path bad = path("bad.csv");
  writeRecording(bad, r);
  const CliResult a = cli({"estimate", bad.string(), "--out", path("a.csv").string()});
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_FALSE(movementLine(a.err).empty()) << a.err;
  const std::vector<double> rmse = reportedRmse(a.out);
  EXPECT_EQ(rmse.size(), 5u) << a.out;
  for (double v : rmse) EXPECT_TRUE(std::isfinite(v)) << a.out;

  // A reading that is not a number makes the file malformed: the estimate fails as it did
  // without the calibration from movement, and the line says it was not tried.
  writeRecording(bad, r);
  std::string text = fileText(bad);
  const auto row = text.find('\n', text.find('\n') + 1) + 1;  // the second data row
  const auto cell = text.find(',', row) + 1;                  // its second column
  text.replace(cell, text.find(',', cell) - cell, "nan");
  std::ofstream(bad, std::ios::binary | std::ios::trunc) << text;
  const CliResult b = cli({"estimate", bad.string()});
  const CliResult c = cli({"estimate", bad.string(), "--no-auto-calibration"});
  EXPECT_EQ(b.code, 1) << b.err;
  EXPECT_EQ(b.code, c.code) << b.err << c.err;
  EXPECT_NE(movementLine(b.err).find("not tried"), std::string::npos) << b.err;
  EXPECT_NE(b.err.find("not a finite number"), std::string::npos) << b.err;
}

}  // namespace
}  // namespace armtrack
