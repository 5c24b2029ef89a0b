#include "devices/webcam/WebcamPlugin.h"

#include "devices/webcam/WebcamDevice.h"

namespace armtrack::devices::webcam {

QString WebcamPlugin::description() const {
  return QStringLiteral("wrist and elbow marker pixels from a camera or a video file (OpenCV)");
}

QString WebcamPlugin::optionsHelp() const {
  return QStringLiteral(
      "source=0                   camera index, /dev/videoN, or a video file\n"
      "markers=colour             colour (one coloured patch per marker) or aruco\n"
      "camera=                    calibration file from armtrack-cli camera-calibrate and\n"
      "                           camera-register (gives the stream its camera model)\n"
      "wrist-hsv=45-75:100-255:70-255   colour markers: wrist HSV box (hue 0-179), green\n"
      "elbow-hsv=100-130:100-255:70-255 colour markers: elbow HSV box, blue\n"
      "min-area=20                colour markers: smallest blob, pixels\n"
      "dictionary=DICT_4X4_50     aruco markers: OpenCV dictionary\n"
      "wrist-id=0                 aruco markers: wrist marker id\n"
      "elbow-id=1                 aruco markers: elbow marker id\n"
      "loop=off                   files: start again at the end\n"
      "speed=1                    files: 1 = the file's frame rate, 0 = as fast as possible\n"
      "width=0                    cameras: requested frame width, 0 = default\n"
      "height=0                   cameras: requested frame height, 0 = default\n"
      "retry=1                    cameras: s between attempts to reopen\n"
      "timeout=2                  cameras: s without a frame before reopening");
}

std::unique_ptr<Device> WebcamPlugin::create(const QVariantMap& options, QString* error) {
  auto settings = readWebcamSettings(options, error);
  if (!settings) return nullptr;
  return std::make_unique<WebcamDevice>(std::move(*settings));
}

}  // namespace armtrack::devices::webcam
