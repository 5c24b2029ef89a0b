#include "core/storage/Database.h"

#include <sys/stat.h>
#include <unistd.h>

#include <QAtomicInt>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QSqlDriver>
#include <QSqlError>
#include <QSqlField>
#include <QSqlRecord>
#include <cmath>
#include <map>
#include <mutex>

#include "core/storage/DatabaseFiles.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

// SQLite's locks are POSIX advisory locks: they belong to the process, and closing *any*
// descriptor of the file drops all of them (sqlite.org/howtocorrupt.html, 2.2). Reading the
// header through a descriptor of our own while another connection of this process has the file
// open would drop that connection's locks; another process could then take the database for
// unused, checkpoint it and delete the write-ahead log this process is still appending to (its
// commits would be invisible to others, and lost if it were killed). So only the first
// connection of a process to a file reads it before opening; later ones (a recorder's connection
// beside the command's own) rely on that check. Keyed by device and inode.
using FileId = std::pair<std::uint64_t, std::uint64_t>;
std::mutex g_openFilesMutex;
std::map<FileId, int> g_openFiles;

std::optional<FileId> fileIdOf(const QString& path) {
  struct stat st {};
  if (::stat(QFile::encodeName(path).constData(), &st) != 0) return std::nullopt;
  return FileId{static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)};
}

bool openInThisProcess(const QString& path) {
  const std::optional<FileId> id = fileIdOf(path);
  const std::lock_guard lock(g_openFilesMutex);
  return id && g_openFiles.count(*id) > 0;
}

QString nextConnectionName() {
  static QAtomicInt counter;
  return QStringLiteral("armtrack-storage-%1").arg(counter.fetchAndAddRelaxed(1));
}

// Runs PRAGMA integrity_check on an open connection; "ok" or the problems, one a line.
QString runIntegrityCheck(QSqlDatabase& db) {
  QSqlQuery q(db);
  if (!q.exec("PRAGMA integrity_check")) return q.lastError().text();
  QStringList problems;
  while (q.next()) problems << q.value(0).toString();
  return problems.join('\n');
}

}  // namespace

QString utcNow() {
  return QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
}

Database::Database(const DatabaseUrl& url, Options options) : m_url(url) {
  m_dialect.engine = url.engine;
  if (isPostgres())
    openPostgres();
  else
    openSqlite(options.create);

  m_version = readVersion();
  const int latest = latestSchemaVersion();
  if (m_version > latest)
    throw StorageError(
        Kind::NewerSchema,
        ("database '" + url.display() + "' has schema version " + QString::number(m_version) +
         ", newer than this ArmTrack knows (" + QString::number(latest) +
         "); update ArmTrack, or open a backup made by this version")
            .toStdString());
  if (m_version < latest && m_version > 0 && !options.migrate)
    throw StorageError(
        Kind::OlderSchema,
        ("database '" + url.display() + "' has schema version " + QString::number(m_version) +
         "; this ArmTrack needs " + QString::number(latest) +
         ": back it up (db backup) and run 'armtrack-cli db migrate'")
            .toStdString());
  if (m_version == 0 && !options.create)
    fail(Kind::Corrupt, "is not an ArmTrack database",
         "it has no schema_version table; create one with 'armtrack-cli db init'");
  // Only now, when the file is known to be ArmTrack's (or a new one): switching the journal
  // mode writes to the file, which someone else's database must never see.
  useWriteAheadLog();
  for (const MigrationStep& step : migrationSteps())
    if (step.toVersion > m_version) applyStep(step);
}

