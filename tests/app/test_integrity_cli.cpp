// Hostile tests of what `db check`, `audit --verify` and the exports say about records changed
// behind ArmTrack's back, on SQLite and PostgreSQL: an audit log forged three ways (an entry
// edited, deleted, inserted back-dated) through plain SQL, a tail cut off, recordings with a
// flipped bit or a missing chunk (docs/storage.md, "Audit log" and "Checks"; docs/cli.md).
#include <gtest/gtest.h>

#include <unistd.h>

#include <QProcess>
#include <QSysInfo>
#include <filesystem>
#include <functional>
#include <regex>

#include "core/storage/Database.h"
#include "tests/app/StorageCliFixture.h"

namespace fs = std::filesystem;
using armtrack::test::Engine;
using armtrack::test::Result;
namespace storage = armtrack::storage;

namespace {

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The real executable (tests/app/CliRun.h).
Result runProcess(const QStringList& args) {
  return armtrack::test::cliProcess(QStringLiteral(ARMTRACK_CLI), args);
}

class IntegrityCli : public armtrack::test::StorageCli {
 protected:
  // What a forger holding the file (SQLite) or the database role (PostgreSQL) does first.
  void dropAuditTriggers() {
    if (m_engine == Engine::Sqlite)
      sql({"DROP TRIGGER audit_log_no_update", "DROP TRIGGER audit_log_no_delete"});
    else
      sql({"DROP TRIGGER audit_log_no_change ON audit_log",
           "DROP TRIGGER audit_log_no_truncate ON audit_log"});
  }
  // Work on the database with bound values (bytes), outside the CLI.
  void withDatabase(const std::function<void(storage::Database&)>& work) {
    storage::Database db(storage::DatabaseUrl::parse(QString::fromStdString(m_db)), {});
    work(db);
  }
  void flipByteOfChunk(const std::string& session, int seq) {
    withDatabase([&](storage::Database& db) {
      QSqlQuery q = db.exec("SELECT data FROM recording_chunks WHERE session_id = ? AND seq = ?",
                            {std::stoll(session), seq});
      ASSERT_TRUE(q.next());
      QByteArray data = q.value(0).toByteArray();
      q.finish();
      data[data.size() / 2] = static_cast<char>(data[data.size() / 2] ^ 0x04);
      db.exec("UPDATE recording_chunks SET data = ? WHERE session_id = ? AND seq = ?",
              {data, std::stoll(session), seq});
    });
  }
  qint64 newestAuditId() { return query("SELECT max(id) FROM audit_log")[0][0].toLongLong(); }
};

}  // namespace

