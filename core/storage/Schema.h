// The one schema of the clinical records and its numbered migrations (docs/storage.md).
#pragma once

#include <QString>
#include <QStringList>
#include <functional>
#include <vector>

#include "core/storage/DatabaseUrl.h"

namespace armtrack::storage {

class Database;

/// Where SQLite and PostgreSQL spell things differently. Everything else in the DDL and in the
/// service's queries is SQL both accept.
struct SqlDialect {
  DatabaseUrl::Engine engine = DatabaseUrl::Engine::Sqlite;
  QString idColumn() const;  ///< an auto-numbered 64-bit primary key
  QString blobType() const;  ///< BLOB / BYTEA
  /// text with {id} and {blob} replaced.
  QString expand(QString text) const;
  /// Engine-only statements run right after migration step toVersion, in its transaction
  /// (PostgreSQL: chunk data stored without TOAST compression, as it is compressed already).
  QStringList afterStep(int toVersion) const;
};

/// One migration: the statements that take a database from version toVersion - 1 to toVersion,
/// applied in one transaction together with the new schema_version row.
struct MigrationStep {
  int toVersion;
  QString description;
  QStringList statements;  ///< with {id} and {blob} placeholders (SqlDialect::expand)
  /// Work SQL alone cannot do (hashes, Unicode case folding, engine-specific triggers), run after
  /// the statements in the same transaction; may be empty.
  std::function<void(Database&)> hook;
};

/// Every step, in order; step i takes the schema from version i to i + 1.
const std::vector<MigrationStep>& migrationSteps();
/// The schema version this build writes (the last step's toVersion).
int latestSchemaVersion();

}  // namespace armtrack::storage
