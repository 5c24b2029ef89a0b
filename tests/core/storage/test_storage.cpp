// The clinical records service: opening checks, migrations, CRUD of every table, sign-in and
// access control (docs/storage.md).
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QFile>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <bit>
#include <cmath>
#include <limits>

#include "core/storage/AuditLog.h"
#include "core/storage/PasswordHash.h"
#include "tests/core/storage/StorageTestSupport.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;

namespace {

using Crud = Engines;
using SignIn = Engines;
using AccessControl = Engines;
using Migration = Engines;
using Performance = Engines;
using Schema = Engines;

}  // namespace

TEST(DatabaseUrl, PathsAndPostgres) {
  EXPECT_EQ(DatabaseUrl::parse("/tmp/a.db").path, "/tmp/a.db");
  EXPECT_EQ(DatabaseUrl::parse("sqlite:rel/a.db").path, "rel/a.db");
  EXPECT_EQ(DatabaseUrl::parse("sqlite:///abs/a.db").path, "/abs/a.db");
  const DatabaseUrl pg = DatabaseUrl::parse("postgresql://clinic@db.local:5433/armtrack");
  EXPECT_EQ(pg.engine, DatabaseUrl::Engine::Postgres);
  EXPECT_EQ(pg.user, "clinic");
  EXPECT_EQ(pg.host, "db.local");
  EXPECT_EQ(pg.port, 5433);
  EXPECT_EQ(pg.database, "armtrack");
  expectError([] { DatabaseUrl::parse("postgresql://u:secret@h/db"); }, Kind::Usage);
  expectError([] { DatabaseUrl::parse("postgresql://h"); }, Kind::Usage);
  expectError([] { DatabaseUrl::parse("mysql://h/db"); }, Kind::Usage);
  expectError([] { DatabaseUrl::parse(""); }, Kind::Usage);
  EXPECT_TRUE(DatabaseUrl::defaultLocation().path.endsWith("/armtrack.db"));
}

TEST(Database, CreatesWalWithForeignKeysAndCurrentSchema) {
  Fixture f;
  EXPECT_EQ(f.db->schemaVersion(), latestSchemaVersion());
  EXPECT_EQ(f.db->integrityCheck(), "ok");
  QSqlQuery wal = f.db->exec("PRAGMA journal_mode");
  ASSERT_TRUE(wal.next());
  EXPECT_EQ(wal.value(0).toString(), "wal");
  QSqlQuery fk = f.db->exec("PRAGMA foreign_keys");
  ASSERT_TRUE(fk.next());
  EXPECT_EQ(fk.value(0).toInt(), 1);
  // A foreign key is enforced: a session for a patient that does not exist is refused.
  expectError(
      [&] {
        f.db->exec(
            "INSERT INTO sessions (patient_id, started_at, status) VALUES (999, 'x', 'complete')");
      },
      Kind::Io);
}

TEST(Database, MissingFileIsNotCreatedWithoutInit) {
  QTemporaryDir dir;
  const QString path = dir.filePath("none.db");
  const StorageError e =
      expectError([&] { Database db(DatabaseUrl::parse(path), {}); }, Kind::NotFound);
  EXPECT_NE(std::string(e.what()).find("db init"), std::string::npos);
  EXPECT_FALSE(QFile::exists(path));
}

