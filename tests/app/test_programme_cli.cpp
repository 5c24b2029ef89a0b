// armtrack-cli programme: a home programme made, listed and changed from the command line, on
// SQLite and PostgreSQL, with its refusals (bad values, an unknown protocol, a home account).
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "tests/app/StorageCliFixture.h"

using armtrack::test::CliFixture;
using armtrack::test::Engine;
using armtrack::test::Result;

namespace {

QJsonObject at(const QJsonArray& a, int i) {
  return a[i].toObject();
}

class ProgrammeCli : public CliFixture, public ::testing::WithParamInterface<Engine> {
 protected:
  void SetUp() override {
    init(GetParam());
    addPatients();
    for (const std::vector<std::string>& p :
         {std::vector<std::string>{"--name", "Elbow flexion", "--angle", "elbow_flexion",
                                   "--target-min", "30", "--target-max", "130", "--reps", "12"},
          std::vector<std::string>{"--name", "Shoulder flexion", "--angle", "shoulder_flexion",
                                   "--target-min", "10", "--target-max", "120", "--reps", "10"}}) {
      std::vector<std::string> args{"protocol", "add"};
      args.insert(args.end(), p.begin(), p.end());
      const Result r = run(args);
      ASSERT_EQ(r.code, 0) << r.err;
    }
  }
  QJsonArray list(const char* patient, const char* user = "boss",
                  const char* password = armtrack::test::kAdminPass) {
    const Result r = run({"programme", "list", "--patient", patient, "--json"}, user, password);
    EXPECT_EQ(r.code, 0) << r.err;
    return QJsonDocument::fromJson(QByteArray::fromStdString(r.out)).array();
  }
};

}  // namespace

