#include "app/gui/services/AppSettings.h"

#include <QCoreApplication>
#include <QDir>
#include <QStandardPaths>

namespace armtrack::gui {

namespace {
constexpr auto kDataFolder = "data/folder";
constexpr auto kDatabase = "data/database";
constexpr auto kPlugins = "devices/pluginFolders";
constexpr auto kUnits = "display/units";
constexpr auto kFilter = "analysis/filter";
constexpr auto kMethod = "analysis/method";
constexpr auto kLanguage = "display/language";
constexpr auto kSyncServer = "sync/serverAddress";
}  // namespace

void setApplicationIdentity() {
  QCoreApplication::setOrganizationName(QStringLiteral("ArmTrack"));
  QCoreApplication::setApplicationName(QStringLiteral("ArmTrack"));
}

AppSettings AppSettings::load(QSettings& s) {
  AppSettings a;
  a.dataFolder = s.value(kDataFolder).toString();
  a.databaseUrl = s.value(kDatabase).toString();
  a.pluginFolders = s.value(kPlugins).toStringList();
  a.units =
      s.value(kUnits).toString() == QLatin1String("rad") ? AngleUnit::Radians : AngleUnit::Degrees;
  const QString filter = s.value(kFilter, a.filter).toString().toLower();
  if (filter == QLatin1String("ekf") || filter == QLatin1String("ukf")) a.filter = filter;
  const QString method = s.value(kMethod, a.method).toString().toUpper();
  if (method == QLatin1String("A") || method == QLatin1String("B") || method == QLatin1String("C"))
    a.method = method;
  a.language = s.value(kLanguage).toString();
  a.syncServerAddress = s.value(kSyncServer).toString().trimmed();
  return a;
}

void AppSettings::save(QSettings& s) const {
  s.setValue(kDataFolder, dataFolder);
  s.setValue(kDatabase, databaseUrl);
  s.setValue(kPlugins, pluginFolders);
  s.setValue(kUnits, units == AngleUnit::Radians ? QStringLiteral("rad") : QStringLiteral("deg"));
  s.setValue(kFilter, filter);
  s.setValue(kMethod, method);
  s.setValue(kLanguage, language);
  s.setValue(kSyncServer, syncServerAddress);
  s.sync();
}

QString AppSettings::effectiveDataFolder() const {
  if (!dataFolder.isEmpty()) return QDir(dataFolder).absolutePath();
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
}

storage::DatabaseUrl AppSettings::effectiveDatabase() const {
  if (!databaseUrl.isEmpty()) return storage::DatabaseUrl::parse(databaseUrl);
  storage::DatabaseUrl url;
  url.path = QDir(effectiveDataFolder()).filePath(QStringLiteral("armtrack.db"));
  return url;
}

QString AppSettings::exportFolder() const {
  return QDir(effectiveDataFolder()).filePath(QStringLiteral("exports"));
}

}  // namespace armtrack::gui
