// The trunk limit of protocols and home exercises (issue 26; docs/storage.md, "Protocols" and
// "Home programmes"), on both engines: stored and read back, off by default, an exercise's own or
// its protocol's, refused out of range saying what to give, named in the audit log, and added to
// a version 7 database by the migration without touching what was there.
#include <gtest/gtest.h>

#include <limits>

#include "tests/core/storage/StorageTestSupport.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;

namespace {

using TrunkLimit = Engines;
using MigrationToTrunkLimit = Engines;

std::vector<AuditEntry> entriesFor(ClinicalStore& store, const QString& type, const QString& id) {
  std::vector<AuditEntry> out;
  for (const AuditEntry& e : store.auditLog())
    if (e.objectType == type && e.objectId == id) out.push_back(e);
  return out;
}

}  // namespace

TEST_P(TrunkLimit, AProtocolsLimitIsStoredOffByDefaultAndAudited) {
  Fixture f(GetParam());
  f.store->addProtocol(makeProtocol("plain", "shoulder_flexion", 0, 120, 10));
  Protocol reach = makeProtocol("reach", "shoulder_flexion", 0, 120, 10);
  reach.trunkLimitDeg = 12.5;
  f.store->addProtocol(reach);
  EXPECT_FALSE(f.store->protocol("plain").trunkLimitDeg.has_value());
  EXPECT_EQ(f.store->protocol("reach").trunkLimitDeg, 12.5);
  for (const Protocol& p : f.store->listProtocols())
    EXPECT_EQ(p.trunkLimitDeg, p.name == "reach" ? std::optional(12.5) : std::nullopt)
        << p.name.toStdString();

  // Off, then on again; the audit log names each change of the limit, not other edits.
  reach = f.store->protocol("reach");
  reach.trunkLimitDeg.reset();
  f.store->updateProtocol(reach);
  EXPECT_FALSE(f.store->protocol("reach").trunkLimitDeg.has_value());
  reach.repetitions = 12;
  f.store->updateProtocol(reach);
  reach.trunkLimitDeg = 20;
  f.store->updateProtocol(reach);
  EXPECT_EQ(f.store->protocol("reach").trunkLimitDeg, 20.0);
  const std::vector<AuditEntry> log = entriesFor(*f.store, "protocol", "reach");
  ASSERT_EQ(log.size(), 4u);
  EXPECT_EQ(log[0].action, "create");
  EXPECT_EQ(log[0].detail, "trunk limit 12.5 deg");
  EXPECT_EQ(log[1].detail, "trunk limit off");
  EXPECT_EQ(log[2].action, "update");
  EXPECT_EQ(log[2].detail, "");
  EXPECT_EQ(log[3].detail, "trunk limit 20 deg");
}

TEST_P(TrunkLimit, AnExerciseTakesItsOwnLimitElseItsProtocols) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("MINE"));
  Protocol reach = makeProtocol("reach", "shoulder_flexion", 0, 120, 10);
  reach.trunkLimitDeg = 15;
  f.store->addProtocol(reach);
  f.store->addProtocol(makeProtocol("plain", "elbow_flexion", 0, 120, 10));
  ProgrammeItem own;
  own.protocolName = "reach";
  own.trunkLimitDeg = 8;
  f.store->setProgrammeExercise("MINE", own);
  ProgrammeItem inherits;
  inherits.protocolName = "plain";
  f.store->setProgrammeExercise("MINE", inherits);
  const std::vector<ProgrammeItem> p = f.store->programme("MINE");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].trunkLimitDeg, 8.0);
  EXPECT_EQ(effectiveTrunkLimit(p[0], f.store->protocol("reach")), 8.0);
  EXPECT_FALSE(p[1].trunkLimitDeg.has_value());
  EXPECT_FALSE(effectiveTrunkLimit(p[1], f.store->protocol("plain")).has_value());
  // Without its own, the exercise follows its protocol's, now and when the protocol changes.
  own.trunkLimitDeg.reset();
  f.store->setProgrammeExercise("MINE", own);
  EXPECT_EQ(effectiveTrunkLimit(f.store->programme("MINE")[0], f.store->protocol("reach")), 15.0);
  const std::vector<AuditEntry> log = entriesFor(*f.store, "programme", "MINE");
  ASSERT_EQ(log.size(), 3u);
  EXPECT_EQ(log[0].detail, "set reach, trunk limit 8 deg");
  EXPECT_EQ(log[2].detail, "set reach");
}

