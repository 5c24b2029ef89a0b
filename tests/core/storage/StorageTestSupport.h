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
#include "core/storage/PasswordHash.h"
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
    if (!mustSay.empty()) {
      EXPECT_NE(std::string(e.what()).find(mustSay), std::string::npos) << e.what();
    }
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

/// A protocol on one clinical angle (its key), with a target range (deg) and a repetition count.
inline Protocol makeProtocol(const QString& name, const QString& angle, double lo, double hi,
                             int reps) {
  Protocol p;
  p.name = name;
  p.angleKey = angle;
  p.targetMinDeg = lo;
  p.targetMaxDeg = hi;
  p.repetitions = reps;
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

/// Version 1 of the schema exactly as released (a copy, so that later edits to Schema.cpp cannot
/// hide a broken migration), with a patient, the administrator (kAdminPassword), a session
/// ("first visit") and its metrics.
inline QStringList version1Schema(Engine engine) {
  QStringList v1 = {
      "CREATE TABLE schema_version (version INTEGER NOT NULL)",
      "INSERT INTO schema_version VALUES (1)",
      "CREATE TABLE patients (id INTEGER PRIMARY KEY, code TEXT NOT NULL UNIQUE, name TEXT NOT "
      "NULL, birth_date TEXT, sex TEXT CHECK (sex IN ('f', 'm', 'x')), affected_side TEXT "
      "CHECK "
      "(affected_side IN ('left', 'right', 'both', 'none')), diagnosis TEXT NOT NULL DEFAULT "
      "'', "
      "segment_lengths_json TEXT NOT NULL DEFAULT '{}', notes TEXT NOT NULL DEFAULT '', "
      "created_at TEXT NOT NULL)",
      "CREATE TABLE users (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, role TEXT NOT "
      "NULL "
      "CHECK (role IN ('admin', 'therapist', 'home')), password_hash TEXT NOT NULL, patient_id "
      "BIGINT REFERENCES patients (id), created_at TEXT NOT NULL, CHECK ((role = 'home') = "
      "(patient_id IS NOT NULL)))",
      "CREATE TABLE protocols (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, angle_key "
      "TEXT "
      "NOT NULL, target_min_deg DOUBLE PRECISION NOT NULL, target_max_deg DOUBLE PRECISION NOT "
      "NULL, repetitions INTEGER NOT NULL CHECK (repetitions >= 0), side TEXT CHECK (side IN "
      "('left', 'right', 'either')))",
      "CREATE TABLE sessions (id INTEGER PRIMARY KEY, patient_id BIGINT NOT NULL REFERENCES "
      "patients (id), therapist_id BIGINT REFERENCES users (id), protocol_id BIGINT REFERENCES "
      "protocols (id), started_at TEXT NOT NULL, duration_s DOUBLE PRECISION NOT NULL DEFAULT "
      "0, "
      "devices_json TEXT NOT NULL DEFAULT '{}', calibration_json TEXT NOT NULL DEFAULT '{}', "
      "filter_json TEXT NOT NULL DEFAULT '{}', notes TEXT NOT NULL DEFAULT '', status TEXT NOT "
      "NULL CHECK (status IN ('complete', 'interrupted', 'recording')), columns_mask INTEGER "
      "NOT "
      "NULL DEFAULT 0, sample_rows BIGINT NOT NULL DEFAULT 0, imu_samples BIGINT NOT NULL "
      "DEFAULT "
      "0, recorder_host TEXT, recorder_pid BIGINT)",
      "CREATE INDEX sessions_by_patient ON sessions (patient_id, started_at)",
      "CREATE TABLE recording_chunks (session_id BIGINT NOT NULL REFERENCES sessions (id) ON "
      "DELETE CASCADE, seq INTEGER NOT NULL, t_first DOUBLE PRECISION NOT NULL, t_last DOUBLE "
      "PRECISION NOT NULL, row_count INTEGER NOT NULL, codec TEXT NOT NULL, data BLOB NOT "
      "NULL, "
      "PRIMARY KEY (session_id, seq))",
      "CREATE TABLE estimates (id INTEGER PRIMARY KEY, session_id BIGINT NOT NULL REFERENCES "
      "sessions (id) ON DELETE CASCADE, version INTEGER NOT NULL, created_at TEXT NOT NULL, "
      "params_json TEXT NOT NULL DEFAULT '{}', codec TEXT NOT NULL, data BLOB NOT NULL, UNIQUE "
      "(session_id, version))",
      "CREATE TABLE metrics (id INTEGER PRIMARY KEY, session_id BIGINT NOT NULL REFERENCES "
      "sessions (id) ON DELETE CASCADE, version INTEGER NOT NULL, created_at TEXT NOT NULL, "
      "per_angle_json TEXT NOT NULL DEFAULT '{}', per_repetition_json TEXT NOT NULL DEFAULT "
      "'[]', "
      "UNIQUE (session_id, version))",
      "CREATE TABLE audit_log (id INTEGER PRIMARY KEY, at TEXT NOT NULL, user_name TEXT NOT "
      "NULL, "
      "action TEXT NOT NULL, object_type TEXT NOT NULL, object_id TEXT NOT NULL, detail TEXT "
      "NOT "
      "NULL DEFAULT '')",
      "INSERT INTO patients (code, name, birth_date, sex, affected_side, created_at) VALUES "
      "('OLD1', 'Old Patient', '1950-01-31', 'm', 'left', '2025-01-01T00:00:00.000Z')",
      QString("INSERT INTO users (name, role, password_hash, created_at) VALUES ('admin', 'admin', "
              "'%1', '2025-01-01T00:00:00.000Z')")
          .arg(QString::fromStdString(PasswordHash::hash(kAdminPassword))),
      "INSERT INTO sessions (patient_id, started_at, status, notes) VALUES (1, "
      "'2025-01-02T10:00:00.000Z', 'complete', 'first visit')",
      "INSERT INTO metrics (session_id, version, created_at, per_angle_json) VALUES (1, 1, "
      "'2025-01-02T10:05:00.000Z', '{\"elbow_flexion\":{\"rom_deg\":91.5}}')",
  };
  // Version 1 on PostgreSQL was the same DDL with the dialect's two words (Schema.cpp).
  if (engine == Engine::Postgres)
    for (QString& st : v1)
      st.replace("INTEGER PRIMARY KEY", "BIGINT GENERATED BY DEFAULT AS IDENTITY PRIMARY KEY")
          .replace("BLOB", "BYTEA");
  return v1;
}

inline std::string fileBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace armtrack::storage::test
