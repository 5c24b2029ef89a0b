#include "core/calibration/TrajectoryMoves.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "core/estimation/Heading.h"

namespace armtrack::calib {

Vec3 DeadReckoning::gyro(int imu, double t) const {
  const std::vector<ImuBin>& b = bins[imu];
  const double* bias = imu == 0 ? biasUa : biasFa;
  const auto it =
      std::lower_bound(b.begin(), b.end(), t, [](const ImuBin& x, double v) { return x.t < v; });
  Vec3 g;
  if (it == b.begin()) {
    g = b.front().gyr;
  } else if (it == b.end()) {
    g = b.back().gyr;
  } else {
    const ImuBin& hi = *it;
    const ImuBin& lo = *(it - 1);
    const double u = (t - lo.t) / (hi.t - lo.t);
    g = (1.0 - u) * lo.gyr + u * hi.gyr;
  }
  return g - Vec3(bias[0], bias[1], bias[2]);
}

Eigen::Matrix<double, 6, 1> DeadReckoning::predict(const JointVector& th,
                                                   const JointVector& thd) const {
  ArmGeometryT<double> geo = geometryAs<double>(nominal);
  geo.l3 = seg[0];
  geo.l6 = seg[1];
  geo.lu3 = mountUa[0];
  geo.lu5 = mountUa[1];
  geo.thu4 = mountUa[2];
  geo.lf6 = mountFa[0];
  geo.lf8 = mountFa[1];
  geo.thf7 = mountFa[2];
  const JointVector zero = JointVector::Zero();
  const FrameState<double> f3 = shoulderKinematics<double>(th, thd, zero, gUp);
  const FrameState<double> u = upperImuKinematics<double>(f3, geo);
  const FrameState<double> f = forearmImuKinematics<double>(f3, th, thd, zero, geo);
  Eigen::Matrix<double, 6, 1> out;
  out.head<3>() = toSensor<double>(u.omega, mountUa[3], mountUa[4]);
  out.tail<3>() = toSensor<double>(f.omega, mountFa[3], mountFa[4]);
  return out;
}

JointVector DeadReckoning::rates(const JointVector& th, double t) const {
  Eigen::Matrix<double, 6, kNumJoints> a;
  for (int k = 0; k < kNumJoints; ++k) a.col(k) = predict(th, JointVector::Unit(k));
  Eigen::Matrix<double, 6, 1> b;
  b << gyro(0, t), gyro(1, t);
  const Eigen::Matrix<double, kNumJoints, kNumJoints> n =
      a.transpose() * a + 1e-6 * Eigen::Matrix<double, kNumJoints, kNumJoints>::Identity();
  return n.ldlt().solve(a.transpose() * b);
}

void DeadReckoning::extend(std::vector<double>& ctrl, double from, double to) const {
  const int n = grid.controlPoints();
  const SplineWeights w0 = splineWeights(grid, from);
  const double* const c[4] = {ctrl.data() + 5 * w0.first, ctrl.data() + 5 * (w0.first + 1),
                              ctrl.data() + 5 * (w0.first + 2), ctrl.data() + 5 * (w0.first + 3)};
  Vec5T<double> th5, thd5, thdd5;
  evalSpline(w0, c, th5, thd5, thdd5);
  JointVector th = th5;
  double t = from;
  for (int i = w0.first + 4; i < n; ++i) {
    const double knotTime = grid.t0 + (i - 1) * grid.dt;
    if (knotTime > to) break;
    const int steps = std::max(1, static_cast<int>(std::ceil((knotTime - t) / (grid.dt / 4))));
    const double h = (knotTime - t) / steps;
    for (int k = 0; k < steps; ++k) {
      const JointVector r1 = rates(th, t);
      const JointVector mid = th + 0.5 * h * r1;
      th += h * rates(mid, t + 0.5 * h);
      t += h;
    }
    Eigen::Map<JointVector>(ctrl.data() + 5 * i) = th;
  }
}

JointVector unwrappedNear(const JointVector& turned, const JointVector& near) {
  JointVector out = turned;
  for (int j = 0; j < kNumJoints; ++j) out(j) = near(j) + wrapAngle(turned(j) - near(j));
  return out;
}

void turnKnots(std::vector<double>& ctrl, int from, double alpha, const Vec3& up,
               const JointVector* seedOrig, const JointVector* seedTurned) {
  const int n = static_cast<int>(ctrl.size()) / kNumJoints;
  const bool seeded = seedOrig && seedTurned;
  JointVector prev = seeded ? *seedOrig : JointVector::Zero();
  JointVector prevTurned = seeded ? *seedTurned : JointVector::Zero();
  for (int i = from; i < n; ++i) {
    Eigen::Map<JointVector> c(ctrl.data() + kNumJoints * i);
    const JointVector orig = c;
    const JointVector guess = i == from && !seeded ? orig : JointVector(prevTurned + (orig - prev));
    const JointVector turned = unwrappedNear(turnAboutVertical(orig, alpha, up), guess);
    prev = orig;
    prevTurned = turned;
    c = turned;
  }
}

}  // namespace armtrack::calib