void Database::openSqlite(bool create) {
  // A file this process cannot write (or whose folder it cannot write, where SQLite would create
  // the -wal and -shm) is opened read-only, and said so on every write; it is not damaged.
  m_readOnlyReason = sqliteReadOnlyReason(m_url.path);
  if (!openInThisProcess(m_url.path)) checkFileBeforeOpening(create);
  m_connection = nextConnectionName();
  m_db = QSqlDatabase::addDatabase("QSQLITE", m_connection);
  if (!m_db.isValid())
    fail(Kind::Io, "the Qt SQLite driver is not installed", "install libqt6sql6-sqlite");
  if (!isReadOnly()) {
    m_db.setDatabaseName(m_url.path);
    m_db.setConnectOptions("QSQLITE_BUSY_TIMEOUT=5000");
  } else if (QFileInfo::exists(m_url.path + "-wal")) {
    // Another connection has it open (or died with it open): SQLite reads the write-ahead log
    // through the -shm that is there, without creating anything (wal.html, "Read-Only
    // Databases").
    m_db.setDatabaseName(m_url.path);
    m_db.setConnectOptions("QSQLITE_OPEN_READONLY;QSQLITE_BUSY_TIMEOUT=5000");
  } else {
    // No write-ahead log: everything is in the file, which SQLite can then read without the
    // -shm it could not create (immutable: no locks, nothing created beside it).
    m_db.setDatabaseName(immutableUri(m_url.path));
    m_db.setConnectOptions("QSQLITE_OPEN_URI;QSQLITE_OPEN_READONLY");
  }
  if (!m_db.open()) fail(Kind::Io, "cannot open", m_db.lastError().text());
  if (const std::optional<FileId> id = fileIdOf(m_url.path)) {
    {
      const std::lock_guard lock(g_openFilesMutex);
      ++g_openFiles[*id];
    }
    // Released by the destructor, or when a later check of this constructor throws.
    m_fileHold = std::shared_ptr<void>(nullptr, [id = *id](void*) {
      const std::lock_guard lock(g_openFilesMutex);
      const auto it = g_openFiles.find(id);
      if (it != g_openFiles.end() && --it->second == 0) g_openFiles.erase(it);
    });
  }
  exec("PRAGMA foreign_keys = ON");
}

void Database::useWriteAheadLog() {
  if (isPostgres() || isReadOnly()) return;  // a read-only file keeps the mode it was written in
  // WAL: readers never block the recorder; NORMAL: a killed process loses nothing committed
  // (only a power cut may lose the last transactions), at one fsync per checkpoint.
  {
    QSqlQuery wal = exec("PRAGMA journal_mode = WAL");
    if (!wal.next() || wal.value(0).toString().toLower() != "wal")
      fail(Kind::Io, "cannot switch to write-ahead logging", "is the folder writable?");
  }
  exec("PRAGMA synchronous = NORMAL");
}

void Database::openPostgres() {
  m_connection = nextConnectionName();
  m_db = QSqlDatabase::addDatabase("QPSQL", m_connection);
  if (!m_db.isValid())
    fail(Kind::Unsupported, "needs the Qt PostgreSQL driver, which is not installed",
         "install libqt6sql6-psql");
  // An empty host makes libpq use its default socket folder; a host starting with '/' is a
  // socket folder.
  if (!m_url.host.isEmpty()) m_db.setHostName(m_url.host);
  m_db.setPort(m_url.port);
  m_db.setDatabaseName(m_url.database);
  if (!m_url.user.isEmpty()) m_db.setUserName(m_url.user);
  // With no password libpq looks in ~/.pgpass (or PGPASSFILE) itself.
  const QByteArray password = qgetenv("ARMTRACK_DB_PASSWORD");
  if (!password.isEmpty()) m_db.setPassword(QString::fromUtf8(password));
  m_db.setConnectOptions("connect_timeout=10;application_name=armtrack");
  if (!m_db.open()) explainConnectFailure(m_db.lastError().text());
  exec("SET client_min_messages = warning");
  // As SQLite's busy timeout: a statement waiting more than 5 s for another's lock gives up.
  exec("SET lock_timeout = '5s'");
}

