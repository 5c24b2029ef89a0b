// Shared helpers for the storage tests: a fresh database folder, a signed-in store, and a small
// simulated recording.
#pragma once

#include <QTemporaryDir>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/storage/ClinicalStore.h"

namespace armtrack::storage::test {

inline constexpr const char* kAdminPassword = "correct horse battery";

/// A temporary folder with an initialised database and its administrator signed in.
struct Fixture {
  QTemporaryDir dir;
  QString path = dir.filePath("armtrack.db");
  std::unique_ptr<Database> db;
  std::unique_ptr<ClinicalStore> store;

  Fixture() {
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
