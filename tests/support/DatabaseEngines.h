// The two engines of the clinical records, for tests that run on both: a fresh database of each
// (a SQLite file in a temporary folder, or a database on the test PostgreSQL server), and plain SQL
// on it outside the service (to look at what the service stored, or to damage it).
#pragma once

#include <gtest/gtest.h>

#include <QAtomicInt>
#include <QSqlDatabase>
#include <QSqlError>
#include <QStringList>
#include <QTemporaryDir>
#include <QVariantList>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/storage/DatabaseUrl.h"
#include "tests/support/PostgresServer.h"

namespace armtrack::test {

/// The engines a value-parameterised test runs on.
enum class Engine { Sqlite, Postgres };

inline void PrintTo(Engine e, std::ostream* os) {
  *os << (e == Engine::Sqlite ? "SQLite" : "PostgreSQL");
}

inline std::string engineName(const testing::TestParamInfo<Engine>& info) {
  return info.param == Engine::Sqlite ? "Sqlite" : "Postgres";
}

/// A new, empty database of engine, as a --db location: a file named stem in dir, or a new
/// database on the test server (PostgresServer::shared(); a server that cannot start throws, so
/// the test fails with the reason). Names carry the process id: the server may be shared by
/// test processes.
inline QString newDatabase(Engine engine, const QTemporaryDir& dir, const QString& stem) {
  if (engine == Engine::Sqlite) return dir.filePath(stem + ".db");
  return PostgresServer::shared().createDatabase(PostgresServer::uniqueName(stem));
}

namespace detail {
/// Runs statements on a SQLite file through a connection of its own; the rows of the last one
/// go to rows when given. Throws std::runtime_error naming the statement.
inline void sqliteRun(const QString& path, const QStringList& statements,
                      std::vector<QVariantList>* rows) {
  static QAtomicInt counter;
  const QString name = QString("raw-sqlite-%1").arg(counter.fetchAndAddRelaxed(1));
  QString error;
  {
    QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", name);
    db.setDatabaseName(path);
    if (!db.open()) {
      error = "cannot open " + path + ": " + db.lastError().text();
    } else {
      error = runSql(db, statements, rows);
      db.close();
    }
  }
  QSqlDatabase::removeDatabase(name);
  if (!error.isEmpty()) throw std::runtime_error(error.toStdString());
}
}  // namespace detail

/// Runs raw SQL on a database outside the service (to build old or damaged ones). On PostgreSQL
/// as the test role, so the service may alter what is created. Throws std::runtime_error.
inline void rawSql(const QString& location, const QStringList& statements) {
  const storage::DatabaseUrl url = storage::DatabaseUrl::parse(location);
  if (url.engine == storage::DatabaseUrl::Engine::Postgres) {
    PostgresServer::shared().superuserSql(
        url.database, QStringList{QString("SET ROLE ") + PostgresServer::kRole} + statements);
    return;
  }
  detail::sqliteRun(url.path, statements, nullptr);
}

/// The rows of one query on a database, read outside the service. Throws std::runtime_error.
inline std::vector<QVariantList> rawQuery(const QString& location, const QString& sql) {
  const storage::DatabaseUrl url = storage::DatabaseUrl::parse(location);
  if (url.engine == storage::DatabaseUrl::Engine::Postgres)
    return PostgresServer::shared().superuserQuery(url.database, sql);
  std::vector<QVariantList> rows;
  detail::sqliteRun(url.path, {sql}, &rows);
  return rows;
}

}  // namespace armtrack::test
