// The device-health rules on the session's figures as they evolve: a stream that goes silent or
// whose device reconnects turns red and comes back green; losses give a warning; the summary
// says which stream and why.
#include <gtest/gtest.h>

#include <limits>

#include "ui/DeviceHealthPanel.h"

namespace armtrack::ui {
namespace {

session::SessionStats twoDevices() {
  session::SessionStats s;
  s.deviceLabels = {"virtual-arm#1", "virtual-arm#2"};
  s.deviceStates = {DeviceState::Streaming, DeviceState::Streaming};
  session::StreamStats imu;
  imu.device = "virtual-arm#1";
  imu.stream = "upper";
  imu.rateHz = 1000;
  session::StreamStats kinect = imu;
  kinect.device = "virtual-arm#2";
  kinect.stream = "kinect";
  kinect.rateHz = 30;
  s.streams = {imu, kinect};
  return s;
}

/// Advances the figures by dt seconds with both streams delivering (unless silenced).
void advance(session::SessionStats& s, double dt, bool kinectSilent = false) {
  s.elapsed += dt;
  s.streams[0].received += static_cast<std::uint64_t>(1000 * dt);
  if (!kinectSilent) s.streams[1].received += static_cast<std::uint64_t>(30 * dt) + 1;
}

TEST(HealthTracker, SilentStreamTurnsRedAndRecovers) {
  HealthTracker h;
  session::SessionStats s = twoDevices();
  h.update(s, s.elapsed);
  EXPECT_EQ(h.rows()[0].level, HealthLevel::Warning);  // no data yet
  for (int i = 0; i < 10; ++i) {
    advance(s, 0.1);
    h.update(s, s.elapsed);
  }
  EXPECT_TRUE(h.allOk()) << h.summary().toStdString();
  EXPECT_EQ(h.summary(), QStringLiteral("All devices are streaming"));
  // The Kinect goes silent: red within silentAfter, the IMU stays green.
  for (int i = 0; i < 8; ++i) {
    advance(s, 0.1, true);
    h.update(s, s.elapsed);
  }
  EXPECT_EQ(h.rows()[1].level, HealthLevel::Down);
  EXPECT_EQ(h.rows()[0].level, HealthLevel::Ok);
  EXPECT_TRUE(h.summary().contains(QStringLiteral("kinect: no data for")))
      << h.summary().toStdString();
  // It comes back.
  advance(s, 0.1);
  h.update(s, s.elapsed);
  EXPECT_EQ(h.rows()[1].level, HealthLevel::Ok);
}

TEST(HealthTracker, TrunkSensorIsListedByWhatItIsWithItsRateAndHealth) {
  HealthTracker h;
  session::SessionStats s = twoDevices();
  session::StreamStats trunk = s.streams[0];
  trunk.stream = "trunk";
  trunk.role = StreamRole::TrunkImu;
  trunk.rateHz = 200;
  s.streams.push_back(trunk);
  h.update(s, s.elapsed);
  ASSERT_EQ(h.rows().size(), 3u);
  EXPECT_EQ(h.rows()[2].stream, QStringLiteral("Trunk (sternum) sensor"));
  EXPECT_EQ(h.rows()[2].rateHz, 200);
  EXPECT_EQ(h.rows()[0].stream, QStringLiteral("upper"));  // the arm's as their device names them
  EXPECT_EQ(h.rows()[2].level, HealthLevel::Warning);      // no data yet
  for (int i = 0; i < 10; ++i) {
    advance(s, 0.1);
    s.streams[2].received += 20;
    h.update(s, s.elapsed);
  }
  EXPECT_TRUE(h.allOk()) << h.summary().toStdString();
  // It goes silent while the arm sensors stream: it alone turns red, and the summary says so.
  for (int i = 0; i < 10; ++i) {
    advance(s, 0.1);
    h.update(s, s.elapsed);
  }
  EXPECT_EQ(h.rows()[2].level, HealthLevel::Down);
  EXPECT_EQ(h.rows()[0].level, HealthLevel::Ok);
  EXPECT_TRUE(h.summary().contains(QStringLiteral("Trunk (sternum) sensor: no data")))
      << h.summary().toStdString();
  s.streams[2].received += 200;
  advance(s, 0.1);
  h.update(s, s.elapsed);
  EXPECT_EQ(h.rows()[2].level, HealthLevel::Ok);
}

TEST(HealthTracker, DeviceThatReconnectsIsDownWithItsReason) {
  HealthTracker h;
  session::SessionStats s = twoDevices();
  for (int i = 0; i < 5; ++i) {
    advance(s, 0.1);
    h.update(s, s.elapsed);
  }
  s.deviceStates[0] = DeviceState::Connecting;
  h.setDeviceState(0, DeviceState::Connecting, QStringLiteral("link lost at 10 s"));
  h.update(s, s.elapsed);
  EXPECT_EQ(h.rows()[0].level, HealthLevel::Down);
  EXPECT_EQ(h.rows()[0].status, QStringLiteral("reconnecting: link lost at 10 s"));
  s.deviceStates[0] = DeviceState::Streaming;
  h.setDeviceState(0, DeviceState::Streaming, {});
  advance(s, 0.1);
  h.update(s, s.elapsed);
  EXPECT_EQ(h.rows()[0].level, HealthLevel::Ok);
  s.deviceStates[1] = DeviceState::Error;
  h.setDeviceState(1, DeviceState::Error, QStringLiteral("port closed"));
  h.update(s, s.elapsed);
  EXPECT_EQ(h.rows()[1].level, HealthLevel::Down);
  EXPECT_EQ(h.rows()[1].status, QStringLiteral("error: port closed"));
}

TEST(HealthTracker, LossesGiveAWarningThatFades) {
  HealthTracker h;
  session::SessionStats s = twoDevices();
  for (int i = 0; i < 5; ++i) {
    advance(s, 0.1);
    h.update(s, s.elapsed);
  }
  s.streams[0].deviceDropped += 40;
  advance(s, 0.1);
  h.update(s, s.elapsed);
  EXPECT_EQ(h.rows()[0].level, HealthLevel::Warning);
  EXPECT_EQ(h.rows()[0].lost, 40u);
  for (int i = 0; i < 35; ++i) {
    advance(s, 0.1);
    h.update(s, s.elapsed);
  }
  EXPECT_EQ(h.rows()[0].level, HealthLevel::Ok);
}

TEST(HealthTracker, NeverStreamedIsWaitingThenDown) {
  HealthTracker h;
  session::SessionStats s = twoDevices();
  s.streams[1].received = 0;
  for (int i = 0; i < 10; ++i) {
    s.elapsed += 0.1;
    s.streams[0].received += 100;
    h.update(s, s.elapsed);
  }
  EXPECT_EQ(h.rows()[1].level, HealthLevel::Warning);
  for (int i = 0; i < 30; ++i) {
    s.elapsed += 0.1;
    h.update(s, s.elapsed);
  }
  EXPECT_EQ(h.rows()[1].level, HealthLevel::Down);
}

TEST(DeviceHealthModel, SaysTheLevelInWordsNotOnlyInColour) {
  DeviceHealthModel m;
  StreamHealthRow r;
  r.device = QStringLiteral("dev");
  r.stream = QStringLiteral("kinect");
  r.level = HealthLevel::Down;
  r.status = QStringLiteral("no data for 2.0 s");
  m.setRows({r});
  EXPECT_EQ(m.rowCount(), 1);
  EXPECT_EQ(m.data(m.index(0, DeviceHealthModel::Status)).toString(),
            QStringLiteral("down: no data for 2.0 s"));
  EXPECT_TRUE(m.data(m.index(0, DeviceHealthModel::Status), Qt::DecorationRole).isValid());
}

TEST(DeviceHealthModel, ShowsTheBatteryWhereTheDeviceReportsIt) {
  session::SessionStats s = twoDevices();
  s.streams[0].batteryPercent = 64.4;  // the IMU's device reports one, the Kinect's does not
  HealthTracker t;
  advance(s, 0.1);
  t.update(s, s.elapsed);
  ASSERT_EQ(t.rows().size(), 2u);
  EXPECT_EQ(t.rows()[0].batteryPercent, std::optional<double>(64.4));
  EXPECT_FALSE(t.rows()[1].batteryPercent);
  DeviceHealthModel m;
  m.setRows(t.rows());
  const QModelIndex imu = m.index(0, DeviceHealthModel::Battery);
  const QModelIndex kinect = m.index(1, DeviceHealthModel::Battery);
  EXPECT_EQ(m.headerData(DeviceHealthModel::Battery, Qt::Horizontal).toString(),
            QStringLiteral("Battery"));
  EXPECT_EQ(m.data(imu).toString(), QStringLiteral("64 %"));
  EXPECT_FALSE(m.data(imu, Qt::ForegroundRole).isValid());
  EXPECT_EQ(m.data(kinect).toString(), QStringLiteral("\u2013"));
  EXPECT_EQ(m.data(kinect, Qt::AccessibleTextRole).toString(), QStringLiteral("not reported"));
  EXPECT_FALSE(m.data(kinect, Qt::ToolTipRole).toString().isEmpty());

  // Low: in the warning colour and said in words; the stream itself stays OK.
  s.streams[0].batteryPercent = 12.0;
  advance(s, 0.1);
  t.update(s, s.elapsed);
  m.setRows(t.rows());
  EXPECT_EQ(m.data(imu).toString(), QStringLiteral("12 %"));
  EXPECT_EQ(m.data(imu, Qt::ForegroundRole).value<QColor>(),
            healthColour(HealthLevel::Warning, false));
  EXPECT_EQ(m.data(imu, Qt::AccessibleTextRole).toString(), QStringLiteral("12 %, low"));
  EXPECT_EQ(t.rows()[0].level, HealthLevel::Ok);

  // What no battery reports is not shown.
  for (const double absurd : {-1.0, 100.5, 1e9, std::numeric_limits<double>::quiet_NaN(),
                              std::numeric_limits<double>::infinity()}) {
    s.streams[0].batteryPercent = absurd;
    t.update(s, s.elapsed);
    EXPECT_FALSE(t.rows()[0].batteryPercent) << absurd;
  }
}

}  // namespace
}  // namespace armtrack::ui
