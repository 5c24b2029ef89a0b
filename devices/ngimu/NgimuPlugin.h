// The "ngimu" device plugin: an x-io NGIMU sending OSC over UDP.
#pragma once

#include <QObject>

#include "devices/api/Device.h"

namespace armtrack::devices::ngimu {

/// Factory of NgimuDevice. Loaded by QPluginLoader; any thread.
class NgimuPlugin : public QObject, public DevicePlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID ARMTRACK_DEVICE_PLUGIN_IID FILE "ngimu.json")
  Q_INTERFACES(armtrack::devices::DevicePlugin)
 public:
  QString name() const override;
  QString description() const override;
  QString optionsHelp() const override;
  std::unique_ptr<Device> create(const QVariantMap& options, QString* error) override;
};

}  // namespace armtrack::devices::ngimu
