// The live pipeline end to end with the virtual arm: real threads, real time, the plugin loaded
// from the build tree. Each fault the virtual arm can inject must leave the session running,
// reported, and the recording complete.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QTemporaryDir>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <thread>

#include "core/estimation/ArmFilter.h"
#include "core/io/Recording.h"
#include "core/session/Session.h"
#include "devices/api/Options.h"
#include "tests/support/LoadPlugin.h"

namespace armtrack::session {
namespace {

namespace fs = std::filesystem;
using devices::StreamRole;

struct SessionRun {
  SessionStats stats;
  std::vector<std::string> events;
  std::vector<EstimateRow> results;
  Recording rec;
};

bool mentions(const std::vector<std::string>& events, const std::string& text) {
  for (const std::string& e : events)
    if (e.find(text) != std::string::npos) return true;
  return false;
}

const StreamStats& streamOf(const SessionStats& s, const std::string& name) {
  for (const StreamStats& st : s.streams)
    if (st.stream == name) return st;
  throw std::runtime_error("no stream " + name);
}

class SessionTest : public ::testing::Test {
 protected:
  /// Runs a session of the given virtual-arm devices (option strings) for `seconds` and reads
  /// back its recording.
  SessionRun run(const std::vector<QString>& specs, double seconds,
          const std::function<void(SessionParams&)>& tweak = {}) {
    devices::DevicePlugin* plugin = test::loadPlugin(QStringLiteral("virtual-arm"));
    if (!plugin) return {};
    SessionParams params;
    params.recordingPath = fs::path(dir_.path().toStdString()) / "session.csv";
    if (tweak) tweak(params);
    Session session(params);
    for (const QString& spec : specs) {
      QString why;
      auto device = plugin->create(devices::Options::parse(spec), &why);
      if (!device) {
        ADD_FAILURE() << why.toStdString();
        return {};
      }
      session.addDevice(std::move(device), QStringLiteral("arm") + QString::number(specs.size()));
    }
    const QString why = session.start();
    EXPECT_TRUE(why.isEmpty()) << why.toStdString();
    SessionRun r;
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
      std::this_thread::sleep_for(std::chrono::milliseconds(30));  // a GUI timer's pace
      session.takeResults(r.results);
    }
    session.stop();
    session.takeResults(r.results);
    session.takeEvents(r.events);
    r.stats = session.stats();
    r.rec = readRecording(params.recordingPath);
    return r;
  }

  /// Nothing lost between the devices and the recorder: every sample a device published was
  /// received, and every valid one is in the recording.
  static void expectComplete(const SessionRun& r) {
    EXPECT_EQ(r.stats.inputOverflow, 0u);
    EXPECT_EQ(r.stats.recordedRows, r.rec.samples.size());
    EXPECT_EQ(r.stats.recorderError, "");
    std::uint64_t upper = 0, forearm = 0, kinect = 0;
    for (const ArmSample& s : r.rec.samples) {
      upper += s.upperArm.has_value();
      forearm += s.forearm.has_value();
      kinect += s.wrist.has_value();
    }
    for (const StreamStats& st : r.stats.streams) {
      EXPECT_EQ(st.received, st.published) << st.stream;
      const std::uint64_t valid = st.received - st.rejected;
      if (st.stream == "upper") EXPECT_EQ(upper, valid);
      if (st.stream == "forearm") EXPECT_EQ(forearm, valid);
      if (st.stream == "kinect") EXPECT_EQ(kinect, valid);
    }
  }

  /// RMS error (rad) against the true angles over the rows with t in [from, to).
  static JointVector rmse(const Recording& rec, double from, double to) {
    JointVector sum = JointVector::Zero();
    int n = 0;
    for (const ArmSample& s : rec.samples) {
      if (s.t < from || s.t >= to || !s.estimate || !s.trueAngles) continue;
      for (int j = 0; j < kNumJoints; ++j) {
        const double e = std::remainder((*s.estimate)(j) - (*s.trueAngles)(j), 2 * std::numbers::pi);
        sum(j) += e * e;
      }
      ++n;
    }
    EXPECT_GT(n, 0) << "no estimates in [" << from << ", " << to << ")";
    return (sum / std::max(n, 1)).cwiseSqrt();
  }

  static std::size_t rowsWith(const Recording& rec, double from, double to,
                              const std::function<bool(const ArmSample&)>& pred) {
    std::size_t n = 0;
    for (const ArmSample& s : rec.samples) n += s.t >= from && s.t < to && pred(s);
    return n;
  }

