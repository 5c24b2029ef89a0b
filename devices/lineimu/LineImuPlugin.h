// The "line-imu" device plugin: a do-it-yourself IMU speaking ArmTrack's line protocol.
#pragma once

#include <QObject>

#include "devices/api/Device.h"

namespace armtrack::devices::lineimu {

/// Factory of LineImuDevice. Loaded by QPluginLoader; any thread.
class LineImuPlugin : public QObject, public DevicePlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID ARMTRACK_DEVICE_PLUGIN_IID FILE "line-imu.json")
  Q_INTERFACES(armtrack::devices::DevicePlugin)
 public:
  QString name() const override;
  QString description() const override;
  QString optionsHelp() const override;
  std::unique_ptr<Device> create(const QVariantMap& options, QString* error) override;
};

}  // namespace armtrack::devices::lineimu
