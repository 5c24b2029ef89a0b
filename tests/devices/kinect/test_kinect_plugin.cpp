// The kinect plugin without hardware: option errors, and a device that finds no Kinect waits in
// Connecting with a reason instead of failing or crashing.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>

#include "devices/vision/CameraFile.h"
#include "tests/devices/vision/Synthetic.h"
#include "tests/support/LoadPlugin.h"

using namespace armtrack;
using namespace armtrack::devices;

namespace {

std::string writeCamera(const test::webcam::TempDir& dir, bool withPose,
                        cv::Size size = {640, 480}) {
  webcam::CameraFile f;
  f.intrinsics.imageSize = size;
  f.intrinsics.fx = f.intrinsics.fy = 525;
  f.intrinsics.cx = 319.5;
  f.intrinsics.cy = 239.5;
  if (withPose) f.extrinsics = webcam::Extrinsics{};
  const std::string path = dir.file(withPose ? "cam.json" : "intrinsics.json");
  webcam::writeCameraFile(path, f);
  return path;
}

}  // namespace

TEST(KinectPlugin, OptionsAreCheckedWithReasons) {
  DevicePlugin* plugin = test::loadPlugin(QStringLiteral("kinect"));
  ASSERT_TRUE(plugin);
  EXPECT_EQ(plugin->name(), QStringLiteral("kinect"));
  const test::webcam::TempDir dir("kinect-plugin");
  const auto refuse = [&](const QVariantMap& options, const char* needle) {
    QString error;
    EXPECT_FALSE(plugin->create(options, &error));
    EXPECT_TRUE(error.contains(QLatin1String(needle))) << error.toStdString();
  };
  refuse({}, "camera= is required");
  refuse({{"camera", QString::fromStdString(writeCamera(dir, false))}}, "camera-register");
  refuse({{"camera", QString::fromStdString(dir.file("nope.json"))}}, "no such file");
  const QString cam = QString::fromStdString(writeCamera(dir, true));
  refuse({{"camera", cam}, {"window", "4"}}, "odd");
  refuse({{"camera", cam}, {"markers", "laser"}}, "colour or aruco");
  refuse({{"camera", cam}, {"depth", "1"}}, "unknown option 'depth'");
  QString error;
  auto device = plugin->create({{"camera", cam}}, &error);
  ASSERT_TRUE(device) << error.toStdString();
  ASSERT_EQ(device->streams().size(), 1u);
  EXPECT_EQ(device->streams()[0].role, StreamRole::Optical);
  EXPECT_EQ(device->streams()[0].name, "Kinect elbow and wrist");
}

// A third marker on the shoulder: a colour or an id of its own, which the arm markers do not
// have; the stream then says it brings the shoulder.
TEST(KinectPlugin, AShoulderMarkerNeedsAThirdColourOrId) {
  DevicePlugin* plugin = test::loadPlugin(QStringLiteral("kinect"));
  ASSERT_TRUE(plugin);
  const test::webcam::TempDir dir("kinect-shoulder");
  const QString cam = QString::fromStdString(writeCamera(dir, true));
  const auto refuse = [&](const QVariantMap& options, const char* needle) {
    QString error;
    EXPECT_FALSE(plugin->create(options, &error));
    EXPECT_TRUE(error.contains(QLatin1String(needle))) << error.toStdString();
  };
  refuse({{"camera", cam}, {"shoulder-hsv", "magenta"}}, "expected H1-H2:S1-S2:V1-V2");
  refuse({{"camera", cam}, {"shoulder-hsv", "60-90:100-255:70-255"}}, "overlap the wrist's");
  refuse({{"camera", cam}, {"shoulder-hsv", "170-50:100-255:70-255"}}, "overlap");  // wraps
  refuse({{"camera", cam}, {"shoulder-id", "2"}}, "shoulder-id is for ArUco markers");
  refuse({{"camera", cam}, {"markers", "aruco"}, {"shoulder-hsv", "140-170:100-255:70-255"}},
         "shoulder-hsv is for colour markers");
  refuse({{"camera", cam}, {"markers", "aruco"}, {"shoulder-id", "1"}},
         "the wrist's or the elbow's marker");
  refuse({{"camera", cam}, {"markers", "aruco"}, {"shoulder-id", "50"}}, "shoulder-id:");
  refuse({{"camera", cam}, {"markers", "aruco"}, {"shoulder-id", "-1"}}, "option 'shoulder-id'");
  for (const QVariantMap& options :
       {QVariantMap{{"camera", cam}, {"shoulder-hsv", "140-170:100-255:70-255"}},
        QVariantMap{{"camera", cam}, {"markers", "aruco"}, {"shoulder-id", "2"}}}) {
    QString error;
    auto device = plugin->create(options, &error);
    ASSERT_TRUE(device) << error.toStdString();
    EXPECT_EQ(device->streams()[0].role, StreamRole::Optical);
    EXPECT_EQ(device->streams()[0].name, "Kinect elbow, wrist and shoulder");
  }
}

TEST(KinectPlugin, NoKinectMeansConnectingWithAReason) {
  DevicePlugin* plugin = test::loadPlugin(QStringLiteral("kinect"));
  ASSERT_TRUE(plugin);
  const test::webcam::TempDir dir("kinect-none");
  QString error;
  // index 15: no machine running the tests has sixteen Kinects.
  auto device = plugin->create({{"camera", QString::fromStdString(writeCamera(dir, true))},
                                {"index", "15"},
                                {"retry", "0.1"}},
                               &error);
  ASSERT_TRUE(device) << error.toStdString();
  QString reason;
  QObject::connect(device.get(), &Device::stateChanged,
                   [&](DeviceState, const QString& why) { reason = why; });
  QMetaObject::invokeMethod(device.get(), "start", Qt::DirectConnection);
  QElapsedTimer clock;
  clock.start();
  while (clock.elapsed() < 300) QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
  EXPECT_EQ(device->state(), DeviceState::Connecting);
  EXPECT_TRUE(reason.contains("retrying")) << reason.toStdString();
  EXPECT_TRUE(device->health().streams[0].samples == 0);
  QMetaObject::invokeMethod(device.get(), "stop", Qt::DirectConnection);
  EXPECT_EQ(device->state(), DeviceState::Disconnected);
}
