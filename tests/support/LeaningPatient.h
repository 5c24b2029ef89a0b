// A simulated patient who leans and turns the trunk with each reach (issue 26): shoulder flexion
// reaches from 10 to 110 deg after 4 s at rest, the trunk leaning forward (by default 18 deg;
// sideways and axially half of that) at the fullest reach, with a sternum IMU beside the two arm
// IMUs (by default 200 Hz) and a Kinect that sees the shoulder. Shared by the CLI and GUI tests of
// the trunk's records.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/io/Recording.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack::test {

/// The recording of seconds of leaning reaches, simulated with seed; the lean at the fullest reach
/// (deg) and the IMUs' rate (Hz) as given.
inline Recording leaningReaches(double seconds, std::uint64_t seed, double leanDeg = 18,
                                double rateHz = 200) {
  TrajectoryOptions options;
  options.exercise.angle = 0;  // shoulder flexion
  options.exercise.fromDeg = 10;
  options.exercise.toDeg = 110;
  options.exercise.startSeconds = 4;
  const auto trajectory = makeTrajectory("exercise", options);
  SimulationParams sim = defaultSimulation();
  sim.duration = seconds;
  sim.seed = seed;
  sim.upperArm.rateHz = sim.forearm.rateHz = sim.trunkImu.rateHz = rateHz;
  sim.trunk.enabled = true;
  sim.trunk.leanDeg = leanDeg;
  sim.trunkImu.enabled = true;
  sim.kinect.shoulder = true;
  return simulateRecording(*trajectory, sim);
}

/// The recording's largest true trunk flexion, forward or back (deg).
inline double trueLeanDeg(const Recording& rec) {
  double lean = 0;
  for (const ArmSample& a : rec.samples)
    if (a.trueTrunk) lean = std::max(lean, std::abs((*a.trueTrunk)(0)) * 180 / std::numbers::pi);
  return lean;
}

}  // namespace armtrack::test
