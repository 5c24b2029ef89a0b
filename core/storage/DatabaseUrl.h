// Which database to open: `--db URL` of the CLI (docs/storage.md).
#pragma once

#include <QString>

namespace armtrack::storage {

/// A parsed database location. Engine::Sqlite with a file path, or Engine::Postgres with its
/// connection parts (docs/storage.md, "PostgreSQL").
struct DatabaseUrl {
  enum class Engine { Sqlite, Postgres };
  Engine engine = Engine::Sqlite;
  QString path;      ///< SQLite: the database file
  QString user;      ///< PostgreSQL: role name ("" = the login name)
  QString host;      ///< PostgreSQL: host name, or a Unix-socket folder (starts with '/')
  int port = 5432;   ///< PostgreSQL: TCP port
  QString database;  ///< PostgreSQL: database name

  /// Accepts a plain path, `sqlite:PATH`, `sqlite://PATH`, or
  /// `postgresql://[user@]host[:port]/dbname` (also `postgres://`). The host may be a
  /// Unix-socket folder, percent-encoded (`postgresql://u@%2Frun%2Fpostgresql/db`) or as a
  /// query (`postgresql://u@/db?host=/run/postgresql&port=5433`), as libpq spells it; no host
  /// means libpq's default socket. Throws StorageError(Usage) for an empty or malformed URL, or a
  /// password in it.
  static DatabaseUrl parse(const QString& text);
  /// `armtrack.db` in QStandardPaths::AppDataLocation. The folder is created 0700 when missing,
  /// and tightened to 0700 when it exists and belongs to this user (privateAppDataFolder()).
  static DatabaseUrl defaultLocation();
  /// For messages: the path, or postgresql://user@host:port/dbname (never a password).
  QString display() const;
  /// PostgreSQL: whether host names a Unix-socket folder rather than a TCP host.
  bool isSocket() const { return host.isEmpty() || host.startsWith('/'); }
};

}  // namespace armtrack::storage
