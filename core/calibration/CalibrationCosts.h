// Building blocks of the batch calibration (core/calibration/Calibrator.cpp): the uniform cubic
// B-spline of the joint trajectory and the Ceres cost functors on the filter's measurement model.
// Internal to armtrack_core (it includes Ceres); docs/calibration.md, "Formulation".
#pragma once

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "core/estimation/ArmFilter.h"
#include "core/kinematics/ArmModel.h"

namespace armtrack::calib {

using Vec3 = Eigen::Vector3d;
template <typename T>
using Vec5T = Eigen::Matrix<T, 5, 1>;

// ---------------------------------------------------------------------------------------------
// The uniform cubic B-spline of the joint trajectory.

struct SplineGrid {
  double t0 = 0.0, dt = 0.04;
  int segments = 1;
  int controlPoints() const { return segments + 3; }
};

/// Basis weights at time t: th = sum_i w[i] c[first + i], and likewise for rates (bd) and
/// accelerations (bdd).
struct SplineWeights {
  int first = 0;
  double b[4], bd[4], bdd[4];
};

/// The weights at time t (s); t is clamped to the grid.
SplineWeights splineWeights(const SplineGrid& g, double t);

template <typename T>
void evalSpline(const SplineWeights& w, const T* const c[4], Vec5T<T>& th, Vec5T<T>& thd,
                Vec5T<T>& thdd) {
  for (int j = 0; j < kNumJoints; ++j) {
    th(j) = w.b[0] * c[0][j] + w.b[1] * c[1][j] + w.b[2] * c[2][j] + w.b[3] * c[3][j];
    thd(j) = w.bd[0] * c[0][j] + w.bd[1] * c[1][j] + w.bd[2] * c[2][j] + w.bd[3] * c[3][j];
    thdd(j) = w.bdd[0] * c[0][j] + w.bdd[1] * c[1][j] + w.bdd[2] * c[2][j] + w.bdd[3] * c[3][j];
  }
}

/// Least-squares fit of the spline to the filter's angles (unwrapped), with a light second-
/// difference penalty so knots without data stay put.
/// Control points, 5 per knot, joint-major within a knot; fallback where the fit fails.
std::vector<double> fitSpline(const SplineGrid& grid, const std::vector<JointEstimate>& est,
                              const JointVector& fallback);

// ---------------------------------------------------------------------------------------------
// Residuals.

/// Predicted sensor reading from a model-frame vector: R^T v with R = exp([tx, 0, tz]).
template <typename T>
Eigen::Matrix<T, 3, 1> toSensor(const Eigen::Matrix<T, 3, 1>& v, const T& tx, const T& tz) {
  const T negTilt[3] = {-tx, T(0), -tz};
  Eigen::Matrix<T, 3, 1> out;
  ceres::AngleAxisRotatePoint(negTilt, v.data(), out.data());
  return out;
}

/// One binned reading of one IMU.
struct ImuBin {
  double t = 0.0;
  Vec3 gyr = Vec3::Zero(), acc = Vec3::Zero();
  int count = 0;
};

/// One IMU's readings averaged over bins of binSeconds from t0 (the forearm's or the upper arm's);
/// `bias` is taken out while binning and put back, so only the binning sees the guess.
std::vector<ImuBin> binImu(const std::vector<ArmSample>& samples, bool forearm, double t0,
                           double binSeconds, const Vec3& bias);

/// Mean and per-axis standard deviation of one IMU's gyroscope over [from, to].
struct StillStats {
  Vec3 mean = Vec3::Zero();
  double maxStd = 0.0;
  int count = 0;
};

StillStats stillStats(const std::vector<ArmSample>& samples, bool forearm, double from, double to);

struct ImuCost {
  ImuCost(const SplineWeights& w, const ImuBin& bin, const ArmGeometry& nominal, const Vec3& gUp,
          double gyroStd, double accelStd, bool forearm)
      : m_w(w), m_bin(bin), m_nominal(nominal), m_gUp(gUp), m_forearm(forearm) {
    const double n = std::sqrt(static_cast<double>(bin.count));
    m_gyroWeight = n / gyroStd;
    m_accelWeight = n / accelStd;
  }

