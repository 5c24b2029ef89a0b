// Shared helpers for the storage tests: a fresh database (a SQLite file, or a database on a
// PostgreSQL server the tests start), a signed-in store, and a small simulated recording.
#pragma once

#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/storage/ClinicalStore.h"
#include "tests/support/DatabaseEngines.h"

namespace armtrack::storage::test {

inline constexpr const char* kAdminPassword = "correct horse battery";

// The engines every storage test runs on (value-parameterised tests), a fresh database of each,
// and raw SQL on it: tests/support/DatabaseEngines.h.
using armtrack::test::Engine;
using armtrack::test::engineName;
using armtrack::test::newDatabase;
using armtrack::test::rawQuery;
using armtrack::test::rawSql;

using Kind = StorageError::Kind;

/// Value-parameterised storage tests run on every engine (INSTANTIATE_TEST_SUITE_P with Engine).
class Engines : public testing::TestWithParam<Engine> {};

/// Whether two doubles are the same bit pattern (NaN payloads and -0 included).
inline bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// Runs f, which must throw a StorageError of kind whose message contains mustSay; returns it
/// (a failure, and an empty Io error, when f throws nothing).
template <typename F>
StorageError expectError(F&& f, Kind kind, const std::string& mustSay = {}) {
  try {
    f();
  } catch (const StorageError& e) {
    EXPECT_EQ(static_cast<int>(e.kind()), static_cast<int>(kind)) << e.what();
    if (!mustSay.empty())
      EXPECT_NE(std::string(e.what()).find(mustSay), std::string::npos) << e.what();
    return e;
  }
  ADD_FAILURE() << "no StorageError";
  return StorageError(Kind::Io, "");
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
