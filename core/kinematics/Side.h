// Left and right arms. The model (docs/arm-model.md) is written for the right arm; a left arm is
// its mirror image through the body's sagittal plane. Left-arm data are mapped onto a virtual
// right arm, estimated there, and the joint angles come back unchanged: mirroring keeps flexion,
// abduction, rotation, elbow flexion and pronation what they are. The mirror of a whole sample
// (mirrorImu, mirrorSample) is in core/ArmSample.h, which builds on this header.
#pragma once

#include <Eigen/Core>
#include <string>

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

/// The same mirror for a rotation between two mirrored frames, D R D with D = diag(1, 1, -1): a
/// sensor's axes F (columns in frame 0) become those of its twin (z reversed, still right-handed),
/// and a turn of frame 0 becomes the mirror image's turn. An involution.
inline Eigen::Matrix3d mirrorRotation(const Eigen::Matrix3d& r) {
  const Eigen::Matrix3d d = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();
  return d * r * d;
}

}  // namespace armtrack