void Database::explainConnectFailure(const QString& error) {
  const QString where =
      m_url.isSocket()
          ? "the socket in " +
                (m_url.host.isEmpty() ? QString("libpq's default folder") : m_url.host) +
                " (port " + QString::number(m_url.port) + ")"
          : "host " + m_url.host + " port " + QString::number(m_url.port);
  const QString e = error.simplified();
  if (e.contains("password authentication failed") || e.contains("no password supplied") ||
      e.contains("authentication failed"))
    throw StorageError(
        Kind::Authentication,
        ("PostgreSQL refused the password of role '" +
         (m_url.user.isEmpty() ? QString("(login name)") : m_url.user) + "' at " + where +
         ": set ARMTRACK_DB_PASSWORD, or a line 'host:port:database:user:password' in "
         "~/.pgpass (mode 0600) [" +
         e.left(300) + "]")
            .toStdString());
  if (e.contains("does not exist") && e.contains("database"))
    throw StorageError(Kind::NotFound,
                       ("PostgreSQL at " + where + " has no database '" + m_url.database +
                        "': an administrator creates it (createdb -O " +
                        (m_url.user.isEmpty() ? QString("ROLE") : m_url.user) + " " +
                        m_url.database + "), then 'armtrack-cli db init'")
                           .toStdString());
  if (e.contains("role") && e.contains("does not exist"))
    throw StorageError(Kind::Authentication,
                       ("PostgreSQL at " + where + " has no role '" + m_url.user +
                        "': an administrator creates it (createuser --pwprompt " + m_url.user +
                        ") [" + e.left(300) + "]")
                           .toStdString());
  if (e.contains("pg_hba.conf"))
    throw StorageError(Kind::Authentication, ("PostgreSQL at " + where +
                                              " does not let this machine or role in: its "
                                              "administrator adds a line to pg_hba.conf [" +
                                              e.left(300) + "]")
                                                 .toStdString());
  throw StorageError(
      Kind::Io,
      ("cannot reach the PostgreSQL server at " + where + ": is it running (pg_isready" +
       (m_url.host.isEmpty() ? QString() : " -h " + m_url.host) + " -p " +
       QString::number(m_url.port) +
       "), are host and port right, does a firewall let the port through? [" + e.left(300) + "]")
          .toStdString());
}

Database::~Database() {
  m_db.close();
  m_db = QSqlDatabase();
  if (!m_connection.isEmpty()) QSqlDatabase::removeDatabase(m_connection);
  m_fileHold.reset();  // after the connection has closed
}

void Database::checkFileBeforeOpening(bool create) {
  const QString& path = m_url.path;
  const QFileInfo info(path);
  if (!info.exists()) {
    if (create) {
      // Made here, 0600 whatever the umask, so SQLite never makes it world-readable; its -wal and
      // -shm take the database's mode.
      const QString why = createPrivateFile(path);
      if (!why.isEmpty())
        fail(Kind::Io, "cannot be created",
             why +
                 "; choose a folder you may write to (docs/storage.md, \"Files and permissions\")");
      return;
    }
    throw StorageError(Kind::NotFound, ("no database at '" + path +
                                        "': create one with 'armtrack-cli db init --db " + path +
                                        " --admin NAME', or check --db")
                                           .toStdString());
  }
  if (info.isDir())
    throw StorageError(Kind::Usage,
                       ("'" + path + "' is a folder, not a database file").toStdString());
  if (info.size() == 0) {
    if (create) {
      QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);  // it becomes the database
      return;
    }
    fail(Kind::Corrupt, "is empty", "create the database with 'armtrack-cli db init'");
  }
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly))
    throw StorageError(Kind::Io, ("cannot read '" + path + "': " + f.errorString()).toStdString());
  const QByteArray header = f.read(16);
  f.close();
  if (header != QByteArray("SQLite format 3\0", 16))
    fail(Kind::Corrupt, "is not a SQLite database (it may be damaged or another kind of file)",
         "it was left untouched; restore a backup or pass another --db");
  // The check runs on a read-only connection so a damaged file is never written to. Such a
  // connection still creates the -wal and -shm of a database in WAL mode when they are missing
  // and the folder may be written; when the database is refused, what it created is removed
  // again (an empty -wal and its index) unless another connection uses them. A database this
  // process cannot write is read with the immutable flag when it has no write-ahead log, as it
  // is opened below, so nothing is created beside it.
  const bool immutable = isReadOnly() && !QFileInfo::exists(path + "-wal");
  const QStringList leftovers = immutable ? QStringList() : missingCompanions(path);
  const QString name = nextConnectionName();
  QString verdict;
  bool ran = false;  // the check ran (its verdict is about the file, not about reaching it)
  {
    QSqlDatabase ro = QSqlDatabase::addDatabase("QSQLITE", name);
    ro.setDatabaseName(immutable ? immutableUri(path) : path);
    ro.setConnectOptions(immutable ? "QSQLITE_OPEN_URI;QSQLITE_OPEN_READONLY"
                                   : "QSQLITE_OPEN_READONLY;QSQLITE_BUSY_TIMEOUT=5000");
    if (ro.open()) {
      QSqlQuery probe(ro);
      ran = probe.exec("SELECT count(*) FROM sqlite_master");
      probe.finish();
      verdict = ran ? runIntegrityCheck(ro) : probe.lastError().text();
    } else {
      verdict = ro.lastError().text();
    }
    ro.close();
  }
  QSqlDatabase::removeDatabase(name);
  if (!ran && isReadOnly())  // e.g. a -wal without its -shm in a folder it cannot write
    throw StorageError(Kind::Io,
                       ("database '" + m_url.display() + "' is read-only (" + m_readOnlyReason +
                        ") and cannot be read as it is: " + verdict.left(300) +
                        "; it was left untouched. Open it with write access, or copy "
                        "it (with its -wal) to a folder you may write to")
                           .toStdString());
  if (verdict != "ok") {
    removeCheckLeftovers(path, leftovers);
    fail(Kind::Corrupt, "failed its integrity check",
         verdict.left(400) + "\nit was left untouched; restore a backup (db backup)");
  }
}

