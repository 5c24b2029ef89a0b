// devices / record / live through the CLI, plugin loading and refusals, and a recording that
// survives the process being killed.
#include <gtest/gtest.h>

#include <QProcess>
#include <QTemporaryDir>
#include <chrono>
#include <filesystem>
#include <fstream>
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
  {
    std::ofstream(dir.filePath(QStringLiteral("armtrack-garbage.so")).toStdString()) << "not ELF";
  }
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
      EXPECT_NE(r.refusal.indexOf(QStringLiteral("built for device interface org.armtrack.DevicePlugin/0")), -1)
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
  for (const app::PluginRecord& r : reg.records()) EXPECT_EQ(r.refusal.indexOf("already loaded"), -1);
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
  Result r = cli({"record", "--device", "no-such-device", "--duration", "1", "--out", "/tmp/x.csv"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("no device plugin 'no-such-device'; found:"), std::string::npos) << r.err;
  r = cli({"record", "--device", "virtual-arm:sensors=elbow", "--duration", "1", "--out", "/tmp/x.csv"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown sensor 'elbow'"), std::string::npos) << r.err;
  r = cli({"record", "--device", "virtual-arm", "--out", "/tmp/x.csv"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--duration is required"), std::string::npos) << r.err;
  r = cli({"record", "--device", "virtual-arm", "--duration", "1", "--out",
           "/no-such-folder/rec.csv"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("cannot record"), std::string::npos) << r.err;
}

TEST(LiveCli, LiveStatsAndReplayEndsTheSession) {
  QTemporaryDir dir;
  const std::string rec = dir.filePath(QStringLiteral("r.csv")).toStdString();
  ASSERT_EQ(cli({"record", "--device", "virtual-arm", "--duration", "2", "--out", rec, "--quiet"}).code, 0);
  // A 2 s recording replayed at 4x ends on its own well before --duration.
  const auto t0 = std::chrono::steady_clock::now();
  const Result r = cli({"live", "--device", "replay:speed=4,file=" + rec, "--duration", "30",
                        "--stats", "--quiet"});
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_LT(took, 5.0);
  EXPECT_NE(r.out.find("every device has ended"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("p99"), std::string::npos) << r.out;
}

TEST(LiveCli, KilledRecordingIsReadableUpToTheKill) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("killed.csv"));
  QProcess p;
  p.start(QStringLiteral(ARMTRACK_CLI),
          {QStringLiteral("record"), QStringLiteral("--device"), QStringLiteral("virtual-arm"),
           QStringLiteral("--duration"), QStringLiteral("60"), QStringLiteral("--out"), out,
           QStringLiteral("--plugins"), QStringLiteral(ARMTRACK_PLUGIN_DIR), QStringLiteral("--quiet")});
  ASSERT_TRUE(p.waitForStarted());
  std::this_thread::sleep_for(std::chrono::milliseconds(3500));
  p.kill();  // SIGKILL: no chance to close the file
  ASSERT_TRUE(p.waitForFinished());
  const Recording rec = readRecording(out.toStdString());
  // Flushed every 0.5 s: at least the first 2.5 s are there, in order.
  ASSERT_GT(rec.samples.size(), 2500u);
  EXPECT_GT(rec.samples.back().t, 2.5);
  for (const std::string& w : rec.warnings) EXPECT_NE(w.find("cut short"), std::string::npos) << w;
}

}  // namespace
}  // namespace armtrack