TEST_P(ProgrammeCli, AddListReorderRemove) {
  Result r = run({"programme", "add", "--patient", "P01", "--protocol", "Elbow flexion", "--sets",
                  "3", "--reps", "8", "--target", "20:140", "--rest", "45", "--per-week", "5",
                  "--notes", "slowly"});
  ASSERT_EQ(r.code, 0) << r.err;
  r = run({"programme", "add", "--patient", "P01", "--protocol", "Shoulder flexion", "--position",
           "1"});
  ASSERT_EQ(r.code, 0) << r.err;
  QJsonArray p = list("P01");
  ASSERT_EQ(p.size(), 2);
  EXPECT_EQ(at(p, 0)["protocol"].toString(), "Shoulder flexion");
  EXPECT_EQ(at(p, 0)["position"].toInt(), 1);
  // The protocol's values where the programme has none of its own, and saying so.
  EXPECT_EQ(at(p, 0)["sets"].toInt(), 1);
  EXPECT_EQ(at(p, 0)["repetitions"].toInt(), 10);
  EXPECT_TRUE(at(p, 0)["repetitions_from_protocol"].toBool());
  EXPECT_EQ(at(p, 0)["target_min_deg"].toDouble(), 10);
  EXPECT_TRUE(at(p, 0)["target_from_protocol"].toBool());
  EXPECT_EQ(at(p, 0)["rest_s"].toDouble(), 60);
  EXPECT_EQ(at(p, 1)["protocol"].toString(), "Elbow flexion");
  EXPECT_EQ(at(p, 1)["angle"].toString(), "elbow_flexion");
  EXPECT_EQ(at(p, 1)["sets"].toInt(), 3);
  EXPECT_EQ(at(p, 1)["repetitions"].toInt(), 8);
  EXPECT_FALSE(at(p, 1)["repetitions_from_protocol"].toBool());
  EXPECT_EQ(at(p, 1)["target_min_deg"].toDouble(), 20);
  EXPECT_EQ(at(p, 1)["target_max_deg"].toDouble(), 140);
  EXPECT_EQ(at(p, 1)["rest_s"].toDouble(), 45);
  EXPECT_EQ(at(p, 1)["sessions_per_week"].toInt(), 5);
  EXPECT_EQ(at(p, 1)["notes"].toString(), "slowly");
  // The text form: one line per exercise, in order.
  r = run({"programme", "list", "--patient", "P01"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.find("1\tShoulder flexion"), 0u) << r.out;
  EXPECT_NE(r.out.find("2\tElbow flexion\telbow_flexion\t3 x 8\t20 to 140 deg\trest 45 s"),
            std::string::npos)
      << r.out;
  // `patient programme` says the same.
  EXPECT_EQ(run({"patient", "programme", "P01"}).out, r.out);
  // A negative target (e.g. supination) reads as a range, not an option.
  r = run({"programme", "add", "--patient", "P02", "--protocol", "Elbow flexion", "--target",
           "-10:90"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(at(list("P02"), 0)["target_min_deg"].toDouble(), -10);

  r = run({"programme", "remove", "--patient", "P01", "--protocol", "Shoulder flexion"});
  ASSERT_EQ(r.code, 0) << r.err;
  p = list("P01");
  ASSERT_EQ(p.size(), 1);
  EXPECT_EQ(at(p, 0)["position"].toInt(), 1);
  r = run({"programme", "remove", "--patient", "P01", "--protocol", "Shoulder flexion"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("not in the programme"), std::string::npos) << r.err;
}

TEST_P(ProgrammeCli, BadValuesAreRefusedAndNothingIsStored) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> bad{
      {{"--sets", "0"}, "sets must be 1-20"},
      {{"--sets", "99999999999"}, "too large"},
      {{"--sets", "-1"}, "--sets"},
      {{"--reps", "0"}, "repetitions must be 1-200"},
      {{"--target", "130:30"}, "min < max"},
      {{"--target", "30"}, "MIN:MAX"},
      {{"--target", "a:b"}, "MIN:MAX"},
      {{"--target", "nan:90"}, "MIN:MAX"},
      {{"--rest", "-5"}, "rest"},
      {{"--rest", "1e9"}, "rest"},
      {{"--position", "0"}, "places start at 1"},
  };
  for (const auto& [extra, says] : bad) {
    std::vector<std::string> args{"programme", "add",        "--patient",
                                  "P01",       "--protocol", "Elbow flexion"};
    args.insert(args.end(), extra.begin(), extra.end());
    const Result r = run(args);
    EXPECT_NE(r.code, 0) << extra[0] << " " << extra[1];
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  }
  Result r = run({"programme", "add", "--patient", "P01", "--protocol", "Juggling"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown protocol 'Juggling'"), std::string::npos) << r.err;
  r = run({"programme", "add", "--patient", "P99", "--protocol", "Elbow flexion"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown patient"), std::string::npos) << r.err;
  EXPECT_EQ(run({"programme", "add", "--protocol", "Elbow flexion"}).code, 2);
  EXPECT_EQ(run({"programme", "juggle"}).code, 2);
  EXPECT_TRUE(list("P01").isEmpty());
}

TEST_P(ProgrammeCli, AHomeAccountListsItsOwnAndChangesNothing) {
  ASSERT_EQ(run({"programme", "add", "--patient", "P01", "--protocol", "Elbow flexion"}).code, 0);
  ASSERT_EQ(run({"programme", "add", "--patient", "P02", "--protocol", "Shoulder flexion"}).code,
            0);
  ::setenv("ARMTRACK_NEW_PASSWORD", "home-pass-1", 1);
  ASSERT_EQ(run({"user", "add", "home1", "--role", "home", "--patient", "P01"}).code, 0);
  const QJsonArray mine = list("P01", "home1", "home-pass-1");
  ASSERT_EQ(mine.size(), 1);
  EXPECT_EQ(at(mine, 0)["protocol"].toString(), "Elbow flexion");
  Result r = run({"programme", "list", "--patient", "P02"}, "home1", "home-pass-1");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown patient"), std::string::npos) << r.err;
  r = run({"programme", "add", "--patient", "P01", "--protocol", "Shoulder flexion"}, "home1",
          "home-pass-1");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("may not change home programmes"), std::string::npos) << r.err;
  EXPECT_EQ(run({"programme", "remove", "--patient", "P01", "--protocol", "Elbow flexion"}, "home1",
                "home-pass-1")
                .code,
            1);
  EXPECT_EQ(list("P01").size(), 1);
}

// The trunk limit (issue 26): a protocol's set, changed and turned off with `protocol add|edit
// --trunk-limit`, an exercise's own or its protocol's with `programme add --trunk-limit`, each
// listed; values out of range or not numbers refused saying what to give.
TEST_P(ProgrammeCli, TrunkLimitsOfProtocolsAndExercises) {
  const auto protocols = [&] {
    const Result r = run({"protocol", "list", "--json"});
    EXPECT_EQ(r.code, 0) << r.err;
    QJsonObject byName;
    for (const QJsonValue& v : QJsonDocument::fromJson(QByteArray::fromStdString(r.out)).array())
      byName[v.toObject()["name"].toString()] = v;
    return byName;
  };
  EXPECT_TRUE(protocols()["Elbow flexion"].toObject()["trunk_limit_deg"].isNull());
  Result r =
      run({"protocol", "add", "--name", "Reach", "--angle", "shoulder_flexion", "--target-min", "0",
           "--target-max", "100", "--reps", "8", "--trunk-limit", "15"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(protocols()["Reach"].toObject()["trunk_limit_deg"].toDouble(), 15);
  r = run({"protocol", "list"});
  EXPECT_NE(r.out.find("Reach\tshoulder_flexion\t0\t100\t8\teither\ttrunk limit 15 deg"),
            std::string::npos)
      << r.out;
  // An edit changes what it is given and keeps the rest.
  r = run({"protocol", "edit", "Elbow flexion", "--trunk-limit", "12"});
  ASSERT_EQ(r.code, 0) << r.err;
  QJsonObject elbow = protocols()["Elbow flexion"].toObject();
  EXPECT_EQ(elbow["trunk_limit_deg"].toDouble(), 12);
  EXPECT_EQ(elbow["repetitions"].toInt(), 12);
  EXPECT_EQ(elbow["target_max_deg"].toDouble(), 130);
  r = run({"protocol", "edit", "Elbow flexion", "--reps", "5"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(protocols()["Elbow flexion"].toObject()["trunk_limit_deg"].toDouble(), 12);
  r = run({"protocol", "edit", "Elbow flexion", "--trunk-limit", "off"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(protocols()["Elbow flexion"].toObject()["trunk_limit_deg"].isNull());

  // Exercises: the protocol's, or their own.
  ASSERT_EQ(run({"programme", "add", "--patient", "P01", "--protocol", "Reach"}).code, 0);
  ASSERT_EQ(run({"programme", "add", "--patient", "P01", "--protocol", "Elbow flexion",
                 "--trunk-limit", "20"})
                .code,
            0);
  QJsonArray p = list("P01");
  ASSERT_EQ(p.size(), 2);
  EXPECT_EQ(at(p, 0)["trunk_limit_deg"].toDouble(), 15);
  EXPECT_TRUE(at(p, 0)["trunk_limit_from_protocol"].toBool());
  EXPECT_EQ(at(p, 1)["trunk_limit_deg"].toDouble(), 20);
  EXPECT_FALSE(at(p, 1)["trunk_limit_from_protocol"].toBool());
  r = run({"programme", "list", "--patient", "P01"});
  EXPECT_NE(r.out.find("/week\ttrunk limit 20 deg"), std::string::npos) << r.out;
  ASSERT_EQ(run({"programme", "add", "--patient", "P01", "--protocol", "Elbow flexion",
                 "--trunk-limit", "protocol"})
                .code,
            0);
  EXPECT_TRUE(at(list("P01"), 1)["trunk_limit_deg"].isNull());

  // Refusals, and nothing changed by them.
  for (const auto& [args, says] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"protocol", "edit", "Reach", "--trunk-limit", "0"}, "1-90 deg"},
           {{"protocol", "edit", "Reach", "--trunk-limit", "120"}, "1-90 deg"},
           {{"protocol", "edit", "Reach", "--trunk-limit", "lots"}, "expected degrees"},
           {{"protocol", "edit", "Reach", "--trunk-limit", "nan"}, "expected degrees"},
           {{"protocol", "edit", "Juggling", "--trunk-limit", "10"}, "unknown protocol"},
           {{"protocol", "add", "--name", "X", "--angle", "elbow_flexion", "--target-min", "0",
             "--target-max", "90", "--trunk-limit", "-5"},
            "1-90 deg"},
           {{"programme", "add", "--patient", "P01", "--protocol", "Reach", "--trunk-limit", "95"},
            "1-90 deg"},
           {{"programme", "add", "--patient", "P01", "--protocol", "Reach", "--trunk-limit", "off"},
            "turn it off in the protocol"}}) {
    r = run(args);
    EXPECT_NE(r.code, 0) << args[0] << " " << args.back();
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  }
  EXPECT_EQ(protocols()["Reach"].toObject()["trunk_limit_deg"].toDouble(), 15);
  EXPECT_FALSE(protocols().contains("X"));
  EXPECT_TRUE(at(list("P01"), 0)["trunk_limit_from_protocol"].toBool());
}

INSTANTIATE_TEST_SUITE_P(Engines, ProgrammeCli, testing::Values(Engine::Sqlite, Engine::Postgres),
                         armtrack::test::engineName);
