#include "core/reports/ReportText.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimeZone>
#include <array>
#include <cmath>

#include "core/kinematics/ClinicalAngles.h"
#include "core/metrics/RangeOfMotion.h"
#include "core/storage/TextRules.h"

namespace armtrack::reports {
namespace {

// clinicalAngleInfo()'s English names, for lupdate.
constexpr std::array<const char*, kNumClinicalAngles> kAngleNames = {
    QT_TRANSLATE_NOOP("armtrack::reports", "Shoulder flexion"),
    QT_TRANSLATE_NOOP("armtrack::reports", "Shoulder abduction"),
    QT_TRANSLATE_NOOP("armtrack::reports", "Shoulder internal rotation"),
    QT_TRANSLATE_NOOP("armtrack::reports", "Elbow flexion"),
    QT_TRANSLATE_NOOP("armtrack::reports", "Forearm pronation"),
};

QString scalar(const QJsonValue& v) {
  if (v.isDouble()) return reportLocale().toString(v.toDouble(), 'g', 5);
  if (v.isBool()) return v.toBool() ? Text::tr("yes") : Text::tr("no");
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

QString angleName(int index) {
  if (index < 0 || index >= kNumClinicalAngles) return {};
  return Text::tr(kAngleNames[static_cast<std::size_t>(index)]);
}

std::optional<int> angleIndex(const QString& key) {
  for (int i = 0; i < kNumClinicalAngles; ++i) {
    const auto k = clinicalAngleInfo()[static_cast<std::size_t>(i)].key;
    if (key == QString::fromUtf8(k.data(), static_cast<qsizetype>(k.size()))) return i;
  }
  return std::nullopt;
}

QString word(const QString& stored) {
  static const std::pair<const char*, const char*> kWords[] = {
      {"left", QT_TRANSLATE_NOOP("armtrack::reports", "left")},
      {"right", QT_TRANSLATE_NOOP("armtrack::reports", "right")},
      {"both", QT_TRANSLATE_NOOP("armtrack::reports", "both")},
      {"none", QT_TRANSLATE_NOOP("armtrack::reports", "none")},
      {"either", QT_TRANSLATE_NOOP("armtrack::reports", "either")},
      {"f", QT_TRANSLATE_NOOP("armtrack::reports", "female")},
      {"m", QT_TRANSLATE_NOOP("armtrack::reports", "male")},
      {"x", QT_TRANSLATE_NOOP("armtrack::reports", "diverse")},
      {"complete", QT_TRANSLATE_NOOP("armtrack::reports", "complete")},
      {"interrupted", QT_TRANSLATE_NOOP("armtrack::reports", "interrupted")},
      {"recording", QT_TRANSLATE_NOOP("armtrack::reports", "recording")},
  };
  for (const auto& [key, text] : kWords)
    if (stored == QLatin1String(key)) return Text::tr(text);
  return orDash(stored);
}

QLocale reportLocale() {
  QLocale locale;
  if (locale.language() == QLocale::C) locale.setNumberOptions(QLocale::OmitGroupSeparator);
  return locale;
}

QString fullYearDateFormat(const QLocale& locale) {
  if (locale.language() == QLocale::C) return QStringLiteral("yyyy-MM-dd");
  QString format = locale.dateFormat(QLocale::ShortFormat);
  if (!format.contains(QLatin1String("yyyy")))
    format.replace(QLatin1String("yy"), QLatin1String("yyyy"));
  return format;
}

QString formatDeg(std::optional<double> deg) {
  if (!deg || !std::isfinite(*deg)) return QStringLiteral("-");
  const double shown = std::round(*deg * 10) == 0 ? 0.0 : *deg;  // never "-0.0"
  return reportLocale().toString(shown, 'f', 1);
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

QString formatDate(const QDate& date) {
  const QLocale locale = reportLocale();
  return locale.toString(date, fullYearDateFormat(locale));
}

QString formatDate(const QString& iso) {
  const QDateTime t = parseIso(iso);
  return t.isValid() ? formatDate(t.date()) : iso;
}

QString formatDateTime(const QString& iso) {
  const QDateTime t = parseIso(iso);
  return t.isValid() ? Text::tr("%1 %2 UTC", "a date and a time of day")
                           .arg(formatDate(t.date()), t.time().toString(QStringLiteral("HH:mm")))
                     : iso;
}

QString orDash(const QString& s) {
  return s.trimmed().isEmpty() ? QStringLiteral("-") : s;
}

QString nameText(const QString& s) {
  if (s.trimmed().isEmpty()) return QStringLiteral("-");
  QString out;
  out.reserve(s.size() + 2);
  out += QChar(0x2068);  // first strong isolate
  for (const QChar c : s)
    out += storage::isControlCharacter(c.unicode()) || storage::isLayoutControl(c.unicode())
               ? QChar(QChar::ReplacementCharacter)
               : c;
  out += QChar(0x2069);  // pop directional isolate
  return out;
}

QString pageFooter(const QString& patientName, const QString& kind, const QDateTime& generatedAt) {
  const QDateTime at = generatedAt.isValid() ? generatedAt : QDateTime::currentDateTimeUtc();
  return Text::tr("%1 - %2 - generated %3")
      .arg(orDash(patientName), kind, formatDateTime(at.toUTC().toString(Qt::ISODate)));
}

QString formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return QStringLiteral("-");
  if (seconds < 60) return Text::tr("%1 s").arg(reportLocale().toString(seconds, 'f', 1));
  const long long s = std::llround(seconds);
  if (s < 3600) return Text::tr("%1 min %2 s").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
  return Text::tr("%1 h %2 min").arg(s / 3600).arg((s % 3600) / 60, 2, 10, QLatin1Char('0'));
}

QStringList summariseJson(const QString& json, int maxLines) {
  const QString trimmed = json.trimmed();
  if (trimmed.isEmpty() || trimmed == QStringLiteral("{}") || trimmed == QStringLiteral("null"))
    return {};
  QJsonParseError error;
  const QJsonDocument doc = QJsonDocument::fromJson(trimmed.toUtf8(), &error);
  if (doc.isNull())
    return {
        Text::tr("(not valid JSON: %1 at offset %2)").arg(error.errorString()).arg(error.offset)};
  QStringList out;
  flatten(doc.isObject() ? QJsonValue(doc.object()) : QJsonValue(doc.array()), QString(), out);
  if (out.size() > maxLines) {
    const qsizetype more = out.size() - maxLines;
    out = out.mid(0, maxLines);
    out << Text::tr("... %n more", nullptr, static_cast<int>(more));
  }
  return out;
}

QString jsonString(const QString& json, const QString& key) {
  const QJsonDocument doc = QJsonDocument::fromJson(json.toUtf8());
  return doc.isObject() ? doc.object().value(key).toString() : QString();
}

}  // namespace armtrack::reports
