// The trunk (sternum) IMU through real plugins into a session: any IMU plugin can be the third
// sensor, a session takes one upper-arm, one forearm and one trunk IMU, and two devices claiming
// the trunk are refused with a message that names them and says what to do.
#include <gtest/gtest.h>

#include <QUdpSocket>
#include <memory>

#include "core/session/Session.h"
#include "devices/api/Options.h"
#include "tests/support/LoadPlugin.h"

using namespace armtrack;
using namespace armtrack::devices;

namespace {

std::uint16_t freeUdpPort() {
  QUdpSocket s;
  EXPECT_TRUE(s.bind(QHostAddress::LocalHost, 0));
  return s.localPort();
}

std::unique_ptr<Device> create(const QString& plugin, const QString& options) {
  DevicePlugin* p = test::loadPlugin(plugin);
  if (!p) return nullptr;
  QString error;
  auto d = p->create(Options::parse(options), &error);
  EXPECT_TRUE(d) << plugin.toStdString() << ":" << options.toStdString() << ": "
                 << error.toStdString();
  return d;
}

}  // namespace

TEST(TrunkRoleSession, EveryImuPluginCanBeTheTrunkSensor) {
  const QString trunk = QStringLiteral("role=trunk");
  for (const auto& [plugin, options] :
       {std::pair{QStringLiteral("shimmer3"), QStringLiteral("port=/dev/nonexistent-shimmer")},
        std::pair{QStringLiteral("line-imu"), QStringLiteral("udp=%1").arg(freeUdpPort())},
        std::pair{QStringLiteral("ngimu"), QStringLiteral("port=%1").arg(freeUdpPort())}}) {
    auto d = create(plugin, options + u',' + trunk);
    ASSERT_TRUE(d);
    ASSERT_EQ(d->streams().size(), 1u);
    EXPECT_EQ(d->streams()[0].role, StreamRole::TrunkImu) << plugin.toStdString();
  }
}

TEST(TrunkRoleSession, ThreeImusWithTheirOwnRolesStart) {
  session::SessionParams params;
  session::Session s(params);
  const char* roles[] = {"upper", "forearm", "trunk"};
  for (const char* role : roles) {
    auto d = create(QStringLiteral("line-imu"),
                    QStringLiteral("udp=%1,role=%2").arg(freeUdpPort()).arg(QLatin1String(role)));
    ASSERT_TRUE(d);
    s.addDevice(test::hosted(std::move(d), QLatin1String(role)), QLatin1String(role));
  }
  EXPECT_EQ(s.start(), QString());
  s.stop();
}

// Hostile: a second sensor also set to the trunk (a typo in a device's options, or a sensor
// assigned twice). The session refuses to start, names the role and both devices, and says what
// to do, before it opens any device.
TEST(TrunkRoleSession, TwoDevicesClaimingTheTrunkAreRefused) {
  session::SessionParams params;
  session::Session s(params);
  auto upper =
      create(QStringLiteral("line-imu"), QStringLiteral("udp=%1,role=upper").arg(freeUdpPort()));
  auto chest = create(QStringLiteral("shimmer3"),
                      QStringLiteral("port=/dev/nonexistent-shimmer,role=trunk"));
  auto sternum =
      create(QStringLiteral("ngimu"), QStringLiteral("port=%1,role=Sternum").arg(freeUdpPort()));
  ASSERT_TRUE(upper && chest && sternum);
  s.addDevice(test::hosted(std::move(upper), QStringLiteral("arm")), QStringLiteral("arm"));
  s.addDevice(test::hosted(std::move(chest), QStringLiteral("chest Shimmer")),
              QStringLiteral("chest Shimmer"));
  s.addDevice(test::hosted(std::move(sternum), QStringLiteral("sternum NGIMU")),
              QStringLiteral("sternum NGIMU"));
  const QString why = s.start();
  EXPECT_EQ(why, QStringLiteral("two streams provide the trunk IMU (chest Shimmer and sternum "
                                "NGIMU); keep one"));
  // Nothing was started: the devices are still disconnected.
  const session::SessionStats st = s.stats();
  ASSERT_EQ(st.deviceStates.size(), 3u);
  for (DeviceState state : st.deviceStates) EXPECT_EQ(state, DeviceState::Disconnected);
}
