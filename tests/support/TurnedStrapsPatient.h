// A simulated patient whose straps sit wrong (issue 27): a session of reaches from a resting hand
// (SessionTrajectory, seed 31, up to 150 deg/s), the two arm IMUs at 100 Hz with Table 5 noise,
// no optics, both straps turned turnDeg about random axes (seeds 63 and 64). Shared by the live
// session's and the live screen's tests of the straps checked from the movement.
#pragma once

#include "core/io/Recording.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack::test {

/// The recording of seconds of the session, both straps turned turnDeg (deg).
inline Recording turnedStrapsSession(double turnDeg, double seconds) {
  SimulationParams sim = defaultSimulation();
  sim.duration = seconds;
  sim.seed = 31;
  sim.kinect.enabled = false;
  sim.upperArm.rateHz = sim.forearm.rateHz = 100.0;
  sim.upperArm.misalignment = randomMisalignment(turnDeg * kDeg, 63);
  sim.forearm.misalignment = randomMisalignment(turnDeg * kDeg, 64);
  const SessionTrajectory traj(31, 150 * kDeg, 1500 * kDeg, seconds);
  return simulateRecording(traj, sim);
}

}  // namespace armtrack::test
