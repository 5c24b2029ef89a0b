// PostgreSQL only: URL forms (socket folders), connection failures that say what to check, the
// password from ARMTRACK_DB_PASSWORD or a password file, pg_dump instead of `db backup`, two
// workstations on one record, and a recording stored and read back bit for bit; and the test
// server's own clean-up after a killed test. The server is the shared test server
// (tests/support/PostgresServer); when it cannot start, these fail.
#include <gtest/gtest.h>

#include <signal.h>

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QThread>
#include <cstdlib>

#include "tests/core/storage/StorageTestSupport.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;
using armtrack::test::PostgresServer;

namespace {

bool contains(const StorageError& e, const char* text) {
  return std::string(e.what()).find(text) != std::string::npos;
}

// Sets (or, with nullptr, removes) an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : m_name(name) {
    if (const char* old = std::getenv(name)) m_old = old, m_had = true;
    value ? ::setenv(name, value, 1) : ::unsetenv(name);
  }
  ~ScopedEnv() { m_had ? ::setenv(m_name, m_old.c_str(), 1) : ::unsetenv(m_name); }

 private:
  const char* m_name;
  std::string m_old;
  bool m_had = false;
};

}  // namespace

TEST(DatabaseUrl, PostgresSocketForms) {
  const DatabaseUrl encoded = DatabaseUrl::parse("postgresql://clinic@%2Frun%2Fpostgresql/rec");
  EXPECT_EQ(encoded.host, "/run/postgresql");
  EXPECT_TRUE(encoded.isSocket());
  EXPECT_EQ(encoded.database, "rec");
  EXPECT_EQ(encoded.port, 5432);
  const DatabaseUrl query = DatabaseUrl::parse("postgres://clinic@/rec?host=/tmp/pg&port=5440");
  EXPECT_EQ(query.host, "/tmp/pg");
  EXPECT_EQ(query.port, 5440);
  EXPECT_EQ(query.user, "clinic");
  const DatabaseUrl none = DatabaseUrl::parse("postgresql:///rec");
  EXPECT_TRUE(none.host.isEmpty());
  EXPECT_TRUE(none.isSocket());
  EXPECT_FALSE(DatabaseUrl::parse("postgresql://u@db.local/rec").isSocket());
  EXPECT_EQ(DatabaseUrl::parse("postgresql://u@[::1]:5433/rec").host, "::1");
  expectError([] { DatabaseUrl::parse("postgresql://u@h:99999/rec"); }, Kind::Usage);
  expectError([] { DatabaseUrl::parse("postgresql://u@h/rec?password=x"); }, Kind::Usage);
  expectError([] { DatabaseUrl::parse("postgresql://u@h/rec?sslmode=x"); }, Kind::Usage);
  expectError([] { DatabaseUrl::parse("postgresql://u@h;rm/rec"); }, Kind::Usage);
}

TEST(Postgres, ServerDownSaysWhichHostAndPortAndWhatToCheck) {
  // Port 1 on the loopback: nothing listens there, so the connection is refused at once.
  const StorageError e = expectError(
      [] {
        Database db(DatabaseUrl::parse("postgresql://nobody@127.0.0.1:1/rec"), {true, false});
      },
      Kind::Io);
  EXPECT_TRUE(contains(e, "host 127.0.0.1 port 1")) << e.what();
  EXPECT_TRUE(contains(e, "pg_isready")) << e.what();
  const StorageError s = expectError(
      [] { Database db(DatabaseUrl::parse("postgresql://nobody@/rec?host=/nonexistent"), {}); },
      Kind::Io);
  EXPECT_TRUE(contains(s, "/nonexistent")) << s.what();
}

TEST(Postgres, MissingDatabaseIsNotFound) {
  PostgresServer& server = PostgresServer::shared();
  const QString name = PostgresServer::uniqueName("exists_here");
  const QString url = server.createDatabase(name);
  QString other = url;
  other.replace("/" + name + "?", "/not_here?");
  const StorageError e = expectError(
      [&] {
        Database db(DatabaseUrl::parse(other), {true, false});
      },
      Kind::NotFound);
  EXPECT_TRUE(contains(e, "createdb")) << e.what();
}