// Acceptance 2 of issue 24: the audit log forged through plain SQL, as someone holding the file
// or the database role could (the append-only triggers dropped first), three ways. Each time
// db check fails naming the entry; put back as it was, it passes again.
TEST_P(IntegrityCli, ForgedAuditLogFailsDbCheckNamingTheEntry) {
  addPatients();
  ASSERT_EQ(run({"protocol", "add", "--name", "reach", "--angle", "shoulder_flexion",
                 "--target-min", "0", "--target-max", "120", "--reps", "8"})
                .code,
            0);
  Result check = run({"db", "check"});
  ASSERT_EQ(check.code, 0) << check.err;
  EXPECT_TRUE(has(check.out, "audit log: 4 entries, hash chain intact")) << check.out;
  dropAuditTriggers();
  // The forger's first step is told already (the links all fit still).
  check = run({"db", "check"});
  EXPECT_EQ(check.code, 1);
  EXPECT_TRUE(has(check.out, "audit log: the triggers that keep it append-only are missing"))
      << check.out;
  EXPECT_FALSE(has(check.out, "audit log: entry")) << check.out;

  // 1. Edited: who added patient P02.
  sql({"UPDATE audit_log SET user_name = 'someone-else' WHERE id = 3"});
  EXPECT_TRUE(has(run({"audit"}).out, "someone-else"));  // the forged row is shown as stored...
  check = run({"db", "check"});
  EXPECT_EQ(check.code, 1);
  EXPECT_TRUE(has(check.out, "audit log: entry 3 was edited")) << check.out;
  EXPECT_TRUE(has(check.err, "the audit log was changed outside ArmTrack (first at entry 3)"))
      << check.err;  // ...and db check says it is not what was written
  sql({"UPDATE audit_log SET user_name = 'boss' WHERE id = 3"});
  ASSERT_FALSE(has(run({"db", "check"}).out, "audit log: entry"));  // as written again

  // 2. Deleted: the entry of patient P02's creation.
  const QVariantList row = query(
      "SELECT id, at, user_name, action, object_type, object_id, detail, prev_hash, hash "
      "FROM audit_log WHERE id = 3")[0];
  sql({"DELETE FROM audit_log WHERE id = 3"});
  check = run({"db", "check"});
  EXPECT_EQ(check.code, 1);
  EXPECT_TRUE(has(check.out, "audit log: entry 4 does not follow entry 2")) << check.out;
  EXPECT_TRUE(has(check.out, "entry 3 was deleted")) << check.out;
  QStringList values;
  for (const QVariant& v : row)
    values << (v.typeId() == QMetaType::QString ? "'" + v.toString() + "'" : v.toString());
  sql(
      {"INSERT INTO audit_log (id, at, user_name, action, object_type, object_id, detail, "
       "prev_hash, hash) VALUES (" +
       values.join(", ") + ")"});
  ASSERT_FALSE(has(run({"db", "check"}).out, "audit log: entry")) << run({"db", "check"}).out;

  // 3. Inserted, back-dated: a deletion nobody made, dated last year.
  const qint64 next = newestAuditId() + 1;
  sql({QString("INSERT INTO audit_log (id, at, user_name, action, object_type, object_id, "
               "detail) VALUES (%1, '2025-03-01T09:00:00.000Z', 'boss', 'delete', 'patient', "
               "'P07', '')")
           .arg(next)});
  check = run({"db", "check"});
  EXPECT_EQ(check.code, 1);
  EXPECT_TRUE(has(check.out, "audit log: entry " + std::to_string(next) + " was inserted"))
      << check.out;
  EXPECT_TRUE(has(check.err, "first at entry " + std::to_string(next))) << check.err;
}

// audit --verify prints the newest entry's id and hash to keep elsewhere; --expect gives it back
// and shows what no broken link can: the newest entries deleted. Administrators only.
TEST_P(IntegrityCli, AuditVerifyKeepsTheNewestAndExpectShowsACutTail) {
  addPatients();
  ::setenv("ARMTRACK_NEW_PASSWORD", "therapist-pass-1", 1);
  ASSERT_EQ(run({"user", "add", "kim", "--role", "therapist"}).code, 0);
  Result r = run({"audit", "--verify"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "audit log: 4 entries, hash chain intact")) << r.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex("(\\d+):([0-9a-f]{64})"))) << r.out;
  const std::string kept = m[0], keptId = m[1];  // m points into r.out, reused below
  EXPECT_EQ(keptId, std::to_string(newestAuditId()));

  r = run({"audit", "--verify", "--expect", kept});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "entry " + keptId + " still has the hash kept")) << r.out;
  EXPECT_EQ(run({"audit", "--verify", "--expect", "4:abc"}).code, 2);
  EXPECT_EQ(run({"audit", "--expect", kept}).code, 2);  // --expect goes with --verify
  r = run({"audit", "--verify"}, "kim", "therapist-pass-1");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "may not verify the audit log")) << r.err;

  // The newest entry deleted: every remaining link fits (only the dropped triggers are told);
  // the kept line shows it.
  dropAuditTriggers();
  sql({"DELETE FROM audit_log WHERE id >= " + QString::fromStdString(keptId)});
  r = run({"audit", "--verify"});
  EXPECT_TRUE(has(r.out, "hash chain intact")) << r.out;
  EXPECT_FALSE(has(r.err, "is gone")) << r.err;
  EXPECT_FALSE(has(run({"db", "check"}).out, "audit log: entry"));
  r = run({"audit", "--verify", "--expect", kept});
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "entry " + keptId + " is gone")) << r.err;
  EXPECT_TRUE(has(r.err, "the tail was cut off")) << r.err;
  r = run({"audit", "--verify", "--json", "--expect", kept});
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.out, "\"intact\": false")) << r.out;
}

