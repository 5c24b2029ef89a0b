// The "shimmer3" device plugin: a Shimmer3 IMU over its Bluetooth serial port.
#pragma once

#include <QObject>

#include "devices/api/Device.h"

namespace armtrack::devices::shimmer3 {

/// Factory of Shimmer3Device. Loaded by QPluginLoader; any thread.
class Shimmer3Plugin : public QObject, public DevicePlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID ARMTRACK_DEVICE_PLUGIN_IID FILE "shimmer3.json")
  Q_INTERFACES(armtrack::devices::DevicePlugin)
 public:
  QString name() const override;
  QString description() const override;
  QString optionsHelp() const override;
  std::unique_ptr<Device> create(const QVariantMap& options, QString* error) override;
};

}  // namespace armtrack::devices::shimmer3
