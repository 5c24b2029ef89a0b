#include "devices/shimmer3/Shimmer3Plugin.h"

#include "devices/shimmer3/Shimmer3Device.h"

namespace armtrack::devices::shimmer3 {

QString Shimmer3Plugin::name() const {
  return QStringLiteral("shimmer3");
}

QString Shimmer3Plugin::description() const {
  return QStringLiteral("Shimmer3 IMU (LogAndStream firmware) over its Bluetooth serial port");
}

QString Shimmer3Plugin::optionsHelp() const {
  return QStringLiteral(
      "port=         serial port of the Shimmer, required (e.g. /dev/rfcomm0)\n"
      "role=         upper, forearm or trunk, required: where the sensor is strapped (trunk:\n"
      "              a third sensor flat on the sternum, measuring the patient's lean)\n"
      "retry=1       seconds between attempts to open the port\n"
      "timeout=3     seconds without an answer or data before the port is reopened");
}

std::unique_ptr<Device> Shimmer3Plugin::create(const QVariantMap& options, QString* error) {
  const auto settings = readShimmer3Settings(options, error);
  if (!settings) return nullptr;
  return std::make_unique<Shimmer3Device>(*settings);
}

}  // namespace armtrack::devices::shimmer3
