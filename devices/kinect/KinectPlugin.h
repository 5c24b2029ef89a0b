// Plugin "kinect": creates KinectDevice from string options (docs/devices/kinect.md).
#pragma once

#include <QObject>

#include "devices/api/Device.h"

namespace armtrack::devices::kinect {

class KinectPlugin final : public QObject, public DevicePlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID ARMTRACK_DEVICE_PLUGIN_IID FILE "kinect.json")
  Q_INTERFACES(armtrack::devices::DevicePlugin)
 public:
  QString name() const override { return QStringLiteral("kinect"); }
  QString description() const override;
  QString optionsHelp() const override;
  std::unique_ptr<Device> create(const QVariantMap& options, QString* error) override;
};

}  // namespace armtrack::devices::kinect