int Database::readVersion() {
  if (isPostgres()) {
    QSqlQuery q = exec(
        "SELECT count(*) FROM information_schema.tables WHERE table_schema = current_schema() "
        "AND table_name = 'schema_version'");
    if (!q.next() || q.value(0).toInt() == 0) {
      QSqlQuery any = exec(
          "SELECT count(*) FROM information_schema.tables WHERE table_schema = "
          "current_schema()");
      if (any.next() && any.value(0).toInt() > 0)
        fail(Kind::Corrupt, "holds tables but is not ArmTrack's",
             "it has no schema_version table; name another database in --db");
      return 0;
    }
    QSqlQuery v = exec("SELECT max(version) FROM schema_version");
    return v.next() ? v.value(0).toInt() : 0;
  }
  QSqlQuery q = exec(
      "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = "
      "'schema_version'");
  if (!q.next() || q.value(0).toInt() == 0) {
    QSqlQuery any = exec("SELECT count(*) FROM sqlite_master");
    if (any.next() && any.value(0).toInt() > 0)
      fail(Kind::Corrupt, "is a SQLite database but not ArmTrack's",
           "it has tables but no schema_version; pass another --db");
    return 0;
  }
  QSqlQuery v = exec("SELECT max(version) FROM schema_version");
  return v.next() ? v.value(0).toInt() : 0;
}

void Database::applyStep(const MigrationStep& step) {
  bool applied = false;
  transaction([&] {
    if (isPostgres()) {
      // Two programs opening an old database at once: the second waits here, then finds the
      // step done (PostgreSQL's DDL is transactional). SQLite's write lock does the same.
      exec("SELECT pg_advisory_xact_lock(7261540)");
      if (readVersion() >= step.toVersion) return;
    }
    applied = true;
    for (const QString& s : step.statements) exec(m_dialect.expand(s));
    if (step.hook) step.hook(*this);
    for (const QString& s : m_dialect.afterStep(step.toVersion)) exec(s);
    exec("DELETE FROM schema_version");
    exec("INSERT INTO schema_version (version) VALUES (?)", {step.toVersion});
  });
  m_version = step.toVersion;
  if (applied) ++m_applied;
}

QString Database::integrityCheck() {
  if (!isPostgres()) return runIntegrityCheck(m_db);
  // The server checks its own pages (checksums, WAL); here: every table answers. A page-level
  // check of a server is pg_amcheck's job (docs/storage.md).
  for (const char* table :
       {"schema_version", "users", "patients", "protocols", "programmes", "sessions",
        "recording_chunks", "estimates", "estimate_chunks", "metrics", "audit_log",
        "enrolment_codes", "devices", "sync_uploads", "sync_upload_chunks"}) {
    QSqlQuery q(m_db);
    if (!q.exec(QString("SELECT count(*) FROM ") + table))
      return QString(table) + ": " + q.lastError().text();
  }
  return "ok";
}

void Database::backup(const QString& outPath) {
  if (isPostgres())
    throw StorageError(
        Kind::Unsupported,
        ("'db backup' copies SQLite files; back up PostgreSQL (" + m_url.display() +
         ") with pg_dump, which takes a consistent snapshot while others write: pg_dump -Fc " +
         (m_url.host.isEmpty() ? QString() : "-h " + m_url.host + " ") + "-p " +
         QString::number(m_url.port) + (m_url.user.isEmpty() ? QString() : " -U " + m_url.user) +
         " -f " + outPath + " " + m_url.database + " (docs/storage.md)")
            .toStdString());
  refuseOwnFile(outPath, "the backup");
  requireWritable("a backup must be written to the audit log, which cannot be");
  if (QFileInfo::exists(outPath) || QFileInfo(outPath).isSymLink())
    throw StorageError(Kind::Exists,
                       ("'" + outPath + "' exists; a backup never replaces a file").toStdString());
  // VACUUM INTO writes into a new or empty file: made here 0600 (O_EXCL, no link followed) so
  // the copy of every record is as private as the database.
  if (const QString why = createPrivateFile(outPath); !why.isEmpty())
    throw StorageError(Kind::Io, ("cannot create the backup '" + outPath + "': " + why +
                                  "; choose a folder you may write to")
                                     .toStdString());
  try {
    exec("VACUUM INTO ?", {outPath});
  } catch (...) {
    QFile::remove(outPath);  // the file made above, never anyone else's
    throw;
  }
}

