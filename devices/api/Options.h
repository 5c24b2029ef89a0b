// Typed reading of a plugin's string options ("rate=1000,port=/dev/rfcomm0"), with one error
// message that names every bad or unknown key.
#pragma once

#include <QString>
#include <QStringList>
#include <QVariantMap>

#include "devices/api/Device.h"

namespace armtrack::devices {

/// Reads options one key at a time; every key read is marked as known. After the reads,
/// error() is empty when all values parsed and no unknown key was given. Not thread-safe.
class Options {
 public:
  explicit Options(QVariantMap values) : m_values(std::move(values)) {}

  /// A number in [min, max]; the default when the key is absent.
  double number(const QString& key, double fallback, double min, double max);
  int integer(const QString& key, int fallback, int min, int max);
  /// "1/0", "true/false", "yes/no", "on/off".
  bool flag(const QString& key, bool fallback);
  QString text(const QString& key, const QString& fallback = {});
  /// Where an IMU is strapped: "upper" (UpperArmImu), "forearm" (ForearmImu), or "trunk" or
  /// "sternum" (TrunkImu, the third sensor on the sternum); required, any case. On a missing or
  /// bad value the problem is noted and UpperArmImu returned.
  StreamRole imuRole(const QString& key = QStringLiteral("role"));
  bool has(const QString& key) const { return m_values.contains(key); }

  /// Empty when everything was fine, else "option 'x': ...; unknown option 'y' (known: ...)".
  QString error() const;

  /// Parses "a=1,b=two" into a map. A key without '=' maps to "1". Empty keys are ignored.
  static QVariantMap parse(const QString& text);

 private:
  QVariantMap m_values;
  QStringList m_known;
  QStringList m_problems;
};

/// Where an IMU of this role is worn, as the start of a stream's name: "upper-arm", "forearm" or
/// "trunk" (e.g. "trunk Shimmer3").
const char* imuPlaceName(StreamRole role);

}  // namespace armtrack::devices
