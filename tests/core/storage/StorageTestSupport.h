// Shared helpers for the storage tests: a fresh database (a SQLite file, or a database on a
// PostgreSQL server the tests start), a signed-in store, and a small simulated recording.
#pragma once

#include <gtest/gtest.h>

#include <QAtomicInt>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/storage/ClinicalStore.h"
#include "tests/support/PostgresServer.h"

namespace armtrack::storage::test {

inline constexpr const char* kAdminPassword = "correct horse battery";

/// The engines every storage test runs on (value-parameterised tests).
enum class Engine { Sqlite, Postgres };

inline void PrintTo(Engine e, std::ostream* os) {
  *os << (e == Engine::Sqlite ? "SQLite" : "PostgreSQL");
}

inline std::string engineName(const testing::TestParamInfo<Engine>& info) {
  return info.param == Engine::Sqlite ? "Sqlite" : "Postgres";
}

/// A new, empty database of engine: a file named stem in dir, or a new database on the test
/// server of this process (started on first use; a server that cannot start throws, so the test
/// fails with the reason).
inline QString newDatabase(Engine engine, const QTemporaryDir& dir, const QString& stem) {
  if (engine == Engine::Sqlite) return dir.filePath(stem + ".db");
  static QAtomicInt counter;
  return armtrack::test::PostgresServer::shared().createDatabase(
      QString("t%1_%2").arg(counter.fetchAndAddRelaxed(1)).arg(stem.toLower()));
}

/// Runs raw SQL on a database outside the service (to build old or damaged ones). On
/// PostgreSQL as the test role, so the service may alter what is created.
inline void rawSql(const QString& location, const QStringList& statements) {
  const DatabaseUrl url = DatabaseUrl::parse(location);
  if (url.engine == DatabaseUrl::Engine::Postgres) {
    armtrack::test::PostgresServer::shared().superuserSql(
        url.database,
        QStringList{QString("SET ROLE ") + armtrack::test::PostgresServer::kRole} + statements);
    return;
  }
  const QString name = "raw-" + location;
  {
    QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", name);
    db.setDatabaseName(url.path);
    ASSERT_TRUE(db.open());
    for (const QString& s : statements) {
      QSqlQuery q(db);
      ASSERT_TRUE(q.exec(s)) << s.toStdString() << ": " << q.lastError().text().toStdString();
    }
    db.close();
  }
  QSqlDatabase::removeDatabase(name);
}

/// A temporary folder with an initialised database and its administrator signed in. path is the
/// --db location (a file, or a postgresql:// URL).
struct Fixture {
  QTemporaryDir dir;
  Engine engine;
  QString path;
  std::unique_ptr<Database> db;
  std::unique_ptr<ClinicalStore> store;

  explicit Fixture(Engine e = Engine::Sqlite) : engine(e), path(newDatabase(e, dir, "armtrack")) {
    db = std::make_unique<Database>(DatabaseUrl::parse(path), Database::Options{true, false});
    store = std::make_unique<ClinicalStore>(*db);
    store->initialise("admin", kAdminPassword);
    store->signIn("admin", kAdminPassword);
  }
  std::filesystem::path file(const char* name) const { return dir.filePath(name).toStdString(); }
  void close() {
    store.reset();
    db.reset();
  }
};

inline Patient makePatient(const QString& code) {
  Patient p;
  p.code = code;
  p.name = "Name of " + code;
  p.birthDate = "1960-04-02";
  p.sex = "f";
  p.affectedSide = "right";
  p.diagnosis = "stroke";
  p.segmentLengthsJson = R"({"upper_arm_m":0.3,"forearm_m":0.26})";
  return p;
}

/// A simulated recording (two IMUs at imuRate, Kinect at 30 Hz, true angles) written to csv.
inline Recording simulateTo(const std::filesystem::path& csv, double seconds,
                            double imuRate = 1000.0, bool truth = true) {
  SimulationParams sim;
  sim.duration = seconds;
  sim.upperArm.rateHz = imuRate;
  sim.forearm.rateHz = imuRate;
  sim.upperArm.gyroNoiseStd = sim.forearm.gyroNoiseStd = Table5::gyroStd();
  sim.upperArm.accelNoiseStd = sim.forearm.accelNoiseStd = Table5::accelStd();
  sim.includeTruth = truth;
  TrajectoryOptions options;
  options.seed = 7;
  const auto trajectory = makeTrajectory("multi-joint", options);
  Recording rec = simulateRecording(*trajectory, sim);
  writeRecording(csv, rec);
  return readRecording(csv);  // what a reader of the CSV sees, bit for bit
}

inline std::string fileBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace armtrack::storage::test
