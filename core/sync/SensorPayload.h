// What a sensor stream carries: its role in the arm's data (which part of an ArmSample it fills)
// and the payload of one of its samples. Plain C++20 + Eigen: devices produce these, the
// synchroniser and the row assembler consume them.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <variant>

#include "core/ArmSample.h"

namespace armtrack {

/// What one stream measures, and so which part of an ArmSample its samples fill.
enum class StreamRole {
  UpperArmImu,  ///< ImuReading in the upper-arm sensor's axes
  ForearmImu,   ///< ImuReading in the forearm sensor's axes
  Optical,      ///< OpticalPositions in the shoulder frame (m)
  Camera,       ///< MarkerPixels in the camera image (pixels)
  Truth,        ///< TruthAngles of a simulated arm (rad)
  TrunkImu,     ///< ImuReading in the sternum (trunk) sensor's axes (docs/trunk.md)
};
/// "upper-arm IMU", "forearm IMU", "optical positions", "camera markers", "true angles",
/// "trunk IMU".
const char* toString(StreamRole role);

/// Kinect (or external tracker) positions (m): in the shoulder frame, or, when the session has a
/// trunk IMU or a shoulder, in the world frame (frame 0 with the trunk upright at the start;
/// docs/recording-format.md). The shoulder centre, where the tracker sees it, is the optional
/// `shoulder_*` group of a recording.
struct OpticalPositions {
  std::optional<Eigen::Vector3d> elbow;
  std::optional<Eigen::Vector3d> wrist;
  std::optional<Eigen::Vector3d> shoulder;
};

/// Webcam marker pixels (u, v).
struct MarkerPixels {
  std::optional<Eigen::Vector2d> wrist;
  std::optional<Eigen::Vector2d> elbow;
};

/// The true joint angles (rad) of a simulated arm, for end-to-end accuracy checks.
struct TruthAngles {
  JointVector th = JointVector::Zero();
  /// The simulated trunk's flexion, lateral bending and axial rotation (rad, patient terms,
  /// core/kinematics/Trunk.h), when the simulation has a trunk.
  std::optional<Eigen::Vector3d> trunk;
};

/// Payload of a sensor sample: an IMU reading, optical positions, marker pixels or simulated truth.
using SensorPayload = std::variant<ImuReading, OpticalPositions, MarkerPixels, TruthAngles>;

/// True when the payload is the kind the role promises and every value in it is finite.
bool validPayload(StreamRole role, const SensorPayload& payload);

}  // namespace armtrack
