// armtrack-cli driven in-process through runCli: simulate/estimate round trips, the no-optical
// note, and the exit codes and messages of bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "app/cli/Cli.h"
#include "app/cli/Estimate.h"
#include "core/io/Recording.h"
#include "tests/app/CliRun.h"
#include "tests/support/TempDirTest.h"

namespace fs = std::filesystem;
using armtrack::cli::runCli;

namespace {

using armtrack::test::cli;
using armtrack::test::CliResult;

std::vector<std::string> readLines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

/// A scratch directory per test, with a 6 s and a 3 s multi-joint recording made on demand.
class CliTest : public armtrack::test::TempDirTest {
 protected:
  CliTest() : TempDirTest("armtrack_cli_") {}

  fs::path simulated(double duration) {
    const fs::path p = path("rec" + std::to_string(static_cast<int>(duration)) + ".csv");
    if (!fs::exists(p)) {
      const CliResult r = cli({"simulate", "--trajectory", "multi-joint", "--duration",
                               std::to_string(duration), "--seed", "3", "--out", p.string()});
      EXPECT_EQ(r.code, 0) << r.err;
    }
    return p;
  }
};

TEST_F(CliTest, SimulateThenEstimateRoundTrip) {
  const fs::path rec = simulated(6.0);
  EXPECT_TRUE(fs::exists(armtrack::sidecarPath(rec)));
  const fs::path angles = path("angles.csv");
  const CliResult r = cli({"estimate", rec.string(), "--filter", "ekf", "--joint-accel-std", "10",
                           "--out", angles.string()});
  ASSERT_EQ(r.code, 0) << r.err;

  const armtrack::Recording recording = armtrack::readRecording(rec);
  std::size_t imuRows = 0;
  for (const auto& s : recording.samples) imuRows += s.hasImu();
  const auto lines = readLines(angles);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], "t,th0,th1,th2,th4,th5,sd_th0,sd_th1,sd_th2,sd_th4,sd_th5,status");
  EXPECT_EQ(lines.size() - 1, imuRows);
  EXPECT_EQ(lines[1].substr(0, 2), "0,");
  // Every row: 12 numbers, positive standard deviations, status 2 on the first row (the start)
  // and 0 (fused) on nearly all others.
  std::size_t fused = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::vector<double> v;
    std::istringstream row(lines[i]);
    for (std::string cell; std::getline(row, cell, ',');) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 12u) << lines[i];
    for (int j = 6; j < 11; ++j) EXPECT_GT(v[j], 0.0) << lines[i];
    if (i == 1) {
      EXPECT_EQ(v[11], 2.0) << lines[i];
    }
    fused += v[11] == 0.0;
  }
  EXPECT_GE(fused, lines.size() - 3);

  // The printed table: one row per joint, RMSE in the third-to-last column.
  int tableRows = 0;
  std::istringstream table(r.out);
  for (std::string line; std::getline(table, line);) {
    if (!line.starts_with("| th")) continue;
    ++tableRows;
    const auto c2 = line.rfind('|', line.rfind('|') - 1);
    const auto c1 = line.rfind('|', c2 - 1);
    EXPECT_LE(std::stod(line.substr(c1 + 1, c2 - c1 - 1)), 1.0) << line;
  }
  EXPECT_EQ(tableRows, 5) << r.out;
  EXPECT_EQ(r.out.find("No optical data"), std::string::npos);

  // The same run through the library entry point.
  armtrack::cli::EstimateOptions opt;
  opt.jointAccelStdDeg = 10.0;
  const auto stats = armtrack::cli::estimateRecording(
      recording, armtrack::cli::makeParams(recording.meta, opt), nullptr);
  EXPECT_EQ(stats.estimates, imuRows);
  EXPECT_TRUE(stats.opticalUsed);
  EXPECT_GT(stats.truthCount, imuRows / 2);
  for (int j = 0; j < armtrack::kNumJoints; ++j) EXPECT_LE(stats.rmseDeg(j), 1.0) << "joint " << j;
}

