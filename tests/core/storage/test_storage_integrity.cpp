// The records' own checks, tried as a forger and a broken disk would try them: the audit log's
// hash chain and append-only triggers, and the checks of stored recordings and estimates that
// db check and the exports run (docs/storage.md, "Audit log" and "Checks"). On both engines.
#include <gtest/gtest.h>

#include <unistd.h>

#include <QSqlQuery>
#include <QSysInfo>
#include <atomic>
#include <latch>
#include <set>
#include <thread>

#include "core/storage/AuditLog.h"
#include "core/storage/RecordsCheck.h"
#include "tests/core/storage/StorageTestSupport.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;

namespace {

using AuditChain = Engines;
using RecordsCheck = Engines;

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

namespace {

// A session of 3 s at 200 Hz (at least 3 chunks) for patient P1.
qint64 importSession(Fixture& f, const char* name) {
  simulateTo(f.file(name), 3.0, 200.0);
  return f.store->importRecording(f.file(name), "P1");
}

void flipByteOfChunk(Fixture& f, qint64 session, int seq) {
  QSqlQuery q = f.db->exec("SELECT data FROM recording_chunks WHERE session_id = ? AND seq = ?",
                           {session, seq});
  ASSERT_TRUE(q.next());
  QByteArray data = q.value(0).toByteArray();
  q.finish();
  data[data.size() - 3] = static_cast<char>(data[data.size() - 3] ^ 0x10);
  f.db->exec("UPDATE recording_chunks SET data = ? WHERE session_id = ? AND seq = ?",
             {data, session, seq});
}

std::string joined(const QStringList& problems) {
  return problems.join(" | ").toStdString();
}

}  // namespace

TEST_P(RecordsCheck, NamesEveryDamagedSessionAndWhatIsWrong) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const qint64 flipped = importSession(f, "a.csv");
  const qint64 hole = importSession(f, "b.csv");
  const qint64 tail = importSession(f, "c.csv");
  const qint64 codec = importSession(f, "d.csv");
  const qint64 fine = importSession(f, "e.csv");
  ASSERT_GE(f.store->session(tail).chunks, 3);
  flipByteOfChunk(f, flipped, 1);
  f.db->exec("DELETE FROM recording_chunks WHERE session_id = ? AND seq = 1", {hole});
  f.db->exec("DELETE FROM recording_chunks WHERE session_id = ? AND seq = ?",
             {tail, f.store->session(tail).chunks - 1});
  f.db->exec("UPDATE recording_chunks SET codec = 'atc9-zstd' WHERE session_id = ? AND seq = 0",
             {codec});

  const RecordsCheckReport r = f.store->checkRecords();
  EXPECT_EQ(r.sessionsChecked, 5);
  ASSERT_EQ(r.damaged.size(), 4u);
  std::map<qint64, std::string> found;
  for (const SessionDamage& d : r.damaged) found[d.sessionId] = joined(d.problems);
  EXPECT_EQ(found.count(fine), 0u);
  EXPECT_NE(found[flipped].find("chunk 1: checksum mismatch"), std::string::npos) << found[flipped];
  EXPECT_NE(found[hole].find("chunk 1 is missing"), std::string::npos) << found[hole];
  EXPECT_NE(found[tail].find("(chunks at the end are missing)"), std::string::npos) << found[tail];
  EXPECT_NE(found[codec].find("chunk 0: unknown codec 'atc9-zstd'"), std::string::npos)
      << found[codec];

  // The lighter check exports make finds the same damage without decoding.
  for (const qint64 id : {flipped, hole, tail, codec})
    EXPECT_FALSE(recordingProblems(*f.db, id, RecordingDepth::Checksums).isEmpty()) << id;
  EXPECT_TRUE(recordingProblems(*f.db, fine, RecordingDepth::Checksums).isEmpty());
  EXPECT_TRUE(recordingProblems(*f.db, fine, RecordingDepth::Decode).isEmpty());
}

// What only decoding sees: a chunk whose rows are not the index's, or whose times are not.
TEST_P(RecordsCheck, DecodingFindsWhatTheIndexHides) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const qint64 id = importSession(f, "a.csv");
  f.db->exec("UPDATE recording_chunks SET t_last = t_last - 0.001 WHERE session_id = ? AND seq = 0",
             {id});
  const QStringList problems = recordingProblems(*f.db, id, RecordingDepth::Decode);
  ASSERT_EQ(problems.size(), 1) << joined(problems);
  EXPECT_NE(problems[0].toStdString().find("chunk 0: its times"), std::string::npos)
      << joined(problems);
  EXPECT_NE(problems[0].toStdString().find("are not the index's"), std::string::npos);
}

// A session a live process is writing is not called damaged (it is listed as being recorded);
// once its writer is gone it is marked interrupted and checked like any other.
TEST_P(RecordsCheck, ASessionBeingRecordedIsLeftAlone) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const qint64 id = importSession(f, "a.csv");
  f.db->exec("DELETE FROM recording_chunks WHERE session_id = ? AND seq = 1", {id});
  // As a live recording (an import whose writer died is removed, not checked).
  f.db->exec(
      "UPDATE sessions SET status = 'recording', origin = 'live', recorder_host = ?, "
      "recorder_pid = ? WHERE id = ?",
      {QSysInfo::machineHostName(), static_cast<qint64>(::getpid()), id});
  RecordsCheckReport r = f.store->checkRecords();
  EXPECT_TRUE(r.damaged.empty());
  EXPECT_EQ(r.beingRecorded, std::vector<qint64>{id});
  EXPECT_EQ(r.sessionsChecked, 0);

  // The writer died (a process id that is not running): interrupted on the next open, checked.
  pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ASSERT_GT(dead, 0);
  int status = 0;
  ::waitpid(dead, &status, 0);
  f.db->exec("UPDATE sessions SET recorder_pid = ? WHERE id = ?", {static_cast<qint64>(dead), id});
  f.close();
  Database db(DatabaseUrl::parse(f.path), {});
  ClinicalStore store(db);
  EXPECT_EQ(store.interruptedOnOpen(), 1);
  store.signIn("admin", kAdminPassword);
  r = store.checkRecords();
  ASSERT_EQ(r.damaged.size(), 1u);
  EXPECT_EQ(r.damaged[0].sessionId, id);
  EXPECT_TRUE(r.beingRecorded.empty());
}

