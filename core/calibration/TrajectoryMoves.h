// Moves of the calibration's fitted joint trajectory (core/calibration/Calibrator.cpp) that the
// solver cannot make well by itself: extending it past the data fitted so far by dead reckoning
// on the gyroscopes, and turning it about the vertical, which no IMU reading sees.
// Internal to armtrack_core; docs/calibration.md, "Formulation".
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/calibration/CalibrationCosts.h"
#include "core/kinematics/ArmModel.h"

namespace armtrack::calib {

/// Continues a solved trajectory by integrating the joint rates that best explain both
/// gyroscopes (least squares, 6 readings for 5 rates), with the current calibration.
struct DeadReckoning {
  const SplineGrid& grid;
  const std::vector<ImuBin> (&bins)[2];
  const ArmGeometry& nominal;
  const Vec3& gUp;
  const double* mountUa;
  const double* mountFa;
  const double* biasUa;
  const double* biasFa;
  const double* seg;

  /// Gyro reading of one IMU at time t, bias removed, linearly interpolated between bins.
  Vec3 gyro(int imu, double t) const;
  /// Predicted gyros [upper; forearm] in the sensors' axes for angles th and rates thd.
  Eigen::Matrix<double, 6, 1> predict(const JointVector& th, const JointVector& thd) const;
  /// The joint rates that best explain both gyroscopes at time t, at angles th.
  JointVector rates(const JointVector& th, double t) const;
  /// Sets the control points whose knot time lies in (from, to] by integrating from the
  /// trajectory's value at `from` (midpoint rule, steps of at most a quarter knot spacing).
  /// Knot i is tied to time t0 + (i - 1) dt, where th ~ c_i.
  void extend(std::vector<double>& ctrl, double from, double to) const;
};

/// `turned` moved by whole turns, joint by joint, to lie within half a turn of `near`: the finite
/// turn about the vertical gives wrapped angles, a spline's control points must stay continuous.
JointVector unwrappedNear(const JointVector& turned, const JointVector& near);

/// Turns knots [from, end) of a control-point vector about the vertical by alpha. Each knot is
/// unwrapped next to its predecessor's turn plus its own step, so the result stays on one branch
/// of the shoulder angles and continuous.
/// seedOrig/seedTurned: a knot before `from` and its turned value, to start the chain from.
void turnKnots(std::vector<double>& ctrl, int from, double alpha, const Vec3& up,
               const JointVector* seedOrig = nullptr, const JointVector* seedTurned = nullptr);

}  // namespace armtrack::calib
