// The records' own checks, tried as a forger would try them: the audit log's hash chain and
// append-only triggers (docs/storage.md, "Audit log"). On both engines.
#include <gtest/gtest.h>

#include <unistd.h>

#include <QSqlQuery>
#include <QSysInfo>
#include <atomic>
#include <latch>
#include <set>
#include <thread>

#include "core/storage/AuditLog.h"
#include "tests/core/storage/StorageTestSupport.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;

namespace {

using AuditChain = Engines;

// What a forger holding the file (SQLite) or the database role (PostgreSQL) does first.
void dropAuditTriggers(const Fixture& f) {
  if (f.engine == Engine::Sqlite)
    rawSql(f.path, {"DROP TRIGGER audit_log_no_update", "DROP TRIGGER audit_log_no_delete"});
  else
    rawSql(f.path, {"DROP TRIGGER audit_log_no_change ON audit_log",
                    "DROP TRIGGER audit_log_no_truncate ON audit_log"});
}

// Some work, each step audited: 7 entries with the database's creation.
void someActivity(Fixture& f) {
  for (const char* code : {"P1", "P2", "P3"}) f.store->addPatient(makePatient(code));
  Patient p = f.store->patient("P2");
  p.notes = "moved";
  f.store->updatePatient(p);
  f.store->addProtocol(makeProtocol("reach", "shoulder_flexion", 0, 120, 8));
  f.store->addUser("kim", Role::Therapist, "a good password");
}

qint64 auditCount(const Fixture& f) {
  return rawQuery(f.path, "SELECT count(*) FROM audit_log")[0][0].toLongLong();
}

ChainedAuditEntry entry(const Fixture& f, qint64 id) {
  const auto rows = rawQuery(f.path,
                             "SELECT id, at, user_name, action, object_type, object_id, detail, "
                             "prev_hash, hash FROM audit_log WHERE id = " +
                                 QString::number(id));
  EXPECT_EQ(rows.size(), 1u) << id;
  ChainedAuditEntry e;
  if (rows.empty()) return e;
  const QVariantList& r = rows[0];
  e = {r[0].toLongLong(), r[1].toString(), r[2].toString(), r[3].toString(), r[4].toString(),
       r[5].toString(),   r[6].toString(), r[7].toString(), r[8].toString()};
  return e;
}

std::string problemOf(const AuditChainReport& r) {
  return r.problem.toStdString();
}

}  // namespace

// The encoding is fixed for good: changing it would break every stored chain. The expected hash
// was computed outside ArmTrack (Python's hashlib over the same length-prefixed UTF-8 fields).
TEST(AuditHash, KnownAnswerAndUnambiguousFields) {
  ChainedAuditEntry e{7,
                      "2026-11-25T07:05:33.123Z",
                      QString::fromUtf8("Zo\xc3\xab"),
                      "create",
                      "patient",
                      "P1",
                      "",
                      auditGenesisHash(),
                      ""};
  EXPECT_EQ(auditEntryHash(e), "88eaa191ee9f78eda371a7eb4e9ba4762e5c24c1dd4e01d457921571e900aa65");
  // A character moved from one field to the next is another entry.
  ChainedAuditEntry a = e, b = e;
  a.objectType = "patientP";
  a.objectId = "1";
  EXPECT_NE(auditEntryHash(a), auditEntryHash(e));
  b.id = 71;
  b.at = "2026-11-25T07:05:33.123Z";
  EXPECT_NE(auditEntryHash(b), auditEntryHash(e));

  EXPECT_EQ(AuditAnchor::parse("12:" + QString(64, 'A'))->hash, QString(64, 'a'));
  EXPECT_FALSE(AuditAnchor::parse("12:abc").has_value());
  EXPECT_FALSE(AuditAnchor::parse("x:" + QString(64, 'a')).has_value());
  EXPECT_FALSE(AuditAnchor::parse("0:" + QString(64, 'a')).has_value());
}

TEST_P(AuditChain, EveryEntryLinksToTheOneBefore) {
  Fixture f(GetParam());
  someActivity(f);
  const qint64 n = auditCount(f);
  ASSERT_EQ(n, 7);
  QString prev = auditGenesisHash();
  for (qint64 id = 1; id <= n; ++id) {
    const ChainedAuditEntry e = entry(f, id);
    EXPECT_EQ(e.prevHash, prev) << id;
    EXPECT_EQ(e.hash, auditEntryHash(e)) << id;
    prev = e.hash;
  }
  const AuditChainReport r = verifyAuditChain(*f.db);
  EXPECT_TRUE(r.intact()) << problemOf(r);
  EXPECT_EQ(r.entries, n);
  ASSERT_TRUE(r.newest.has_value());
  EXPECT_EQ(r.newest->id, n);
  EXPECT_EQ(r.newest->hash, prev);
  EXPECT_TRUE(verifyAuditChain(*f.db, r.newest).intact());
  EXPECT_TRUE(verifyAuditChain(*f.db, AuditAnchor{3, entry(f, 3).hash}).intact());
}

