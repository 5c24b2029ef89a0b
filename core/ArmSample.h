// One row of sensor data, as it flows from a recording or a device into the estimators.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "core/kinematics/ArmModel.h"
#include "core/kinematics/Side.h"

namespace armtrack {

/// One IMU sample in the sensor's own axes.
struct ImuReading {
  Eigen::Vector3d gyr = Eigen::Vector3d::Zero();  ///< angular velocity (rad/s)
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();  ///< specific force (m/s^2), ~ +9.81 up at rest
  /// Set by the estimator's plausibility gate (SampleGate): the value repeats the sensor's
  /// previous one bit for bit, as a logger does when the sensor had nothing new. Such a value
  /// is an old measurement, not a new one, and the filter treats it as absent.
  bool gyrHeld = false;
  bool accHeld = false;
};

/// Everything measured at one instant. Sensors run at different rates: absent ones are empty.
struct ArmSample {
  double t = 0.0;                      ///< time (s)
  std::optional<ImuReading> upperArm;  ///< upper-arm IMU
  std::optional<ImuReading> forearm;   ///< forearm IMU
  /// Sternum (trunk) IMU, optional. When a recording has one, or an optical shoulder, the
  /// optical positions and the camera's pose are in the world frame: frame 0 as it was with the
  /// trunk upright at the start (docs/arm-model.md, "Trunk"); otherwise in the shoulder frame.
  std::optional<ImuReading> trunk;
  std::optional<Eigen::Vector3d> elbow;     ///< optical elbow position (m), see trunk
  std::optional<Eigen::Vector3d> wrist;     ///< optical wrist position (m), see trunk
  std::optional<Eigen::Vector3d> shoulder;  ///< optical shoulder position, world frame (m)
  std::optional<Eigen::Vector2d> camWrist;  ///< wrist marker pixel (u, v)
  std::optional<Eigen::Vector2d> camElbow;  ///< elbow marker pixel (u, v)
  std::optional<JointVector> trueAngles;    ///< known true joint angles (rad), simulations
  /// Known true trunk flexion, lateral bending and axial rotation (rad, core/kinematics/Trunk.h),
  /// simulations.
  std::optional<Eigen::Vector3d> trueTrunk;
  std::optional<JointVector> estimate;  ///< angles a live session estimated (rad), if recorded

  bool hasImu() const { return upperArm.has_value() || forearm.has_value(); }
};

/// An IMU reading mapped between a left-arm sensor and its right-arm twin (core/kinematics/Side.h).
/// The twin of a sensor frame is its mirror image with the z axis reversed (so it stays
/// right-handed): polar vectors (specific force) flip z, axial vectors (angular velocity) flip x
/// and y.
inline ImuReading mirrorImu(const ImuReading& r) {
  ImuReading m;
  m.acc = {r.acc.x(), r.acc.y(), -r.acc.z()};
  m.gyr = {-r.gyr.x(), -r.gyr.y(), r.gyr.z()};
  return m;
}

/// Maps a whole sample (IMUs and optical positions; true joint angles are the same on both
/// sides). An involution: applying it twice gives the sample back exactly. Camera pixels are
/// left as they are (the camera model handles the side itself).
ArmSample mirrorSample(const ArmSample& s);

}  // namespace armtrack
