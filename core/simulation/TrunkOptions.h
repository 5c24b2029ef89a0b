// The trunk options a user gives a simulation (armtrack-cli simulate's --trunk-* flags, the
// virtual arm's trunk-* options), mapped onto SimulationParams in one place so the two front ends
// simulate the same patient from the same words.
#pragma once

#include <optional>

#include "core/simulation/SensorSimulator.h"

namespace armtrack {

/// What was asked for; unset values keep TrunkSimParams' defaults.
struct TrunkSimOptions {
  /// Forward lean at the fullest reach (deg, 0 to kMaxLeanDeg). Set: the trunk moves (even at 0,
  /// when it only sways); unset: a still trunk.
  std::optional<double> leanDeg;
  /// Lateral bending and axial rotation at the fullest reach per degree of lean
  /// (-kMaxRatio to kMaxRatio); negative: towards the patient's left, the left shoulder forward.
  std::optional<double> lateralRatio;
  std::optional<double> rotationRatio;
  /// The trunk's own slow sway, at most this per angle (deg, 0 to kMaxSwayDeg).
  std::optional<double> swayDeg;
  /// The sternum IMU (tr_* columns): the upper-arm IMU's rate, noise and bias.
  bool trunkImu = false;
  /// Whether the Kinect also reports the shoulder; unset: when the trunk moves.
  std::optional<bool> kinectShoulder;

  static constexpr double kMaxLeanDeg = 45.0;
  static constexpr double kMaxRatio = 2.0;
  static constexpr double kMaxSwayDeg = 5.0;
};

/// Sets sim.trunk, sim.trunkImu and sim.kinect.shoulder from the options. Call after the arm IMUs
/// and sim.seed are set: the sternum IMU copies the upper-arm IMU's rate, noise and bias (enabled
/// as asked), with a misalignment of misalignmentRad about its own random axis (seed
/// 2 * sim.seed + 3), and the sway is drawn from sim.seed. Throws std::invalid_argument naming
/// the value for one out of range (the front ends check their own, with their own words, first).
void applyTrunkSimOptions(const TrunkSimOptions& options, SimulationParams& sim,
                          double misalignmentRad = 0.0);

}  // namespace armtrack
