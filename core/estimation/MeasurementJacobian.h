// The filter's measurement model with its Jacobian, differentiated by hand through the arm's
// recursion (core/kinematics/ArmModel.h): the same predictions as armKinematics, and the same
// derivatives as automatic differentiation over the 15 states, at a fraction of the cost.
// Qt-free; no allocation.
#pragma once

#include <Eigen/Core>

#include "core/kinematics/ArmModel.h"

namespace armtrack {

/// Rows of the model: upper-arm gyroscope, upper-arm accelerometer, forearm gyroscope, forearm
/// accelerometer, elbow position, wrist position (3 each, eq. 16's order).
inline constexpr int kMeasurementModelRows = 18;
/// The state [th'' th' th] (rad/s^2, rad/s, rad), 5 joints each.
inline constexpr int kMeasurementStates = 15;

using ModelReadings = Eigen::Matrix<double, kMeasurementModelRows, 1>;
using ModelJacobian = Eigen::Matrix<double, kMeasurementModelRows, kMeasurementStates>;

/// Predicted readings h(x) for the state x (gyroscopes rad/s, accelerometers m/s^2 as specific
/// force: g up plus, when bodyAccel, the body acceleration; positions m in frame 0), and when jac
/// is given, dh/dx. gUp is g times the unit vector up in frame 0 (m/s^2). Forward-mode
/// differentiation written out for the arm, in place on one frame per chain: each frame's
/// derivatives are computed only for the joints before it, gravity's only with respect to angles,
/// positions' only with respect to angles, and the body acceleration only when bodyAccel.
/// Without positions, the elbow and wrist rows (12-17) of h and jac are not written: a sample
/// without optical data needs the IMU rows alone.
void predictReadings(const ArmGeometry& geometry, const Eigen::Vector3d& gUp, bool bodyAccel,
                     const Eigen::Matrix<double, kMeasurementStates, 1>& x, ModelReadings& h,
                     ModelJacobian* jac, bool positions = true);
/// The same with frame 0 moving with the trunk: base is its motion (armKinematics' base).
void predictReadings(const ArmGeometry& geometry, const FrameState<double>& base, bool bodyAccel,
                     const Eigen::Matrix<double, kMeasurementStates, 1>& x, ModelReadings& h,
                     ModelJacobian* jac, bool positions = true);

}  // namespace armtrack