// Item 9 of issue 24: db check names each damaged recording and what is wrong; every export and
// the report of such a session refuse, saying so, and write nothing. Intact sessions still pass.
TEST_P(IntegrityCli, DbCheckNamesDamagedRecordingsAndTheirExportsRefuse) {
  addPatients();
  const std::string csv = simulate("rec.csv", 3.0);
  const std::string flipped = importFor("P01", csv);
  const std::string holed = importFor("P01", csv);
  const std::string fine = importFor("P02", csv);
  ASSERT_EQ(run({"export", flipped, "--format", "csv", "--out", path("before.csv")}).code, 0);
  flipByteOfChunk(flipped, 1);
  sql({"DELETE FROM recording_chunks WHERE session_id = " + QString::fromStdString(holed) +
       " AND seq = 1"});

  const Result check = run({"db", "check"});
  EXPECT_EQ(check.code, 1);
  EXPECT_TRUE(has(check.out, "session " + flipped + ": damaged: chunk 1: checksum mismatch"))
      << check.out;
  EXPECT_TRUE(has(check.out, "session " + holed + ": damaged: chunk 1 is missing")) << check.out;
  EXPECT_FALSE(has(check.out, "session " + fine + ":")) << check.out;
  EXPECT_TRUE(has(check.err, "2 damaged session(s) (" + flipped + ", " + holed + ") of 3 checked"))
      << check.err;
  EXPECT_TRUE(has(check.err, "restore a backup")) << check.err;

  for (const std::string& id : {flipped, holed}) {
    for (const char* format : {"csv", "mot", "bids", "recording"}) {
      const std::string out = path((id + "." + format).c_str());
      const Result r = run({"export", id, "--format", format, "--out", out});
      EXPECT_EQ(r.code, 1) << format;
      EXPECT_TRUE(has(r.err, "The recording of session " + id + " is damaged: restore a backup"))
          << format << ": " << r.err;
      EXPECT_TRUE(has(r.err, "'armtrack-cli db check' lists every damaged session")) << r.err;
      EXPECT_FALSE(fs::exists(out)) << format;
    }
  }
  EXPECT_EQ(run({"export", fine, "--format", "csv", "--out", path("fine.csv")}).code, 0);

  const QStringList signIn{"--db", QString::fromStdString(m_db), "--user", "boss"};
  const std::string pdf = path("damaged.pdf");
  Result r = runProcess(
      QStringList{"report", QString::fromStdString(flipped), "--pdf", QString::fromStdString(pdf)} +
      signIn);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(has(r.err, "The recording of session " + flipped + " is damaged")) << r.err;
  EXPECT_FALSE(fs::exists(pdf));
}

// A session a live recorder is writing is not called damaged; db check says it was not checked.
TEST_P(IntegrityCli, DbCheckLeavesALiveRecordingAlone) {
  addPatients();
  const std::string id = importFor("P01", simulate("rec.csv", 3.0));
  sql({"DELETE FROM recording_chunks WHERE session_id = " + QString::fromStdString(id) +
       " AND seq = 1"});
  withDatabase([&](storage::Database& db) {
    db.exec(
        "UPDATE sessions SET status = 'recording', recorder_host = ?, recorder_pid = ? WHERE "
        "id = ?",
        {QSysInfo::machineHostName(), static_cast<qint64>(::getpid()), std::stoll(id)});
  });
  const Result check = run({"db", "check"});
  EXPECT_EQ(check.code, 0) << check.err;
  EXPECT_TRUE(has(check.out,
                  "recordings: 0 session(s) checked, none damaged; being recorded now, "
                  "not checked: " +
                      id))
      << check.out;
}

INSTANTIATE_TEST_SUITE_P(Engines, IntegrityCli, testing::Values(Engine::Sqlite, Engine::Postgres),
                         armtrack::test::engineName);