// Append-only in the schema: an UPDATE, a DELETE (and on PostgreSQL a TRUNCATE) of the audit log
// is refused, by the service's own connection as by anyone else's.
TEST_P(AuditChain, TheTableRefusesChangesAndDeletions) {
  Fixture f(GetParam());
  someActivity(f);
  expectError([&] { f.db->exec("UPDATE audit_log SET user_name = 'nobody' WHERE id = 2"); },
              Kind::Io, "append-only");
  expectError([&] { f.db->exec("DELETE FROM audit_log WHERE id = 2"); }, Kind::Io, "append-only");
  EXPECT_THROW(rawSql(f.path, {"UPDATE audit_log SET detail = 'x'"}), std::runtime_error);
  EXPECT_THROW(rawSql(f.path, {"DELETE FROM audit_log"}), std::runtime_error);
  if (GetParam() == Engine::Postgres) {
    EXPECT_THROW(rawSql(f.path, {"TRUNCATE audit_log"}), std::runtime_error);
  }
  EXPECT_EQ(auditCount(f), 7);
  EXPECT_EQ(entry(f, 2).userName, "admin");
  EXPECT_TRUE(verifyAuditChain(*f.db).intact());
}

// No path of the product changes or deletes an entry: everything that deletes works with the
// triggers in place, and the chain stays whole.
TEST_P(AuditChain, RemovingRecordsLeavesTheLogWhole) {
  Fixture f(GetParam());
  someActivity(f);
  simulateTo(f.file("rec.csv"), 2.0, 200.0);
  const qint64 id = f.store->importRecording(f.file("rec.csv"), "P1");
  f.store->addUser("home1", Role::Home, "another good one", "P3");
  f.store->removeSession(id);
  f.store->removeUser("kim");
  f.store->removeProtocol("reach");
  f.store->removePatient("P3");
  const AuditChainReport r = verifyAuditChain(*f.db);
  EXPECT_TRUE(r.intact()) << problemOf(r);
  EXPECT_EQ(r.entries, auditCount(f));
  EXPECT_GE(r.entries, 13);
}

// The forger's first step shows too: triggers dropped, or (PostgreSQL) disabled.
TEST_P(AuditChain, DroppedOrDisabledTriggersAreTold) {
  Fixture f(GetParam());
  someActivity(f);
  EXPECT_EQ(verifyAuditChain(*f.db).guardProblem, "");
  if (GetParam() == Engine::Postgres) {
    rawSql(f.path, {"ALTER TABLE audit_log DISABLE TRIGGER audit_log_no_change"});
    const AuditChainReport r = verifyAuditChain(*f.db);
    EXPECT_FALSE(r.intact());
    EXPECT_EQ(r.brokenAt, 0);
    EXPECT_NE(r.guardProblem.toStdString().find("missing or disabled (audit_log_no_change)"),
              std::string::npos)
        << r.guardProblem.toStdString();
  }
  dropAuditTriggers(f);
  const AuditChainReport r = verifyAuditChain(*f.db);
  EXPECT_FALSE(r.intact());
  const std::string expected = GetParam() == Engine::Sqlite
                                   ? "(audit_log_no_update, audit_log_no_delete)"
                                   : "(audit_log_no_change, audit_log_no_truncate)";
  EXPECT_NE(r.guardProblem.toStdString().find(expected), std::string::npos)
      << r.guardProblem.toStdString();
}

TEST_P(AuditChain, AnEditedEntryIsNamed) {
  Fixture f(GetParam());
  someActivity(f);
  dropAuditTriggers(f);
  rawSql(f.path, {"UPDATE audit_log SET object_id = 'P9' WHERE id = 3"});
  AuditChainReport r = verifyAuditChain(*f.db);
  EXPECT_FALSE(r.intact());
  EXPECT_EQ(r.brokenAt, 3);
  EXPECT_EQ(r.brokenLinks, 1);
  EXPECT_NE(problemOf(r).find("entry 3 was edited (or written in by hand): its content does not "
                              "match its hash"),
            std::string::npos)
      << problemOf(r);
  // Back as it was: whole again (the check judges content, not the rows' history).
  rawSql(f.path, {"UPDATE audit_log SET object_id = 'P2' WHERE id = 3"});
  EXPECT_EQ(verifyAuditChain(*f.db).brokenAt, 0) << problemOf(verifyAuditChain(*f.db));

  // A forger who recomputes the edited entry's hash breaks the next link instead.
  ChainedAuditEntry e = entry(f, 3);
  e.objectId = "P9";
  rawSql(f.path, {"UPDATE audit_log SET object_id = 'P9', hash = '" + auditEntryHash(e) +
                  "' WHERE id = 3"});
  r = verifyAuditChain(*f.db);
  EXPECT_EQ(r.brokenAt, 4);
  EXPECT_NE(problemOf(r).find("entry 4 does not follow entry 3"), std::string::npos)
      << problemOf(r);
}

