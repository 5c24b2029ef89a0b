// Batch calibration by Ceres. Layout of the problem (docs/calibration.md, "Formulation"):
//   - joint trajectory: uniform cubic B-spline, one 5-vector control point per knot;
//   - per IMU a mounting block [l_axial, l_radial, strap angle, tilt_x, tilt_z] and a gyro bias;
//   - segment lengths [l3, l6], estimated only with optical positions;
//   - residuals: binned gyro/accelerometer readings of both IMUs, optical elbow/wrist positions,
//     the start-pose prior along the gauge directions, weak priors on the calibration blocks.
#include "core/calibration/Calibrator.h"

#include <ceres/ceres.h>
#include <ceres/normal_prior.h>
#include <ceres/rotation.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "core/estimation/ArmFilter.h"
#include "core/kinematics/Side.h"

namespace armtrack {
namespace {

constexpr double kMinDuration = 10.0;  // s
// The start-pose prior only fixes gauges (directions the data cannot see), so it can be stiff;
// a stiff one keeps the solver's damped steps from drifting along them (rad).
constexpr double kGaugeStd = 0.01 * std::numbers::pi / 180.0;

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

SplineWeights splineWeights(const SplineGrid& g, double t) {
  const double s = (t - g.t0) / g.dt;
  int j = static_cast<int>(std::floor(s));
  j = std::clamp(j, 0, g.segments - 1);
  const double u = s - j;
  SplineWeights w;
  w.first = j;
  const double u2 = u * u, u3 = u2 * u, v = 1.0 - u;
  w.b[0] = v * v * v / 6.0;
  w.b[1] = (3.0 * u3 - 6.0 * u2 + 4.0) / 6.0;
  w.b[2] = (-3.0 * u3 + 3.0 * u2 + 3.0 * u + 1.0) / 6.0;
  w.b[3] = u3 / 6.0;
  const double i1 = 1.0 / g.dt, i2 = i1 * i1;
  w.bd[0] = -0.5 * v * v * i1;
  w.bd[1] = (1.5 * u2 - 2.0 * u) * i1;
  w.bd[2] = (-1.5 * u2 + u + 0.5) * i1;
  w.bd[3] = 0.5 * u2 * i1;
  w.bdd[0] = v * i2;
  w.bdd[1] = (3.0 * u - 2.0) * i2;
  w.bdd[2] = (1.0 - 3.0 * u) * i2;
  w.bdd[3] = u * i2;
  return w;
}

template <typename T>
void evalSpline(const SplineWeights& w, const T* const c[4], Vec5T<T>& th, Vec5T<T>& thd,
                Vec5T<T>& thdd) {
  for (int j = 0; j < kNumJoints; ++j) {
    th(j) = w.b[0] * c[0][j] + w.b[1] * c[1][j] + w.b[2] * c[2][j] + w.b[3] * c[3][j];
    thd(j) = w.bd[0] * c[0][j] + w.bd[1] * c[1][j] + w.bd[2] * c[2][j] + w.bd[3] * c[3][j];
    thdd(j) = w.bdd[0] * c[0][j] + w.bdd[1] * c[1][j] + w.bdd[2] * c[2][j] + w.bdd[3] * c[3][j];
  }
}

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

ceres::CostFunction* normalPrior(const Eigen::VectorXd& mean, const Eigen::VectorXd& std) {
  const Eigen::MatrixXd a = std.cwiseInverse().asDiagonal();
  return new ceres::NormalPrior(a, mean);
}

// ---------------------------------------------------------------------------------------------
// Preparation.

std::vector<ImuBin> binImu(const std::vector<ArmSample>& samples, bool forearm, double t0,
                           double binSeconds, const Vec3& bias) {
  std::vector<ImuBin> bins;
  long current = -1;
  ImuBin acc;
  auto flush = [&] {
    if (acc.count > 0) {
      acc.t /= acc.count;
      acc.gyr /= acc.count;
      acc.acc /= acc.count;
      bins.push_back(acc);
    }
    acc = ImuBin{};
  };
  for (const ArmSample& s : samples) {
    const std::optional<ImuReading>& r = forearm ? s.forearm : s.upperArm;
    if (!r || !r->gyr.allFinite() || !r->acc.allFinite() || !std::isfinite(s.t)) continue;
    const long k = static_cast<long>(std::floor((s.t - t0) / binSeconds));
    if (k != current) {
      flush();
      current = k;
    }
    acc.t += s.t;
    acc.gyr += r->gyr - bias;
    acc.acc += r->acc;
    ++acc.count;
  }
  flush();
  // The bias guess is subtracted for binning only; the residual adds the fitted bias back.
  for (ImuBin& b : bins) b.gyr += bias;
  return bins;
}

/// Mean and per-axis standard deviation of one IMU's gyroscope over [from, to].
struct StillStats {
  Vec3 mean = Vec3::Zero();
  double maxStd = 0.0;
  int count = 0;
};

StillStats stillStats(const std::vector<ArmSample>& samples, bool forearm, double from, double to) {
  StillStats st;
  Vec3 sum = Vec3::Zero(), sumSq = Vec3::Zero();
  for (const ArmSample& s : samples) {
    if (s.t < from || s.t > to) continue;
    const std::optional<ImuReading>& r = forearm ? s.forearm : s.upperArm;
    if (!r || !r->gyr.allFinite()) continue;
    sum += r->gyr;
    sumSq += r->gyr.cwiseProduct(r->gyr);
    ++st.count;
  }
  if (st.count == 0) return st;
  st.mean = sum / st.count;
  const Vec3 var = (sumSq / st.count - st.mean.cwiseProduct(st.mean)).cwiseMax(0.0);
  st.maxStd = std::sqrt(var.maxCoeff());
  return st;
}

/// Least-squares fit of the spline to the filter's angles (unwrapped), with a light second-
/// difference penalty so knots without data stay put.
std::vector<double> fitSpline(const SplineGrid& grid, const std::vector<JointEstimate>& est,
                              const JointVector& fallback) {
  const int k = grid.controlPoints();
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(k, kNumJoints);
  JointVector prev = JointVector::Zero(), offset = JointVector::Zero();
  bool first = true;
  for (const JointEstimate& e : est) {
    JointVector th = e.th;
    if (!th.allFinite()) continue;
    if (first) {
      first = false;
    } else {
      for (int j = 0; j < kNumJoints; ++j) {
        const double d = th(j) + offset(j) - prev(j);
        offset(j) -= 2.0 * std::numbers::pi * std::round(d / (2.0 * std::numbers::pi));
      }
    }
    th += offset;
    prev = th;
    const SplineWeights w = splineWeights(grid, e.t);
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) trip.emplace_back(w.first + a, w.first + b, w.b[a] * w.b[b]);
      rhs.row(w.first + a) += w.b[a] * th.transpose();
    }
  }
  // Second differences of the control points, weighted lightly, plus a tiny pull to fallback.
  const double smooth = 1e-3, ridge = 1e-9;
  for (int i = 0; i + 2 < k; ++i) {
    const int idx[3] = {i, i + 1, i + 2};
    const double c[3] = {1.0, -2.0, 1.0};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) trip.emplace_back(idx[a], idx[b], smooth * c[a] * c[b]);
  }
  for (int i = 0; i < k; ++i) {
    trip.emplace_back(i, i, ridge);
    rhs.row(i) += ridge * fallback.transpose();
  }
  Eigen::SparseMatrix<double> ata(k, k);
  ata.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(ata);
  std::vector<double> ctrl(static_cast<std::size_t>(k) * kNumJoints);
  if (solver.info() != Eigen::Success) {
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < kNumJoints; ++j) ctrl[5 * i + j] = fallback(j);
    return ctrl;
  }
  const Eigen::MatrixXd x = solver.solve(rhs);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < kNumJoints; ++j) ctrl[5 * i + j] = x(i, j);
  return ctrl;
}

