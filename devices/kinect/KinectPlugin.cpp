#include "devices/kinect/KinectPlugin.h"

#include "devices/kinect/KinectDevice.h"

namespace armtrack::devices::kinect {

QString KinectPlugin::description() const {
  // Word for word as in ui/DeviceWords.cpp, which translates it. "Shoulder frame": the one it was
  // registered in, which is the world frame of a session with a trunk sensor.
  return QStringLiteral("Kinect v1 (libfreenect): elbow and wrist markers in 3D, shoulder frame");
}

QString KinectPlugin::optionsHelp() const {
  return QStringLiteral(
      "camera=                    calibration file of the colour camera with its pose (required;\n"
      "                           armtrack-cli camera-calibrate, then camera-register)\n"
      "index=0                    which Kinect, when several are plugged in\n"
      "markers=colour             colour or aruco\n"
      "wrist-hsv=45-75:100-255:70-255   colour markers: wrist HSV box (hue 0-179), green\n"
      "elbow-hsv=100-130:100-255:70-255 colour markers: elbow HSV box, blue\n"
      "min-area=20                colour markers: smallest blob, pixels\n"
      "dictionary=DICT_4X4_50     aruco markers: OpenCV dictionary\n"
      "wrist-id=0                 aruco markers: wrist marker id\n"
      "elbow-id=1                 aruco markers: elbow marker id\n"
      "shoulder-hsv=              colour markers: HSV box of a third marker, on the shoulder\n"
      "                           (acromion), e.g. magenta 140-170:100-255:70-255; empty: none.\n"
      "                           It shows the trunk's lean\n"
      "shoulder-id=               aruco markers: the shoulder marker's id (e.g. 2)\n"
      "window=5                   depth pixels (odd square side) whose median is a marker's depth\n"
      "joint-depth=0              m from the marker's surface to the joint centre, along the ray\n"
      "retry=1                    s between attempts to reopen\n"
      "timeout=2                  s without a depth frame before reopening");
}

std::unique_ptr<Device> KinectPlugin::create(const QVariantMap& options, QString* error) {
  auto settings = readKinectSettings(options, error);
  if (!settings) return nullptr;
  try {
    return std::make_unique<KinectDevice>(std::move(*settings));
  } catch (const std::invalid_argument& e) {
    if (error) *error = QStringLiteral("kinect: %1").arg(e.what());
    return nullptr;
  }
}

}  // namespace armtrack::devices::kinect
