// armtrack-cli estimate on several recordings (--out-dir, in parallel): every good recording gives
// the same files as a single-file run, a corrupt one is reported by name with its error and does
// not stop the others, and the exit status says that one failed.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/Cli.h"
#include "core/io/Recording.h"
#include "tests/app/CliRun.h"
#include "tests/support/TempDirTest.h"

namespace fs = std::filesystem;

namespace {

using armtrack::test::cli;
using armtrack::test::CliResult;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::set<std::string> filesIn(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

class EstimateBatchTest : public armtrack::test::TempDirTest {
 protected:
  EstimateBatchTest() : TempDirTest("armtrack_batch_") {}
  void SetUp() override {
    TempDirTest::SetUp();
    fs::create_directories(m_dir / "in");
  }

  /// Recordings of different kinds in in/: Kinect, IMUs only, webcam, a left arm.
  std::vector<fs::path> goodRecordings() {
    const std::vector<std::vector<std::string>> kinds = {
        {"--seed", "3"},
        {"--seed", "4", "--no-kinect"},
        {"--seed", "5", "--webcam"},
        {"--seed", "6", "--side", "left", "--imu-rate", "500"}};
    std::vector<fs::path> recs;
    for (std::size_t i = 0; i < kinds.size(); ++i) {
      const fs::path p = path("in") / ("rec" + std::to_string(i) + ".csv");
      std::vector<std::string> args = {"simulate", "--trajectory", "multi-joint", "--duration",
                                       "4",        "--out",        p.string()};
      args.insert(args.end(), kinds[i].begin(), kinds[i].end());
      const CliResult r = cli(args);
      EXPECT_EQ(r.code, 0) << r.err;
      recs.push_back(p);
    }
    return recs;
  }

  /// A copy of good whose row 1500 holds a word where a number belongs.
  fs::path corruptCopy(const fs::path& good, const std::string& name) {
    std::istringstream in(slurp(good));
    std::string text;
    int lineNo = 0;
    for (std::string line; std::getline(in, line);) {
      if (++lineNo == 1500)
        line = line.substr(0, line.find(',')) + ",oops" +
               line.substr(line.find(',', line.find(',') + 1));
      text += line + "\n";
    }
    const fs::path p = path("in") / name;
    std::ofstream(p, std::ios::binary) << text;
    fs::copy_file(armtrack::sidecarPath(good), armtrack::sidecarPath(p));
    return p;
  }
};

const std::vector<std::string> kOptions = {"--joint-accel-std", "10"};

TEST_F(EstimateBatchTest, EveryGoodRecordingIsEstimatedAndTheCorruptOneReported) {
  const std::vector<fs::path> good = goodRecordings();
  const fs::path bad = corruptCopy(good[0], "broken.csv");
  const fs::path out = path("out");  // made by the command

  std::vector<std::string> args = {"estimate"};
  for (const fs::path& p : good) args.push_back(p.string());
  args.insert(args.begin() + 3, bad.string());  // in the middle of the list
  args.insert(args.end(), {"--out-dir", out.string(), "--jobs", "2"});
  args.insert(args.end(), kOptions.begin(), kOptions.end());
  const CliResult batch = cli(args);

  EXPECT_EQ(batch.code, 1) << "one recording failed: " << batch.err;
  // The corrupt one, by name, with the reader's error (file:line:column).
  EXPECT_NE(batch.err.find(bad.string() + ": failed: " + bad.string() + ":1500:2: bad number"),
            std::string::npos)
      << batch.err;
  EXPECT_NE(batch.err.find("4 of 5 recordings estimated, 1 failed, in "), std::string::npos)
      << batch.err;
  EXPECT_NE(batch.err.find(" s on 2 threads; wrote "), std::string::npos) << batch.err;
  EXPECT_NE(batch.out.find("| " + bad.string() + " | - | - | - |"), std::string::npos) << batch.out;

  std::set<std::string> expected;
  for (const fs::path& rec : good) {
    SCOPED_TRACE(rec.string());
    const std::string stem = rec.stem().string();
    expected.insert({stem + ".csv", stem + ".md"});
    // The same recording alone gives the same angles, byte for byte, and the same report.
    const fs::path single = path(stem + "-single.csv");
    std::vector<std::string> one = {"estimate", rec.string(), "--out", single.string()};
    one.insert(one.end(), kOptions.begin(), kOptions.end());
    const CliResult r = cli(one);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string angles = slurp(out / (stem + ".csv"));
    EXPECT_GT(angles.size(), 100000u);
    EXPECT_TRUE(angles == slurp(single)) << "angles differ from a single-file run";
    const std::string report = slurp(out / (stem + ".md"));
    EXPECT_NE(report.find(r.out), std::string::npos) << report << "\n---\n" << r.out;
    EXPECT_NE(report.find("estimate: "), std::string::npos) << report;
    // Its row of the summary table says ok, with the rows the single run read.
    const std::string rows = r.err.substr(r.err.find(" estimates from ") + 16);
    EXPECT_NE(batch.out.find("| " + rec.string() + " | " + rows.substr(0, rows.find(' ')) + " |"),
              std::string::npos)
        << batch.out;
  }
  // Nothing else: no angles for the corrupt recording, no temporary file left behind.
  EXPECT_EQ(filesIn(out), expected);
  EXPECT_EQ(std::count(batch.out.begin(), batch.out.end(), '\n'), 2 + 5) << batch.out;
  std::size_t oks = 0;
  for (std::size_t at = 0; (at = batch.out.find(" | ok |\n", at)) != std::string::npos; ++at) ++oks;
  EXPECT_EQ(oks, good.size()) << batch.out;

  // All good: exit status 0, and the existing outputs are refused without --overwrite.
  std::vector<std::string> again = {"estimate"};
  for (const fs::path& p : good) again.push_back(p.string());
  again.insert(again.end(), {"--out-dir", out.string()});
  const CliResult refused = cli(again);
  EXPECT_EQ(refused.code, 1);
  EXPECT_NE(refused.err.find("exists; pass --overwrite"), std::string::npos) << refused.err;
  again.push_back("--overwrite");
  const CliResult ok = cli(again);
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_NE(ok.err.find("4 of 4 recordings estimated, 0 failed"), std::string::npos) << ok.err;
}

// Failures of every kind are per recording: a missing file, a header without rows, a file cut
// in the middle of a line with a row after it, a sidecar that is not JSON.
TEST_F(EstimateBatchTest, EachKindOfBadRecordingFailsAlone) {
  const std::vector<fs::path> good = goodRecordings();
  const fs::path empty = path("in") / "empty.csv";
  std::ofstream(empty) << "t,ua_gx,ua_gy,ua_gz,ua_ax,ua_ay,ua_az\n";
  const fs::path cut = path("in") / "cut.csv";
  {
    const std::string text = slurp(good[1]);
    std::ofstream(cut, std::ios::binary) << text.substr(0, text.size() / 2) << "\n1e9,1,2\n";
  }
  const fs::path badSidecar = path("in") / "sidecar.csv";
  fs::copy_file(good[2], badSidecar);
  std::ofstream(armtrack::sidecarPath(badSidecar)) << "{ not json";
  const fs::path missing = path("in") / "missing.csv";

  const CliResult r =
      cli({"estimate", empty.string(), good[0].string(), cut.string(), badSidecar.string(),
           missing.string(), "--out-dir", path("out").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(empty.string() + ": failed: " + empty.string() +
                       ": no IMU samples to estimate from"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(cut.string() + ": failed: " + cut.string() + ":"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(badSidecar.string() + ": failed: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(missing.string() + ": failed: " + missing.string() + ": no such file"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("1 of 5 recordings estimated, 4 failed"), std::string::npos) << r.err;
  EXPECT_EQ(filesIn(path("out")), (std::set<std::string>{"rec0.csv", "rec0.md"}));
}

TEST_F(EstimateBatchTest, StatisticsOnlyWithoutAnOutputFolder) {
  const std::vector<fs::path> good = goodRecordings();
  const CliResult r = cli({"estimate", good[0].string(), good[1].string(), "--jobs", "1"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("| " + good[1].string() + " |"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("2 of 2 recordings estimated, 0 failed, in "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("on 1 threads"), std::string::npos) << r.err;
  EXPECT_EQ(filesIn(path("in")).size(), 8u);  // four recordings and their sidecars, nothing more
}

TEST_F(EstimateBatchTest, UsageMistakesAreRefusedBeforeAnyWork) {
  const std::vector<fs::path> good = goodRecordings();
  fs::create_directories(path("other"));
  fs::copy_file(good[0], path("other") / "rec0.csv");
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{good[0].string(), (path("other") / "rec0.csv").string(), "--out-dir", path("o").string()},
       "would both be written as \"rec0.csv\""},
      {{good[0].string(), good[1].string(), "--out", path("a.csv").string()},
       "--out takes one recording"},
      {{good[0].string(), good[1].string(), "--method", "tao-hu"}, "one recording at a time"},
      {{good[0].string(), good[1].string(), "--jobs", "0"}, "--jobs: must be between"},
      {{good[0].string(), "--out-dir", path("in").string()}, "would overwrite the recording"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"estimate"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const CliResult r = cli(args);
    EXPECT_EQ(r.code, 2) << c.message << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
  }
  EXPECT_FALSE(fs::exists(path("o")));
  // An output folder that is a file.
  std::ofstream(path("file")) << "x";
  const CliResult r = cli({"estimate", good[0].string(), "--out-dir", path("file").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("is not a folder"), std::string::npos) << r.err;
}

}  // namespace