  QTemporaryDir dir_;
};

constexpr double kDeg = std::numbers::pi / 180.0;

// Acceptance 1: a 60 s session re-estimated offline gives the same angles as live.
TEST_F(SessionTest, SixtySecondsLiveEqualsOfflineReestimate) {
  const SessionRun r = run({QStringLiteral("sensors=upper+forearm+kinect+webcam")}, 60.0);
  ASSERT_GT(r.rec.samples.size(), 55000u);
  expectComplete(r);
  EXPECT_EQ(r.stats.lost(), 0u);
  EXPECT_NEAR(r.rec.samples.back().t - r.rec.samples.front().t, 60.0, 0.5);

  // Offline: the same rows through a fresh filter with the recording's parameters.
  const BatchResult offline = estimateSamples(r.rec.samples, recordingParams(r.rec.meta));
  std::vector<JointVector> live;
  for (const ArmSample& s : r.rec.samples)
    if (s.estimate) live.push_back(*s.estimate);
  ASSERT_EQ(offline.estimates.size(), live.size());
  ASSERT_GT(live.size(), 55000u);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < live.size(); ++i) differing += offline.estimates[i].th != live[i];
  EXPECT_EQ(differing, 0u) << "live and offline estimates differ on " << differing << " rows";
  // The GUI buffer got every estimate, in order.
  ASSERT_EQ(r.results.size(), live.size());
  EXPECT_EQ(r.results.back().th, live.back());

  // And the live angles are right: the recording carries the truth.
  const JointVector e = rmse(r.rec, 5.0, 1e9);
  for (int j = 0; j < kNumJoints; ++j) EXPECT_LT(e(j), 1.0 * kDeg) << "joint " << j;
  EXPECT_LT(r.stats.latency.quantile(0.99), 0.05);
}

TEST_F(SessionTest, KinectDropoutIsReportedAndFusionResumes) {
  const SessionRun r = run({QStringLiteral("sensors=upper+forearm+kinect,dropout=kinect@3+2")}, 8.0);
  expectComplete(r);
  EXPECT_TRUE(mentions(r.events, "kinect dropped out at 3 s")) << r.events.size();
  EXPECT_TRUE(mentions(r.events, "kinect back at 5 s"));
  EXPECT_NEAR(static_cast<double>(streamOf(r.stats, "kinect").deviceDropped), 60.0, 2.0);
  // IMU rows and estimates go on through the dropout; Kinect rows stop, then come back.
  auto est = [](const ArmSample& s) { return s.estimate.has_value(); };
  auto kin = [](const ArmSample& s) { return s.wrist.has_value(); };
  EXPECT_GT(rowsWith(r.rec, 3.3, 4.7, est), 1300u);
  EXPECT_EQ(rowsWith(r.rec, 3.3, 4.7, kin), 0u);
  EXPECT_GT(rowsWith(r.rec, 5.3, 7.5, kin), 60u);
  const JointVector e = rmse(r.rec, 5.5, 1e9);
  for (int j = 0; j < kNumJoints; ++j) EXPECT_LT(e(j), 2.0 * kDeg) << "joint " << j;
}

TEST_F(SessionTest, OpticalDeviceDisappearsAndSessionRunsOnImus) {
  const SessionRun r = run({QStringLiteral("sensors=upper+forearm"),
                     QStringLiteral("sensors=kinect,disappear=3+2")},
                    8.0);
  expectComplete(r);
  EXPECT_TRUE(mentions(r.events, "connecting (virtual arm: link lost at 3 s"));
  EXPECT_TRUE(mentions(r.events, "streaming (virtual arm: link back at 5 s"));
  auto est = [](const ArmSample& s) { return s.estimate.has_value(); };
  auto kin = [](const ArmSample& s) { return s.wrist.has_value(); };
  EXPECT_GT(rowsWith(r.rec, 3.3, 4.7, est), 1300u);
  EXPECT_EQ(rowsWith(r.rec, 3.3, 4.7, kin), 0u);
  EXPECT_GT(rowsWith(r.rec, 5.3, 7.5, kin), 60u);
}

TEST_F(SessionTest, ImuDeviceDisappearsAndComesBackWithARestartedClock) {
  const SessionRun r = run({QStringLiteral("sensors=upper+forearm+kinect,disappear=3+1.5,restart-clock=on")},
                    9.0);
  expectComplete(r);
  EXPECT_TRUE(mentions(r.events, "link lost at 3 s"));
  EXPECT_TRUE(mentions(r.events, "its clock restarted from 0"));
  auto imu = [](const ArmSample& s) { return s.upperArm.has_value(); };
  EXPECT_EQ(rowsWith(r.rec, 3.2, 4.3, imu), 0u);
  EXPECT_GT(rowsWith(r.rec, 5.0, 8.5, imu), 3000u);
  // The estimator restarts after the gap and converges again on IMUs + Kinect.
  const JointVector e = rmse(r.rec, 7.0, 1e9);
  for (int j = 0; j < kNumJoints; ++j) EXPECT_LT(e(j), 3.0 * kDeg) << "joint " << j;
}