TEST(Postgres, PasswordFromEnvironmentOrPasswordFile) {
  PostgresServer& server = PostgresServer::shared();
  const QString name = PostgresServer::uniqueName("pw");
  server.createDatabase(name);
  const DatabaseUrl tcp = DatabaseUrl::parse(server.tcpUrl(name));
  QTemporaryDir dir;
  const QString passFile = dir.filePath("pgpass");
  ScopedEnv noFile("PGPASSFILE", passFile.toLocal8Bit().constData());  // not the user's own

  {
    ScopedEnv none("ARMTRACK_DB_PASSWORD", nullptr);
    expectError([&] { Database db(tcp, {true, false}); }, Kind::Authentication);
  }
  {
    ScopedEnv wrong("ARMTRACK_DB_PASSWORD", "not-the-password");
    const StorageError e = expectError(
        [&] {
          Database db(tcp, {true, false});
        },
        Kind::Authentication);
    EXPECT_TRUE(contains(e, PostgresServer::kRole)) << e.what();
    EXPECT_FALSE(contains(e, "not-the-password")) << e.what();
  }
  {
    ScopedEnv right("ARMTRACK_DB_PASSWORD", PostgresServer::kPassword);
    Database db(tcp, {true, false});
    EXPECT_EQ(db.schemaVersion(), latestSchemaVersion());
  }
  {
    // libpq reads the password file itself when no password is given (mode 0600 or it is
    // ignored).
    QFile f(passFile);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(QString("127.0.0.1:%1:%2:%3:%4\n")
                .arg(server.port())
                .arg(name, PostgresServer::kRole, PostgresServer::kPassword)
                .toUtf8());
    f.close();
    f.setPermissions(QFile::ReadOwner | QFile::WriteOwner);
    ScopedEnv none("ARMTRACK_DB_PASSWORD", nullptr);
    Database db(tcp, {});
    EXPECT_EQ(db.schemaVersion(), latestSchemaVersion());
  }
}

TEST(Postgres, BackupPointsToPgDump) {
  Fixture f(Engine::Postgres);
  const StorageError e =
      expectError([&] { f.db->backup(f.dir.filePath("b.dump")); }, Kind::Unsupported);
  EXPECT_TRUE(contains(e, "pg_dump -Fc")) << e.what();
  EXPECT_EQ(f.db->integrityCheck(), "ok");
}

TEST(Postgres, ForeignTablesAreRefused) {
  QTemporaryDir dir;
  const QString url = newDatabase(Engine::Postgres, dir, "foreign");
  rawSql(url, {"CREATE TABLE t (x INTEGER)"});
  expectError([&] { Database db(DatabaseUrl::parse(url), {true, true}); }, Kind::Corrupt);
}

TEST(Postgres, TwoWorkstationsShareOneRecord) {
  Fixture a(Engine::Postgres);
  Database second(DatabaseUrl::parse(a.path), {});
  ClinicalStore b(second);
  b.signIn("admin", kAdminPassword);
  a.store->addPatient(makePatient("SHARED"));
  ASSERT_EQ(b.listPatients().size(), 1u);
  expectError([&] { b.addPatient(makePatient("SHARED")); }, Kind::Exists);
  // A failed statement inside a transaction leaves the connection usable (rolled back).
  b.addPatient(makePatient("SECOND"));
  EXPECT_EQ(a.store->listPatients().size(), 2u);
}

TEST(Postgres, RecordingIsStoredAndReadBackBitForBit) {
  Fixture f(Engine::Postgres);
  f.store->addPatient(makePatient("P1"));
  const auto csv = f.file("rec.csv");
  simulateTo(csv, 5.0);
  const qint64 id = f.store->importRecording(csv, "P1");
  const SessionInfo s = f.store->session(id);
  EXPECT_EQ(s.status, kStatusComplete);
  EXPECT_GE(s.chunks, 5);
  EXPECT_GT(s.storedBytes, 0);
  const auto exported = f.file("exported.csv");
  f.store->exportRecording(id, exported);
  EXPECT_EQ(fileBytes(exported), fileBytes(csv));  // every double and the sidecar, exactly
  EXPECT_EQ(fileBytes(sidecarPath(exported)), fileBytes(sidecarPath(csv)));
  f.store->removeSession(id);
  QSqlQuery left = f.db->exec("SELECT count(*) FROM recording_chunks");
  ASSERT_TRUE(left.next());
  EXPECT_EQ(left.value(0).toInt(), 0);
}

