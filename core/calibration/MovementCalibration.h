// Calibration from ordinary movement (no protocol): each arm IMU's strap rotation and lever arm,
// and its gyroscope bias, from 20-60 s of natural arm movement that includes a moment of rest,
// in the methods of the IMU literature (docs/calibration.md, "Calibration from movement"):
// gravity and the gyroscope bias at rest; the shoulder as a fixed point and the elbow as the point
// whose acceleration both IMUs agree on (joint positions, Seel et al. 2012); the elbow's flexion
// axis in the upper-arm IMU and the pronation axis in the forearm IMU from the two IMUs'
// relative motion (the two-axis elbow of Laidig et al. 2017 and Mueller et al. 2017). What the
// movement did not excite stays at the sidecar's (prior) value and is named. The result is a
// normal Calibration (core/calibration/Calibration.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/calibration/Calibration.h"
#include "core/io/Recording.h"

namespace armtrack {

/// Settings of calibrateFromMovement. The defaults suit 20-60 s of natural movement.
struct MovementCalibrationParams {
  double minSeconds = 15.0;          ///< shorter recordings are refused (s)
  double minRestSeconds = 0.5;       ///< the shortest rest that counts (s)
  double restGyroSpread = 0.1;       ///< rad/s: at rest each gyro stays this close to its mean
  double restGyroMean = 0.25;        ///< rad/s: and its mean (the bias) is below this
  double restAccelSpread = 0.5;      ///< m/s^2: each accelerometer stays this close to its mean
  double restAccelTolerance = 0.15;  ///< |accel norm / g - 1| at rest
  double minMovingSeconds = 8.0;     ///< seconds with the arm turning faster than movingRate
  double movingRate = 0.5;           ///< rad/s
  /// The pose at the rest (rad), when the user knows it (e.g. protocolStartPose(): the upper arm
  /// hanging, the elbow at 90 deg, the thumb up). Gravity at rest then gives the upper-arm
  /// sensor's inclination relative to that pose, and its pronation fixes the forearm sensor's
  /// roll about the forearm, which no movement can tell from pronation. Unset, the rest pose is
  /// taken as unknown: the upper arm's long axis comes from the joint positions alone and the
  /// forearm's roll stays at the sidecar's.
  std::optional<JointVector> restPose;
  /// The pose the user was told to rest in, when it is not known that every rest is in it (the
  /// calibration used automatically: protocolStartPose(), docs/calibration.md, "The rest pose").
  /// Each rest that looks like it (gravity in the upper-arm sensor within restPoseTolerance of
  /// where the pose puts it, the forearm's inclination from its sensor's gravity and the elbow's
  /// flexion from the fit within restPoseTolerance of the pose's) is taken as that pose, and the
  /// forearm sensor's gravity there, "thumb up", gives its roll about the forearm. Without such a
  /// rest the roll stays the sidecar's and is reported as not observable. Ignored when restPose
  /// is set.
  std::optional<JointVector> expectedRestPose;
  double restPoseTolerance = 25.0 * kDeg;  ///< rad
  /// The rolls found at the matching rests must agree this closely, and the roll is believed only
  /// up to maxPoseRoll (a larger one means the thumb was not up: a hand flat on the thigh).
  double poseRollSpread = 15.0 * kDeg;  ///< rad
  double maxPoseRoll = 50.0 * kDeg;     ///< rad
  /// A parameter whose standard deviation after the fit exceeds this fraction of its prior's is
  /// "not excited": it falls back to the prior.
  double excitedFraction = 0.35;
  double rotationPriorStd = 45.0 * kDeg;  ///< rad, the sidecar's mounting as a weak prior
  double positionPriorStd = 0.05;         ///< m, the sidecar's lever arms as a weak prior
  int maxIterations = 60;
};

/// One calibrated quantity, in the units named by `unit` ("deg", "cm").
struct MovementParameter {
  std::string name;        ///< e.g. "upper-arm strap turn about the arm"
  double value = 0.0;      ///< the estimate (the prior's value when not excited)
  double prior = 0.0;      ///< the sidecar's value
  double sd = 0.0;         ///< standard deviation after the fit
  std::string unit;        ///< "deg" or "cm"
  bool excited = true;     ///< false: the movement did not determine it; value = prior
  bool observable = true;  ///< false: no movement can determine it (a gauge)
};

struct MovementCalibration {
  Calibration calibration;  ///< ready for writeCalibration / applyCalibration
  std::vector<MovementParameter> parameters;
  double restStart = 0.0, restEnd = 0.0;  ///< the rest used (s, recording time)
  /// With MovementCalibrationParams::expectedRestPose: the still stretches found, and those taken
  /// as the pose (the forearm's roll then comes from them).
  int rests = 0, poseRests = 0;
  bool rollFromPose = false;   ///< the forearm's roll came from a rest in a known pose
  double movingSeconds = 0.0;  ///< time with the arm turning faster than movingRate
  /// The whole mounting rotation of each IMU relative to the sidecar's strap angles (what the
  /// simulator's ImuSimParams::misalignment describes): mountingRotation(thu4, thu4_sidecar, R).
  Eigen::Matrix3d upperMounting = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d forearmMounting = Eigen::Matrix3d::Identity();
  /// Each IMU's position relative to its joint (upper arm: from the shoulder centre; forearm:
  /// from the elbow centre), in the segment's frame (frame 3, frame 6 of docs/arm-model.md; m).
  Eigen::Vector3d upperLever = Eigen::Vector3d::Zero();
  Eigen::Vector3d forearmLever = Eigen::Vector3d::Zero();
  /// Whether the movement placed each IMU in every direction (the shoulder, the elbow centre);
  /// false: some direction is the sidecar's.
  bool upperLeverExcited = true, forearmLeverExcited = true;
  double axisResidualRms = 0.0;   ///< rad/s, the relative-motion fit's gyroscope residual
  double leverResidualRms = 0.0;  ///< m/s^2, the joint-position fit's residual
  std::vector<std::string> warnings;
};

/// Estimates the calibration from ordinary movement. A left arm is fitted on its right-arm twin
/// and given back in the real sensors' axes. Throws std::invalid_argument with a message that
/// says what to do when the recording cannot be used: an IMU missing, shorter than minSeconds,
/// no moment of rest, too little movement, readings mostly saturated or not numbers. Readings
/// that are not finite, repeated (sample-and-hold) or at a sensor's range are left out (counted in
/// the warnings). Ceres writes nothing to the process's output.
MovementCalibration calibrateFromMovement(const Recording& recording,
                                          const MovementCalibrationParams& params = {});

/// The same, without exceptions: empty on failure, with the reason in *why when given.
std::optional<MovementCalibration> tryCalibrateFromMovement(
    const Recording& recording, const MovementCalibrationParams& params = {},
    std::string* why = nullptr);

/// The plain-language report: what was found ("upper-arm strap turned 23 deg about the arm"),
/// how sure (sd), and what the movement did not excite (left at the sidecar's values). English;
/// one paragraph per sensor, then a table of every parameter.
std::string formatMovementReport(const MovementCalibration& m);

}  // namespace armtrack
