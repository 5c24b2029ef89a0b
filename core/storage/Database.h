// One open connection to the clinical records: opening checks, schema version, migrations,
// backup, and small query helpers that turn engine errors into StorageError.
#pragma once

#include <QSqlDatabase>
#include <QSqlQuery>
#include <QString>
#include <QVariant>
#include <functional>
#include <memory>
#include <vector>

#include "core/storage/DatabaseUrl.h"
#include "core/storage/Schema.h"
#include "core/storage/StorageError.h"

namespace armtrack::storage {

/// A connection, opened with every check of docs/storage.md ("Opening a database"). Not
/// copyable; use from the thread that opened it (a Qt Sql rule).
class Database {
 public:
  struct Options {
    bool create = false;   ///< create the file and the schema when there is none
    bool migrate = false;  ///< bring an older schema up to date (otherwise refused)
  };

  /// Opens url. Throws StorageError: NotFound (no file and not create; no such PostgreSQL
  /// database), Corrupt (not SQLite, or integrity_check fails: the file is left untouched; a
  /// database with someone else's tables), NewerSchema, OlderSchema (unless migrate),
  /// Authentication (PostgreSQL refused the role or password), Unsupported (the Qt driver is
  /// missing), Io (e.g. the server cannot be reached: the message names host and port).
  /// PostgreSQL: the password comes from ARMTRACK_DB_PASSWORD, else libpq reads ~/.pgpass.
  Database(const DatabaseUrl& url, Options options);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  const DatabaseUrl& url() const { return m_url; }
  const SqlDialect& dialect() const { return m_dialect; }
  int schemaVersion() const { return m_version; }
  /// The migration steps applied while opening (0 when the schema was current).
  int migrationsApplied() const { return m_applied; }

  bool isPostgres() const { return m_url.engine == DatabaseUrl::Engine::Postgres; }
  /// PostgreSQL: the connection's libpq handle (a PGconn*) for what Qt Sql cannot do (binary
  /// results, see readChunks); nullptr on SQLite or when the driver does not give it. Use it
  /// only between statements of this object, on its thread.
  void* postgresConnection() const;

  /// SQLite: whether this connection only reads, because the file or its folder cannot be
  /// written (docs/storage.md, "Opening a read-only database"); readOnlyReason() says which.
  /// Always false on PostgreSQL.
  bool isReadOnly() const { return !m_readOnlyReason.isEmpty(); }
  /// Why the database is read-only (names the file or folder and the system's reason); empty
  /// when it is not.
  const QString& readOnlyReason() const { return m_readOnlyReason; }
  /// Throws StorageError(Io) saying that the database is read-only and why, when it is;
  /// consequence says what that stops (e.g. "the export is written to the audit log, which
  /// cannot be").
  void requireWritable(const QString& consequence) const;
  /// Throws StorageError(Usage) when writing `what` (e.g. "the export") to path would write over
  /// this database's file or its -wal, -shm or -journal file (sqliteFileAt: by identity, links
  /// and ".." resolved). Never on PostgreSQL, whose files are the server's.
  void refuseOwnFile(const QString& path, const QString& what) const;
  /// refuseOwnFile for the SQLite database at dbPath, before it is opened (the CLI's early
  /// check of its outputs).
  static void refuseSqliteFile(const QString& dbPath, const QString& path, const QString& what);

  /// Runs PRAGMA integrity_check (SQLite; on PostgreSQL every table is read) and returns "ok"
  /// or the problems found.
  QString integrityCheck();
  /// A consistent copy of the whole database into a new file (SQLite: VACUUM INTO), while others
  /// may keep writing. The file is created with mode 0600 (whatever the umask) before SQLite
  /// writes into it. Throws StorageError(Exists) when outPath exists, Usage when it is one of
  /// this database's own files (refuseOwnFile), Io when the database is read-only (a backup is
  /// audited), Unsupported on PostgreSQL (the message gives the pg_dump command).
  void backup(const QString& outPath);

  /// Prepares and runs sql with positional (?) bindings. Throws StorageError(Io) naming the
  /// database and the engine's message (never the bound values: they may be patient data).
  QSqlQuery exec(const QString& sql, const QVariantList& binds = {});
  /// exec for an INSERT into a table with an {id} key; returns the new id (PostgreSQL: through
  /// RETURNING id).
  qint64 insert(const QString& sql, const QVariantList& binds);
  /// Runs body in a transaction: committed when body returns, rolled back when it throws.
  /// Not nested: body must not call transaction() again (inTransaction() tells).
  void transaction(const std::function<void()>& body);
  /// Whether a transaction() body is running on this connection.
  bool inTransaction() const { return m_inTransaction; }
  /// Runs work once the running transaction() has ended, committed or rolled back, outside it
  /// (at once when none is running): what must be written whatever becomes of the transaction,
  /// such as the audit entry of a denied access (AfterTransaction.cpp). An exception from work
  /// is dropped: it ran while another may be propagating.
  void afterTransaction(std::function<void()> work);

 private:
  QString inlineValues(const QString& sql, const QVariantList& binds);
  void openSqlite(bool create);
  void openPostgres();
  [[noreturn]] void explainConnectFailure(const QString& error);
  void checkFileBeforeOpening(bool create);
  void useWriteAheadLog();  // SQLite, once the file is known to be ArmTrack's
  QString readOnlyMessage(const QString& consequence = {}) const;
  int readVersion();
  void applyStep(const MigrationStep& step);
  [[noreturn]] void fail(StorageError::Kind kind, const QString& what, const QString& detail);
  /// Held by each transaction() call: when it ends, the afterTransaction() work runs.
  struct TransactionEnd {
    Database& db;
    ~TransactionEnd() { db.runAfterTransaction(); }
  };
  void runAfterTransaction() noexcept;

  DatabaseUrl m_url;
  SqlDialect m_dialect;
  QString m_connection;
  QSqlDatabase m_db;
  int m_version = 0;
  int m_applied = 0;
  bool m_inTransaction = false;
  std::vector<std::function<void()>> m_afterTransaction;
  /// SQLite: why the file cannot be written (then the connection is read-only); else empty.
  QString m_readOnlyReason;
  /// SQLite: counts this connection among the process's connections to its file while it is
  /// open (Database.cpp says why).
  std::shared_ptr<void> m_fileHold;
};

/// Now as ISO 8601 UTC text with milliseconds, the form every time column holds.
QString utcNow();

}  // namespace armtrack::storage
