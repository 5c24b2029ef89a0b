// The trunk's pose (docs/arm-model.md, "Trunk"). The shoulder frame 0 is fixed to the thorax;
// when the patient leans or turns, frame 0 turns with the thorax relative to the world frame,
// which is frame 0 as it was with the trunk upright at the start. The trunk's three angles follow
// the ISB's thorax order: flexion about the lateral axis, then lateral bending, then axial
// rotation, in the patient's terms (the same numbers for a left and a right arm):
//   flexion > 0 leans forward, lateral bending > 0 leans to the patient's right,
//   axial rotation > 0 brings the right shoulder forward.
// Both arms' own frame 0 have x0 down, y0 forward and z0 to the patient's right
// (core/kinematics/Side.h), and there the trunk's rotation to the world is
// R = Rz(-flexion) Ry(lateral) Rx(-rotation): trunkRotation(a) (Side::Right). The estimator and
// the simulator work on a left arm as its mirror image, a virtual right arm whose z0 is reversed;
// in that frame the same trunk turns by M R M (M = diag(1, 1, -1)), which is
// Rz(-flexion) Ry(-lateral) Rx(rotation): trunkRotation(a, Side::Left).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/kinematics/Side.h"

namespace armtrack {

/// Trunk flexion, lateral bending and axial rotation (rad), in that order.
using TrunkAngles = Eigen::Vector3d;

/// The trunk's rotation to the world (columns: frame 0's axes as the trunk holds them, in world
/// coordinates): in an arm's own frame 0 with Side::Right, in a left arm's mirror image (the
/// virtual right arm) with Side::Left.
inline Eigen::Matrix3d trunkRotation(const TrunkAngles& a, Side side = Side::Right) {
  const double s = side == Side::Left ? -1.0 : 1.0;
  return (Eigen::AngleAxisd(-a(0), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(s * a(1), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(-s * a(2), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

/// The angles of a trunk rotation (the inverse of trunkRotation for |lateral| < 90 deg).
inline TrunkAngles trunkAngles(const Eigen::Matrix3d& r, Side side = Side::Right) {
  // R = Rz(a) Ry(b) Rx(c): R(2,0) = -sin b, R(1,0) / R(0,0) = tan a, R(2,1) / R(2,2) = tan c.
  const double a = std::atan2(r(1, 0), r(0, 0));
  const double b = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  const double c = std::atan2(r(2, 1), r(2, 2));
  const double s = side == Side::Left ? -1.0 : 1.0;
  return {-a, s * b, -s * c};
}

}  // namespace armtrack
