// Home programmes (exercises in order, with sets, repetitions, target ranges and rest) and home
// sessions (marked home, the patient's pain score, comment and summary), on both engines, and the
// migration that added them (docs/storage.md, "Home programmes").
#include <gtest/gtest.h>

#include <QSqlQuery>
#include <cmath>
#include <limits>

#include "tests/core/storage/StorageTestSupport.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;

namespace {

using Programmes = Engines;
using HomeSessions = Engines;
using MigrationToHome = Engines;

ProgrammeItem exercise(const QString& protocol, int position = 0) {
  ProgrammeItem item;
  item.protocolName = protocol;
  item.position = position;
  return item;
}

QStringList names(const std::vector<ProgrammeItem>& items) {
  QStringList out;
  for (const ProgrammeItem& i : items) out << i.protocolName;
  return out;
}

/// A patient with three protocols and a home account "home" (password "h-pass-long").
void fill(Fixture& f) {
  f.store->addPatient(makePatient("MINE"));
  f.store->addPatient(makePatient("OTHER"));
  f.store->addProtocol(makeProtocol("elbow", "elbow_flexion", 30, 130, 12));
  f.store->addProtocol(makeProtocol("flexion", "shoulder_flexion", 20, 120, 10));
  f.store->addProtocol(makeProtocol("pronation", "forearm_pronation", -40, 60, 8));
  f.store->addUser("home", Role::Home, "h-pass-long", "MINE");
}

}  // namespace

TEST_P(Programmes, ExercisesKeepTheirOrderAndValues) {
  Fixture f(GetParam());
  fill(f);
  ProgrammeItem elbow = exercise("elbow");
  elbow.sets = 3;
  elbow.repetitions = 8;
  elbow.targetMinDeg = 20.5;
  elbow.targetMaxDeg = 140.25;
  elbow.restS = 45;
  elbow.sessionsPerWeek = 5;
  elbow.notes = "slowly, it's \"fine\" to stop; ?";
  f.store->setProgrammeExercise("MINE", elbow);
  f.store->setProgrammeExercise("MINE", exercise("flexion"));
  // At the front: the others move down.
  f.store->setProgrammeExercise("MINE", exercise("pronation", 1));
  std::vector<ProgrammeItem> p = f.store->programme("MINE");
  ASSERT_EQ(names(p), (QStringList{"pronation", "elbow", "flexion"}));
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(p[i].position, static_cast<int>(i + 1));
  EXPECT_EQ(p[1].sets, 3);
  EXPECT_EQ(p[1].repetitions, 8);
  EXPECT_EQ(p[1].targetMinDeg, 20.5);
  EXPECT_EQ(p[1].targetMaxDeg, 140.25);
  EXPECT_EQ(p[1].restS, 45);
  EXPECT_EQ(p[1].sessionsPerWeek, 5);
  EXPECT_EQ(p[1].notes, elbow.notes);
  // Defaults: one set, the protocol's repetitions and target, a minute's rest.
  EXPECT_EQ(p[2].sets, 1);
  EXPECT_FALSE(p[2].repetitions.has_value());
  EXPECT_FALSE(p[2].targetMinDeg.has_value());
  EXPECT_EQ(p[2].restS, 60);

  // Replacing an exercise at another place moves it; removing one closes the gap.
  f.store->setProgrammeExercise("MINE", exercise("flexion", 1));
  EXPECT_EQ(names(f.store->programme("MINE")), (QStringList{"flexion", "pronation", "elbow"}));
  f.store->unassignProtocol("MINE", "pronation");
  p = f.store->programme("MINE");
  ASSERT_EQ(names(p), (QStringList{"flexion", "elbow"}));
  EXPECT_EQ(p[0].position, 1);
  EXPECT_EQ(p[1].position, 2);
  EXPECT_EQ(p[1].sets, 3);  // the others are untouched
  // A position past the end is the end.
  f.store->setProgrammeExercise("MINE", exercise("pronation", 9));
  p = f.store->programme("MINE");
  EXPECT_EQ(names(p), (QStringList{"flexion", "elbow", "pronation"}));
  EXPECT_EQ(p[2].position, 3);
  // assignProtocol (the older call) keeps the place and sets the defaults.
  f.store->assignProtocol("MINE", "elbow", 2, "twice");
  p = f.store->programme("MINE");
  ASSERT_EQ(names(p), (QStringList{"flexion", "elbow", "pronation"}));
  EXPECT_EQ(p[1].sessionsPerWeek, 2);
  EXPECT_EQ(p[1].sets, 1);
  // Another patient's programme is apart.
  EXPECT_TRUE(f.store->programme("OTHER").empty());
}