TEST_F(SessionTest, StalledLinkDeliversItsBurstWithoutLoss) {
  const SessionRun r = run({QStringLiteral("sensors=upper+forearm+kinect,stall=3+0.5")}, 6.0);
  expectComplete(r);
  EXPECT_EQ(r.stats.lost(), 0u);
  EXPECT_TRUE(mentions(r.events, "link stalled at 3 s"));
  EXPECT_TRUE(mentions(r.events, "held samples"));
  // The held samples keep their own times: one IMU row per millisecond through the stall.
  auto imu = [](const ArmSample& s) { return s.upperArm.has_value(); };
  EXPECT_NEAR(static_cast<double>(rowsWith(r.rec, 3.05, 3.45, imu)), 400.0, 5.0);
  auto est = [](const ArmSample& s) { return s.estimate.has_value(); };
  EXPECT_NEAR(static_cast<double>(rowsWith(r.rec, 3.05, 3.45, est)), 400.0, 5.0);
}

TEST_F(SessionTest, ClockJumpsBackAndForthKeepTheSessionRunning) {
  const SessionRun r = run({QStringLiteral("sensors=upper+forearm+kinect,jump=3:-0.5|5:1")}, 8.0);
  expectComplete(r);
  EXPECT_EQ(r.stats.lost(), 0u);
  EXPECT_TRUE(mentions(r.events, "IMU clock stepped by -0.5 s"));
  EXPECT_TRUE(mentions(r.events, "IMU clock stepped by 1 s"));
  // Session time keeps running forward (the reader would refuse anything else) and the
  // estimates stay right after the synchroniser re-locks.
  auto est = [](const ArmSample& s) { return s.estimate.has_value(); };
  EXPECT_GT(rowsWith(r.rec, 5.5, 7.5, est), 1800u);
  const JointVector e = rmse(r.rec, 6.0, 1e9);
  for (int j = 0; j < kNumJoints; ++j) EXPECT_LT(e(j), 2.0 * kDeg) << "joint " << j;
}

TEST_F(SessionTest, CorruptSamplesAreRejectedCountedAndReported) {
  const SessionRun r = run({QStringLiteral("sensors=upper+forearm+kinect,corrupt=0.01")}, 6.0);
  expectComplete(r);
  const StreamStats& up = streamOf(r.stats, "upper");
  EXPECT_NEAR(static_cast<double>(up.rejected) / static_cast<double>(up.received), 0.01, 0.004);
  EXPECT_EQ(r.stats.lost(), up.rejected + streamOf(r.stats, "forearm").rejected);
  EXPECT_TRUE(mentions(r.events, "NaN/infinite values"));
  const JointVector e = rmse(r.rec, 2.0, 1e9);
  for (int j = 0; j < kNumJoints; ++j) EXPECT_LT(e(j), 2.0 * kDeg) << "joint " << j;
}

TEST_F(SessionTest, DriftingImuClockIsEstimated) {
  const SessionRun r = run({QStringLiteral("sensors=upper+forearm+kinect,drift=500")}, 8.0);
  expectComplete(r);
  EXPECT_NEAR(streamOf(r.stats, "upper").driftPpm, -500.0, 60.0);
  const JointVector e = rmse(r.rec, 2.0, 1e9);
  for (int j = 0; j < kNumJoints; ++j) EXPECT_LT(e(j), 2.0 * kDeg) << "joint " << j;
}

TEST_F(SessionTest, RefusesAmbiguousOrIncompleteSetups) {
  devices::DevicePlugin* plugin = test::loadPlugin(QStringLiteral("virtual-arm"));
  ASSERT_NE(plugin, nullptr);
  QString why;
  {
    Session s(SessionParams{});
    s.addDevice(plugin->create(devices::Options::parse(QStringLiteral("sensors=upper")), &why), "a");
    s.addDevice(plugin->create(devices::Options::parse(QStringLiteral("sensors=upper")), &why), "b");
    EXPECT_NE(s.start().indexOf(QStringLiteral("two streams provide the upper-arm IMU")), -1);
  }
  {
    Session s(SessionParams{});
    s.addDevice(plugin->create(devices::Options::parse(QStringLiteral("sensors=kinect")), &why), "k");
    EXPECT_NE(s.start().indexOf(QStringLiteral("no IMU")), -1);
  }
  {
    SessionParams p;
    p.recordingPath = "/nonexistent-folder/x.csv";
    Session s(p);
    s.addDevice(plugin->create(devices::Options::parse(QStringLiteral("sensors=upper")), &why), "u");
    EXPECT_NE(s.start().indexOf(QStringLiteral("cannot record")), -1);
    EXPECT_FALSE(s.running());
  }
  EXPECT_EQ(plugin->create(devices::Options::parse(QStringLiteral("sensors=upper,bogus=1")), &why),
            nullptr);
  EXPECT_NE(why.indexOf(QStringLiteral("unknown option 'bogus'")), -1);
  EXPECT_EQ(plugin->create(devices::Options::parse(QStringLiteral("dropout=elbow@1+1")), &why),
            nullptr);
  EXPECT_NE(why.indexOf(QStringLiteral("does not have")), -1);
}

}  // namespace
}  // namespace armtrack::session