TEST(Database, GarbageFileIsRefusedAndLeftUntouched) {
  QTemporaryDir dir;
  const QString path = dir.filePath("garbage.db");
  std::string garbage(8192, '\0');
  for (std::size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<char>((i * 7919) >> 3);
  {
    QFile out(path);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(garbage.data(), static_cast<qint64>(garbage.size()));
  }
  const StorageError e = expectError(
      [&] {
        Database db(DatabaseUrl::parse(path), {true, true});
      },
      Kind::Corrupt);
  EXPECT_NE(std::string(e.what()).find(path.toStdString()), std::string::npos) << e.what();
  EXPECT_EQ(fileBytes(path.toStdString()), garbage);
  EXPECT_FALSE(QFile::exists(path + "-wal"));
}

TEST(Database, DamagedPagesFailTheIntegrityCheckAndAreLeftUntouched) {
  Fixture f;
  for (int i = 0; i < 40; ++i)
    f.store->addPatient(makePatient(QString("P%1").arg(i, 3, 10, QChar('0'))));
  f.db->exec("PRAGMA wal_checkpoint(TRUNCATE)");
  f.close();
  // Overwrite the middle of the file (past the 100-byte header, inside b-tree pages).
  std::string bytes = fileBytes(f.path.toStdString());
  ASSERT_GT(bytes.size(), 8192u);
  for (std::size_t i = 4096 + 8; i < 8192; ++i) bytes[i] = static_cast<char>(0xA5);
  {
    QFile out(f.path);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
    out.write(bytes.data(), static_cast<qint64>(bytes.size()));
  }
  const StorageError e =
      expectError([&] { Database db(DatabaseUrl::parse(f.path), {}); }, Kind::Corrupt);
  EXPECT_NE(std::string(e.what()).find("untouched"), std::string::npos) << e.what();
  EXPECT_EQ(fileBytes(f.path.toStdString()), bytes);
}

TEST_P(Schema, NewerSchemaIsRefused) {
  Fixture f(GetParam());
  f.close();
  rawSql(f.path, {"UPDATE schema_version SET version = 99"});
  const StorageError e = expectError(
      [&] {
        Database db(DatabaseUrl::parse(f.path), {false, true});
      },
      Kind::NewerSchema);
  EXPECT_NE(std::string(e.what()).find("newer"), std::string::npos);
}

// Someone else's SQLite database (here in rollback-journal mode, as most programs leave theirs)
// is refused and left as it was, byte for byte: before, it was switched to write-ahead logging
// (a write to its header) before its tables were looked at.
TEST(Database, ForeignSqliteFileIsRefusedAndLeftUntouched) {
  QTemporaryDir dir;
  const QString path = dir.filePath("other.db");
  rawSql(path, {"CREATE TABLE t (x)", "INSERT INTO t VALUES (1)"});
  const std::string before = fileBytes(path.toStdString());
  ASSERT_EQ(before[18], 1);  // the header's write version: 1, rollback journal; 2 would be WAL
  expectError([&] { Database db(DatabaseUrl::parse(path), {true, true}); }, Kind::Corrupt,
              "not ArmTrack's");
  EXPECT_EQ(fileBytes(path.toStdString()), before);
  EXPECT_FALSE(QFileInfo::exists(path + "-wal"));
}

TEST(Database, BackupIsACompleteDatabase) {
  Fixture f;
  f.store->addPatient(makePatient("B1"));
  const QString out = f.dir.filePath("backup.db");
  f.db->backup(out);
  expectError([&] { f.db->backup(out); }, Kind::Exists);
  Database copy(DatabaseUrl::parse(out), {});
  ClinicalStore store(copy);
  store.signIn("admin", kAdminPassword);
  ASSERT_EQ(store.listPatients().size(), 1u);
  EXPECT_EQ(store.listPatients()[0].code, "B1");
}

// Version 1 exactly as released (a copy, so that later edits to Schema.cpp cannot hide a broken
// migration). Version 2 added the sign-in throttling columns to users.
TEST_P(Migration, FromVersion1KeepsEveryRowAndAddsTheNewColumns) {
  QTemporaryDir dir;
  const QString path = newDatabase(GetParam(), dir, "v1");
  rawSql(path, version1Schema(GetParam()));
  // Audit entries written by version 1, without a hash chain.
  rawSql(path, {"INSERT INTO audit_log (at, user_name, action, object_type, object_id, detail) "
                "VALUES ('2025-01-01T00:00:00.000Z', 'admin', 'create', 'database', 'v1', ''), "
                "('2025-01-02T10:00:00.000Z', 'admin', 'create', 'patient', 'OLD1', ''), "
                "('2025-01-02T10:05:00.000Z', 'admin', 'view', 'session', '1', 'first visit')"});

  // Without migrate the older schema is refused with what to do.
  const StorageError e =
      expectError([&] { Database db(DatabaseUrl::parse(path), {}); }, Kind::OlderSchema);
  EXPECT_NE(std::string(e.what()).find("db migrate"), std::string::npos);

  Database db(DatabaseUrl::parse(path), {false, true});
  EXPECT_EQ(db.migrationsApplied(), latestSchemaVersion() - 1);
  EXPECT_EQ(db.schemaVersion(), latestSchemaVersion());
  ClinicalStore store(db);
  EXPECT_EQ(store.signIn("admin", kAdminPassword).failedAttempts, 0);
  const Patient p = store.patient("OLD1");
  EXPECT_EQ(p.name, "Old Patient");
  EXPECT_EQ(p.birthDate, "1950-01-31");
  EXPECT_EQ(p.affectedSide, "left");
  const auto sessions = store.listSessions("OLD1");
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_EQ(sessions[0].notes, "first visit");
  EXPECT_EQ(sessions[0].status, kStatusComplete);
  ASSERT_TRUE(store.latestMetrics(sessions[0].id).has_value());
  EXPECT_EQ(store.latestMetrics(sessions[0].id)->first, "{\"elbow_flexion\":{\"rom_deg\":91.5}}");
  // The new column works: a wrong password is counted.
  expectError([&] { store.signIn("admin", "wrong"); }, Kind::Authentication);
  QSqlQuery q = db.exec("SELECT failed_attempts FROM users WHERE name = 'admin'");
  ASSERT_TRUE(q.next());
  EXPECT_EQ(q.value(0).toInt(), 1);
  q.finish();
  // Version 6 keyed the names without regard to case (case-duplicates: test_storage_access).
  EXPECT_EQ(store.patient("old1").code, "OLD1");
  QSqlQuery keys = db.exec("SELECT name_key FROM users WHERE name = 'admin'");
  ASSERT_TRUE(keys.next());
  EXPECT_EQ(keys.value(0).toString(), "admin");
  // The old entries were chained in id order, unchanged, and the failure is chained after them.
  QString prev = auditGenesisHash();
  QSqlQuery log = db.exec(
      "SELECT id, at, user_name, action, object_type, object_id, detail, prev_hash, hash FROM "
      "audit_log ORDER BY id");
  QStringList actions;
  while (log.next()) {
    const ChainedAuditEntry e{
        log.value(0).toLongLong(), log.value(1).toString(), log.value(2).toString(),
        log.value(3).toString(),   log.value(4).toString(), log.value(5).toString(),
        log.value(6).toString(),   log.value(7).toString(), log.value(8).toString()};
    EXPECT_EQ(e.prevHash, prev) << e.id;
    EXPECT_EQ(e.hash, auditEntryHash(e)) << e.id;
    prev = e.hash;
    actions << e.action + " " + e.objectId;
  }
  log.finish();
  EXPECT_EQ(actions, QStringList({"create v1", "create OLD1", "view 1", "sign-in-failed admin"}));
  const AuditChainReport chain = verifyAuditChain(db);
  EXPECT_TRUE(chain.intact()) << chain.problem.toStdString();
  EXPECT_EQ(chain.entries, 4);
  expectError([&] { db.exec("UPDATE audit_log SET detail = ''"); }, Kind::Io, "append-only");
}

TEST_P(Crud, Patients) {
  Fixture f(GetParam());
  const qint64 id = f.store->addPatient(makePatient("P1"));
  EXPECT_GT(id, 0);
  expectError([&] { f.store->addPatient(makePatient("P1")); }, Kind::Exists);
  Patient bad = makePatient("P2");
  bad.birthDate = "02/04/1960";
  expectError([&] { f.store->addPatient(bad); }, Kind::Usage);
  Patient p = f.store->patient("P1");
  EXPECT_EQ(p.name, "Name of P1");
  EXPECT_EQ(p.segmentLengthsJson, R"({"upper_arm_m":0.3,"forearm_m":0.26})");
  p.notes = "prefers mornings";
  p.affectedSide = "both";
  f.store->updatePatient(p);
  EXPECT_EQ(f.store->patient("P1").notes, "prefers mornings");
  EXPECT_EQ(f.store->patient("P1").affectedSide, "both");
  f.store->addPatient(makePatient("P0"));
  ASSERT_EQ(f.store->listPatients().size(), 2u);
  EXPECT_EQ(f.store->listPatients()[0].code, "P0");
  f.store->removePatient("P1");
  expectError([&] { f.store->patient("P1"); }, Kind::NotFound);
}

// Text that would break a statement built by hand: quotes, backslashes, placeholders, a comment,
// non-ASCII; and binary data with every byte value. Each reads back as written.
TEST_P(Crud, HostileTextAndBytesRoundTrip) {
  Fixture f(GetParam());
  Patient p = makePatient("Q'1?");
  p.name = "O'Brien \\ \"x\" ? ?? $1 :name -- ); DROP TABLE patients; --";
  p.notes = QString::fromUtf8("Grüße, 患者, \\x00 \\' E'\\n'");
  p.diagnosis = "";
  f.store->addPatient(p);
  const Patient back = f.store->patient("Q'1?");
  EXPECT_EQ(back.name, p.name);
  EXPECT_EQ(back.notes, p.notes);
  EXPECT_EQ(back.diagnosis, "");
  const qint64 s = f.store->beginSession("Q'1?", "", "{}", 0);
  QByteArray bytes;
  for (int i = 0; i < 256; ++i) bytes.append(static_cast<char>(i));
  bytes += QByteArray("\\x'?", 5);
  f.store->saveEstimates(s, "{\"k\":\"'?\"}", "raw", bytes);
  QSqlQuery q = f.db->exec("SELECT data, params_json FROM estimates WHERE session_id = ?", {s});
  ASSERT_TRUE(q.next());
  EXPECT_EQ(q.value(0).toByteArray(), bytes);
  EXPECT_EQ(q.value(1).toString(), "{\"k\":\"'?\"}");
  EXPECT_EQ(f.store->listPatients().size(), 1u);  // the table is still there
}

TEST_P(Crud, ProtocolsUsersMetricsEstimatesAudit) {
  Fixture f(GetParam());
  Protocol pr = makeProtocol("elbow reps", "elbow_flexion", 10, 120, 10);
  pr.side = "right";
  f.store->addProtocol(pr);
  expectError([&] { f.store->addProtocol(pr); }, Kind::Exists);
  Protocol wrongAngle = pr;
  wrongAngle.name = "other";
  wrongAngle.angleKey = "knee_flexion";
  expectError([&] { f.store->addProtocol(wrongAngle); }, Kind::Usage);
  pr.repetitions = 12;
  f.store->updateProtocol(pr);
  EXPECT_EQ(f.store->protocol("elbow reps").repetitions, 12);
  EXPECT_EQ(f.store->listProtocols().size(), 1u);

  f.store->addPatient(makePatient("P1"));
  f.store->addUser("thera", Role::Therapist, "t-pass-long");
  f.store->addUser("home1", Role::Home, "h-pass-long", "P1");
  expectError([&] { f.store->addUser("home2", Role::Home, "x-password"); }, Kind::Usage);
  expectError([&] { f.store->addUser("home3", Role::Home, "x-password", "NOPE"); }, Kind::NotFound);
  EXPECT_EQ(f.store->listUsers().size(), 3u);
  f.store->setPassword("thera", "t-pass-long-2");
  f.store->removeUser("thera");
  EXPECT_EQ(f.store->listUsers().size(), 2u);

  f.store->assignProtocol("P1", "elbow reps", 3, "mornings");
  f.store->assignProtocol("P1", "elbow reps", 4);  // replaces
  ASSERT_EQ(f.store->programme("P1").size(), 1u);
  EXPECT_EQ(f.store->programme("P1")[0].sessionsPerWeek, 4);
  f.store->unassignProtocol("P1", "elbow reps");
  EXPECT_TRUE(f.store->programme("P1").empty());
  expectError([&] { f.store->unassignProtocol("P1", "elbow reps"); }, Kind::NotFound);
  f.store->assignProtocol("P1", "elbow reps", 2);
  const qint64 s = f.store->beginSession("P1", "elbow reps", "{}", 0);
  f.store->finishSession(s);
  EXPECT_EQ(f.store->session(s).protocolName, "elbow reps");
  f.store->updateSessionNotes(s, "tired today");
  EXPECT_EQ(f.store->session(s).notes, "tired today");
  EXPECT_EQ(f.store->saveMetrics(s, "{\"a\":1}", "[]"), 1);
  EXPECT_EQ(f.store->saveMetrics(s, "{\"a\":2}", "[]"), 2);
  EXPECT_EQ(f.store->latestMetrics(s)->first, "{\"a\":2}");
  EXPECT_EQ(f.store->saveEstimates(s, "{}", "raw", QByteArray("abc")), 1);
  EXPECT_EQ(f.store->estimateVersions(s), 1);
  f.store->removeProtocol("elbow reps");
  EXPECT_EQ(f.store->session(s).protocolName, "");
  EXPECT_TRUE(f.store->programme("P1").empty());  // cascaded with the protocol
  f.store->removeSession(s);
  expectError([&] { f.store->session(s); }, Kind::NotFound);
  QSqlQuery left = f.db->exec("SELECT count(*) FROM metrics");
  ASSERT_TRUE(left.next());
  EXPECT_EQ(left.value(0).toInt(), 0);  // cascaded with the session

  const auto log = f.store->auditLog();
  ASSERT_FALSE(log.empty());
  EXPECT_EQ(log.back().action, "delete");
  EXPECT_EQ(log.back().objectType, "session");
  for (const AuditEntry& e : log) EXPECT_EQ(e.detail.indexOf("Name of"), -1);  // no names
}

TEST_P(SignIn, WrongPasswordAndThrottling) {
  Fixture f(GetParam());
  ClinicalStore fresh(*f.db);
  const StorageError unknown =
      expectError([&] { fresh.signIn("nobody", "x"); }, Kind::Authentication);
  const StorageError wrong = expectError([&] { fresh.signIn("admin", "x"); }, Kind::Authentication);
  EXPECT_EQ(std::string(wrong.what()).find("nobody"), std::string::npos);
  EXPECT_NE(std::string(wrong.what()).find("wrong user name or password"), std::string::npos);
  expectError([&] { fresh.signIn("admin", "y"); }, Kind::Authentication);
  fresh.signIn("admin", kAdminPassword);  // two failures: still free, and the count resets
  for (int i = 0; i < 3; ++i)
    expectError([&] { fresh.signIn("admin", "z"); }, Kind::Authentication);
  const StorageError slow =
      expectError([&] { fresh.signIn("admin", kAdminPassword); }, Kind::Authentication);
  EXPECT_NE(std::string(slow.what()).find("try again in"), std::string::npos) << slow.what();
  ClinicalStore anonymous(*f.db);
  expectError([&] { anonymous.listPatients(); }, Kind::Authentication);  // never signed in
}

TEST_P(AccessControl, HomeAccountSeesOnlyItsPatient) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("MINE"));
  f.store->addPatient(makePatient("OTHER"));
  f.store->addUser("home", Role::Home, "h-pass-long", "MINE");
  f.store->addUser("thera", Role::Therapist, "t-pass-long");
  const qint64 mine = f.store->beginSession("MINE", "", "{}", 0);
  const qint64 other = f.store->beginSession("OTHER", "", "{}", 0);
  f.store->finishSession(mine);
  f.store->finishSession(other);

  Protocol pr;
  pr.name = "reach";
  pr.angleKey = "shoulder_flexion";
  pr.targetMaxDeg = 90;
  f.store->addProtocol(pr);
  f.store->assignProtocol("MINE", "reach", 5);
  f.store->assignProtocol("OTHER", "reach", 2);

  ClinicalStore home(*f.db);
  home.signIn("home", "h-pass-long");
  ASSERT_EQ(home.programme("MINE").size(), 1u);
  EXPECT_EQ(home.programme("MINE")[0].sessionsPerWeek, 5);
  expectError([&] { home.programme("OTHER"); }, Kind::NotFound);
  expectError([&] { home.assignProtocol("MINE", "reach", 9); }, Kind::AccessDenied);
  ASSERT_EQ(home.listPatients().size(), 1u);
  EXPECT_EQ(home.listPatients()[0].code, "MINE");
  EXPECT_EQ(home.listSessions("MINE").size(), 1u);
  EXPECT_EQ(home.session(mine).patientCode, "MINE");
  expectError([&] { home.patient("OTHER"); }, Kind::NotFound);
  expectError([&] { home.listSessions("OTHER"); }, Kind::NotFound);
  expectError([&] { home.session(other); }, Kind::NotFound);
  expectError([&] { home.readRecording(other); }, Kind::NotFound);
  expectError([&] { home.exportRecording(other, f.file("x.csv")); }, Kind::NotFound);
  expectError([&] { home.beginSession("OTHER", "", "{}", 0); }, Kind::NotFound);
  expectError([&] { home.addPatient(makePatient("NEW")); }, Kind::AccessDenied);
  expectError([&] { home.addUser("x", Role::Admin, "x"); }, Kind::AccessDenied);
  expectError([&] { home.auditLog(); }, Kind::AccessDenied);
  expectError([&] { home.saveMetrics(mine, "{}", "[]"); }, Kind::AccessDenied);
  EXPECT_FALSE(std::filesystem::exists(f.file("x.csv")));

  ClinicalStore thera(*f.db);
  thera.signIn("thera", "t-pass-long");
  EXPECT_EQ(thera.listPatients().size(), 2u);
  expectError([&] { thera.addUser("x", Role::Admin, "x"); }, Kind::AccessDenied);
  expectError([&] { thera.removePatient("OTHER"); }, Kind::AccessDenied);
}