void Database::refuseSqliteFile(const QString& dbPath, const QString& path, const QString& what) {
  const QString hit = sqliteFileAt(dbPath, path);
  if (hit.isEmpty()) return;
  const QString of = " ('" + hit + "') of the database '" + dbPath + "'";
  const QString which = hit.endsWith("-wal")       ? "the write-ahead log" + of
                        : hit.endsWith("-shm")     ? "the shared-memory index" + of
                        : hit.endsWith("-journal") ? "the rollback journal" + of
                                                   : "the database '" + dbPath + "' itself";
  throw StorageError(Kind::Usage, ("'" + path + "' is " + which + ": writing " + what +
                                   " there would destroy the records, so nothing was written; "
                                   "choose another file name")
                                      .toStdString());
}

void Database::refuseOwnFile(const QString& path, const QString& what) const {
  if (!isPostgres()) refuseSqliteFile(m_url.path, path, what);
}

QString Database::readOnlyMessage(const QString& consequence) const {
  const QString why = !m_readOnlyReason.isEmpty() ? m_readOnlyReason
                      : !sqliteReadOnlyReason(m_url.path).isEmpty()
                          ? sqliteReadOnlyReason(m_url.path)
                          : QString("SQLite opened it read-only");
  return "database '" + m_url.display() + "' is read-only: " + why +
         (consequence.isEmpty() ? QString() : ", and " + consequence) +
         "; nothing was changed. It is not damaged: reading works, and to change the records "
         "the account running ArmTrack needs write access to the file and its folder "
         "(docs/storage.md, \"Opening a read-only database\")";
}

void Database::requireWritable(const QString& consequence) const {
  if (!isReadOnly()) return;
  throw StorageError(Kind::Io, readOnlyMessage(consequence).toStdString());
}

void* Database::postgresConnection() const {
  if (!isPostgres() || !m_db.driver()) return nullptr;
  // QPSQL hands out its PGconn* (Qt's documented handle()); the type is named after the struct
  // behind libpq's typedef, pg_conn.
  const QVariant v = m_db.driver()->handle();
  if (!v.isValid() ||
      (qstrcmp(v.typeName(), "PGconn*") != 0 && qstrcmp(v.typeName(), "pg_conn*") != 0))
    return nullptr;
  return *static_cast<void* const*>(v.data());
}

QSqlQuery Database::exec(const QString& sql, const QVariantList& binds) {
  QSqlQuery q(m_db);
  q.setForwardOnly(true);
  bool ok = false;
  if (binds.isEmpty()) {
    // Unprepared: PostgreSQL cannot PREPARE every statement (SET, LOCK), and it saves a round
    // trip there.
    ok = q.exec(sql);
  } else if (isPostgres()) {
    // QPSQL would PREPARE, EXECUTE with the values formatted by its driver, and DEALLOCATE:
    // three round trips, and a DEALLOCATE that fails noisily in an aborted transaction. The
    // same driver formatting inlined gives one.
    ok = q.exec(inlineValues(sql, binds));
  } else {
    if (!q.prepare(sql)) fail(Kind::Io, "refused a statement", q.lastError().text());
    for (const QVariant& b : binds) {
      // An empty QString() would bind as NULL; text columns mean "" by it.
      if (b.typeId() == QMetaType::QString && b.toString().isNull())
        q.addBindValue(QString(""));
      else
        q.addBindValue(b);
    }
    ok = q.exec();
  }
  if (!ok) {
    QString text = q.lastError().text();
    if (text.contains("database is locked", Qt::CaseInsensitive))
      text +=
          " (another program has been writing to it for more than 5 s; try again, or close "
          "the other program)";
    if (text.contains("lock timeout", Qt::CaseInsensitive))
      text +=
          " (another workstation has held a lock for more than 5 s; try again, or see which "
          "program holds it: pg_stat_activity)";
    if (!isPostgres() && text.contains("readonly database", Qt::CaseInsensitive))
      throw StorageError(Kind::Io, readOnlyMessage().toStdString());
    if (text.contains("disk is full", Qt::CaseInsensitive) ||
        text.contains("disk I/O error", Qt::CaseInsensitive))
      text += " (free some space: what was committed before is intact)";
    const Kind kind = text.contains("UNIQUE constraint", Qt::CaseInsensitive) ||
                              text.contains("duplicate key value", Qt::CaseInsensitive)
                          ? Kind::Exists
                          : Kind::Io;
    fail(kind, "refused a statement", text);
  }
  return q;
}