TEST_P(AuditChain, ADeletedEntryIsNamed) {
  Fixture f(GetParam());
  someActivity(f);
  dropAuditTriggers(f);
  rawSql(f.path, {"DELETE FROM audit_log WHERE id IN (3, 4)"});
  const AuditChainReport r = verifyAuditChain(*f.db);
  EXPECT_EQ(r.brokenAt, 5);
  EXPECT_EQ(r.brokenLinks, 1);
  EXPECT_NE(problemOf(r).find("entry 5 does not follow entry 2"), std::string::npos)
      << problemOf(r);
  EXPECT_NE(problemOf(r).find("entries 3 to 4 were deleted"), std::string::npos) << problemOf(r);

  Fixture g(GetParam());
  someActivity(g);
  dropAuditTriggers(g);
  rawSql(g.path, {"DELETE FROM audit_log WHERE id = 1"});
  EXPECT_NE(problemOf(verifyAuditChain(*g.db))
                .find("entry 2 is the first entry but does not "
                      "start the chain"),
            std::string::npos);
}

TEST_P(AuditChain, AnInsertedEntryIsNamed) {
  // Back-dated, at the end, as a forger typing INSERT would: no hash.
  Fixture f(GetParam());
  someActivity(f);
  dropAuditTriggers(f);
  rawSql(f.path, {"INSERT INTO audit_log (id, at, user_name, action, object_type, object_id, "
                  "detail) VALUES (8, '2024-01-01T09:00:00.000Z', 'admin', 'delete', "
                  "'patient', 'P7', '')"});
  AuditChainReport r = verifyAuditChain(*f.db);
  EXPECT_EQ(r.brokenAt, 8);
  EXPECT_NE(problemOf(r).find("entry 8 was inserted: it has no hash"), std::string::npos)
      << problemOf(r);

  // Among older ones: the later entries moved up by one to make room, a hash copied in.
  Fixture g(GetParam());
  someActivity(g);
  dropAuditTriggers(g);
  const QString copied = entry(g, 3).hash;
  rawSql(g.path, {"UPDATE audit_log SET id = -id WHERE id >= 3",
                  "UPDATE audit_log SET id = 1 - id WHERE id < 0",
                  "INSERT INTO audit_log (id, at, user_name, action, object_type, object_id, "
                  "detail, prev_hash, hash) VALUES (3, '2020-01-01T09:00:00.000Z', 'admin', "
                  "'delete', 'patient', 'P7', '', '" +
                      entry(g, 2).hash + "', '" + copied + "')"});
  r = verifyAuditChain(*g.db);
  EXPECT_EQ(r.brokenAt, 3);
  EXPECT_NE(problemOf(r).find("entry 3 was edited"), std::string::npos) << problemOf(r);
  EXPECT_EQ(r.brokenLinks, 6);  // the moved entries' ids are in their hashes
  EXPECT_NE(r.problem, QString());
}