// The issue's figure: opening a database of 1,000 sessions and listing one patient's sessions
// takes under 100 ms (the bound here is looser: the machine is shared while tests run).
TEST_P(Performance, OpenAndListOnePatientAmongAThousandSessions) {
  Fixture f(GetParam());
  for (int p = 0; p < 50; ++p) f.store->addPatient(makePatient(QString("Q%1").arg(p)));
  f.db->transaction([&] {
    for (int i = 0; i < 1000; ++i)
      f.db->exec("INSERT INTO sessions (patient_id, started_at, status) VALUES (?, ?, 'complete')",
                 {1 + i % 50, QString("2026-01-01T00:00:%1.000Z").arg(i % 60, 2, 10, QChar('0'))});
  });
  f.close();
  QElapsedTimer timer;
  timer.start();
  Database db(DatabaseUrl::parse(f.path), {});
  ClinicalStore store(db);
  const double openMs = timer.nsecsElapsed() * 1e-6;
  store.signIn("admin", kAdminPassword);  // Argon2id: deliberately slow, not counted
  timer.restart();
  const auto sessions = store.listSessions("Q7");
  const double listMs = timer.nsecsElapsed() * 1e-6;
  EXPECT_EQ(sessions.size(), 20u);
  std::printf(
      "[ figures  ] 1,000 sessions: open (with integrity check) %.1f ms, list one "
      "patient's 20 sessions %.1f ms\n",
      openMs, listMs);
  EXPECT_LT(openMs + listMs, 500.0);
}

