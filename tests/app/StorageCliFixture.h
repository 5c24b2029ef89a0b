// The fixture of the clinical-records CLI tests: armtrack-cli run in-process against a fresh
// database of either engine (tests/support/DatabaseEngines.h), signed in as its administrator.
#pragma once

#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/Cli.h"
#include "core/io/Recording.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "tests/app/CliRun.h"
#include "tests/support/DatabaseEngines.h"

namespace armtrack::test {

using Result = CliResult;

inline constexpr const char* kAdminPass = "admin-pass-1";

// The commands against a database of either engine: a SQLite file, or a database on the shared
// PostgreSQL test server (tests/support/DatabaseEngines.h; the tests fail with the reason when
// the server cannot start).
class CliFixture : public ::testing::Test {
 protected:
  void init(Engine engine) {
    ASSERT_TRUE(m_dir.isValid());
    m_engine = engine;
    m_db = armtrack::test::newDatabase(engine, m_dir, "clinic").toStdString();
    ::setenv("ARMTRACK_PASSWORD", kAdminPass, 1);
    const Result r = run({"db", "init", "--admin", "boss"}, nullptr);
    ASSERT_EQ(r.code, 0) << r.err;
  }
  void TearDown() override {
    ::unsetenv("ARMTRACK_PASSWORD");
    ::unsetenv("ARMTRACK_NEW_PASSWORD");
  }
  // Runs the tool with --db appended, signed in as user (nullptr: no --user) with password.
  Result run(std::vector<std::string> args, const char* user = "boss",
             const char* password = kAdminPass) {
    args.push_back("--db");
    args.push_back(m_db);
    if (user) {
      args.push_back("--user");
      args.push_back(user);
      ::setenv("ARMTRACK_PASSWORD", password, 1);
    }
    return cli(args);
  }
  std::string path(const char* name) const { return m_dir.filePath(name).toStdString(); }
  std::string simulate(const char* name, double seconds) {
    armtrack::SimulationParams sim;
    sim.duration = seconds;
    armtrack::TrajectoryOptions options;
    const auto trajectory = armtrack::makeTrajectory("multi-joint", options);
    armtrack::writeRecording(path(name), armtrack::simulateRecording(*trajectory, sim));
    return path(name);
  }
  std::string importFor(const char* patient, const std::string& csv) {
    const Result r = run({"session", "import", csv, "--patient", patient});
    EXPECT_EQ(r.code, 0) << r.err;
    return r.out.substr(0, r.out.find('\n'));
  }
  void addPatients() {
    for (const char* code : {"P01", "P02"}) {
      const Result r = run({"patient", "add", "--code", code, "--name", std::string("Name ") + code,
                            "--birth", "1958-03-04", "--sex", "m", "--side", "left"});
      ASSERT_EQ(r.code, 0) << r.err;
    }
  }
  /// Plain SQL on the database, outside the CLI.
  void sql(const QStringList& statements) {
    armtrack::test::rawSql(QString::fromStdString(m_db), statements);
  }
  std::vector<QVariantList> query(const QString& sql) {
    return armtrack::test::rawQuery(QString::fromStdString(m_db), sql);
  }

  QTemporaryDir m_dir;
  Engine m_engine = Engine::Sqlite;
  std::string m_db;
};

/// On SQLite and on PostgreSQL.
class StorageCli : public CliFixture, public ::testing::WithParamInterface<Engine> {
 protected:
  void SetUp() override { init(GetParam()); }
};

}  // namespace armtrack::test
