// armtrack-cli session reestimate of several sessions in parallel, on SQLite and PostgreSQL: every
// good session is re-estimated as its first analysis was, a damaged one is reported by name and
// chunk without stopping the others, and the exit status says that one failed.
#include <gtest/gtest.h>

#include <QString>
#include <string>
#include <vector>

#include "tests/app/StorageCliFixture.h"

namespace {

using armtrack::test::Engine;
using armtrack::test::Result;
using armtrack::test::StorageCli;

class ReestimateBatch : public StorageCli {
 protected:
  // The estimate blobs of a session, by version.
  std::vector<QByteArray> blobs(const std::string& id) {
    std::vector<QByteArray> out;
    for (const QVariantList& row :
         query(QString("SELECT data FROM estimates WHERE session_id = %1 ORDER BY version")
                   .arg(QString::fromStdString(id))))
      out.push_back(row[0].toByteArray());
    return out;
  }
  // The summary table's line for a session ("" when there is none).
  static std::string tableLine(const std::string& table, const std::string& id) {
    const std::string start = "\n| " + id + " | ";
    const std::size_t at = table.find(start);
    if (at == std::string::npos) return "";
    return table.substr(at + 1, table.find('\n', at + 1) - at - 1);
  }
};

// Three sessions of one patient, the middle one with a truncated chunk, on two threads: the other
// two get a version 2 identical to version 1 (the same settings, made at import on one thread),
// the damaged one keeps its single version and is named with its chunk in the table and on
// standard error, and the exit status is 1.
TEST_P(ReestimateBatch, OneDamagedSessionIsReportedAndTheOthersAreDone) {
  addPatients();
  std::vector<std::string> ids;
  for (int i = 0; i < 3; ++i) {
    const std::string name = "rec" + std::to_string(i) + ".csv";
    ids.push_back(importFor("P01", simulate(name.c_str(), 3.0 + i)));
  }
  for (const std::string& id : ids) ASSERT_EQ(blobs(id).size(), 1u) << id;
  sql({QString("UPDATE recording_chunks SET data = substr(data, 1, 20) WHERE session_id = %1 AND "
               "seq = 1")
           .arg(QString::fromStdString(ids[1]))});

  const Result r = run({"session", "reestimate", ids[0], ids[1], ids[2], "--jobs", "2"});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("| session | patient | rows | estimates |"), std::string::npos) << r.out;
  for (const std::size_t good : {0u, 2u}) {
    const std::string line = tableLine(r.out, ids[good]);
    EXPECT_NE(line.find("| P01 |"), std::string::npos) << r.out;
    EXPECT_NE(line.find("| 2 | ok |"), std::string::npos) << r.out;
    const std::vector<QByteArray> b = blobs(ids[good]);
    ASSERT_EQ(b.size(), 2u) << ids[good];
    EXPECT_EQ(b[1], b[0]) << "session " << ids[good] << " was estimated differently in parallel";
  }
  const std::string bad = tableLine(r.out, ids[1]);
  EXPECT_NE(bad.find("failed: session " + ids[1] + ", chunk 1"), std::string::npos) << r.out;
  EXPECT_EQ(blobs(ids[1]).size(), 1u);
  EXPECT_NE(r.err.find("session " + ids[1] + ": failed: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2 of 3 sessions re-estimated, 1 failed"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("on 2 threads"), std::string::npos) << r.err;
}

// --patient takes every finished session of that patient and no other; overrides become each
// session's filter settings, as for one session.
TEST_P(ReestimateBatch, PatientTakesItsSessionsAndOverridesBecomeTheirSettings) {
  addPatients();
  const std::string a = importFor("P01", simulate("a.csv", 2.0));
  const std::string b = importFor("P02", simulate("b.csv", 2.5));
  const std::string c = importFor("P02", simulate("c.csv", 3.0));
  const Result r = run({"session", "reestimate", "--patient", "P02", "--filter", "ukf"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(tableLine(r.out, a), "") << r.out;
  for (const std::string& id : {b, c}) {
    EXPECT_NE(tableLine(r.out, id).find("| 2 | ok |"), std::string::npos) << r.out;
    const auto settings =
        query(QString("SELECT filter_json FROM sessions WHERE id = %1").arg(id.c_str()));
    ASSERT_EQ(settings.size(), 1u);
    EXPECT_NE(settings[0][0].toString().indexOf("\"filter\":\"ukf\""), -1)
        << settings[0][0].toString().toStdString();
  }
  EXPECT_EQ(blobs(a).size(), 1u);
  EXPECT_NE(r.err.find("2 of 2 sessions re-estimated, 0 failed"), std::string::npos) << r.err;

  // A session that does not exist is one failure among the others.
  const Result missing = run({"session", "reestimate", a, "999", "--jobs", "3"});
  EXPECT_EQ(missing.code, 1) << missing.err;
  EXPECT_NE(tableLine(missing.out, a).find("| ok |"), std::string::npos) << missing.out;
  EXPECT_NE(tableLine(missing.out, "999").find("failed: "), std::string::npos) << missing.out;

  EXPECT_EQ(run({"session", "reestimate", a, "--patient", "P01"}).code, 2);
  EXPECT_EQ(run({"session", "reestimate", a, b, "--jobs", "0"}).code, 2);
  EXPECT_EQ(run({"session", "reestimate", a, "x"}).code, 2);
}

INSTANTIATE_TEST_SUITE_P(Engines, ReestimateBatch,
                         testing::Values(Engine::Sqlite, Engine::Postgres),
                         armtrack::test::engineName);

}  // namespace
