// Internals of the calibration from movement (core/calibration/MovementCalibration.cpp): the
// elbow's relative-motion fit of MovementAxes.cpp and the arm model's relative rotation between
// the two IMU frames. Internal to armtrack_core; docs/calibration.md, "Calibration from movement".
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/kinematics/ArmModel.h"

namespace armtrack::movecal {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

inline Mat3 rotZ(double a) {
  return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix();
}
inline Mat3 rotX(double a) {
  return Eigen::AngleAxisd(a, Vec3::UnitX()).toRotationMatrix();
}

/// The model's upper-arm IMU frame in frame 3 (Table 1 rows 4-6): Rz(thu4) Rx(pi/2).
Mat3 upperImuInFrame3(double thu4);
/// The model's forearm IMU frame in frame 6 (Table 3 rows 7-9): Rz(thf7 + pi/2) Rx(pi/2).
Mat3 forearmImuInFrame6(double thf7);
/// The parts of the model's relative rotation A(th4, th5) = C Rz(th4) D Rz(th5) E, which takes
/// forearm-IMU coordinates into upper-arm-IMU coordinates (both model frames).
struct RelativeModel {
  Mat3 c, d, e;
  Vec3 flexionInUpper;  ///< the elbow flexion axis (z4) in the model's upper-arm IMU frame
};
RelativeModel relativeModel(const ArmGeometry& geo);
Mat3 relativeRotation(const RelativeModel& m, double th4, double th5);

/// What the fit of the elbow's two axes needs: per used instant, the rotation increments of each
/// IMU to the next instant (integrated gyroscopes, bias removed), the specific force of the elbow
/// centre as each IMU sees it, the upper arm's long axis in its IMU's axes (shoulder to elbow).
struct AxesInput {
  RelativeModel model;
  double dt = 0.04;                    ///< s between instants
  std::vector<Mat3> inc1, inc2;        ///< size n - 1
  std::vector<Vec3> ae1, ae2, w1, w2;  ///< size n (w: gyroscopes, bias removed)
  Vec3 longAxis1 = Vec3::UnitY();      ///< unit, upper-arm IMU axes
  double longAxisStd = 0.05;           ///< rad
  /// With a known rest pose: gravity at rest in the upper-arm IMU's axes (unit) and where the
  /// model puts it at that pose (unit, model IMU frame).
  std::optional<Vec3> gravity1, gravityModel1;
  double gravityStd = 2.0 * 3.14159265358979323846 / 180.0;  ///< rad (accelerometer bias)
  double gyroStd = 0.05;                                     ///< rad/s, increment residual
  double accelStd = 0.3;                                     ///< m/s^2
  double priorStd = 0.8;                                     ///< rad, each mounting component
  int maxIterations = 60;
};

struct AxesResult {
  Vec3 w1 = Vec3::Zero();  ///< upper-arm mounting, rotation vector (sensor -> model)
  Eigen::Vector2d w2 = Eigen::Vector2d::Zero();  ///< forearm mounting tilt [x, z]
  Eigen::Matrix<double, 5, 5> cov = Eigen::Matrix<double, 5, 5>::Identity();  ///< of [w1 w2]
  std::vector<Eigen::Vector2d> theta;  ///< [th4 th5] per instant
  double gyroRms = 0.0, accelRms = 0.0;
  bool converged = false;
};

Mat3 expRotation(const Vec3& w);
Mat3 forearmTilt(const Eigen::Vector2d& w2);  ///< exp([x, 0, z])

/// Fits the upper-arm mounting (3), the forearm mounting's tilt (2) and the joint angles th4, th5
/// per instant by nonlinear least squares (Ceres); the forearm's roll about its long axis is the
/// gauge of th5 and stays at zero. Starts from a grid search per instant at the prior mounting.
AxesResult fitAxes(const AxesInput& in);

}  // namespace armtrack::movecal