TEST_P(Programmes, BadValuesAreRefusedSayingWhich) {
  Fixture f(GetParam());
  fill(f);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto refused = [&](ProgrammeItem item, const std::string& says) {
    expectError([&] { f.store->setProgrammeExercise("MINE", item); }, Kind::Usage, says);
  };
  ProgrammeItem e = exercise("elbow");
  e.sets = 0;
  refused(e, "sets must be 1-20");
  e.sets = 21;
  refused(e, "sets must be 1-20");
  e = exercise("elbow");
  e.repetitions = 0;
  refused(e, "repetitions must be 1-200");
  e.repetitions = 100000;
  refused(e, "repetitions must be 1-200");
  e = exercise("elbow");
  e.targetMinDeg = 10;
  refused(e, "both ends");
  for (auto [lo, hi] : {std::pair{90.0, 90.0},
                        {100.0, 20.0},
                        {nan, 90.0},
                        {0.0, inf},
                        {-1000.0, 10.0},
                        {0.0, 1e38}}) {
    e.targetMinDeg = lo;
    e.targetMaxDeg = hi;
    refused(e, "min < max");
  }
  e = exercise("elbow");
  for (double rest : {-1.0, 3601.0, nan, inf}) {
    e.restS = rest;
    refused(e, "rest");
  }
  e = exercise("elbow");
  e.sessionsPerWeek = -1;
  refused(e, "sessions per week");
  e = exercise("elbow", -3);
  refused(e, "position");
  expectError([&] { f.store->setProgrammeExercise("MINE", exercise("no such")); }, Kind::NotFound,
              "no such");
  expectError([&] { f.store->setProgrammeExercise("NOBODY", exercise("elbow")); }, Kind::NotFound,
              "NOBODY");
  expectError([&] { f.store->unassignProtocol("MINE", "elbow"); }, Kind::NotFound);
  // Nothing was stored by the refusals.
  EXPECT_TRUE(f.store->programme("MINE").empty());
}

TEST_P(Programmes, AHomeAccountReadsItsOwnAndChangesNothing) {
  Fixture f(GetParam());
  fill(f);
  f.store->setProgrammeExercise("MINE", exercise("elbow"));
  f.store->setProgrammeExercise("OTHER", exercise("flexion"));
  ClinicalStore home(*f.db);
  home.signIn("home", "h-pass-long");
  ASSERT_EQ(names(home.programme("MINE")), QStringList{"elbow"});
  expectError([&] { home.programme("OTHER"); }, Kind::NotFound);
  expectError([&] { home.setProgrammeExercise("MINE", exercise("flexion")); }, Kind::AccessDenied);
  expectError([&] { home.unassignProtocol("MINE", "elbow"); }, Kind::AccessDenied);
  expectError([&] { home.assignProtocol("MINE", "flexion", 1); }, Kind::AccessDenied);
  EXPECT_EQ(names(f.store->programme("MINE")), QStringList{"elbow"});
}