QString Database::inlineValues(const QString& sql, const QVariantList& binds) {
  QString out;
  out.reserve(sql.size() + 64 * binds.size());
  qsizetype next = 0;
  bool inString = false;
  for (const QChar c : sql) {
    if (c == '\'') inString = !inString;
    if (c != '?' || inString) {
      out += c;
      continue;
    }
    if (next >= binds.size()) fail(Kind::Io, "refused a statement", "more ? than values");
    const QVariant& b = binds[next++];
    QSqlField field(QString(), b.metaType());
    // An empty QString() would bind as NULL; text columns mean "" by it (as for SQLite).
    field.setValue(b.typeId() == QMetaType::QString && b.toString().isNull() ? QVariant(QString(""))
                                                                             : b);
    // Qt prints -0.0 as "0": spell it so PostgreSQL keeps the sign (a double goes in exact).
    if (b.typeId() == QMetaType::Double && b.toDouble() == 0.0 && std::signbit(b.toDouble()))
      out += "'-0'";
    else
      out += m_db.driver()->formatValue(field);
  }
  if (next != binds.size()) fail(Kind::Io, "refused a statement", "fewer ? than values");
  return out;
}

qint64 Database::insert(const QString& sql, const QVariantList& binds) {
  if (isPostgres()) {  // QPSQL's lastInsertId is an OID, which tables no longer have
    QSqlQuery q = exec(sql + " RETURNING id", binds);
    if (!q.next()) fail(Kind::Io, "gave no id for a new row", sql.section(' ', 0, 2));
    return q.value(0).toLongLong();
  }
  QSqlQuery q = exec(sql, binds);
  const QVariant id = q.lastInsertId();
  if (!id.isValid()) fail(Kind::Io, "gave no id for a new row", sql.section(' ', 0, 2));
  return id.toLongLong();
}

void Database::transaction(const std::function<void()>& body) {
  const TransactionEnd end{*this};  // afterTransaction() work runs when this call ends
  if (isPostgres()) {
    if (!m_db.transaction()) fail(Kind::Io, "cannot start a transaction", m_db.lastError().text());
  } else {
    // SQLite: take the write lock at the start. A deferred transaction (Qt's BEGIN) that reads
    // and then writes fails at once with "database is locked", without waiting, when another
    // connection wrote in between (its snapshot is stale); two analyses storing their versions at
    // the same time did. BEGIN IMMEDIATE waits for the lock (the busy timeout) instead.
    if (isReadOnly()) throw StorageError(Kind::Io, readOnlyMessage().toStdString());
    exec("BEGIN IMMEDIATE");
  }
  m_inTransaction = true;
  const auto rollback = [&] {
    m_inTransaction = false;
    if (isPostgres())
      m_db.rollback();
    else
      QSqlQuery(m_db).exec("ROLLBACK");
  };
  try {
    body();
  } catch (...) {
    rollback();
    throw;
  }
  m_inTransaction = false;
  QSqlQuery commit(m_db);
  const bool committed = isPostgres() ? m_db.commit() : commit.exec("COMMIT");
  if (!committed) {
    const QString why = isPostgres() ? m_db.lastError().text() : commit.lastError().text();
    rollback();
    fail(Kind::Io, "cannot commit", why);
  }
}

void Database::fail(StorageError::Kind kind, const QString& what, const QString& detail) {
  throw StorageError(kind, ("database '" + m_url.display() + "' " + what +
                            (detail.isEmpty() ? QString() : ": " + detail))
                               .toStdString());
}

}  // namespace armtrack::storage