TEST_F(CliTest, NoKinectPrintsHeadingNote) {
  const CliResult r = cli({"estimate", simulated(3.0).string(), "--no-kinect"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("No optical data: the arm's heading about the vertical is not observable "
                       "from IMUs alone"),
            std::string::npos)
      << r.out;
  // A 3 s recording: one window, after the start-up second, inside the data (it used to read
  // "first 10 s (1.0-11.0 s)" and "last 10 s (-0.0-10.0 s)").
  EXPECT_NE(r.out.find("| first 2.0 s (1.0-3.0 s) |"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("last"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("-0.0"), std::string::npos) << r.out;
}

// Issue 9: one absurd but finite IMU row used to stop every later estimate while estimate
// exited 0 with a table that looked fine. Now the row is refused, reported with its time, and
// every row still gets an estimate.
TEST_F(CliTest, AFiniteSpikeIsRefusedReportedAndEveryRowEstimated) {
  const fs::path rec = simulated(6.0);
  const fs::path spiked = path("spiked.csv");
  std::vector<std::string> lines = readLines(rec);
  ASSERT_GT(lines.size(), 3000u);
  // Line 0 names the format, line 1 is the header; line 3002 is near t = 2.9 s. Every upper-arm
  // value of that row becomes 6e36.
  std::vector<std::string> header;
  {
    std::istringstream h(lines[1]);
    for (std::string c; std::getline(h, c, ',');) header.push_back(c);
  }
  std::vector<std::string> cells;
  {
    std::istringstream row(lines[3002]);
    for (std::string c; std::getline(row, c, ',');) cells.push_back(c);
  }
  ASSERT_EQ(cells.size(), header.size());
  int replaced = 0;
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c].starts_with("ua_") && !cells[c].empty()) cells[c] = "6e36", ++replaced;
  ASSERT_EQ(replaced, 6);
  std::string joined;
  for (std::size_t c = 0; c < cells.size(); ++c) joined += (c ? "," : "") + cells[c];
  lines[3002] = joined;
  {
    std::ofstream out(spiked);
    for (const std::string& l : lines) out << l << "\n";
  }
  fs::copy_file(armtrack::sidecarPath(rec), armtrack::sidecarPath(spiked));
  const fs::path angles = path("angles.csv");
  const CliResult r = cli({"estimate", spiked.string(), "--out", angles.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("refused 1 implausible reading (beyond the sensor's range 1: upper-arm "
                       "IMU 1) at 2.9"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("got no estimate"), std::string::npos) << r.err;
  // One estimate per row with IMU data, plus the header.
  std::size_t imuRows = 0;
  for (const auto& smp : armtrack::readRecording(spiked).samples) imuRows += smp.hasImu();
  EXPECT_EQ(readLines(angles).size(), imuRows + 1);
  // The errors stay small after the spike (the table's RMSE column).
  std::istringstream table(r.out);
  int tableRows = 0;
  for (std::string line; std::getline(table, line);) {
    if (!line.starts_with("| th")) continue;
    ++tableRows;
    const auto c2 = line.rfind('|', line.rfind('|') - 1);
    const auto c1 = line.rfind('|', c2 - 1);
    EXPECT_LE(std::stod(line.substr(c1 + 1, c2 - c1 - 1)), 1.0) << line;
  }
  EXPECT_EQ(tableRows, 5) << r.out;
}

// Issue 9 item 12: Kinect-only recordings no longer print a webcam line, and a recording shorter
// than the start-up second says why it has no statistics.
TEST_F(CliTest, MessagesFitTheRecording) {
  const CliResult r = cli({"estimate", simulated(6.0).string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("webcam"), std::string::npos) << r.err;
  const fs::path shortRec = path("short.csv");
  ASSERT_EQ(cli({"simulate", "--trajectory", "multi-joint", "--duration", "0.8", "--out",
                 shortRec.string()})
                .code,
            0);
  const CliResult s = cli({"estimate", shortRec.string()});
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_EQ(s.err.find("no true angles in the recording"), std::string::npos) << s.err;
  EXPECT_NE(s.err.find("every estimate with true angles lies in the first 1 s"), std::string::npos)
      << s.err;
}

TEST_F(CliTest, MethodBAndUkfAccepted) {
  const fs::path rec = simulated(3.0);
  const CliResult b = cli({"estimate", rec.string(), "--method", "B"});
  EXPECT_EQ(b.code, 0) << b.err;
  EXPECT_NE(b.err.find("method B"), std::string::npos) << b.err;
  const CliResult u =
      cli({"estimate", rec.string(), "--filter", "ukf", "--out", path("u.csv").string()});
  EXPECT_EQ(u.code, 0) << u.err;
  EXPECT_NE(u.err.find("UKF"), std::string::npos) << u.err;
  EXPECT_TRUE(fs::exists(path("u.csv")));
}

// The IMUs' noise can be set for sensors noisier than Table 5's: a larger noise must widen every
// joint's standard deviation (the filter trusts the readings less), and a noise that is not a
// positive number is a usage error naming the option.
TEST_F(CliTest, ImuNoiseOptionsWidenTheStandardDeviations) {
  const fs::path rec = simulated(3.0);
  const auto meanSd = [&](const std::vector<std::string>& extra, const std::string& name) {
    std::vector<std::string> args = {"estimate", rec.string(), "--out", path(name).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliResult r = cli(args);
    EXPECT_EQ(r.code, 0) << r.err;
    std::vector<double> sum(5, 0.0);
    const auto lines = readLines(path(name));
    for (std::size_t i = 1; i < lines.size(); ++i) {
      std::vector<double> v;
      std::istringstream row(lines[i]);
      for (std::string cell; std::getline(row, cell, ',');) v.push_back(std::stod(cell));
      for (int j = 0; j < 5; ++j) sum[j] += v.at(6 + j) / double(lines.size() - 1);
    }
    return sum;
  };
  const std::vector<double> table5 = meanSd({}, "a.csv");
  const std::vector<double> noisy =
      meanSd({"--gyro-noise-std", "3", "--accel-noise-std", "1"}, "b.csv");
  // With a Kinect the shoulder rests on the optics too, so it widens less than the elbow.
  for (int j = 0; j < 5; ++j) EXPECT_GT(noisy[j], 1.15 * table5[j]) << "joint " << j;
  EXPECT_GT(noisy[3], 1.5 * table5[3]);
  for (const std::string bad : {"0", "-1", "abc", "nan"}) {
    const CliResult r = cli({"estimate", rec.string(), "--gyro-noise-std", bad});
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("--gyro-noise-std"), std::string::npos) << r.err;
  }
}

TEST_F(CliTest, UsageErrorsExitWithTwo) {
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"frobnicate"}, "unknown command 'frobnicate'"},
      {{}, "missing command"},
      {{"estimate", "x.csv", "--bogus"}, "unknown option '--bogus'"},
      {{"estimate", "x.csv", "--out"}, "--out: missing value"},
      {{"simulate", "--trajectory", "sinusoid", "--duration", "abc", "--out", "x.csv"},
       "--duration: expected a number, got \"abc\""},
      {{"simulate", "--trajectory", "circle", "--out", "x.csv"},
       "--trajectory: unknown trajectory 'circle'"},
      {{"estimate", "x.csv", "--filter", "pf"}, "--filter: expected ekf or ukf"},
      {{"estimate", "x.csv", "--method", "D"}, "--method: unknown method \"D\""},
      {{"study", "table7"}, "unknown study"},
      {{"study", "fig5", "--runs", "-1"}, "--runs: expected a non-negative integer"},
  };
  for (const Case& c : cases) {
    const CliResult r = cli(c.args);
    EXPECT_EQ(r.code, 2) << c.message;
    EXPECT_NE(r.err.find("armtrack-cli: error: " + c.message), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--help'"), std::string::npos) << r.err;
  }
  EXPECT_NE(cli({"estimate", "--bogus"}).err.find("run 'armtrack-cli estimate --help'"),
            std::string::npos);
}

TEST_F(CliTest, HelpAndVersion) {
  const CliResult v = cli({"--version"});
  EXPECT_EQ(v.code, 0);
  EXPECT_EQ(v.out, "armtrack-cli 0.1.0\n");
  for (const std::string cmd : {"simulate", "estimate", "study"}) {
    const CliResult h = cli({cmd, "--help"});
    EXPECT_EQ(h.code, 0);
    EXPECT_NE(h.out.find("Usage: armtrack-cli " + cmd), std::string::npos);
  }
  EXPECT_EQ(cli({"--help"}).code, 0);
}

TEST_F(CliTest, MissingFileExitsWithOne) {
  const std::string missing = path("nope.csv").string();
  const CliResult r = cli({"estimate", missing});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("--help"), std::string::npos);
}

// estimateStream with reading and writing in threads of their own gives the serial loop's bytes,
// progress calls and statistics; a bad row late in the file (thousands of rows after the first
// batches) is the same error in both.
TEST_F(CliTest, OverlappedStreamingEqualsTheSerialLoop) {
  const fs::path rec = simulated(6.0);
  struct Run {
    std::string csv;
    std::vector<std::uint64_t> progress;
    armtrack::cli::EstimateStats stats;
  };
  const auto run = [](const fs::path& file, bool overlap) {
    Run r;
    armtrack::RecordingReader reader(file);
    armtrack::cli::EstimateOptions opt;
    opt.jointAccelStdDeg = 10.0;
    std::ostringstream out;
    armtrack::cli::CsvOutput writer(armtrack::cli::kEstimateHeader, std::nullopt, &out);
    r.stats = armtrack::cli::estimateStream(
        reader, armtrack::cli::makeParams(reader.meta(), opt), nullptr, &writer,
        [&](std::uint64_t rows, std::uint64_t bytes, std::uint64_t size) {
          r.progress.insert(r.progress.end(), {rows, bytes, size});
        },
        nullptr, overlap);
    writer.commit();
    r.csv = out.str();
    return r;
  };
  const Run serial = run(rec, false), overlapped = run(rec, true);
  EXPECT_GT(std::count(serial.csv.begin(), serial.csv.end(), '\n'), 6000);
  EXPECT_EQ(overlapped.csv, serial.csv);
  EXPECT_EQ(overlapped.progress, serial.progress);
  EXPECT_GT(serial.progress.size(), 3u);
  EXPECT_EQ(overlapped.stats.estimates, serial.stats.estimates);
  EXPECT_EQ(overlapped.stats.imuRows, serial.stats.imuRows);
  for (int j = 0; j < armtrack::kNumJoints; ++j)
    EXPECT_EQ(overlapped.stats.rmseDeg(j), serial.stats.rmseDeg(j));

  // Row 5000 of the data made unreadable: both stop with the same error.
  std::vector<std::string> lines;
  {
    std::ifstream in(rec);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
  }
  std::size_t row = 0, bad = 0;
  for (std::size_t i = 0; i < lines.size() && !bad; ++i)
    if (!lines[i].empty() && lines[i][0] != '#' && ++row == 5001) bad = i;
  ASSERT_GT(bad, 0u);
  lines[bad] = "x" + lines[bad];
  const fs::path broken = path("broken.csv");
  {
    std::ofstream out(broken);
    for (const std::string& l : lines) out << l << "\n";
  }
  fs::copy_file(armtrack::sidecarPath(rec), armtrack::sidecarPath(broken));
  std::string errors[2];
  for (int k = 0; k < 2; ++k) {
    try {
      run(broken, k == 1);
      ADD_FAILURE() << "no error";
    } catch (const armtrack::RecordingError& e) {
      errors[k] = e.what();
    }
  }
  EXPECT_NE(errors[0].find(broken.string() + ":" + std::to_string(bad + 1) + ":1:"),
            std::string::npos)
      << errors[0];
  EXPECT_EQ(errors[1], errors[0]);
}

TEST_F(CliTest, MalformedRecordingNamesLineAndColumn) {
  const fs::path bad = path("bad.csv");
  std::ofstream(bad) << "t,ua_gx,ua_gy,ua_gz,ua_ax,ua_ay,ua_az\n"
                     << "0,0,0,0,9.81,0,0\n"
                     << "0.001,0,0.1.2,0,9.81,0,0\n";
  const CliResult r = cli({"estimate", bad.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(bad.string() + ":3:3: bad number"), std::string::npos) << r.err;
}

TEST_F(CliTest, UnwritableOutputExitsWithOne) {
  const CliResult r =
      cli({"estimate", simulated(3.0).string(), "--out", path("missing-dir/angles.csv").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("missing-dir/angles.csv"), std::string::npos) << r.err;
  const CliResult s = cli({"simulate", "--trajectory", "sinusoid", "--duration", "1", "--out",
                           path("missing-dir/rec.csv").string()});
  EXPECT_EQ(s.code, 1) << s.err;
}

// ---------------------------------------------------------------------------------------------
// Issue 9, items 7, 8, 10, 12 through the CLI.

std::string fileText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void writeFile(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

TEST_F(CliTest, ImpossibleSidecarGeometryIsRefusedNamingFileAndKey) {
  const fs::path rec = simulated(3.0);
  const fs::path json = armtrack::sidecarPath(rec);
  const std::string good = fileText(json);
  // Before: l3 = 0 and negative lengths gave exit 0 and 14-172 deg errors, 1e300 one estimate.
  for (const std::string& bad : {std::string("0"), std::string("-0.22"), std::string("1e300")}) {
    std::string text = good;
    const auto at = text.find("\"l3\": ");
    ASSERT_NE(at, std::string::npos) << text;
    text.replace(at, text.find(',', at) - at, "\"l3\": " + bad);
    writeFile(json, text);
    const CliResult r = cli({"estimate", rec.string()});
    EXPECT_EQ(r.code, 1) << bad << "\n" << r.err;
    EXPECT_NE(r.err.find(json.string() + ": \"geometry.l3\" is "), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("RMSE"), std::string::npos) << r.out;
  }
  std::string text = good;
  text.replace(text.find("\"l3\": "), text.find(',', text.find("\"l3\": ")) - text.find("\"l3\": "),
               "\"l3\": 1e999");
  writeFile(json, text);
  const CliResult r = cli({"estimate", rec.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(json.string() + ":"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1e999"), std::string::npos) << r.err;
}

TEST_F(CliTest, CameraFileErrorsNameTheFileAndWhereInIt) {
  const fs::path cam = path("cam.json");
  const fs::path pose = path("pose.json");
  writeFile(pose, R"({"R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "t_m": [0, 0, 0]})");
  auto registerWith = [&](const std::string& camText) {
    writeFile(cam, camText);
    return cli({"camera-register", "--camera", cam.string(), "--image", path("none.png").string(),
                "--board-pose", pose.string(), "--out", path("o.json").string()});
  };
  CliResult r = registerWith("{\"format\": \"armtrack-camera\",\n \"version\": 1, \"x\": 1e999}");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(cam.string() + ": not valid JSON"), std::string::npos) << r.err;
  // Before: "number overflow parsing '1e999'" without a position.
  EXPECT_NE(r.err.find("'1e999' at line 2, column 21"), std::string::npos) << r.err;
  r = registerWith("{\"format\": \"armtrack-camera\",\n \"version\": 1, \"x\": }");
  EXPECT_NE(r.err.find(cam.string() + ": not valid JSON"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("line 2, column 21"), std::string::npos) << r.err;
  r = registerWith(R"({"format": "armtrack-camera", "version": 1, "image_size": [640, 480],
    "intrinsics": {"fx": 0, "fy": 600, "cx": 320, "cy": 240}, "distortion": [0, 0, 0, 0, 0]})");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(cam.string() + ": 'intrinsics.fx': must be > 0"), std::string::npos)
      << r.err;
}

TEST_F(CliTest, NulByteInACellIsShownEscapedInTheError) {
  const fs::path rec = path("nul.csv");
  writeFile(rec, "t,ua_gx,ua_gy,ua_gz,ua_ax,ua_ay,ua_az\n" + std::string("0,0\0zz", 6) +
                     ",0,0,0,0,9.81\n");
  const CliResult r = cli({"estimate", rec.string()});
  EXPECT_EQ(r.code, 1);
  // Before: the message ended at "bad number \"0". A NUL is now refused as binary content at the
  // door (docs/recording-format.md, "Limits"), named by its line and field.
  EXPECT_NE(r.err.find(rec.string() + ":2:2: binary content (byte 0x00)"), std::string::npos)
      << r.err;
  // The orientation command's own IMU reader likewise.
  const fs::path imu = path("nul-imu.csv");
  writeFile(imu, "t,gyr_x,gyr_y,gyr_z,acc_x,acc_y,acc_z\n" + std::string("0,0\0zz", 6) +
                     ",0,0,0,0,9.81\n");
  const CliResult o = cli({"orientation", imu.string()});
  EXPECT_EQ(o.code, 1);
  EXPECT_NE(o.err.find("bad number \"0\\x00zz\" in column \"gyr_x\""), std::string::npos) << o.err;
}

TEST_F(CliTest, ExistingOutputsAreReplacedOnlyWithOverwrite) {
  const fs::path rec = simulated(3.0);
  const std::string keep = "do not lose me\n";
  // simulate: the recording and, separately, its sidecar.
  const fs::path sim = path("sim.csv");
  writeFile(sim, keep);
  CliResult r =
      cli({"simulate", "--trajectory", "sinusoid", "--duration", "1", "--out", sim.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(sim.string() + ": exists; pass --overwrite"), std::string::npos) << r.err;
  EXPECT_EQ(fileText(sim), keep);
  EXPECT_FALSE(fs::exists(path("sim.json")));
  fs::remove(sim);
  writeFile(path("sim.json"), keep);
  r = cli({"simulate", "--trajectory", "sinusoid", "--duration", "1", "--out", sim.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(path("sim.json").string() + ": exists"), std::string::npos) << r.err;
  EXPECT_EQ(fileText(path("sim.json")), keep);
  EXPECT_FALSE(fs::exists(sim));
  r = cli({"simulate", "--trajectory", "sinusoid", "--duration", "1", "--out", sim.string(),
           "--overwrite"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_GE(armtrack::readRecording(sim).samples.size(), 1000u);  // 1 s of IMU rows at 1 kHz

  // estimate, orientation and calibrate --out.
  const fs::path out = path("out.csv");
  writeFile(out, keep);
  r = cli({"estimate", rec.string(), "--out", out.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(out.string() + ": exists; pass --overwrite"), std::string::npos) << r.err;
  EXPECT_EQ(fileText(out), keep);
  const fs::path imu = path("imu.csv");
  writeFile(imu, "t,gyr_x,gyr_y,gyr_z,acc_x,acc_y,acc_z\n0,0,0,0,0,0,9.81\n0.01,0,0,0,0,0,9.81\n");
  r = cli({"orientation", imu.string(), "--out", out.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(out.string() + ": exists"), std::string::npos) << r.err;
  EXPECT_EQ(fileText(out), keep);
  r = cli({"calibrate", rec.string(), "--out", out.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(out.string() + ": exists"), std::string::npos) << r.err;
  EXPECT_EQ(fileText(out), keep);
  r = cli({"calibrate", "--help"});
  EXPECT_NE(r.out.find("--overwrite"), std::string::npos) << r.out;

  r = cli({"orientation", imu.string(), "--out", out.string(), "--overwrite"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(fileText(out).find("t,qw,qx,qy,qz"), std::string::npos);
  r = cli({"estimate", rec.string(), "--out", out.string(), "--overwrite"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(fileText(out).find("t,th0"), std::string::npos);
  // A recording being written (its writer holds a lock) is not replaced even with --overwrite.
  {
    const fs::path live = path("live.csv");
    armtrack::RecordingWriter writer(live, armtrack::RecordingMeta{}, armtrack::RecordingColumns{});
    r = cli({"simulate", "--trajectory", "sinusoid", "--duration", "1", "--out", live.string(),
             "--overwrite"});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find(live.string() + ": another recording is being written to this file"),
              std::string::npos)
        << r.err;
    r = cli({"estimate", rec.string(), "--out", live.string(), "--overwrite"});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("another recording is being written"), std::string::npos) << r.err;
    writer.close();
    EXPECT_TRUE(armtrack::readRecording(live).samples.empty());
  }
  // A directory is never an output, with or without --overwrite.
  r = cli({"estimate", rec.string(), "--out", m_dir.string(), "--overwrite"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
}

/// A stream whose every write fails, as standard output on /dev/full or a full disk.
class FullStreamBuf : public std::streambuf {
 protected:
  int overflow(int) override { return traits_type::eof(); }
  std::streamsize xsputn(const char*, std::streamsize) override { return 0; }
};

TEST_F(CliTest, AReportThatCannotBeWrittenIsAFailure) {
  const fs::path rec = simulated(3.0);
  FullStreamBuf full;
  std::ostream out(&full);
  std::ostringstream err;
  // Before: exit 0 with the RMSE table lost.
  EXPECT_EQ(runCli({"estimate", rec.string()}, out, err), 1);
  EXPECT_NE(err.str().find("cannot write the results to standard output"), std::string::npos)
      << err.str();
}

}  // namespace

// --method tao-hu: one row per camera frame with positions and angles, position errors in cm next
// to the paper's +/-5 cm, and exit 1 with a clear message without a camera or a forearm IMU.
TEST_F(CliTest, TaoHuMethodWritesFramesAndPositionErrors) {
  const fs::path rec = path("webcam.csv");
  const CliResult sim = cli({"simulate", "--trajectory", "multi-joint", "--duration", "8",
                             "--webcam", "--no-kinect", "--out", rec.string()});
  ASSERT_EQ(sim.code, 0) << sim.err;
  const fs::path out = path("taohu.csv");
  const CliResult r = cli({"estimate", rec.string(), "--method", "tao-hu", "--out", out.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("method tao-hu"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("| wrist |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("+/-5 cm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("th5 forearm pronation"), std::string::npos) << r.out;
  const std::vector<std::string> lines = readLines(out);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], "t,wrist_x,wrist_y,wrist_z,elbow_x,elbow_y,elbow_z,th0,th1,th2,th4,th5");
  EXPECT_NEAR(static_cast<double>(lines.size() - 1), 7.0 * 30.0, 3.0);  // 1 s warm-up
  EXPECT_EQ(std::count(lines[1].begin(), lines[1].end(), ','), 11);

  // No camera block: exit 1, named.
  const CliResult noCam = cli({"estimate", simulated(3.0).string(), "--method", "tao-hu"});
  EXPECT_EQ(noCam.code, 1);
  EXPECT_NE(noCam.err.find("no camera block"), std::string::npos) << noCam.err;

  // No forearm IMU: exit 1, named.
  armtrack::Recording noForearm = armtrack::readRecording(rec);
  for (armtrack::ArmSample& s : noForearm.samples) s.forearm.reset();
  const fs::path nf = path("noforearm.csv");
  armtrack::writeRecording(nf, noForearm);
  const CliResult noFa = cli({"estimate", nf.string(), "--method", "tao-hu"});
  EXPECT_EQ(noFa.code, 1);
  EXPECT_NE(noFa.err.find("no forearm IMU"), std::string::npos) << noFa.err;

  // Options of the joint-angle filter are named as ignored.
  const CliResult warn = cli({"estimate", rec.string(), "--method", "tao-hu", "--filter", "ukf"});
  EXPECT_EQ(warn.code, 0);
  EXPECT_NE(warn.err.find("--filter does not apply"), std::string::npos) << warn.err;
}
