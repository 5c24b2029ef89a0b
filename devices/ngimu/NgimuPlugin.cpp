#include "devices/ngimu/NgimuPlugin.h"

#include "devices/ngimu/NgimuDevice.h"

namespace armtrack::devices::ngimu {

QString NgimuPlugin::name() const {
  return QStringLiteral("ngimu");
}

QString NgimuPlugin::description() const {
  return QStringLiteral("x-io NGIMU over Wi-Fi (OSC over UDP, /sensors messages)");
}

QString NgimuPlugin::optionsHelp() const {
  return QStringLiteral(
      "port=         local UDP port the NGIMU sends to, required (e.g. 8001)\n"
      "role=         upper, forearm or trunk, required: where the sensor is strapped (trunk:\n"
      "              a third sensor flat on the sternum, measuring the patient's lean)\n"
      "timeout=3     seconds without a sample before the state goes back to connecting");
}

std::unique_ptr<Device> NgimuPlugin::create(const QVariantMap& options, QString* error) {
  const auto settings = readNgimuSettings(options, error);
  if (!settings) return nullptr;
  return std::make_unique<NgimuDevice>(*settings);
}

}  // namespace armtrack::devices::ngimu
