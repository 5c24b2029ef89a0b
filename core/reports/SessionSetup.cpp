// The session report's devices and calibration in words (docs/reports.md, "Devices and
// calibration"): what a therapist reads, not the stored JSON.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>

#include "core/reports/ReportText.h"

namespace armtrack::reports {
namespace {

QJsonObject objectOf(const QString& json) {
  return QJsonDocument::fromJson(json.toUtf8()).object();
}

/// A length in metres as centimetres ("22.0 cm"); empty when not a finite number.
std::optional<QString> cm(const QJsonValue& v) {
  if (!v.isDouble() || !std::isfinite(v.toDouble())) return std::nullopt;
  return Text::tr("%1 cm").arg(reportLocale().toString(v.toDouble() * 100, 'f', 1));
}

/// An angle in radians as degrees ("90 deg").
std::optional<QString> deg(const QJsonValue& v) {
  if (!v.isDouble() || !std::isfinite(v.toDouble())) return std::nullopt;
  return Text::tr("%1 deg").arg(formatDeg(v.toDouble() * 180.0 / 3.14159265358979323846));
}

}  // namespace

QStringList devicesText(const QString& devicesJson) {
  QStringList out;
  const QString trimmed = devicesJson.trimmed();
  if (!trimmed.isEmpty() && !QJsonDocument::fromJson(trimmed.toUtf8()).isObject())
    return summariseJson(trimmed);  // says that it is not valid JSON
  const QJsonObject devices = objectOf(devicesJson);
  for (auto it = devices.begin(); it != devices.end(); ++it) {
    if (!it.value().isObject()) {
      out << QStringLiteral("%1: %2").arg(nameText(it.key()), it.value().toVariant().toString());
      continue;
    }
    const QJsonObject d = it.value().toObject();
    QString plugin = d["plugin"].toString();
    if (plugin.isEmpty()) plugin = it.key().section(u'#', 0, 0);
    QString line = nameText(plugin);
    const QString streams = d["streams"].toString();
    if (!streams.isEmpty()) line += QStringLiteral(": ") + streams;
    QStringList options;
    const QJsonObject given = d["options"].toObject();
    for (auto o = given.begin(); o != given.end(); ++o)
      options << QStringLiteral("%1 %2").arg(o.key(), o.value().toVariant().toString());
    for (auto o = d.begin(); o != d.end(); ++o)  // anything else a version stored beside them
      if (o.key() != QLatin1String("plugin") && o.key() != QLatin1String("streams") &&
          o.key() != QLatin1String("options") && !o.value().isObject() && !o.value().isArray())
        options << QStringLiteral("%1 %2").arg(o.key(), o.value().toVariant().toString());
    if (!options.isEmpty()) line += QStringLiteral(" (") + options.join(QStringLiteral(", ")) + ')';
    out << line;
  }
  return out;
}

QStringList calibrationText(const QString& calibrationJson, const QString& filterJson) {
  QStringList out;
  const QJsonObject fit = objectOf(filterJson)["sensor_calibration"].toObject();
  const QString verdict = fit["verdict"].toString();
  const QString reason = fit["reason"].toString().trimmed();
  if (verdict == QLatin1String("good") || verdict == QLatin1String("usable") ||
      verdict == QLatin1String("poor")) {
    const QString v = verdict == QLatin1String("good")     ? Text::tr("Good")
                      : verdict == QLatin1String("usable") ? Text::tr("Usable")
                                                           : Text::tr("Poor");
    // The GUI's reason begins with the verdict ("Usable, not perfect ..."): not said twice.
    if (reason.isEmpty())
      out << Text::tr("Sensor calibration: %1.").arg(v);
    else if (reason.startsWith(v))
      out << Text::tr("Sensor calibration: %1").arg(reason);
    else
      out << Text::tr("Sensor calibration: %1. %2").arg(v, reason);
  } else {
    out << Text::tr(
        "Sensor calibration: none was made for this session; the lengths below are the ones "
        "the session was recorded with (measured or default).");
  }
  const QJsonObject meta = objectOf(calibrationJson);
  const QJsonObject g = meta["geometry"].toObject();
  const auto upper = cm(g["l3"]), fore = cm(g["l6"]);
  if (upper || fore)
    out << Text::tr("Segments: upper arm %1 (shoulder to elbow), forearm %2 (elbow to wrist).")
               .arg(upper.value_or(QStringLiteral("-")), fore.value_or(QStringLiteral("-")));
  const auto strap = [&](const QString& from, const char* at, const char* angle,
                         const char* radius) -> std::optional<QString> {
    const auto a = cm(g[QLatin1String(at)]);
    if (!a) return std::nullopt;
    return Text::tr("%1 from the %2, mounted at %3 about the segment, %4 off its axis")
        .arg(*a, from, deg(g[QLatin1String(angle)]).value_or(QStringLiteral("-")),
             cm(g[QLatin1String(radius)]).value_or(QStringLiteral("-")));
  };
  if (const auto s = strap(Text::tr("shoulder"), "lu3", "thu4", "lu5"))
    out << Text::tr("Upper-arm sensor: %1.").arg(*s);
  if (const auto s = strap(Text::tr("elbow"), "lf6", "thf7", "lf8"))
    out << Text::tr("Forearm sensor: %1.").arg(*s);
  const QString side = meta["side"].toString();
  if (!side.isEmpty()) out << Text::tr("Arm: %1.").arg(word(side));
  if (meta["camera"].isObject()) {
    const QJsonArray t = meta["camera"].toObject()["t"].toArray();
    double d = 0;
    for (const QJsonValue& v : t) d += v.toDouble() * v.toDouble();
    out << (t.size() == 3 && std::isfinite(d)
                ? Text::tr("Camera: calibrated, %1 m from the shoulder.")
                      .arg(reportLocale().toString(std::sqrt(d), 'f', 2))
                : Text::tr("Camera: calibrated."));
  }
  return out;
}

}  // namespace armtrack::reports