TEST_P(TrunkLimit, LimitsOutOfRangeAreRefusedSayingWhatToGive) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("MINE"));
  f.store->addProtocol(makeProtocol("reach", "shoulder_flexion", 0, 120, 10));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {0.0, 0.5, -15.0, 90.5, 1e300, nan, inf, -inf}) {
    Protocol p = makeProtocol("other", "shoulder_flexion", 0, 120, 10);
    p.trunkLimitDeg = bad;
    expectError([&] { f.store->addProtocol(p); }, Kind::Usage, "trunk limit must be 1-90 deg");
    Protocol reach = f.store->protocol("reach");
    reach.trunkLimitDeg = bad;
    expectError([&] { f.store->updateProtocol(reach); }, Kind::Usage, "or off");
    ProgrammeItem item;
    item.protocolName = "reach";
    item.trunkLimitDeg = bad;
    expectError([&] { f.store->setProgrammeExercise("MINE", item); }, Kind::Usage,
                "trunk limit must be 1-90 deg");
  }
  // Nothing was stored by the refusals; the ends of the range are taken.
  EXPECT_EQ(f.store->listProtocols().size(), 1u);
  EXPECT_FALSE(f.store->protocol("reach").trunkLimitDeg.has_value());
  EXPECT_TRUE(f.store->programme("MINE").empty());
  Protocol reach = f.store->protocol("reach");
  for (double good : {1.0, 90.0}) {
    reach.trunkLimitDeg = good;
    f.store->updateProtocol(reach);
    EXPECT_EQ(f.store->protocol("reach").trunkLimitDeg, good);
  }
  // The database refuses them too, whoever writes.
  ProgrammeItem item;
  item.protocolName = "reach";
  f.store->setProgrammeExercise("MINE", item);
  expectError([&] { f.db->exec("UPDATE protocols SET trunk_limit_deg = 0"); }, Kind::Io);
  expectError([&] { f.db->exec("UPDATE programmes SET trunk_limit_deg = 91"); }, Kind::Io);
}

// A version 7 database (the latest before the limit) with protocols and a programme: made by
// taking the columns away again and setting the version back.
TEST_P(MigrationToTrunkLimit, FromVersion7KeepsEverythingWithTheLimitOff) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("OLD"));
  f.store->addProtocol(makeProtocol("reach", "shoulder_flexion", 10, 110, 9));
  ProgrammeItem item;
  item.protocolName = "reach";
  item.sets = 2;
  f.store->setProgrammeExercise("OLD", item);
  f.close();
  // Version 9's tables (home devices, docs/sync.md) first, then version 8's columns.
  rawSql(f.path, {"DROP TABLE sync_upload_chunks", "DROP TABLE sync_uploads", "DROP TABLE devices",
                  "DROP TABLE enrolment_codes"});
  rawSql(f.path, {"ALTER TABLE protocols DROP COLUMN trunk_limit_deg",
                  "ALTER TABLE programmes DROP COLUMN trunk_limit_deg",
                  "UPDATE schema_version SET version = 7"});

  expectError([&] { Database db(DatabaseUrl::parse(f.path), {}); }, Kind::OlderSchema);
  Database db(DatabaseUrl::parse(f.path), {false, true});
  EXPECT_EQ(db.migrationsApplied(), latestSchemaVersion() - 7);
  ClinicalStore store(db);
  store.signIn("admin", kAdminPassword);
  Protocol p = store.protocol("reach");
  EXPECT_EQ(p.repetitions, 9);
  EXPECT_FALSE(p.trunkLimitDeg.has_value());
  const std::vector<ProgrammeItem> items = store.programme("OLD");
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items[0].sets, 2);
  EXPECT_FALSE(items[0].trunkLimitDeg.has_value());
  p.trunkLimitDeg = 10;
  store.updateProtocol(p);
  EXPECT_EQ(store.protocol("reach").trunkLimitDeg, 10.0);
  // The migrated columns check their values too.
  expectError([&] { db.exec("UPDATE protocols SET trunk_limit_deg = 95"); }, Kind::Io);
  expectError([&] { db.exec("UPDATE programmes SET trunk_limit_deg = 0"); }, Kind::Io);
}

INSTANTIATE_TEST_SUITE_P(Engines, TrunkLimit, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
INSTANTIATE_TEST_SUITE_P(Engines, MigrationToTrunkLimit,
                         testing::Values(Engine::Sqlite, Engine::Postgres), engineName);
