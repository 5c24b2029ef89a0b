// Plugin "webcam": creates WebcamDevice from string options (docs/devices/webcam.md).
#pragma once

#include <QObject>

#include "devices/api/Device.h"

namespace armtrack::devices::webcam {

class WebcamPlugin final : public QObject, public DevicePlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID ARMTRACK_DEVICE_PLUGIN_IID FILE "webcam.json")
  Q_INTERFACES(armtrack::devices::DevicePlugin)
 public:
  QString name() const override { return QStringLiteral("webcam"); }
  QString description() const override;
  QString optionsHelp() const override;
  std::unique_ptr<Device> create(const QVariantMap& options, QString* error) override;
};

}  // namespace armtrack::devices::webcam
