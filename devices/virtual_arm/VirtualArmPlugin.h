// Plugin "virtual-arm": creates VirtualArmDevice from string options (docs/devices/virtual-arm.md).
#pragma once

#include <QObject>

#include "devices/api/Device.h"

namespace armtrack::devices::virtualarm {

class VirtualArmPlugin final : public QObject, public DevicePlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID ARMTRACK_DEVICE_PLUGIN_IID FILE "virtual-arm.json")
  Q_INTERFACES(armtrack::devices::DevicePlugin)
 public:
  QString name() const override { return QStringLiteral("virtual-arm"); }
  QString description() const override;
  QString optionsHelp() const override;
  std::unique_ptr<Device> create(const QVariantMap& options, QString* error) override;
};

}  // namespace armtrack::devices::virtualarm
