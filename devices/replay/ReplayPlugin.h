// Plugin "replay": plays a recording file (docs/devices/replay.md).
#pragma once

#include <QObject>

#include "devices/api/Device.h"

namespace armtrack::devices::replay {

class ReplayPlugin final : public QObject, public DevicePlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID ARMTRACK_DEVICE_PLUGIN_IID FILE "replay.json")
  Q_INTERFACES(armtrack::devices::DevicePlugin)
 public:
  QString name() const override { return QStringLiteral("replay"); }
  QString description() const override {
    return QStringLiteral("plays a recording (open format) at real time or faster");
  }
  QString optionsHelp() const override {
    return QStringLiteral(
        "file=REC.csv   the recording (its .json sidecar beside it)\n"
        "speed=1        recording seconds per second, 0.1 to 100\n"
        "loop=off       start again at the end");
  }
  std::unique_ptr<Device> create(const QVariantMap& options, QString* error) override;
};

}  // namespace armtrack::devices::replay
