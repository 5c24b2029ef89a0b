// A throw-away PostgreSQL server for tests and benchmarks: initdb into a temporary folder, postgres
// listening on a Unix socket in that folder and on a free loopback port, stopped and removed on
// destruction. Runs the server binaries as the `postgres` account when the tests run as root
// (PostgreSQL refuses to run as root).
//
// Under CTest one server serves every test (a fixture: tests/CMakeLists.txt starts it with
// armtrack_test_pg_server before the first test that needs it and stops it after the last, and
// ARMTRACK_TEST_PG_STATE names the file that says where it listens); a test run by hand starts
// its own. A server whose owner died without stopping it (a crashed test, a killed CTest) is
// stopped and removed by the next one that starts.
#pragma once

#include <QString>
#include <QVariantList>
#include <memory>
#include <stdexcept>
#include <vector>

class QSqlDatabase;

namespace armtrack::test {

/// Runs statements on an open connection, stopping at the first that fails; the rows of the
/// results go to rows when given. Returns "" or the failing statement with the engine's error.
QString runSql(QSqlDatabase& db, const QStringList& statements, std::vector<QVariantList>* rows);

class PostgresServer {
 public:
  /// The role the tests connect as (trust on the socket; password kPassword over TCP).
  static constexpr const char* kRole = "armtrack_test";
  static constexpr const char* kPassword = "test-pass-8472";

  /// Starts the server. fsync off makes the tests quicker; benchmarks pass true. Throws
  /// std::runtime_error saying why when it cannot (no binaries, initdb or start failed: the
  /// server log's tail is in the message).
  explicit PostgresServer(bool durable = false);
  ~PostgresServer();
  PostgresServer(const PostgresServer&) = delete;
  PostgresServer& operator=(const PostgresServer&) = delete;

  /// The server of this test process: the CTest fixture's when ARMTRACK_TEST_PG_STATE names its
  /// state file (throwing with the reason when the fixture could not start it), else one started
  /// on first use (the same throw as the constructor).
  static PostgresServer& shared();

  /// The fixture: starts a server that outlives this process and writes where it listens to
  /// stateFile (after stopping the one an earlier state file describes). When it cannot start,
  /// the reason goes to the state file and this returns false, so that only the tests that use
  /// PostgreSQL fail, with that reason.
  static bool startDetached(const QString& stateFile);
  /// Stops and removes the server stateFile describes, and the state file.
  static void stopDetached(const QString& stateFile);

  /// A database name no other test process uses on a shared server: stem, this process's id and
  /// a counter.
  static QString uniqueName(const QString& stem);

  /// Creates a fresh, empty database owned by kRole and returns its --db URL over the socket
  /// (`postgresql://armtrack_test@/NAME?host=DIR&port=PORT`).
  QString createDatabase(const QString& name);
  /// The same database over TCP on 127.0.0.1 (password authentication).
  QString tcpUrl(const QString& database) const;
  /// Runs SQL as the superuser in database (for building old schemas); throws on failure.
  void superuserSql(const QString& database, const QStringList& statements);
  /// Runs one query as the superuser in database and returns its rows; throws on failure.
  std::vector<QVariantList> superuserQuery(const QString& database, const QString& sql);

  QString socketDir() const { return m_dir; }
  int port() const { return m_port; }
  /// The bin folder used (initdb, pg_ctl, postgres).
  QString binDir() const { return m_bin; }

 private:
  struct AttachTag {};
  explicit PostgresServer(AttachTag) {}
  static std::unique_ptr<PostgresServer> attach(const QString& stateFile);
  void start(bool durable, const QString& owner);
  void stop();
  static void sweepAbandoned();
  QString run(const QString& program, const QStringList& args, int timeoutMs = 120000);
  void run(const QString& database, const QStringList& statements, std::vector<QVariantList>* rows);
  QString m_bin, m_dir, m_data;
  int m_port = 0;
  bool m_asPostgresUser = false;
  bool m_started = false;
  bool m_owned = true;  ///< false: the fixture's server, which this process only uses
};

}  // namespace armtrack::test