class ProgressCallback final : public ceres::IterationCallback {
 public:
  explicit ProgressCallback(const CalibrationProgress& progress) : m_progress(progress) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (m_progress) {
      char line[160];
      std::snprintf(line, sizeof line, "calibrate: iteration %d, cost %.6g, step %s, %.1f s",
                    s.iteration, s.cost, s.step_is_successful ? "taken" : "rejected",
                    s.cumulative_time_in_seconds);
      m_progress(line);
    }
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const CalibrationProgress& m_progress;
};

double rmsOf(ceres::Problem& problem, const std::vector<ceres::ResidualBlockId>& blocks, int offset,
             int stride, int count) {
  if (blocks.empty()) return 0.0;
  ceres::Problem::EvaluateOptions opt;
  opt.residual_blocks = blocks;
  opt.apply_loss_function = false;
  std::vector<double> r;
  problem.Evaluate(opt, nullptr, &r, nullptr, nullptr);
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i + stride <= r.size(); i += stride) {
    for (int k = 0; k < count; ++k) sum += r[i + offset + k] * r[i + offset + k];
    n += count;
  }
  return n ? std::sqrt(sum / n) : 0.0;
}

/// Orientation of frame 3 (the upper arm) in frame 0 for shoulder angles th0..th2.
Eigen::Matrix3d shoulderRotation(const JointVector& th) {
  const auto rz = [](double a) { return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix(); };
  const Eigen::Matrix3d rx =
      Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitX()).toRotationMatrix();
  return rz(th(0)) * rx * rz(th(1) + std::numbers::pi / 2) * rx * rz(th(2));
}

