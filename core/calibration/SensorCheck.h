// Are the two IMUs on the right segments and the right way round? Judged from a few seconds of
// a known movement (core/simulation SensorCheckTrajectory): the arm hangs still, elbow straight,
// then the elbow bends and straightens a few times with the upper arm still.
//
// - Swapped sensors: bending the elbow turns the forearm and not the upper arm, so the forearm's
//   gyroscope must see far more rotation than the upper arm's. When the sensor plugged in as the
//   upper arm's sees it instead, the two are swapped.
// - A sensor upside down: with the arm hanging straight, gravity lies along each segment, and the
//   arm model (core/kinematics) says where that axis is in each sensor's frame, whatever the
//   strap's angle around the arm. A sensor whose accelerometer reads gravity the other way along
//   it is upside down; far from either way, it is tilted (or the arm did not hang straight).
// - The sternum sensor (when the session has one): the patient sits upright and still, so its
//   accelerometer reads gravity along the direction its mounting (RecordingMeta::trunk) says is
//   up. Read the other way it is upside down; more than trunkToleranceDeg away, it is turned.
// Plain C++ and Eigen, no Qt.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/ArmSample.h"
#include "core/io/Recording.h"
#include "core/kinematics/ArmModel.h"
#include "core/kinematics/Side.h"

namespace armtrack {

struct SensorCheckParams {
  ArmGeometry geometry;                ///< the arm model (mounting of the sensors)
  Side side = Side::Right;             ///< the arm wearing the sensors
  Eigen::Vector3d up{-1.0, 0.0, 0.0};  ///< unit, shoulder frame of the side
  double g = 9.81;                     ///< m/s^2
  double restEndS = 3.0;               ///< s: the arm hangs still before this time
  double settleS = 0.3;                ///< s at the start left out (the sensors settle)
  double minRestS = 0.8;               ///< s of stillness needed to judge the hang
  double stillRateRadS = 0.25;         ///< |gyro| below this (rad/s) counts as still
  double minMotionRadS = 0.35;         ///< RMS rotation (rad/s) that counts as a bend
  double swapRatio = 2.0;              ///< one gyroscope this many times the other's
  double uprightCos = 0.7;             ///< cos of the angle to gravity: within ~45 deg
  /// The sternum sensor's expected mounting (frame 0 of the side, the trunk upright): set when
  /// the session has a trunk IMU, whose readings are then checked as well.
  std::optional<TrunkMount> trunk;
  double trunkToleranceDeg = 25.0;  ///< gravity read this far from expected: the sensor is turned
};

/// Whether the check could judge at all.
enum class SensorCheckStatus {
  Judged,           ///< findings (possibly none) below
  MissingUpperArm,  ///< no reading of the upper-arm sensor
  MissingForearm,   ///< no reading of the forearm sensor
  MissingTrunk,     ///< the session has a sternum sensor but it sent no readings
  NotStill,         ///< the arm did not hang still long enough at the start
  NoMovement,       ///< no elbow bend was seen
  BothMoved,        ///< both sensors turned alike: the upper arm moved, or both are on one segment
  ImplausibleReadings  ///< an accelerometer does not read gravity (a broken or unconverted sensor)
};

/// What is wrong with the sensors as worn. Upside-down and tilted findings name the segment the
/// sensor is on (after a swap: where it really is).
enum class SensorFinding {
  Swapped,  ///< the upper-arm sensor is on the forearm and the forearm one on the upper arm
  UpperArmUpsideDown,  ///< the sensor on the upper arm is turned end over end
  ForearmUpsideDown,
  UpperArmTilted,  ///< neither way round: crooked on the strap, or the arm was not straight
  ForearmTilted,
  TrunkUpsideDown,  ///< the sternum sensor reads gravity the other way round
  TrunkTurned,      ///< the sternum sensor reads gravity more than trunkToleranceDeg off
};

struct SensorCheckResult {
  SensorCheckStatus status = SensorCheckStatus::Judged;
  std::vector<SensorFinding> findings;  ///< empty: the sensors are worn right
  /// The figures judged on, for the log and the tests.
  double upperMotionRadS = 0;  ///< RMS rotation seen by the sensor plugged in as the upper arm's
  double forearmMotionRadS = 0;
  double upperCos = 0;  ///< cos(angle) between gravity read and expected, sensor on the upper arm
  double forearmCos = 0;
  /// Angle between gravity as the sternum sensor read it and as its mounting expects (deg); NaN
  /// without a sternum sensor.
  double trunkAngleDeg = std::numeric_limits<double>::quiet_NaN();
  double restSeconds = 0;   ///< stillness found at the start
  std::string explanation;  ///< one English line saying what was found (logs, not the GUI)

  bool ok() const { return status == SensorCheckStatus::Judged && findings.empty(); }
  bool has(SensorFinding f) const;
};

/// Judges samples (times from the start of the check, s; IMU readings in their sensors' frames
/// as the session delivers them, left-arm readings mirrored here). Samples without an IMU reading
/// are ignored. Never throws; non-finite readings are skipped.
SensorCheckResult checkSensors(std::span<const ArmSample> samples, const SensorCheckParams& params);

}  // namespace armtrack