// Doubles reach the engine and come back bit for bit, the awkward ones included (the chunk
// index's times, protocol targets and durations are DOUBLE PRECISION; the samples themselves
// are in the chunks, exact on both). The exceptions are SQLite's -0 and NaN, documented.
TEST_P(Schema, DoublesSurviveTheTripExactly) {
  Fixture f(GetParam());
  f.db->exec("CREATE TEMP TABLE d (i INTEGER, x DOUBLE PRECISION)");
  const double values[] = {0.1,
                           -0.0,
                           5e-324,
                           1.7976931348623157e308,
                           2.2250738585072014e-308,
                           0.30000000000000004,
                           std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(),
                           std::nan("")};
  for (int i = 0; i < 9; ++i) f.db->exec("INSERT INTO d VALUES (?, ?)", {i, values[i]});
  QSqlQuery q = f.db->exec("SELECT x FROM d ORDER BY i");
  for (int i = 0; i < 9; ++i) {
    ASSERT_TRUE(q.next());
    const double back = q.value(0).toDouble();
    if (std::isnan(values[i]) && GetParam() == Engine::Sqlite)
      EXPECT_TRUE(q.value(0).isNull());  // SQLite has no NaN: it stores NULL
    else if (std::isnan(values[i]))
      EXPECT_TRUE(std::isnan(back));
    else if (GetParam() == Engine::Sqlite && values[i] == 0.0)
      EXPECT_EQ(back, 0.0);  // SQLite keeps an integral REAL as an integer: -0 reads as 0
    else
      EXPECT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(values[i]))
          << i << ": " << values[i] << " came back as " << back;
  }
}

INSTANTIATE_TEST_SUITE_P(Engines, Schema, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
INSTANTIATE_TEST_SUITE_P(Engines, Migration, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
INSTANTIATE_TEST_SUITE_P(Engines, Crud, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
INSTANTIATE_TEST_SUITE_P(Engines, SignIn, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
INSTANTIATE_TEST_SUITE_P(Engines, AccessControl, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
INSTANTIATE_TEST_SUITE_P(Engines, Performance, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