// An export while the recorder appends chunks on another connection is not refused: the check
// reads the row count and the chunk index in one statement.
TEST_P(RecordsCheck, ARecordingBeingWrittenPassesTheExportCheck) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const Recording rec = simulateTo(f.file("rec.csv"), 20.0, 200.0);
  const qint64 id = f.store->beginRecording("P1", "", rec.meta, RecordingColumns{});
  std::atomic<bool> done{false};
  std::string error;
  std::thread recorder([&] {
    try {
      Database db(DatabaseUrl::parse(f.path), {});
      ClinicalStore store(db);
      store.signIn("admin", kAdminPassword);
      const std::span<const ArmSample> all(rec.samples);
      for (std::size_t i = 0; i + 200 <= all.size(); i += 200)
        store.appendChunk(id, all.subspan(i, 200));
    } catch (const std::exception& e) {
      error = e.what();
    }
    done = true;
  });
  int checks = 0;
  while (!done) {
    EXPECT_NO_THROW(f.store->requireIntactRecording(id));
    ++checks;
  }
  recorder.join();
  EXPECT_EQ(error, "");
  EXPECT_GT(checks, 0);
  EXPECT_EQ(f.store->session(id).sampleRows, static_cast<qint64>(rec.samples.size() / 200 * 200));
  EXPECT_NO_THROW(f.store->requireIntactRecording(id));
}

// Estimates stored in chunks (estimate_chunks): each complete version's chunks in sequence, their
// rows adding up to the row count its parameters give. A version still being written, and one
// stored whole before estimate_chunks, are not judged so.
TEST_P(RecordsCheck, EstimateChunksInSequenceAndAddingUp) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const qint64 id = importSession(f, "a.csv");
  const auto version = [&](int v, int complete, const QString& params, const QByteArray& data) {
    return f.db->insert(
        "INSERT INTO estimates (session_id, version, created_at, params_json, codec, data, "
        "complete) VALUES (?, ?, '2026-01-01T00:00:00.000Z', ?, 'est-f64-zstd-v1', ?, ?)",
        {id, v, params, data, complete});
  };
  const auto chunk = [&](qint64 estimate, int seq, int rows) {
    f.db->exec(
        "INSERT INTO estimate_chunks (estimate_id, seq, row_count, data) VALUES (?, ?, ?, ?)",
        {estimate, seq, rows, QByteArray("x")});
  };
  const QByteArray none("");  // not null: an empty blob
  const qint64 good = version(11, 1, R"({"rows": 300})", none);
  for (int seq = 0; seq < 3; ++seq) chunk(good, seq, 100);
  EXPECT_TRUE(estimateProblems(*f.db, id).isEmpty()) << joined(estimateProblems(*f.db, id));

  const qint64 holed = version(12, 1, R"({"rows": 300})", none);
  chunk(holed, 0, 100);
  chunk(holed, 2, 100);
  const qint64 writing = version(13, 0, R"({"rows": 300})", none);
  chunk(writing, 1, 5);
  version(14, 1, R"({"rows": 300})", QByteArray("a whole blob"));  // before estimate_chunks
  version(15, 1, R"({"rows": 300})", none);                        // nothing at all
  const QStringList problems = estimateProblems(*f.db, id);
  ASSERT_EQ(problems.size(), 3) << joined(problems);
  EXPECT_EQ(problems[0], "estimates version 12: chunk 1 is missing");
  EXPECT_EQ(problems[1], "estimates version 12: its chunks hold 200 rows, its parameters say 300");
  EXPECT_EQ(problems[2], "estimates version 15: it has neither chunks nor data");
  const RecordsCheckReport r = f.store->checkRecords();
  ASSERT_EQ(r.damaged.size(), 1u);
  EXPECT_EQ(r.damaged[0].problems.size(), 3);
}

// Exports and reports refuse a damaged recording before writing anything, saying which session,
// how, and what to do; so does reading it.
TEST_P(RecordsCheck, ADamagedRecordingIsRefusedSayingWhatToDo) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const qint64 id = importSession(f, "a.csv");
  f.store->requireIntactRecording(id);
  flipByteOfChunk(f, id, 1);
  const std::string session = "session " + std::to_string(id);
  for (const auto& refused : std::vector<std::function<void()>>{
           [&] { f.store->requireIntactRecording(id); }, [&] { f.store->readRecording(id); }}) {
    const StorageError e = expectError(refused, Kind::Corrupt, session + ", chunk 1: checksum");
    const std::string what = e.what();
    EXPECT_NE(what.find("The recording of " + session + " is damaged: restore a backup"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("db check"), std::string::npos) << what;
  }
  f.db->exec("DELETE FROM recording_chunks WHERE session_id = ? AND seq = 1", {id});
  expectError([&] { f.store->requireIntactRecording(id); }, Kind::Corrupt,
              session + ", chunk 1 is missing");
}

INSTANTIATE_TEST_SUITE_P(Engines, RecordsCheck, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
