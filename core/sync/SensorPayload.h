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
};
/// "upper-arm IMU", "forearm IMU", "optical positions", "camera markers", "true angles".
const char* toString(StreamRole role);

/// Kinect (or external tracker) positions in the shoulder frame (m).
struct OpticalPositions {
  std::optional<Eigen::Vector3d> elbow;
  std::optional<Eigen::Vector3d> wrist;
};

/// Webcam marker pixels (u, v).
struct MarkerPixels {
  std::optional<Eigen::Vector2d> wrist;
  std::optional<Eigen::Vector2d> elbow;
};

/// The true joint angles (rad) of a simulated arm, for end-to-end accuracy checks.
struct TruthAngles {
  JointVector th = JointVector::Zero();
};

/// Payload of a sensor sample: an IMU reading, optical positions, marker pixels or simulated truth.
using SensorPayload = std::variant<ImuReading, OpticalPositions, MarkerPixels, TruthAngles>;

/// True when the payload is the kind the role promises and every value in it is finite.
bool validPayload(StreamRole role, const SensorPayload& payload);

}  // namespace armtrack
