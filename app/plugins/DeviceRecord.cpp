#include "app/plugins/DeviceRecord.h"

#include <QStringList>

#include "devices/api/Device.h"

namespace armtrack::app {

QJsonObject deviceRecord(const QString& plugin, const QVariantMap& options,
                         const devices::Device& device) {
  QJsonObject given;
  for (auto it = options.begin(); it != options.end(); ++it)
    given.insert(it.key(), it.value().toString());
  QStringList streams;
  for (const StreamInfo& s : device.streams())
    streams << QStringLiteral("%1 (%2, %3 Hz)")
                   .arg(QString::fromStdString(s.name), QLatin1String(toString(s.role)))
                   .arg(s.nominalRateHz, 0, 'g', 6);
  return {{QStringLiteral("plugin"), plugin},
          {QStringLiteral("options"), given},
          {QStringLiteral("streams"), streams.join(QStringLiteral("; "))}};
}

}  // namespace armtrack::app