TEST_P(HomeSessions, MarkedHomeWithThePatientsOwnOutcome) {
  Fixture f(GetParam());
  fill(f);
  f.store->addUser("thera", Role::Therapist, "t-pass-long");
  f.store->addUser("other-home", Role::Home, "o-pass-long", "OTHER");
  ClinicalStore home(*f.db);
  home.signIn("home", "h-pass-long");
  ClinicalStore thera(*f.db);
  thera.signIn("thera", "t-pass-long");
  const qint64 atHome = home.beginSession("MINE", "elbow", "{}", 0);
  const qint64 atClinic = thera.beginSession("MINE", "elbow", "{}", 0);
  home.finishSession(atHome);
  thera.finishSession(atClinic);
  EXPECT_EQ(thera.session(atHome).setting, kSettingHome);
  EXPECT_EQ(thera.session(atClinic).setting, kSettingClinic);
  EXPECT_FALSE(thera.session(atHome).painScore.has_value());

  const QString comment =
      QString::fromUtf8("Ça tirait un peu; 'stop' \"here\" \\ ? $1 \xF0\x9F\x92\xAA");
  const QString summary = R"({"exercises":[{"protocol":"elbow","repetitions":7}]})";
  home.saveHomeOutcome(atHome, 3, comment, summary);
  SessionInfo s;
  for (const SessionInfo& listed : thera.listSessions("MINE"))
    if (listed.id == atHome) s = listed;
  EXPECT_EQ(s.painScore, 3);
  EXPECT_EQ(s.patientComment, comment);
  EXPECT_EQ(s.homeSummaryJson, summary);
  home.saveHomeOutcome(atHome, std::nullopt, "", "{}");  // a patient may leave them out
  s = thera.session(atHome);
  EXPECT_FALSE(s.painScore.has_value());
  EXPECT_TRUE(s.patientComment.isEmpty());

  expectError([&] { home.saveHomeOutcome(atHome, 11, "", "{}"); }, Kind::Usage, "0-10");
  expectError([&] { home.saveHomeOutcome(atHome, -1, "", "{}"); }, Kind::Usage, "0-10");
  expectError([&] { home.saveHomeOutcome(atHome, 2, QString(2001, u'x'), "{}"); }, Kind::Usage,
              "2000");
  expectError([&] { home.saveHomeOutcome(atHome, 2, "", "[1,2]"); }, Kind::Usage, "JSON object");
  expectError([&] { home.saveHomeOutcome(atHome, 2, "", "{truncated"); }, Kind::Usage);
  expectError([&] { home.saveHomeOutcome(atClinic, 2, "", "{}"); }, Kind::Usage,
              "not recorded at home");
  // The words are the patient's: a therapist does not write them, another patient cannot see
  // the session at all.
  expectError([&] { thera.saveHomeOutcome(atHome, 2, "", "{}"); }, Kind::AccessDenied);
  ClinicalStore other(*f.db);
  other.signIn("other-home", "o-pass-long");
  expectError([&] { other.saveHomeOutcome(atHome, 2, "", "{}"); }, Kind::NotFound);
  expectError([&] { home.saveHomeOutcome(999999, 2, "", "{}"); }, Kind::NotFound);
  // Refusals changed nothing.
  s = thera.session(atHome);
  EXPECT_FALSE(s.painScore.has_value());
  EXPECT_EQ(s.homeSummaryJson, "{}");
}

