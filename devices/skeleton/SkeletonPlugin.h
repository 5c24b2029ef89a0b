// The "skeleton-udp" device plugin: arm joints from an external body tracker, JSON over UDP.
#pragma once

#include <QObject>

#include "devices/api/Device.h"

namespace armtrack::devices::skeleton {

/// Factory of SkeletonDevice. Loaded by QPluginLoader; any thread.
class SkeletonPlugin : public QObject, public DevicePlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID ARMTRACK_DEVICE_PLUGIN_IID FILE "skeleton-udp.json")
  Q_INTERFACES(armtrack::devices::DevicePlugin)
 public:
  QString name() const override;
  QString description() const override;
  QString optionsHelp() const override;
  std::unique_ptr<Device> create(const QVariantMap& options, QString* error) override;
};

}  // namespace armtrack::devices::skeleton
