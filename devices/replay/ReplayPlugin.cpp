#include "devices/replay/ReplayPlugin.h"

#include "devices/api/Options.h"
#include "devices/replay/ReplayDevice.h"

namespace armtrack::devices::replay {

std::unique_ptr<Device> ReplayPlugin::create(const QVariantMap& options, QString* error) {
  Options o(options);
  const QString file = o.text(QStringLiteral("file"));
  const double speed = o.number(QStringLiteral("speed"), 1.0, 0.1, 100.0);
  const bool loop = o.flag(QStringLiteral("loop"), false);
  QString problem = o.error();
  if (problem.isEmpty() && file.isEmpty())
    problem = QStringLiteral("give the recording to play: file=REC.csv");
  if (problem.isEmpty()) {
    try {
      return std::make_unique<ReplayDevice>(file.toStdString(), speed, loop);
    } catch (const RecordingError& e) {
      problem = QString::fromStdString(e.what());
    }
  }
  if (error) *error = QStringLiteral("replay: ") + problem;
  return nullptr;
}

}  // namespace armtrack::devices::replay
