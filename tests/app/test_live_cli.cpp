// devices / record / live through the CLI, plugin loading and refusals, and a recording that
// survives the process being killed.
#include <gtest/gtest.h>

#include <sys/mount.h>
#include <unistd.h>
#include <QProcess>
#include <QTemporaryDir>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

#include "app/cli/Cli.h"
#include "app/plugins/PluginRegistry.h"
#include "core/estimation/ArmFilter.h"
#include "core/io/Recording.h"

namespace armtrack {
namespace {

namespace fs = std::filesystem;

struct Result {
  int code;
  std::string out, err;
};

Result cli(std::vector<std::string> args) {
  args.push_back("--plugins");
  args.push_back(ARMTRACK_PLUGIN_DIR);
  std::ostringstream out, err;
  const int code = cli::runCli(args, out, err);
  return {code, out.str(), err.str()};
}

TEST(PluginRegistry, LoadsOursAndRefusesOthersWithAReason) {
  QTemporaryDir dir;
  // Not a library at all, and a library that is not a Qt plugin.
  { std::ofstream(dir.filePath(QStringLiteral("armtrack-garbage.so")).toStdString()) << "not ELF"; }
  app::PluginRegistry reg;
  reg.load({QStringLiteral(ARMTRACK_PLUGIN_DIR), QStringLiteral(ARMTRACK_OLD_PLUGIN_DIR),
            dir.path(), QStringLiteral(ARMTRACK_PLUGIN_DIR)});
  EXPECT_NE(reg.plugin(QStringLiteral("virtual-arm")), nullptr);
  EXPECT_NE(reg.plugin(QStringLiteral("replay")), nullptr);
  EXPECT_EQ(reg.plugin(QStringLiteral("old")), nullptr);
  bool oldRefused = false, garbageRefused = false;
  for (const app::PluginRecord& r : reg.records()) {
    if (r.file.endsWith(QStringLiteral("armtrack_test_old_plugin.so"))) {
      EXPECT_FALSE(r.loaded);
      EXPECT_NE(r.refusal.indexOf(
                    QStringLiteral("built for device interface org.armtrack.DevicePlugin/0")),
                -1)
          << r.refusal.toStdString();
      oldRefused = true;
    }
    if (r.file.endsWith(QStringLiteral("armtrack-garbage.so"))) {
      EXPECT_FALSE(r.loaded);
      EXPECT_EQ(r.refusal, QStringLiteral("not a Qt plugin"));
      garbageRefused = true;
    }
  }
  EXPECT_TRUE(oldRefused);
  EXPECT_TRUE(garbageRefused);
  // The build folder was given twice: its plugins are looked at once, not refused as duplicates.
  for (const app::PluginRecord& r : reg.records())
    EXPECT_EQ(r.refusal.indexOf("already loaded"), -1);
}

TEST(LiveCli, DevicesListsPluginsAndOptions) {
  const Result r = cli({"devices"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("virtual-arm: simulated IMUs"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("dropout=STREAM@START+SECONDS"), std::string::npos);
  EXPECT_NE(r.out.find("replay: plays a recording"), std::string::npos);
}

TEST(LiveCli, RecordWritesSamplesTruthAndLiveEstimates) {
  QTemporaryDir dir;
  const std::string out = dir.filePath(QStringLiteral("rec.csv")).toStdString();
  const Result r = cli({"record", "--device", "virtual-arm:sensors=upper+forearm+kinect",
                        "--duration", "4", "--out", out, "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("lost 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("latency p50"), std::string::npos);
  const Recording rec = readRecording(out);
  ASSERT_GT(rec.samples.size(), 3800u);
  std::size_t truth = 0, est = 0, kinect = 0;
  for (const ArmSample& s : rec.samples) {
    truth += s.trueAngles.has_value();
    est += s.estimate.has_value();
    kinect += s.wrist.has_value();
  }
  EXPECT_EQ(truth, rec.samples.size());  // every row has an IMU sample, and the truth with it
  EXPECT_GT(est, 3800u);
  EXPECT_NEAR(static_cast<double>(kinect), 120.0, 5.0);
  // estimate re-runs the filter offline and compares with true_th*.
  std::ostringstream eout, eerr;
  EXPECT_EQ(cli::runCli({"estimate", out}, eout, eerr), 0) << eerr.str();
  EXPECT_NE(eout.str().find("RMSE"), std::string::npos) << eout.str();
}

TEST(LiveCli, ClearErrors) {
  Result r =
      cli({"record", "--device", "no-such-device", "--duration", "1", "--out", "/tmp/x.csv"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("no device plugin 'no-such-device'; found:"), std::string::npos) << r.err;
  r = cli({"record", "--device", "virtual-arm:sensors=elbow", "--duration", "1", "--out",
           "/tmp/x.csv"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown sensor 'elbow'"), std::string::npos) << r.err;
  r = cli({"record", "--device", "virtual-arm", "--out", "/tmp/x.csv"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--duration is required"), std::string::npos) << r.err;
  r = cli(
      {"record", "--device", "virtual-arm", "--duration", "1", "--out", "/no-such-folder/rec.csv"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("cannot record"), std::string::npos) << r.err;
}

TEST(LiveCli, LiveStatsAndReplayEndsTheSession) {
  QTemporaryDir dir;
  const std::string rec = dir.filePath(QStringLiteral("r.csv")).toStdString();
  ASSERT_EQ(
      cli({"record", "--device", "virtual-arm", "--duration", "2", "--out", rec, "--quiet"}).code,
      0);
  // A 2 s recording replayed at 4x ends on its own well before --duration.
  const auto t0 = std::chrono::steady_clock::now();
  const Result r = cli(
      {"live", "--device", "replay:speed=4,file=" + rec, "--duration", "30", "--stats", "--quiet"});
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_LT(took, 5.0);
  EXPECT_NE(r.out.find("every device has ended"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("p99"), std::string::npos) << r.out;
}

/// Waits (up to 60 s, while p runs) until the recording being written to out holds rows past
/// `seconds` of session time; the rows it then held, or 0.
std::size_t waitForRecordedTime(QProcess& p, const QString& out, double seconds) {
  for (int i = 0; i < 600 && p.state() == QProcess::Running; ++i) {
    try {
      const Recording partial = readRecording(out.toStdString());
      if (!partial.samples.empty() && partial.samples.back().t > seconds)
        return partial.samples.size();
    } catch (const RecordingError&) {
      // not created yet, or only its header so far
    }
    p.waitForFinished(100);
  }
  return 0;
}

TEST(LiveCli, KilledRecordingIsReadableUpToTheKill) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("killed.csv"));
  QProcess p;
  p.start(QStringLiteral(ARMTRACK_CLI),
          {QStringLiteral("record"), QStringLiteral("--device"), QStringLiteral("virtual-arm"),
           QStringLiteral("--duration"), QStringLiteral("60"), QStringLiteral("--out"), out,
           QStringLiteral("--plugins"), QStringLiteral(ARMTRACK_PLUGIN_DIR),
           QStringLiteral("--quiet")});
  ASSERT_TRUE(p.waitForStarted());
  // Kill it once 2.5 s of rows are on disk, however long a loaded machine takes to get there.
  const std::size_t seenRows = waitForRecordedTime(p, out, 2.5);
  ASSERT_GT(seenRows, 0u) << "the recording never reached 2.5 s";
  p.kill();  // SIGKILL: no chance to close the file
  ASSERT_TRUE(p.waitForFinished());
  const Recording rec = readRecording(out.toStdString());
  // Everything flushed before the kill is there, in order: at least the first 2.5 s.
  ASSERT_GE(rec.samples.size(), seenRows);
  EXPECT_GT(rec.samples.back().t, 2.5);
  for (std::size_t i = 1; i < rec.samples.size(); ++i)
    ASSERT_GE(rec.samples[i].t, rec.samples[i - 1].t) << "row " << i;
  for (const std::string& w : rec.warnings) EXPECT_NE(w.find("cut short"), std::string::npos) << w;
}

// ---------------------------------------------------------------------------------------------
// Issue 9, items 8-10: recordings that cannot be lost.

QStringList recordArgs(const QString& out, const QString& duration) {
  return {QStringLiteral("record"),
          QStringLiteral("--device"),
          QStringLiteral("virtual-arm"),
          QStringLiteral("--duration"),
          duration,
          QStringLiteral("--out"),
          out,
          QStringLiteral("--plugins"),
          QStringLiteral(ARMTRACK_PLUGIN_DIR),
          QStringLiteral("--quiet")};
}

std::string textOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Waits until the file holds at least `bytes` bytes (false after 20 s).
bool waitForBytes(const fs::path& p, std::uintmax_t bytes) {
  for (int i = 0; i < 400; ++i) {
    std::error_code ec;
    if (fs::file_size(p, ec) >= bytes && !ec) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

/// The number after `key` in text (e.g. "rows " in the session summary), or -1.
long long numberAfter(const std::string& text, const std::string& key) {
  const auto at = text.find(key);
  if (at == std::string::npos) return -1;
  return std::atoll(text.c_str() + at + key.size());
}

TEST(LiveCli, RecordNeverReplacesAFileWithoutOverwriteAndCreatesNothingForADirectory) {
  QTemporaryDir dir;
  const fs::path out = dir.filePath(QStringLiteral("rec.csv")).toStdString();
  std::ofstream(out) << "an earlier recording\n";
  Result r = cli(
      {"record", "--device", "virtual-arm", "--duration", "1", "--out", out.string(), "--quiet"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(out.string() + ": exists; pass --overwrite"), std::string::npos) << r.err;
  EXPECT_EQ(textOf(out), "an earlier recording\n");
  EXPECT_FALSE(fs::exists(sidecarPath(out)));
  // A folder as --out: refused before anything is written, no stray <folder>.json.
  const fs::path folder = dir.filePath(QStringLiteral("folder")).toStdString();
  fs::create_directory(folder);
  r = cli({"record", "--device", "virtual-arm", "--duration", "1", "--out", folder.string(),
           "--quiet", "--overwrite"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(folder.string() + ".json"));
  // live --out is checked the same way.
  r = cli({"live", "--device", "virtual-arm", "--duration", "1", "--out", out.string(), "--quiet"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("exists; pass --overwrite"), std::string::npos) << r.err;
  EXPECT_EQ(textOf(out), "an earlier recording\n");
  // With --overwrite the old file is replaced by a whole recording.
  r = cli({"record", "--device", "virtual-arm", "--duration", "1", "--out", out.string(), "--quiet",
           "--overwrite"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_GT(readRecording(out).samples.size(), 900u);
  // A failed start (no such device) leaves no file behind.
  const fs::path none = dir.filePath(QStringLiteral("none.csv")).toStdString();
  r = cli({"record", "--device", "virtual-arm:sensors=upper", "--device",
           "virtual-arm:sensors=upper", "--duration", "1", "--out", none.string(), "--quiet"});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_FALSE(fs::exists(none)) << r.err;
  EXPECT_FALSE(fs::exists(sidecarPath(none)));
}

TEST(LiveCli, TwoRecordersOnOneFileTheSecondIsRefusedAndTheFirstRecordingIsWhole) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("shared.csv"));
  QProcess first;
  // Long enough never to end by itself while the others try: it is ended below, as Ctrl-C ends a
  // session, once both have been refused.
  first.start(QStringLiteral(ARMTRACK_CLI), recordArgs(out, QStringLiteral("600")));
  ASSERT_TRUE(first.waitForStarted());
  ASSERT_TRUE(waitForBytes(out.toStdString(), 2000));
  const std::string sidecarBefore = textOf(sidecarPath(out.toStdString()));
  for (const bool overwrite : {false, true}) {
    QProcess second;
    QStringList args = recordArgs(out, QStringLiteral("2"));
    args << QStringLiteral("--side") << QStringLiteral("left");
    if (overwrite) args << QStringLiteral("--overwrite");
    second.start(QStringLiteral(ARMTRACK_CLI), args);
    ASSERT_TRUE(second.waitForFinished(20000));
    const std::string err = second.readAllStandardError().toStdString();
    EXPECT_EQ(second.exitCode(), 1) << err;
    EXPECT_NE(err.find(out.toStdString() + ": another recording is being written to this file"),
              std::string::npos)
        << err;
  }
  ASSERT_EQ(first.state(), QProcess::Running);
  // Some seconds of it before ending it, however quickly the others were refused.
  ASSERT_GT(waitForRecordedTime(first, out, 2.0), 0u) << "the first recording stopped growing";
  first.terminate();  // SIGTERM: ends the session cleanly, every row kept
  ASSERT_TRUE(first.waitForFinished(60000));
  const std::string firstOut = first.readAllStandardOutput().toStdString();
  EXPECT_EQ(first.exitCode(), 0) << first.readAllStandardError().toStdString();
  EXPECT_EQ(textOf(sidecarPath(out.toStdString())), sidecarBefore);
  const Recording rec = readRecording(out.toStdString());
  EXPECT_TRUE(rec.warnings.empty());
  EXPECT_EQ(rec.meta.side, Side::Right);
  EXPECT_EQ(static_cast<long long>(rec.samples.size()), numberAfter(firstOut, "recorded "))
      << firstOut;
  ASSERT_GT(rec.samples.back().t, 2.0);
  for (std::size_t i = 1; i < rec.samples.size(); ++i)
    ASSERT_LT(rec.samples[i].t - rec.samples[i - 1].t, 0.05) << "a gap at row " << i;
}

TEST(LiveCli, SighupEndsARecordingLikeSigterm) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("hup.csv"));
  QProcess p;
  p.start(QStringLiteral(ARMTRACK_CLI), recordArgs(out, QStringLiteral("60")));
  ASSERT_TRUE(p.waitForStarted());
  ASSERT_GT(waitForRecordedTime(p, out, 1.5), 0u) << "the recording never reached 1.5 s";
  ASSERT_EQ(::kill(static_cast<pid_t>(p.processId()), SIGHUP), 0);
  ASSERT_TRUE(p.waitForFinished(20000));
  // Before: killed by the signal (exit 129), the last flush interval lost.
  EXPECT_EQ(p.exitStatus(), QProcess::NormalExit);
  EXPECT_EQ(p.exitCode(), 0);
  const std::string stdoutText = p.readAllStandardOutput().toStdString();
  EXPECT_NE(stdoutText.find("interrupted; session summary"), std::string::npos) << stdoutText;
  const Recording rec = readRecording(out.toStdString());
  EXPECT_TRUE(rec.warnings.empty()) << rec.warnings.front();  // no line cut short
  // Every row the session produced is in the file: nothing of the last 0.5 s is missing.
  EXPECT_EQ(static_cast<long long>(rec.samples.size()), numberAfter(stdoutText, "] rows "))
      << stdoutText;
  EXPECT_EQ(static_cast<long long>(rec.samples.size()), numberAfter(stdoutText, "\nrecorded "));
  EXPECT_GT(rec.samples.back().t, 1.5);
}

TEST(LiveCli, ReportsLostToAFullOutputAreAFailure) {
  QTemporaryDir dir;
  const QString rec = dir.filePath(QStringLiteral("r.csv"));
  std::ostringstream simOut, simErr;
  ASSERT_EQ(cli::runCli({"simulate", "--trajectory", "multi-joint", "--duration", "3", "--out",
                         rec.toStdString()},
                        simOut, simErr),
            0)
      << simErr.str();
  const std::vector<QStringList> commands = {
      {QStringLiteral("estimate"), rec},
      {QStringLiteral("study"), QStringLiteral("table6"), QStringLiteral("--runs"),
       QStringLiteral("1"), QStringLiteral("--duration"), QStringLiteral("2")},
      {QStringLiteral("--help")}};
  for (const QStringList& args : commands) {
    QProcess p;
    p.setStandardOutputFile(QStringLiteral("/dev/full"));
    p.start(QStringLiteral(ARMTRACK_CLI), args);
    ASSERT_TRUE(p.waitForFinished(120000));
    const std::string err = p.readAllStandardError().toStdString();
    // Before: exit 0 and the report gone.
    EXPECT_EQ(p.exitCode(), 1) << args.join(' ').toStdString() << "\n" << err;
    EXPECT_NE(err.find("cannot write the results to standard output"), std::string::npos) << err;
  }
}

/// A small tmpfs mounted for a test (needs root, i.e. CAP_SYS_ADMIN); unmounted when done.
class SmallFilesystem {
 public:
  explicit SmallFilesystem(const std::string& size) {
    m_dir = fs::temp_directory_path() /
            ("armtrack_small_fs_" + std::to_string(::getpid()) + "_" + std::to_string(++s_count));
    fs::create_directories(m_dir);
    if (::mount("armtrack-test", m_dir.c_str(), "tmpfs", MS_NOSUID | MS_NODEV,
                ("size=" + size).c_str()) == 0)
      m_mounted = true;
    else
      m_why = std::strerror(errno);
  }
  ~SmallFilesystem() {
    if (m_mounted) ::umount2(m_dir.c_str(), MNT_DETACH);
    std::error_code ec;
    fs::remove_all(m_dir, ec);
  }
  bool mounted() const { return m_mounted; }
  const std::string& why() const { return m_why; }
  fs::path path(const std::string& name) const { return m_dir / name; }

 private:
  static inline int s_count = 0;
  fs::path m_dir;
  bool m_mounted = false;
  std::string m_why;
};

/// Fills the file system at p with a file, leaving about `leave` bytes free.
void fillUpTo(const fs::path& p, std::uintmax_t leave) {
  const fs::space_info space = fs::space(p.parent_path());
  const std::string block(4096, 'x');
  std::ofstream f(p, std::ios::binary);
  for (std::uintmax_t n = 0; n + leave + block.size() <= space.available; n += block.size())
    f << block;
}

TEST(LiveCli, DiskFullForTheRestOfTheRunTheAccountIsTrue) {
  SmallFilesystem small("256k");
  if (!small.mounted()) GTEST_SKIP() << "cannot mount a small tmpfs to fill: " << small.why();
  const fs::path out = small.path("rec.csv");
  const Result r = cli(
      {"record", "--device", "virtual-arm", "--duration", "3", "--out", out.string(), "--quiet"});
  EXPECT_EQ(r.code, 1) << r.err;
  const Recording rec = readRecording(out);
  const long long onDisk = static_cast<long long>(rec.samples.size());
  const long long total = numberAfter(r.out, "] rows ");
  ASSERT_GT(total, 2500) << r.out;
  ASSERT_LT(onDisk, total);  // the disk really was full
  // Before: "recorded 20003 rows" while the file held about 11,466.
  EXPECT_EQ(numberAfter(r.out, "\nrecorded "), onDisk) << r.out;
  const std::string lost = "the recording is incomplete: " + std::to_string(total - onDisk) +
                           " of " + std::to_string(total) + " rows were lost";
  EXPECT_NE(r.err.find(lost), std::string::npos) << r.err << "\nexpected: " << lost;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
}

TEST(LiveCli, DiskFullThatClearsMidRunGivesAWholeRecordingAndExitZero) {
  SmallFilesystem small("8m");
  if (!small.mounted()) GTEST_SKIP() << "cannot mount a small tmpfs to fill: " << small.why();
  const fs::path filler = small.path("filler");
  fillUpTo(filler, 48 * 1024);
  const fs::path out = small.path("rec.csv");
  std::thread freeSpace([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    fs::remove(filler);
  });
  const Result r = cli(
      {"record", "--device", "virtual-arm", "--duration", "3", "--out", out.string(), "--quiet"});
  freeSpace.join();
  // Before: the file was whole, but the exit was 1 with "the recording is incomplete".
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;  // it did stall
  EXPECT_NE(r.err.find("no row was lost"), std::string::npos) << r.err;
  const Recording rec = readRecording(out);
  EXPECT_TRUE(rec.warnings.empty());
  const long long total = numberAfter(r.out, "] rows ");
  EXPECT_EQ(static_cast<long long>(rec.samples.size()), total) << r.out;
  EXPECT_EQ(numberAfter(r.out, "\nrecorded "), total) << r.out;
  for (std::size_t i = 1; i < rec.samples.size(); ++i)
    ASSERT_LT(rec.samples[i].t - rec.samples[i - 1].t, 0.05) << "a gap at row " << i;
}

}  // namespace
}  // namespace armtrack