// A recorder that died mid-session (its pid no longer exists on this host) leaves a session that
// the next opening marks interrupted, on PostgreSQL as on SQLite.
TEST(Postgres, DeadRecorderSessionIsMarkedInterrupted) {
  Fixture f(Engine::Postgres);
  f.store->addPatient(makePatient("P1"));
  const qint64 id = f.store->beginSession("P1", "", "{}", 0);
  // Above Linux's largest pid (4194304): no process has it.
  f.db->exec("UPDATE sessions SET recorder_pid = 4194399 WHERE id = ?", {id});
  ClinicalStore reopened(*f.db);
  EXPECT_EQ(reopened.interruptedOnOpen(), 1);
  reopened.signIn("admin", kAdminPassword);
  EXPECT_EQ(reopened.session(id).status, kStatusInterrupted);
}

// A workstation holding a row lock does not hang another forever: after 5 s the waiting
// statement gives up with a message saying what happened; the holder's work commits.
TEST(Postgres, LockHeldByAnotherWorkstationTimesOutClearly) {
  Fixture a(Engine::Postgres);
  a.store->addPatient(makePatient("LOCKED"));
  Database second(DatabaseUrl::parse(a.path), {});
  ClinicalStore b(second);
  b.signIn("admin", kAdminPassword);
  Patient edited = b.patient("LOCKED");
  edited.notes = "from b";
  a.db->transaction([&] {
    a.db->exec("UPDATE patients SET notes = 'from a' WHERE code = 'LOCKED'");
    const StorageError e = expectError([&] { b.updatePatient(edited); }, Kind::Io);
    EXPECT_TRUE(contains(e, "more than 5 s")) << e.what();
  });
  EXPECT_EQ(b.patient("LOCKED").notes, "from a");
}

// The test server itself: a test process that dies without stopping its server (a crash, a
// SIGKILL, a timeout) leaves the server running in /tmp; the next server to start stops it and
// removes its folder. The child is this test binary, started with ARMTRACK_PG_CHILD_OUT set: it
// starts a server of its own, writes its folder there and waits to be killed.
TEST(PostgresTestServer, AServerLeftByAKilledTestIsStoppedByTheNextStart) {
  const QString childOut = qEnvironmentVariable("ARMTRACK_PG_CHILD_OUT");
  if (!childOut.isEmpty()) {
    PostgresServer own;
    QFile f(childOut + ".tmp");
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(own.socketDir().toUtf8());
    f.close();
    ASSERT_TRUE(QFile::rename(childOut + ".tmp", childOut));
    QThread::sleep(120);  // killed long before
    return;
  }
  QTemporaryDir dir;
  const QString out = dir.filePath("child-server");
  QProcess child;
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("ARMTRACK_PG_CHILD_OUT", out);
  env.remove("ARMTRACK_TEST_PG_STATE");  // a server of its own, as a test run by hand starts
  child.setProcessEnvironment(env);
  child.start(
      QCoreApplication::applicationFilePath(),
      {"--gtest_filter=PostgresTestServer.AServerLeftByAKilledTestIsStoppedByTheNextStart"});
  ASSERT_TRUE(child.waitForStarted());
  for (int i = 0; i < 600 && !QFile::exists(out) && child.state() == QProcess::Running; ++i)
    child.waitForFinished(100);
  ASSERT_TRUE(QFile::exists(out)) << child.readAll().toStdString();
  child.kill();
  child.waitForFinished();
  QFile f(out);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QString left = QString::fromUtf8(f.readAll());
  QFile pidFile(left + "/data/postmaster.pid");
  ASSERT_TRUE(pidFile.open(QIODevice::ReadOnly)) << "the killed test's server is not running";
  const pid_t postmaster = QString::fromUtf8(pidFile.readLine()).trimmed().toInt();
  pidFile.close();
  ASSERT_GT(postmaster, 0);
  ASSERT_EQ(::kill(postmaster, 0), 0) << "the killed test's server is not running";

  PostgresServer next;  // sweeps before it starts
  EXPECT_FALSE(QFileInfo::exists(left)) << left.toStdString();
  // pg_ctl has waited for the server to stop; the exited postmaster may still wait for its
  // parent (init, since the test that started it died) to collect it.
  auto gone = [&] {
    if (::kill(postmaster, 0) != 0) return true;
    QFile stat(QString("/proc/%1/stat").arg(postmaster));
    return stat.open(QIODevice::ReadOnly) && stat.readAll().contains(") Z ");
  };
  for (int i = 0; i < 300 && !gone(); ++i) QThread::msleep(100);
  EXPECT_TRUE(gone()) << "postmaster " << postmaster << " still runs";
  EXPECT_TRUE(QFileInfo::exists(next.socketDir()));
}
