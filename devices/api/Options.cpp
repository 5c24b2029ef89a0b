#include "devices/api/Options.h"

#include <cmath>

namespace armtrack::devices {

double Options::number(const QString& key, double fallback, double min, double max) {
  m_known << key;
  if (!m_values.contains(key)) return fallback;
  bool ok = false;
  const double v = m_values.value(key).toString().trimmed().toDouble(&ok);
  if (!ok || !std::isfinite(v) || v < min || v > max) {
    m_problems << QStringLiteral("option '%1' must be a number from %2 to %3, not '%4'")
                      .arg(key)
                      .arg(min)
                      .arg(max)
                      .arg(m_values.value(key).toString());
    return fallback;
  }
  return v;
}

int Options::integer(const QString& key, int fallback, int min, int max) {
  m_known << key;
  if (!m_values.contains(key)) return fallback;
  bool ok = false;
  const int v = m_values.value(key).toString().trimmed().toInt(&ok);
  if (!ok || v < min || v > max) {
    m_problems << QStringLiteral("option '%1' must be a whole number from %2 to %3, not '%4'")
                      .arg(key)
                      .arg(min)
                      .arg(max)
                      .arg(m_values.value(key).toString());
    return fallback;
  }
  return v;
}

bool Options::flag(const QString& key, bool fallback) {
  m_known << key;
  if (!m_values.contains(key)) return fallback;
  const QString v = m_values.value(key).toString().trimmed().toLower();
  if (v == u"1" || v == u"true" || v == u"yes" || v == u"on") return true;
  if (v == u"0" || v == u"false" || v == u"no" || v == u"off") return false;
  m_problems << QStringLiteral("option '%1' must be on or off, not '%2'").arg(key, v);
  return fallback;
}

QString Options::text(const QString& key, const QString& fallback) {
  m_known << key;
  return m_values.contains(key) ? m_values.value(key).toString() : fallback;
}

StreamRole Options::imuRole(const QString& key) {
  const QString role = text(key).trimmed().toLower();
  if (role == u"upper") return StreamRole::UpperArmImu;
  if (role == u"forearm") return StreamRole::ForearmImu;
  // The third sensor sits flat on the sternum and measures the trunk (docs/trunk.md).
  if (role == u"trunk" || role == u"sternum") return StreamRole::TrunkImu;
  if (role.isEmpty())
    m_problems << QStringLiteral(
                      "option '%1' is required: %1=upper, %1=forearm or %1=trunk (where the "
                      "sensor is strapped: the upper arm, the forearm, or the sternum for the "
                      "trunk)")
                      .arg(key);
  else
    m_problems << QStringLiteral(
                      "option '%1' must be upper, forearm or trunk (the sternum sensor), not "
                      "'%2'")
                      .arg(key, role);
  return StreamRole::UpperArmImu;
}

const char* imuPlaceName(StreamRole role) {
  switch (role) {
    case StreamRole::ForearmImu:
      return "forearm";
    case StreamRole::TrunkImu:
      return "trunk";
    default:
      return "upper-arm";
  }
}

QString Options::error() const {
  QStringList problems = m_problems;
  for (auto it = m_values.cbegin(); it != m_values.cend(); ++it)
    if (!m_known.contains(it.key()))
      problems << QStringLiteral("unknown option '%1' (known: %2)")
                      .arg(it.key(), m_known.join(QStringLiteral(", ")));
  return problems.join(QStringLiteral("; "));
}

QVariantMap Options::parse(const QString& text) {
  QVariantMap map;
  for (const QString& part : text.split(u',', Qt::SkipEmptyParts)) {
    const qsizetype eq = part.indexOf(u'=');
    const QString key = (eq < 0 ? part : part.left(eq)).trimmed();
    if (key.isEmpty()) continue;
    map.insert(key, eq < 0 ? QStringLiteral("1") : part.mid(eq + 1).trimmed());
  }
  return map;
}

}  // namespace armtrack::devices
