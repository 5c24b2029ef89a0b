#include "core/reports/ReportText.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimeZone>
#include <cmath>

namespace armtrack::reports {
namespace {

QString scalar(const QJsonValue& v) {
  if (v.isDouble()) return QString::number(v.toDouble(), 'g', 5);
  if (v.isBool()) return v.toBool() ? QStringLiteral("yes") : QStringLiteral("no");
  if (v.isString()) return v.toString();
  if (v.isNull()) return QStringLiteral("-");
  return QString();
}

bool allScalars(const QJsonArray& a) {
  for (const QJsonValue& v : a)
    if (v.isArray() || v.isObject()) return false;
  return true;
}

void flatten(const QJsonValue& v, const QString& path, QStringList& out) {
  if (v.isObject()) {
    const QJsonObject o = v.toObject();
    for (auto it = o.begin(); it != o.end(); ++it)
      flatten(it.value(), path.isEmpty() ? it.key() : path + QLatin1Char('.') + it.key(), out);
  } else if (v.isArray()) {
    const QJsonArray a = v.toArray();
    if (allScalars(a)) {
      QStringList items;
      for (const QJsonValue& x : a) items << scalar(x);
      out << path + QStringLiteral(": [") + items.join(QStringLiteral(", ")) + QLatin1Char(']');
    } else {
      for (int i = 0; i < a.size(); ++i) flatten(a[i], path + QStringLiteral("[%1]").arg(i), out);
    }
  } else {
    out << path + QStringLiteral(": ") + scalar(v);
  }
}

}  // namespace

QString formatDeg(std::optional<double> deg) {
  if (!deg || !std::isfinite(*deg)) return QStringLiteral("-");
  const QString text = QString::number(*deg, 'f', 1);
  return text == QStringLiteral("-0.0") ? QStringLiteral("0.0") : text;
}

QDateTime parseIso(const QString& iso) {
  QDateTime t = QDateTime::fromString(iso, Qt::ISODateWithMs);
  if (!t.isValid()) t = QDateTime::fromString(iso, Qt::ISODate);
  if (!t.isValid()) {
    const QDate d = QDate::fromString(iso.left(10), Qt::ISODate);
    if (d.isValid()) t = QDateTime(d, QTime(0, 0), Qt::UTC);
  }
  if (t.isValid() && t.timeSpec() == Qt::LocalTime) t.setTimeSpec(Qt::UTC);
  return t.isValid() ? t.toUTC() : QDateTime();
}

QString formatDate(const QString& iso) {
  const QDateTime t = parseIso(iso);
  return t.isValid() ? t.date().toString(Qt::ISODate) : iso;
}

QString formatDateTime(const QString& iso) {
  const QDateTime t = parseIso(iso);
  return t.isValid() ? t.toString(QStringLiteral("yyyy-MM-dd HH:mm")) + QStringLiteral(" UTC")
                     : iso;
}

QString orDash(const QString& s) {
  return s.trimmed().isEmpty() ? QStringLiteral("-") : s;
}

QString pageFooter(const QString& patientName, const QString& kind, const QDateTime& generatedAt) {
  const QDateTime at = generatedAt.isValid() ? generatedAt : QDateTime::currentDateTimeUtc();
  return QStringLiteral("%1 - %2 - generated %3")
      .arg(orDash(patientName), kind,
           at.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm 'UTC'")));
}

QString formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return QStringLiteral("-");
  if (seconds < 60) return QString::number(seconds, 'f', 1) + QStringLiteral(" s");
  const long long s = std::llround(seconds);
  if (s < 3600)
    return QStringLiteral("%1 min %2 s").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
  return QStringLiteral("%1 h %2 min").arg(s / 3600).arg((s % 3600) / 60, 2, 10, QLatin1Char('0'));
}

QStringList summariseJson(const QString& json, int maxLines) {
  const QString trimmed = json.trimmed();
  if (trimmed.isEmpty() || trimmed == QStringLiteral("{}") || trimmed == QStringLiteral("null"))
    return {};
  QJsonParseError error;
  const QJsonDocument doc = QJsonDocument::fromJson(trimmed.toUtf8(), &error);
  if (doc.isNull())
    return {QStringLiteral("(not valid JSON: %1 at offset %2)")
                .arg(error.errorString())
                .arg(error.offset)};
  QStringList out;
  flatten(doc.isObject() ? QJsonValue(doc.object()) : QJsonValue(doc.array()), QString(), out);
  if (out.size() > maxLines) {
    const qsizetype more = out.size() - maxLines;
    out = out.mid(0, maxLines);
    out << QStringLiteral("... %1 more").arg(more);
  }
  return out;
}

QString jsonString(const QString& json, const QString& key) {
  const QJsonDocument doc = QJsonDocument::fromJson(json.toUtf8());
  return doc.isObject() ? doc.object().value(key).toString() : QString();
}

}  // namespace armtrack::reports