/// th with the whole arm turned by alpha (rad) about the vertical through the shoulder: the
/// shoulder angles that give Rot(up, alpha) * R03(th), by Gauss-Newton from th (elbow unchanged).
/// guess: where Gauss-Newton starts (default th), so that consecutive knots stay on one branch.
JointVector turnAboutVertical(const JointVector& th, double alpha, const Vec3& up,
                              const JointVector* guess = nullptr) {
  const Eigen::Matrix3d target =
      Eigen::AngleAxisd(alpha, up.normalized()).toRotationMatrix() * shoulderRotation(th);
  JointVector x = guess ? *guess : th;
  x.tail<2>() = th.tail<2>();
  auto residual = [&](const JointVector& q) {
    const Eigen::AngleAxisd e(shoulderRotation(q).transpose() * target);
    return Vec3(e.angle() * e.axis());
  };
  for (int it = 0; it < 20; ++it) {
    const Vec3 r = residual(x);
    if (r.norm() < 1e-12) break;
    Eigen::Matrix3d jac;
    for (int k = 0; k < 3; ++k) {
      JointVector q = x;
      const double h = 1e-7;
      q(k) += h;
      jac.col(k) = (residual(q) - r) / h;
    }
    x.head<3>() -= jac.completeOrthogonalDecomposition().solve(r);
  }
  return x;
}

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
  Vec3 gyro(int imu, double t) const {
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

  /// Predicted gyros [upper; forearm] in the sensors' axes for angles th and rates thd.
  Eigen::Matrix<double, 6, 1> predict(const JointVector& th, const JointVector& thd) const {
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

  JointVector rates(const JointVector& th, double t) const {
    Eigen::Matrix<double, 6, kNumJoints> a;
    for (int k = 0; k < kNumJoints; ++k) a.col(k) = predict(th, JointVector::Unit(k));
    Eigen::Matrix<double, 6, 1> b;
    b << gyro(0, t), gyro(1, t);
    const Eigen::Matrix<double, kNumJoints, kNumJoints> n =
        a.transpose() * a + 1e-6 * Eigen::Matrix<double, kNumJoints, kNumJoints>::Identity();
    return n.ldlt().solve(a.transpose() * b);
  }

  /// Sets the control points whose knot time lies in (from, to] by integrating from the
  /// trajectory's value at `from` (midpoint rule, steps of at most a quarter knot spacing).
  /// Knot i is tied to time t0 + (i - 1) dt, where th ~ c_i.
  void extend(std::vector<double>& ctrl, double from, double to) const {
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
};

/// Turns knots [from, end) of a control-point vector about the vertical by alpha. Each knot
/// starts Gauss-Newton from its turned predecessor, so the result stays on one branch of the
/// shoulder angles and continuous.
/// seedOrig/seedTurned: a knot before `from` and its turned value, to start the chain from.
void turnKnots(std::vector<double>& ctrl, int from, double alpha, const Vec3& up,
               const JointVector* seedOrig = nullptr, const JointVector* seedTurned = nullptr) {
  const int n = static_cast<int>(ctrl.size()) / kNumJoints;
  const bool seeded = seedOrig && seedTurned;
  JointVector prev = seeded ? *seedOrig : JointVector::Zero();
  JointVector prevTurned = seeded ? *seedTurned : JointVector::Zero();
  for (int i = from; i < n; ++i) {
    Eigen::Map<JointVector> c(ctrl.data() + kNumJoints * i);
    const JointVector orig = c;
    const JointVector guess = i == from && !seeded ? orig : JointVector(prevTurned + (orig - prev));
    const JointVector turned = turnAboutVertical(orig, alpha, up, &guess);
    prev = orig;
    prevTurned = turned;
    c = turned;
  }
}

}  // namespace

Eigen::Matrix3d mountingRotation(double strapAngle, double referenceStrapAngle,
                                 const Eigen::Matrix3d& residual) {
  return Eigen::AngleAxisd(strapAngle - referenceStrapAngle, Vec3::UnitY()).toRotationMatrix() *
         residual;
}

CalibrationResult calibrate(const Recording& recording, const CalibrationOptions& options,
                            const CalibrationProgress& progress) {
  const auto wallStart = std::chrono::steady_clock::now();
  auto say = [&](const std::string& line) {
    if (progress) progress(line);
  };
  CalibrationResult result;
  const bool left = recording.meta.side == Side::Left;
  const ArmGeometry nominal = recording.meta.geometry;
  const Vec3 up = left ? mirrorPoint(recording.meta.up) : recording.meta.up;
  const Vec3 gUp = recording.meta.g * up;

  // Everything is fitted on the right-arm twin (core/kinematics/Side.h).
  std::vector<ArmSample> samples;
  samples.reserve(recording.samples.size());
  bool hasUpper = false, hasForearm = false, hasOptical = false;
  double tFirst = std::numeric_limits<double>::infinity(), tLast = -tFirst;
  for (const ArmSample& s : recording.samples) {
    samples.push_back(left ? mirrorSample(s) : s);
    hasUpper |= s.upperArm.has_value();
    hasForearm |= s.forearm.has_value();
    hasOptical |= s.elbow.has_value() || s.wrist.has_value();
    if (s.hasImu() && std::isfinite(s.t)) {
      tFirst = std::min(tFirst, s.t);
      tLast = std::max(tLast, s.t);
    }
  }
  if (!hasUpper || !hasForearm)
    throw std::invalid_argument("calibration needs both the upper-arm and the forearm IMU");
  if (!(tLast - tFirst >= kMinDuration)) {
    throw std::invalid_argument(
        "calibration needs at least 10 s of IMU data (the protocol takes "
        "about a minute)");
  }
  const bool optical = hasOptical && options.useOptical;

  // 1. Still start: first gyroscope-bias guess.
  const double stillEnd = tFirst + options.startStillSeconds;
  Vec3 biasGuess[2];
  for (int imu = 0; imu < 2; ++imu) {
    const StillStats st = stillStats(samples, imu == 1, tFirst, stillEnd);
    const char* name = imu == 0 ? "upper-arm" : "forearm";
    // Noise alone gives the per-reading std; a moving arm gives tens of deg/s.
    const double limit = 3.0 * options.gyroStd + 2.0 * kDeg;
    if (st.count < 10 || st.maxStd > limit) {
      result.warnings.push_back(std::string("the ") + name +
                                " IMU was not still during the first " +
                                std::to_string(options.startStillSeconds) +
                                " s: no bias guess from the start, and the start-pose assumption "
                                "may not hold");
      biasGuess[imu].setZero();
    } else {
      biasGuess[imu] = st.mean;
    }
  }
  {
    char line[200];
    std::snprintf(line, sizeof line,
                  "calibrate: start-pose gyro bias guess upper [%.3f %.3f %.3f], forearm "
                  "[%.3f %.3f %.3f] deg/s",
                  biasGuess[0].x() / kDeg, biasGuess[0].y() / kDeg, biasGuess[0].z() / kDeg,
                  biasGuess[1].x() / kDeg, biasGuess[1].y() / kDeg, biasGuess[1].z() / kDeg);
    say(line);
  }

  // 2. First trajectory from the EKF with the nominal mounting and the bias guess.
  std::vector<ArmSample> corrected = samples;
  for (ArmSample& s : corrected) {
    if (s.upperArm) s.upperArm->gyr -= biasGuess[0];
    if (s.forearm) s.forearm->gyr -= biasGuess[1];
  }
  EstimatorParams ekf;
  ekf.geometry = nominal;
  ekf.gUp = gUp;
  ekf.side = Side::Right;
  ekf.useOptical = optical;
  ekf.jointAccelVariance = options.initialFilterJointAccelStd * options.initialFilterJointAccelStd;
  const BatchResult first = estimateSamples(corrected, ekf);
  corrected.clear();
  corrected.shrink_to_fit();
  if (first.estimates.empty())
    throw std::invalid_argument("the joint-angle filter produced no estimate for the recording");
  say("calibrate: first trajectory from the EKF (" + std::to_string(first.estimates.size()) +
      " estimates)");

  SplineGrid grid;
  grid.t0 = tFirst;
  grid.dt = options.knotSpacing;
  grid.segments = std::max(1, static_cast<int>(std::ceil((tLast - tFirst) / grid.dt)));
  std::vector<double> ctrl = fitSpline(grid, first.estimates, options.startPose);
  const int nCtrl = grid.controlPoints();
  const double tPrior = tFirst + 0.5 * options.startStillSeconds;
  const SplineWeights priorWeights = splineWeights(grid, tPrior);
  auto thOf = [](const std::vector<double>& cp, const SplineWeights& w) {
    const double* const c[4] = {cp.data() + 5 * w.first, cp.data() + 5 * (w.first + 1),
                                cp.data() + 5 * (w.first + 2), cp.data() + 5 * (w.first + 3)};
    Vec5T<double> th, thd, thdd;
    evalSpline(w, c, th, thd, thdd);
    return JointVector(th);
  };
  auto thAt = [&](const SplineWeights& w) { return thOf(ctrl, w); };
  {
    const JointVector th = thAt(priorWeights);
    char line[200];
    std::snprintf(line, sizeof line,
                  "calibrate: the filter's start pose [%.1f %.1f %.1f %.1f %.1f] deg", th(0) / kDeg,
                  th(1) / kDeg, th(2) / kDeg, th(3) / kDeg, th(4) / kDeg);
    say(line);
  }

  // 3. Parameter blocks.
  double mountUa[5] = {nominal.lu3, nominal.lu5, nominal.thu4, 0.0, 0.0};
  double mountFa[5] = {nominal.lf6, nominal.lf8, nominal.thf7, 0.0, 0.0};
  double biasUa[3] = {biasGuess[0].x(), biasGuess[0].y(), biasGuess[0].z()};
  double biasFa[3] = {biasGuess[1].x(), biasGuess[1].y(), biasGuess[1].z()};
  double seg[2] = {nominal.l3, nominal.l6};

  // The gauges, moved exactly instead of by the solver (whose damped steps barely move along a
  // direction that only one prior term sees): pronation th5 and the strap angle thf7 only appear
  // as th5 + thf7, and without optical data turning the whole trajectory about the vertical
  // changes no reading. Both are put where the start pose says.
  auto alignGauges = [&](bool report) {
    double alpha = 0.0;
    if (!optical) {
      const JointVector th = thAt(priorWeights);
      const JointVector d = headingDirection(options.startPose, up);
      auto f = [&](double a) { return d.dot(turnAboutVertical(th, a, up) - options.startPose); };
      double a0 = 0.0, a1 = 0.02, f0 = f(a0), f1 = f(a1);
      for (int it = 0; it < 30 && std::abs(f1) > 1e-10 && f1 != f0; ++it) {
        const double a2 = a1 - f1 * (a1 - a0) / (f1 - f0);
        a0 = a1;
        f0 = f1;
        a1 = a2;
        f1 = f(a1);
      }
      if (std::isfinite(a1) && std::abs(f1) < 1e-6) {
        alpha = a1;
        turnKnots(ctrl, 0, alpha, up);
      }
    }
    const double dth5 = thAt(priorWeights)(4) - options.startPose(4);
    for (int i = 0; i < nCtrl; ++i) ctrl[5 * i + 4] -= dth5;
    mountFa[2] += dth5;
    if (report) {
      char line[160];
      std::snprintf(
          line, sizeof line,
          "calibrate: to the start pose: turned %.2f deg about the vertical, th5 %.2f deg",
          alpha / kDeg, -dth5 / kDeg);
      say(line);
    }
  };
  alignGauges(true);

  ceres::Problem::Options popt;
  popt.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(popt);
  auto ctrlAt = [&](int i) { return ctrl.data() + 5 * i; };
  auto ctrlBlocks = [&](const SplineWeights& w) {
    return std::vector<double*>{ctrlAt(w.first), ctrlAt(w.first + 1), ctrlAt(w.first + 2),
                                ctrlAt(w.first + 3)};
  };

  // Priors first (they bring in the calibration blocks): the start pose at the middle of the
  // still start, along pronation (th5 + thf7 is a gauge) and, without optical data, along the
  // heading about the vertical; weak priors on the calibration.
  {
    std::vector<JointVector> directions;
    directions.push_back(JointVector::Unit(4));
    if (!optical) directions.push_back(headingDirection(options.startPose, up));
    for (const JointVector& d : directions) {
      auto* cost = new ceres::AutoDiffCostFunction<StartPoseCost, 1, 5, 5, 5, 5>(
          new StartPoseCost(priorWeights, d, options.startPose, kGaugeStd));
      problem.AddResidualBlock(cost, nullptr, ctrlBlocks(priorWeights));
    }
    Eigen::VectorXd mean(5), std(5);
    const double L = options.lengthPriorStd, A = options.strapAnglePriorStd,
                 R = options.tiltPriorStd;
    mean << nominal.lu3, nominal.lu5, nominal.thu4, 0.0, 0.0;
    std << L, L, A, R, R;
    problem.AddResidualBlock(normalPrior(mean, std), nullptr, mountUa);
    // thf7: no real prior, the start pose fixes it (1e3 rad is only numerical safety).
    mean << nominal.lf6, nominal.lf8, nominal.thf7, 0.0, 0.0;
    std << L, L, 1e3, R, R;
    problem.AddResidualBlock(normalPrior(mean, std), nullptr, mountFa);
    const Eigen::VectorXd b0 = Eigen::VectorXd::Zero(3);
    const Eigen::VectorXd bs = Eigen::VectorXd::Constant(3, options.biasPriorStd);
    problem.AddResidualBlock(normalPrior(b0, bs), nullptr, biasUa);
    problem.AddResidualBlock(normalPrior(b0, bs), nullptr, biasFa);
    Eigen::VectorXd sm(2), ss(2);
    sm << nominal.l3, nominal.l6;
    ss << L, L;
    problem.AddResidualBlock(normalPrior(sm, ss), nullptr, seg);
  }
  for (double* m : {mountUa, mountFa}) {
    problem.SetParameterLowerBound(m, 0, 0.0);
    problem.SetParameterLowerBound(m, 1, 0.0);
  }
  const bool fitSegments = optical && options.estimateSegmentLengths;
  if (fitSegments) {
    problem.SetParameterLowerBound(seg, 0, 0.05);
    problem.SetParameterLowerBound(seg, 1, 0.05);
  } else {
    problem.SetParameterBlockConstant(seg);
  }

  // The data, added in time order up to a horizon.
  const double binSeconds = 1.0 / options.residualRateHz;
  const std::vector<ImuBin> bins[2] = {binImu(samples, false, tFirst, binSeconds, biasGuess[0]),
                                       binImu(samples, true, tFirst, binSeconds, biasGuess[1])};
  struct Point {
    double t;
    Vec3 p;
    bool wrist;
  };
  std::vector<Point> points;
  if (optical) {
    for (const ArmSample& s : samples) {
      if (s.t < tFirst || s.t > tLast) continue;
      if (s.elbow && s.elbow->allFinite()) points.push_back({s.t, *s.elbow, false});
      if (s.wrist && s.wrist->allFinite()) points.push_back({s.t, *s.wrist, true});
    }
  }
  std::vector<ceres::ResidualBlockId> upperBlocks, forearmBlocks, positionBlocks;
  std::size_t nextBin[2] = {0, 0}, nextPoint = 0;
  auto addDataUpTo = [&](double horizon) {
    for (int imu = 0; imu < 2; ++imu) {
      const bool fa = imu == 1;
      for (; nextBin[imu] < bins[imu].size() && bins[imu][nextBin[imu]].t <= horizon;
           ++nextBin[imu]) {
        const ImuBin& bin = bins[imu][nextBin[imu]];
        const SplineWeights w = splineWeights(grid, bin.t);
        auto* cost = new ceres::AutoDiffCostFunction<ImuCost, 6, 5, 5, 5, 5, 5, 3, 2>(
            new ImuCost(w, bin, nominal, gUp, options.gyroStd, options.accelStd, fa));
        std::vector<double*> blocks = ctrlBlocks(w);
        blocks.push_back(fa ? mountFa : mountUa);
        blocks.push_back(fa ? biasFa : biasUa);
        blocks.push_back(seg);
        (fa ? forearmBlocks : upperBlocks)
            .push_back(problem.AddResidualBlock(cost, nullptr, blocks));
      }
    }
    for (; nextPoint < points.size() && points[nextPoint].t <= horizon; ++nextPoint) {
      const Point& pt = points[nextPoint];
      const SplineWeights w = splineWeights(grid, pt.t);
      auto* cost = new ceres::AutoDiffCostFunction<PositionCost, 3, 5, 5, 5, 5, 2>(
          new PositionCost(w, pt.p, pt.wrist, nominal, options.positionStd));
      std::vector<double*> blocks = ctrlBlocks(w);
      blocks.push_back(seg);
      positionBlocks.push_back(problem.AddResidualBlock(cost, nullptr, blocks));
    }
  };
  result.imuBins = bins[0].size() + bins[1].size();
  result.opticalPoints = points.size();

  // 4. Solve.
  ceres::Solver::Options sopt;
  sopt.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  sopt.num_threads = std::max(1, options.threads);
  sopt.function_tolerance = 1e-6;
  sopt.parameter_tolerance = 1e-9;
  sopt.logging_type = ceres::SILENT;
  sopt.minimizer_progress_to_stdout = false;
  ProgressCallback callback(progress);
  sopt.callbacks.push_back(&callback);
  int iterations = 0;
  ceres::Solver::Summary summary;
  auto solve = [&](int maxIterations) {
    sopt.max_num_iterations = maxIterations;
    ceres::Solve(sopt, &problem, &summary);
    iterations += static_cast<int>(summary.iterations.size()) - 1;
    if (!summary.IsSolutionUsable())
      throw std::runtime_error("calibration failed: " + summary.message);
  };

  if (!optical && options.stageSeconds > 0.0) {
    // Without optical data the filter's heading wanders (tens of degrees over a minute with a
    // wrong mounting), and the solver cannot turn a long stretch of trajectory back about the
    // vertical: that is a curved valley of the cost. So the data enter in stages. The first
    // stage starts from the filter; each later one from the solved trajectory continued by
    // integrating the gyroscopes with the calibration found so far (dead reckoning).
    double horizon = tPrior + options.stageSeconds;
    addDataUpTo(horizon);
    say("calibrate: stage 1, data up to " +
        std::to_string(static_cast<int>(std::round(horizon - tFirst))) + " s");
    solve(options.stageIterations);
    for (int stage = 2; horizon < tLast; ++stage) {
      const double next = std::min(horizon + options.stageSeconds, tLast);
      const DeadReckoning dr{grid, bins, nominal, gUp, mountUa, mountFa, biasUa, biasFa, seg};
      dr.extend(ctrl, horizon, next + 3.0 * grid.dt);
      addDataUpTo(next);
      say("calibrate: stage " + std::to_string(stage) + ", data up to " +
          std::to_string(static_cast<int>(std::round(next - tFirst))) + " s");
      solve(options.stageIterations);
      horizon = next;
    }
  }
  addDataUpTo(std::numeric_limits<double>::infinity());
  say("calibrate: solving, " + std::to_string(nCtrl) + " knots, " + std::to_string(result.imuBins) +
      " IMU bins, " + std::to_string(result.opticalPoints) + " optical points");
  solve(options.maxIterations);
  alignGauges(true);
  solve(options.polishIterations);
  result.iterations = iterations;
  result.converged = summary.termination_type == ceres::CONVERGENCE;
  result.initialCost = summary.initial_cost;
  result.finalCost = summary.final_cost;
  if (!result.converged)
    result.warnings.push_back("the solver stopped before converging: " + summary.message);

  result.rmsUpperGyro = rmsOf(problem, upperBlocks, 0, 6, 3);
  result.rmsUpperAcc = rmsOf(problem, upperBlocks, 3, 6, 3);
  result.rmsForearmGyro = rmsOf(problem, forearmBlocks, 0, 6, 3);
  result.rmsForearmAcc = rmsOf(problem, forearmBlocks, 3, 6, 3);
  result.rmsPosition = rmsOf(problem, positionBlocks, 0, 3, 3);

  for (double t = tFirst; t <= tLast; t += binSeconds) {
    const SplineWeights w = splineWeights(grid, t);
    const double* const c[4] = {ctrlAt(w.first), ctrlAt(w.first + 1), ctrlAt(w.first + 2),
                                ctrlAt(w.first + 3)};
    Vec5T<double> th, thd, thdd;
    evalSpline(w, c, th, thd, thdd);
    JointEstimate e;
    e.t = t;
    for (int j = 0; j < kNumJoints; ++j) e.th(j) = wrapAngle(th(j));
    e.thd = thd;
    e.thdd = thdd;
    result.trajectory.push_back(e);
  }

  // 5. The calibration, in the real sensors' axes.
  Calibration& c = result.calibration;
  c.side = recording.meta.side;
  c.geometry = nominal;
  c.geometry.lu3 = mountUa[0];
  c.geometry.lu5 = mountUa[1];
  c.geometry.thu4 = wrapAngle(mountUa[2]);
  c.geometry.lf6 = mountFa[0];
  c.geometry.lf8 = mountFa[1];
  c.geometry.thf7 = wrapAngle(mountFa[2]);
  c.geometry.l3 = seg[0];
  c.geometry.l6 = seg[1];
  auto tilt = [](const double* m) {
    const Vec3 v(m[3], 0.0, m[4]);
    const double a = v.norm();
    return a < 1e-300 ? Eigen::Matrix3d::Identity()
                      : Eigen::AngleAxisd(a, v / a).toRotationMatrix();
  };
  c.upperArm.rotation = tilt(mountUa);
  c.upperArm.gyroBias = Vec3(biasUa[0], biasUa[1], biasUa[2]);
  c.forearm.rotation = tilt(mountFa);
  c.forearm.gyroBias = Vec3(biasFa[0], biasFa[1], biasFa[2]);
  if (left) {
    c.upperArm = mirrorImuCalibration(c.upperArm);
    c.forearm = mirrorImuCalibration(c.forearm);
  }
  c.opticalUsed = optical;
  c.headingFromStartPoseOnly = !optical;
  c.estimated = {"lu3",
                 "lu5",
                 "thu4",
                 "upperArm.rotation",
                 "upperArm.gyroBias",
                 "lf6",
                 "lf8",
                 "forearm.rotation",
                 "forearm.gyroBias"};
  c.fromStartPose = {"thf7"};
  if (!optical) c.fromStartPose.push_back("heading");
  if (fitSegments) {
    c.estimated.push_back("l3");
    c.estimated.push_back("l6");
  } else {
    c.heldFixed = {"l3", "l6"};
  }

  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  char line[200];
  std::snprintf(line, sizeof line, "calibrate: done, %d iterations, cost %.6g -> %.6g, %.1f s",
                result.iterations, result.initialCost, result.finalCost, result.seconds);
  say(line);
  return result;
}

}  // namespace armtrack