// The limit of an unkeyed chain: whoever recomputes every hash from an entry on, or deletes the
// newest entries, leaves no broken link. An anchor kept elsewhere shows both.
TEST_P(AuditChain, ARewrittenOrCutTailShowsOnlyAgainstAKeptAnchor) {
  Fixture f(GetParam());
  someActivity(f);
  const AuditAnchor kept = *verifyAuditChain(*f.db).newest;
  ASSERT_EQ(kept.id, 7);
  dropAuditTriggers(f);

  // Rewritten from entry 4 on, every later hash recomputed.
  QString prev = entry(f, 3).hash;
  for (qint64 id = 4; id <= 7; ++id) {
    ChainedAuditEntry e = entry(f, id);
    if (id == 4) e.detail = "nothing to see";
    e.prevHash = prev;
    e.hash = auditEntryHash(e);
    prev = e.hash;
    rawSql(f.path, {"UPDATE audit_log SET detail = '" + e.detail + "', prev_hash = '" + e.prevHash +
                    "', hash = '" + e.hash + "' WHERE id = " + QString::number(id)});
  }
  AuditChainReport r = verifyAuditChain(*f.db);
  EXPECT_EQ(r.brokenAt, 0);  // no broken link: the limit, stated in docs/storage.md
  r = verifyAuditChain(*f.db, kept);
  EXPECT_FALSE(r.intact());
  EXPECT_NE(r.anchorProblem.toStdString().find("entry 7 has hash " + prev.toStdString() +
                                               ", not the one kept"),
            std::string::npos)
      << r.anchorProblem.toStdString();

  // Cut off: the newest two deleted.
  Fixture g(GetParam());
  someActivity(g);
  const AuditAnchor keptG = *verifyAuditChain(*g.db).newest;
  dropAuditTriggers(g);
  rawSql(g.path, {"DELETE FROM audit_log WHERE id >= 6"});
  EXPECT_EQ(verifyAuditChain(*g.db).brokenAt, 0);
  r = verifyAuditChain(*g.db, keptG);
  EXPECT_NE(r.anchorProblem.toStdString().find("entry 7 is gone: the log now ends at entry 5"),
            std::string::npos)
      << r.anchorProblem.toStdString();
}

// Two connections (two workstations, or the recorder beside the GUI) appending at the same time,
// alone and inside transactions of other work: one chain, every entry in it.
TEST_P(AuditChain, TwoWritersAtOnceMakeOneChain) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  constexpr int kEach = 60;
  std::latch start(2);
  std::atomic<int> failures{0};
  std::string firstError;
  std::mutex errorMutex;
  const auto writer = [&](const QString& name) {
    try {
      Database db(DatabaseUrl::parse(f.path), {});
      start.arrive_and_wait();
      for (int i = 0; i < kEach; ++i) {
        if (i % 3 == 0) {
          db.transaction([&] {
            db.exec("UPDATE patients SET notes = ? WHERE code = 'P1'", {name});
            appendAudit(db, {name, "update", "patient", "P1", QString::number(i)});
          });
        } else {
          appendAudit(db, {name, "view", "session", QString::number(i), {}});
        }
      }
    } catch (const std::exception& e) {
      ++failures;
      const std::lock_guard lock(errorMutex);
      if (firstError.empty()) firstError = e.what();
    }
  };
  std::thread a(writer, QString("writer-a")), b(writer, QString("writer-b"));
  a.join();
  b.join();
  EXPECT_EQ(failures.load(), 0) << firstError;
  const AuditChainReport r = verifyAuditChain(*f.db);
  EXPECT_TRUE(r.intact()) << problemOf(r);
  EXPECT_EQ(r.entries, 2 + 2 * kEach);
  for (const char* name : {"writer-a", "writer-b"})
    EXPECT_EQ(rawQuery(f.path, QString("SELECT count(*) FROM audit_log WHERE user_name = '") +
                                   name + "'")[0][0]
                  .toInt(),
              kEach);
}

// Entries written before the chain existed are chained by the migration, in id order, and the
// table is append-only afterwards. More than one batch of rows (1,000) is chained.
TEST_P(AuditChain, MigrationChainsTheEntriesAlreadyThere) {
  QTemporaryDir dir;
  const QString path = newDatabase(GetParam(), dir, "v1audit");
  rawSql(path, version1Schema(GetParam()));
  constexpr int kOld = 2500;
  QStringList values;
  for (int i = 1; i <= kOld; ++i)
    values << QString("('2025-01-02T10:%1:00.000Z', 'admin', 'view', 'session', '%2', '')")
                  .arg(i % 60, 2, 10, QChar('0'))
                  .arg(i);
  rawSql(path, {"INSERT INTO audit_log (at, user_name, action, object_type, object_id, detail) "
                "VALUES " +
                values.join(", ")});
  Database db(DatabaseUrl::parse(path), {false, true});
  AuditChainReport r = verifyAuditChain(db);
  EXPECT_TRUE(r.intact()) << r.problem.toStdString();
  EXPECT_EQ(r.entries, kOld);
  ClinicalStore store(db);
  store.signIn("admin", kAdminPassword);
  store.addPatient(makePatient("NEW1"));
  r = verifyAuditChain(db);
  EXPECT_TRUE(r.intact()) << r.problem.toStdString();
  EXPECT_EQ(r.newest->id, kOld + 1);
  expectError([&] { db.exec("DELETE FROM audit_log WHERE id = 1"); }, Kind::Io, "append-only");
}

INSTANTIATE_TEST_SUITE_P(Engines, AuditChain, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