  /// Parameters: four control points (5 each), mounting (5), bias (3), segments (2).
  template <typename T>
  bool operator()(const T* c0, const T* c1, const T* c2, const T* c3, const T* mount, const T* bias,
                  const T* seg, T* r) const {
    const T* const c[4] = {c0, c1, c2, c3};
    Vec5T<T> th, thd, thdd;
    evalSpline(m_w, c, th, thd, thdd);
    ArmGeometryT<T> geo = geometryAs<T>(m_nominal);
    geo.l3 = seg[0];
    geo.l6 = seg[1];
    const FrameState<T> f3 = shoulderKinematics<T>(th, thd, thdd, m_gUp);
    FrameState<T> imu;
    if (m_forearm) {
      geo.lf6 = mount[0];
      geo.lf8 = mount[1];
      geo.thf7 = mount[2];
      imu = forearmImuKinematics<T>(f3, th, thd, thdd, geo);
    } else {
      geo.lu3 = mount[0];
      geo.lu5 = mount[1];
      geo.thu4 = mount[2];
      imu = upperImuKinematics<T>(f3, geo);
    }
    const Eigen::Matrix<T, 3, 1> acc = imu.up + imu.accel;
    const Eigen::Matrix<T, 3, 1> gyrS = toSensor<T>(imu.omega, mount[3], mount[4]);
    const Eigen::Matrix<T, 3, 1> accS = toSensor<T>(acc, mount[3], mount[4]);
    for (int i = 0; i < 3; ++i) {
      r[i] = (gyrS(i) + bias[i] - m_bin.gyr(i)) * m_gyroWeight;
      r[3 + i] = (accS(i) - m_bin.acc(i)) * m_accelWeight;
    }
    return true;
  }

  SplineWeights m_w;
  ImuBin m_bin;
  ArmGeometry m_nominal;
  Vec3 m_gUp;
  bool m_forearm;
  double m_gyroWeight = 1.0, m_accelWeight = 1.0;
};

struct PositionCost {
  PositionCost(const SplineWeights& w, const Vec3& measured, bool wrist, const ArmGeometry& nominal,
               double std)
      : m_w(w), m_measured(measured), m_wrist(wrist), m_nominal(nominal), m_weight(1.0 / std) {}

  template <typename T>
  bool operator()(const T* c0, const T* c1, const T* c2, const T* c3, const T* seg, T* r) const {
    const T* const c[4] = {c0, c1, c2, c3};
    Vec5T<T> th, thd, thdd;
    evalSpline(m_w, c, th, thd, thdd);
    ArmGeometryT<T> geo = geometryAs<T>(m_nominal);
    geo.l3 = seg[0];
    geo.l6 = seg[1];
    Eigen::Matrix<T, 3, 1> elbow, wrist;
    armPositions<T>(th, geo, elbow, wrist);
    const Eigen::Matrix<T, 3, 1>& p = m_wrist ? wrist : elbow;
    for (int i = 0; i < 3; ++i) r[i] = (p(i) - m_measured(i)) * m_weight;
    return true;
  }

  SplineWeights m_w;
  Vec3 m_measured;
  bool m_wrist;
  ArmGeometry m_nominal;
  double m_weight;
};

/// d . (th(t) - target) / std: the start-pose prior along one direction.
struct StartPoseCost {
  StartPoseCost(const SplineWeights& w, const JointVector& direction, const JointVector& target,
                double std)
      : m_w(w), m_direction(direction), m_target(target), m_weight(1.0 / std) {}

  template <typename T>
  bool operator()(const T* c0, const T* c1, const T* c2, const T* c3, T* r) const {
    const T* const c[4] = {c0, c1, c2, c3};
    Vec5T<T> th, thd, thdd;
    evalSpline(m_w, c, th, thd, thdd);
    T s(0);
    for (int j = 0; j < kNumJoints; ++j) s += m_direction(j) * (th(j) - m_target(j));
    r[0] = s * m_weight;
    return true;
  }

  SplineWeights m_w;
  JointVector m_direction, m_target;
  double m_weight;
};

/// A ceres::NormalPrior with independent components: (x - mean) / std.
ceres::CostFunction* normalPrior(const Eigen::VectorXd& mean, const Eigen::VectorXd& std);

}  // namespace armtrack::calib