// Version 3 exactly as released: version 1 (StorageTestSupport.h), version 2's sign-in columns
// and version 3's programmes table, copied by hand. Version 4 added the exercises' values and
// the home marks.
TEST_P(MigrationToHome, FromVersion3KeepsProgrammesInTheirOrderAndMarksSessionsClinic) {
  QTemporaryDir dir;
  const QString path = newDatabase(GetParam(), dir, "v3");
  QStringList v3 = version1Schema(GetParam());
  const QString id = GetParam() == Engine::Postgres
                         ? "BIGINT GENERATED BY DEFAULT AS IDENTITY PRIMARY KEY"
                         : "INTEGER PRIMARY KEY";
  v3 << "ALTER TABLE users ADD COLUMN failed_attempts INTEGER NOT NULL DEFAULT 0"
     << "ALTER TABLE users ADD COLUMN last_failed_at TEXT"
     << "CREATE TABLE programmes (id " + id +
            ", patient_id BIGINT NOT NULL REFERENCES patients (id) ON DELETE CASCADE, "
            "protocol_id BIGINT NOT NULL REFERENCES protocols (id) ON DELETE CASCADE, "
            "sessions_per_week INTEGER NOT NULL DEFAULT 0 CHECK (sessions_per_week >= 0), "
            "notes TEXT NOT NULL DEFAULT '', created_at TEXT NOT NULL, "
            "UNIQUE (patient_id, protocol_id))"
     << "UPDATE schema_version SET version = 3"
     << "INSERT INTO patients (code, name, created_at) VALUES ('OLD2', 'Second', "
        "'2025-01-01T00:00:00.000Z')"
     << "INSERT INTO protocols (name, angle_key, target_min_deg, target_max_deg, repetitions, "
        "side) VALUES ('a', 'elbow_flexion', 30, 130, 10, 'either')"
     << "INSERT INTO protocols (name, angle_key, target_min_deg, target_max_deg, repetitions, "
        "side) VALUES ('b', 'shoulder_flexion', 0, 90, 5, 'either')"
     // Made in the order b, a for OLD1; a for OLD2.
     << "INSERT INTO programmes (patient_id, protocol_id, sessions_per_week, notes, created_at) "
        "VALUES (1, 2, 3, 'b first', '2025-01-03T00:00:00.000Z')"
     << "INSERT INTO programmes (patient_id, protocol_id, sessions_per_week, notes, created_at) "
        "VALUES (2, 1, 1, '', '2025-01-03T00:00:00.000Z')"
     << "INSERT INTO programmes (patient_id, protocol_id, sessions_per_week, notes, created_at) "
        "VALUES (1, 1, 4, 'a second', '2025-01-04T00:00:00.000Z')";
  rawSql(path, v3);

  expectError([&] { Database db(DatabaseUrl::parse(path), {}); }, Kind::OlderSchema);
  Database db(DatabaseUrl::parse(path), {false, true});
  EXPECT_EQ(db.migrationsApplied(), latestSchemaVersion() - 3);
  ClinicalStore store(db);
  store.signIn("admin", kAdminPassword);
  const std::vector<ProgrammeItem> p = store.programme("OLD1");
  ASSERT_EQ(names(p), (QStringList{"b", "a"}));
  EXPECT_EQ(p[0].position, 1);
  EXPECT_EQ(p[1].position, 2);
  EXPECT_EQ(p[0].sessionsPerWeek, 3);
  EXPECT_EQ(p[1].notes, "a second");
  EXPECT_EQ(p[1].sets, 1);
  EXPECT_FALSE(p[1].repetitions.has_value());
  EXPECT_FALSE(p[1].targetMinDeg.has_value());
  EXPECT_EQ(p[1].restS, 60);
  const std::vector<ProgrammeItem> p2 = store.programme("OLD2");
  ASSERT_EQ(p2.size(), 1u);
  EXPECT_EQ(p2[0].position, 1);
  const std::vector<SessionInfo> sessions = store.listSessions("OLD1");
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_EQ(sessions[0].notes, "first visit");
  EXPECT_EQ(sessions[0].setting, kSettingClinic);
  EXPECT_FALSE(sessions[0].painScore.has_value());
  EXPECT_EQ(sessions[0].homeSummaryJson, "{}");
  // The new checks hold on migrated tables too.
  expectError([&] { db.exec("UPDATE sessions SET pain_score = 11"); }, Kind::Io);
  expectError([&] { db.exec("UPDATE sessions SET setting = 'car'"); }, Kind::Io);
  expectError([&] { db.exec("UPDATE programmes SET sets = 0"); }, Kind::Io);
}

INSTANTIATE_TEST_SUITE_P(Engines, Programmes, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
INSTANTIATE_TEST_SUITE_P(Engines, HomeSessions, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
INSTANTIATE_TEST_SUITE_P(Engines, MigrationToHome,
                         testing::Values(Engine::Sqlite, Engine::Postgres), engineName);
