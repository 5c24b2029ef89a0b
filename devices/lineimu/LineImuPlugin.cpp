#include "devices/lineimu/LineImuPlugin.h"

#include "devices/lineimu/LineImuDevice.h"

namespace armtrack::devices::lineimu {

QString LineImuPlugin::name() const {
  return QStringLiteral("line-imu");
}

QString LineImuPlugin::description() const {
  return QStringLiteral(
      "do-it-yourself IMU (ESP32/Arduino) sending ArmTrack's $IMU text lines "
      "over a serial port or UDP");
}

QString LineImuPlugin::optionsHelp() const {
  return QStringLiteral(
      "port=         serial port, e.g. /dev/ttyUSB0 (give port or udp)\n"
      "udp=          local UDP port to listen on, e.g. 9871 (give port or udp)\n"
      "role=         upper, forearm or trunk, required: where the sensor is strapped (trunk:\n"
      "              a third sensor flat on the sternum, measuring the patient's lean)\n"
      "baud=115200   serial speed (bit/s), serial only\n"
      "retry=1       seconds between attempts to open the serial port\n"
      "timeout=3     seconds without a sample before the state goes back to connecting");
}

std::unique_ptr<Device> LineImuPlugin::create(const QVariantMap& options, QString* error) {
  const auto settings = readLineImuSettings(options, error);
  if (!settings) return nullptr;
  return std::make_unique<LineImuDevice>(*settings);
}

}  // namespace armtrack::devices::lineimu
