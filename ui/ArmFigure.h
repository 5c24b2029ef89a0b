// What the 3D view draws of an arm, in metres in the shoulder frame of the arm's own side
// (docs/arm-model.md: x0 down, y0 forward, z0 to the patient's right), computed from the arm
// model's forward kinematics. Plain C++ and Eigen: the scene and the tests share it.
#pragma once

#include <Eigen/Geometry>

#include "core/kinematics/ArmModel.h"
#include "core/kinematics/Side.h"

namespace armtrack::ui {

struct ArmFigure {
  Eigen::Vector3d shoulder = Eigen::Vector3d::Zero();
  Eigen::Vector3d elbow = Eigen::Vector3d::Zero();
  Eigen::Vector3d wrist = Eigen::Vector3d::Zero();
  /// The sensors' frames: origin where the model puts the sensor (its strap radius from the
  /// segment's axis), axes the sensor's own (right-handed for either side).
  Eigen::Isometry3d upperImu = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d forearmImu = Eigen::Isometry3d::Identity();
  /// Where each strap goes round its segment (on the segment's axis).
  Eigen::Vector3d upperStrap = Eigen::Vector3d::Zero();
  Eigen::Vector3d forearmStrap = Eigen::Vector3d::Zero();
  /// The hand's frame at the wrist: x along the forearm, z across the palm's thickness (thumb
  /// forward at zero pose means the palm faces the body), y = z x x.
  Eigen::Matrix3d hand = Eigen::Matrix3d::Identity();
};

/// The figure of an arm at joint angles th (rad). A left arm is the mirror image of the right
/// arm with the same angles (core/kinematics/Side.h): points p -> S p and frames F -> S F D with
/// S = D = diag(1, 1, -1).
ArmFigure armFigure(const ArmGeometry& geometry, const JointVector& th, Side side);

/// The figure carried by a rigid motion (the trunk's pose: the arm hangs from the moving
/// shoulder): points p -> T p, frames F -> R F.
ArmFigure transformed(const ArmFigure& figure, const Eigen::Isometry3d& motion);

/// The unit vector towards the body's midline in the shoulder frame of that side: -z0 for the
/// right arm, +z0 for the left.
Eigen::Vector3d medialDirection(Side side);

}  // namespace armtrack::ui
