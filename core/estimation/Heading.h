// The arm's heading: turning the whole arm about the vertical through the shoulder changes no IMU
// reading (gravity and the arm's own motion turn with it), so only optical data can see it.
// These functions describe that turn in joint space, to first order for the filter's updates and
// exactly for the uncertainty it reports (docs/estimator.md, "Heading").
#pragma once

#include <Eigen/Core>

#include "core/kinematics/ArmModel.h"

namespace armtrack {

/// Joint rates that turn the whole arm about `up` (frame 0) at 1 rad/s; elbow entries zero.
/// Damped at the shoulder's gimbal lock, exact elsewhere.
JointVector headingGenerator(const JointVector& th, const Eigen::Vector3d& up);

/// What the heading functions below compute first at a set of angles, for a caller that asks
/// several of them at the same angles: the cosines and sines of th0 and th1, the shoulder axes
/// J_s (columns z0, z1, z2 in frame 0), the inverse of the damped J_s J_s^T, and the generator
/// (headingGenerator).
struct HeadingGeometry {
  double c0 = 1, s0 = 0, c1 = 1, s1 = 0;
  Eigen::Matrix3d axes, normalInverse;
  JointVector generator;
};
HeadingGeometry headingGeometry(const JointVector& th, const Eigen::Vector3d& up);

/// The turn about the vertical that a small change of the joint angles makes: the vertical part
/// of the upper arm's rotation, up . (J_s dth), as a row over the five angles (elbow entries
/// zero). It reads 1 along headingGenerator and 0 along every change that only tilts the arm.
JointVector headingCovector(const JointVector& th, const Eigen::Vector3d& up);
/// The same, from the geometry at th.
JointVector headingCovector(const HeadingGeometry& g, const Eigen::Vector3d& up);

/// The heading direction in joint space at th: the joint-rate direction that turns the whole arm
/// about the vertical through the shoulder (unit norm, elbow entries zero).
JointVector headingDirection(const JointVector& th, const Eigen::Vector3d& up);

/// The full-state direction (15 = [th'' th' th]) along which turning the whole arm about the
/// vertical moves the state: th along h, and the rates and accelerations as the turn carries
/// them. Scaled so its th part has unit norm. IMU readings are constant along it.
Eigen::Matrix<double, 15, 1> headingSymmetry(const Eigen::Matrix<double, 15, 1>& x,
                                             const Eigen::Vector3d& up);
/// The same, given headingGeometry(x's angles, up).
Eigen::Matrix<double, 15, 1> headingSymmetry(const Eigen::Matrix<double, 15, 1>& x,
                                             const Eigen::Vector3d& up, const HeadingGeometry& g);

/// The joint angles of the same arm turned by `angle` (rad, right-handed about `up`) about the
/// vertical through the shoulder: the finite turn whose first-order step is headingGenerator.
/// The elbow angles are unchanged; the shoulder angles are the branch reached by turning
/// continuously from th, so they stay near th for small turns. Angles are wrapped to (-pi, pi].
JointVector turnAboutVertical(const JointVector& th, double angle, const Eigen::Vector3d& up);

/// The second moment of each shoulder joint's change (rad^2) when the arm at th is turned about
/// the vertical by an angle drawn from N(0, turnStd^2) (truncated at half a circle): the exact
/// turn (turnAboutVertical) summed over turns half a standard deviation apart. Elbow entries
/// are zero.
JointVector turnSecondMoment(const JointVector& th, double turnStd, const Eigen::Vector3d& up);

}  // namespace armtrack
