// Left and right arms. The model (docs/arm-model.md) is written for the right arm; a left arm is
// its mirror image through the body's sagittal plane. Left-arm data are mapped onto a virtual
// right arm, estimated there, and the joint angles come back unchanged: mirroring keeps flexion,
// abduction, rotation, elbow flexion and pronation what they are.
#pragma once

#include <Eigen/Core>
#include <string>

#include "core/ArmSample.h"

namespace armtrack {

enum class Side { Right, Left };

/// "right" / "left" (case-insensitive); throws std::invalid_argument otherwise.
Side parseSide(const std::string& name);
std::string sideName(Side side);

/// The mirror through the sagittal plane in shoulder-frame coordinates: z0 (lateral for the
/// right arm) changes sign. For a left arm, frame 0 keeps x0 down and y0 forward, and z0 points
/// to the patient's right, i.e. medially.
inline Eigen::Vector3d mirrorPoint(const Eigen::Vector3d& p) {
  return {p.x(), p.y(), -p.z()};
}

/// An IMU reading mapped between a left-arm sensor and its right-arm twin. The twin of a sensor
/// frame is its mirror image with the z axis reversed (so it stays right-handed): polar vectors
/// (specific force) flip z, axial vectors (angular velocity) flip x and y.
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
