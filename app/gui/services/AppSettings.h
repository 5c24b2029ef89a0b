// The application's settings (units, data folder, plugin folders, default filter and method,
// language), kept in QSettings under the organisation and application name "ArmTrack", the same
// names the command-line tool uses for its data folder.
#pragma once

#include <QSettings>
#include <QString>
#include <QStringList>

#include "core/storage/DatabaseUrl.h"

namespace armtrack::gui {

/// Sets the organisation and application names (before any QSettings or QStandardPaths use).
void setApplicationIdentity();

struct AppSettings {
  enum class AngleUnit { Degrees, Radians };

  /// Where the records and the files the application writes (reports, exports) live. Empty:
  /// QStandardPaths::AppDataLocation, the folder `armtrack-cli` uses by default.
  QString dataFolder;
  /// The records' location as `--db` takes it; empty: armtrack.db in the data folder.
  QString databaseUrl;
  QStringList pluginFolders;  ///< searched before the default plugin folders
  AngleUnit units = AngleUnit::Degrees;
  QString filter = QStringLiteral("ekf");  ///< "ekf" or "ukf"
  QString method = QStringLiteral("A");    ///< "A", "B" or "C" (docs/estimator.md)
  QString language;                        ///< e.g. "de"; empty: the system's
  /// The clinic's armtrack-server as a patient types it on a home install (shown beside an
  /// enrolment code); empty: not told.
  QString syncServerAddress;

  static AppSettings load(QSettings& settings);
  void save(QSettings& settings) const;

  /// The data folder in effect (dataFolder or the default), absolute.
  QString effectiveDataFolder() const;
  /// The database in effect: databaseUrl, else armtrack.db in the data folder. Throws
  /// StorageError(Usage) for a malformed URL.
  storage::DatabaseUrl effectiveDatabase() const;
  /// The folder reports and exports are offered in: <data folder>/exports.
  QString exportFolder() const;
};

}  // namespace armtrack::gui
