// Which database to open: `--db URL` of the CLI (docs/storage.md).
#pragma once

#include <QString>

namespace armtrack::storage {

/// A parsed database location. Engine::Sqlite with a file path, or Engine::Postgres with its
/// connection parts (parsed so the CLI can say clearly that the engine is not wired in yet).
struct DatabaseUrl {
  enum class Engine { Sqlite, Postgres };
  Engine engine = Engine::Sqlite;
  QString path;      ///< SQLite: the database file
  QString user;      ///< PostgreSQL: role name ("" = the login name)
  QString host;      ///< PostgreSQL: host name or socket folder
  int port = 5432;   ///< PostgreSQL: TCP port
  QString database;  ///< PostgreSQL: database name

  /// Accepts a plain path, `sqlite:PATH`, `sqlite://PATH`, or
  /// `postgresql://[user@]host[:port]/dbname` (also `postgres://`). Throws StorageError(Usage)
  /// for an empty or malformed URL.
  static DatabaseUrl parse(const QString& text);
  /// `armtrack.db` in QStandardPaths::AppDataLocation (the folder is created when missing).
  static DatabaseUrl defaultLocation();
  /// For messages: the path, or postgresql://user@host:port/dbname (never a password).
  QString display() const;
};

}  // namespace armtrack::storage
