// Calibration from ordinary movement: readings onto a uniform grid, the rest, the joint positions
// (shoulder and elbow centres), the elbow's axes (MovementAxes.cpp), and the result as a normal
// Calibration. docs/calibration.md, "Calibration from movement".
#include "core/calibration/MovementCalibration.h"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "core/calibration/Calibrator.h"
#include "core/calibration/MovementFit.h"
#include "core/calibration/MovementReadings.h"
#include "core/calibration/MovementRestPose.h"

namespace armtrack {

using namespace movecal;

namespace {

constexpr int kAxesStride = 2;  // grid steps between the instants of the axes fit

[[noreturn]] void refuse(const std::string& message) {
  throw std::invalid_argument(message);
}

/// K r = w' x r + w x (w x r): the acceleration of a point at r on a body turning with w.
template <typename T>
Eigen::Matrix<T, 3, 1> tangential(const Vec3& w, const Vec3& wd, const Eigen::Matrix<T, 3, 1>& r) {
  const Eigen::Matrix<T, 3, 1> wt = w.cast<T>();
  return wd.cast<T>().cross(r) + wt.cross(wt.cross(r));
}

/// |a - K r| = g: the shoulder, a fixed point, feels gravity alone (a still trunk).
struct ShoulderCost {
  ShoulderCost(const Vec3& a, const Vec3& w, const Vec3& wd, double g, double std)
      : m_a(a), m_w(w), m_wd(wd), m_g(g), m_s(1.0 / std) {}
  /// r: the IMU's position from the shoulder; scale: the accelerometer's per-axis scale error and
  /// bias (m/s^2), [s s s b b b].
  template <typename T>
  bool operator()(const T* r, const T* scale, T* res) const {
    const Eigen::Matrix<T, 3, 1> rv(r[0], r[1], r[2]);
    Eigen::Matrix<T, 3, 1> a;
    for (int i = 0; i < 3; ++i) a(i) = (T(m_a(i)) - scale[3 + i]) / (T(1) + scale[i]);
    res[0] = ((a - tangential<T>(m_w, m_wd, rv)).norm() - T(m_g)) * m_s;
    return true;
  }
  Vec3 m_a, m_w, m_wd;
  double m_g, m_s;
};

/// |a1 - K1 e1| = |a2 - K2 e2|: both IMUs agree on the elbow centre's specific force (Seel 2012).
struct ElbowCost {
  ElbowCost(const Grid& g, std::size_t k, double std)
      : m_a1(g.a1[k]),
        m_w1(g.w1[k]),
        m_wd1(g.wd1[k]),
        m_a2(g.a2[k]),
        m_w2(g.w2[k]),
        m_wd2(g.wd2[k]),
        m_s(1.0 / std) {}
  /// scale1, scale2: the accelerometers' per-axis scale errors and biases, [s s s b b b].
  template <typename T>
  bool operator()(const T* e1, const T* e2, const T* scale1, const T* scale2, T* res) const {
    const Eigen::Matrix<T, 3, 1> v1(e1[0], e1[1], e1[2]), v2(e2[0], e2[1], e2[2]);
    Eigen::Matrix<T, 3, 1> a1, a2;
    for (int i = 0; i < 3; ++i) {
      a1(i) = (T(m_a1(i)) - scale1[3 + i]) / (T(1) + scale1[i]);
      a2(i) = (T(m_a2(i)) - scale2[3 + i]) / (T(1) + scale2[i]);
    }
    res[0] = ((a1 - tangential<T>(m_w1, m_wd1, v1)).norm() -
              (a2 - tangential<T>(m_w2, m_wd2, v2)).norm()) *
             m_s;
    return true;
  }
  Vec3 m_a1, m_w1, m_wd1, m_a2, m_w2, m_wd2;
  double m_s;
};

struct VectorPrior {
  VectorPrior(const Vec3& mean, double std) : m_mean(mean), m_s(1.0 / std) {}
  template <typename T>
  bool operator()(const T* x, T* r) const {
    for (int i = 0; i < 3; ++i) r[i] = (x[i] - T(m_mean(i))) * m_s;
    return true;
  }
  Vec3 m_mean;
  double m_s;
};

/// x / std, independent components (the accelerometer's scale and bias: zero expected).
struct SensorPrior {
  explicit SensorPrior(const Eigen::Matrix<double, 6, 1>& std) : m_std(std) {}
  template <typename T>
  bool operator()(const T* x, T* r) const {
    for (int i = 0; i < 6; ++i) r[i] = x[i] / m_std(i);
    return true;
  }
  Eigen::Matrix<double, 6, 1> m_std;
};

/// Solves a small problem and gives the covariance of its blocks (scaled by the residual
/// variance) and the residual RMS in the residuals' units (times unit).
struct SmallFit {
  Eigen::MatrixXd cov;
  double rms = 0.0;
};

SmallFit solveSmall(ceres::Problem& problem, const std::vector<double*>& blocks, int dim,
                    double unit, int residuals) {
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = 50;
  so.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  SmallFit out;
  out.cov = Eigen::MatrixXd::Identity(dim, dim) * 1e-4;
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  co.null_space_rank = -1;
  ceres::Covariance cov(co);
  std::vector<std::pair<const double*, const double*>> pairs;
  for (const double* a : blocks)
    for (const double* b : blocks) pairs.emplace_back(a, b);
  if (cov.Compute(pairs, &problem)) {
    std::vector<const double*> cb(blocks.begin(), blocks.end());
    Eigen::MatrixXd c(dim, dim);
    cov.GetCovarianceMatrix(cb, c.data());
    out.cov = c;
  }
  const double dof = std::max(1.0, static_cast<double>(residuals - dim));
  const double factor = std::max(1.0, 2.0 * summary.final_cost / dof);
  out.cov *= factor;
  out.rms = std::sqrt(2.0 * summary.final_cost / std::max(1, residuals)) * unit;
  return out;
}

/// Moves x back to the prior along the directions the data did not determine: those whose sd
/// exceeds `fraction` of the prior's. Returns how many.
int fallBack(Eigen::VectorXd& x, const Eigen::VectorXd& prior, Eigen::MatrixXd& cov,
             double priorStd, double fraction) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(cov);
  int count = 0;
  for (int i = 0; i < es.eigenvalues().size(); ++i) {
    if (std::sqrt(std::max(0.0, es.eigenvalues()(i))) > fraction * priorStd) {
      const Eigen::VectorXd v = es.eigenvectors().col(i);
      x -= v * v.dot(x - prior);
      ++count;
    }
  }
  return count;
}

/// Quiet glog while Ceres runs (it may warn about a failed evaluation).
class QuietGlog {
 public:
  QuietGlog() : m_saved(FLAGS_minloglevel) { FLAGS_minloglevel = google::GLOG_FATAL; }
  ~QuietGlog() { FLAGS_minloglevel = m_saved; }

 private:
  int m_saved;
};

MovementParameter param(const std::string& name, double value, double prior, double sd,
                        const std::string& unit, double priorSd, double fraction) {
  MovementParameter m;
  m.name = name;
  m.value = value;
  m.prior = prior;
  m.sd = sd;
  m.unit = unit;
  m.excited = sd <= fraction * priorSd;
  if (!m.excited) m.value = prior;
  return m;
}

MovementCalibration calibrateMovementRight(const Recording& rec,
                                           const MovementCalibrationParams& p) {
  MovementCalibration out;
  const ArmGeometry prior = rec.meta.geometry;
  const double gNominal = rec.meta.g > 0.0 ? rec.meta.g : 9.81;
  const ImuChannels u = channels(rec.samples, false), f = channels(rec.samples, true);
  const std::pair<const char*, const ImuChannels*> imus[] = {{"upper-arm", &u}, {"forearm", &f}};
  for (const auto& [name, c] : imus) {
    if (c->rows == 0)
      refuse(std::string("no ") + name +
             " IMU readings: the calibration from movement needs both arm IMUs");
    if (2 * c->nonFinite > c->rows)
      refuse(std::string("most of the ") + name + " IMU's readings are not numbers (" +
             std::to_string(c->nonFinite) + " of " + std::to_string(c->rows) +
             "): check the sensor and its connection, and record again");
    if (c->nonFinite > 0)
      out.warnings.push_back(std::to_string(c->nonFinite) + " " + name +
                             " IMU reading(s) that are not numbers were left out");
    if (static_cast<double>(c->saturated) > 0.02 * static_cast<double>(c->rows))
      refuse(std::string("the ") + name + " IMU's readings are saturated (" +
             std::to_string(c->saturated) + " of " + std::to_string(c->rows) +
             " at the sensor's range): set the sensor to a wider range or move more gently, and "
             "record again");
    if (c->saturated > 0)
      out.warnings.push_back(std::to_string(c->saturated) + " " + name +
                             " IMU reading(s) at the sensor's range were left out");
    if (c->gyr.t.size() < 2 || c->acc.t.size() < 2)
      refuse(std::string("too few ") + name + " IMU readings to calibrate from");
  }
  const double t0 = std::max({u.gyr.t.front(), u.acc.t.front(), f.gyr.t.front(), f.acc.t.front()});
  const double t1 = std::min({u.gyr.t.back(), u.acc.t.back(), f.gyr.t.back(), f.acc.t.back()});
  if (!(t1 - t0 >= p.minSeconds))
    refuse("only " + fixed1(std::max(0.0, t1 - t0)) +
           " s of readings from both IMUs; the calibration from movement needs at least " +
           fixed1(p.minSeconds) + " s (best 20-60 s of natural movement with a moment of rest)");
  Grid g = makeGrid(u, f);
  const std::optional<Rest> rest = findRest(g, p, gNominal);
  if (!rest)
    refuse("no moment of rest: hold the arm still for at least " + fixed1(p.minRestSeconds) +
           " s somewhere in the recording (both sensors still, reading gravity), and record again");
  out.restStart = g.t[rest->from];
  out.restEnd = g.t[rest->to - 1];
  // The biases from the rest's inside: its edges see the movement through the smoother.
  Rest inner = *rest;
  const std::size_t edge = static_cast<std::size_t>(std::ceil(2.0 * kHalfWidth / kGridDt));
  if (inner.to - inner.from > 4 * edge) {
    inner.from += edge;
    inner.to -= edge;
  }
  const Vec3 bias1 = meanOf(g.w1, inner), bias2 = meanOf(g.w2, inner);
  for (std::size_t i = 0; i < g.t.size(); ++i) {
    g.w1[i] -= bias1;
    g.w2[i] -= bias2;
    if (std::max(g.w1[i].norm(), g.w2[i].norm()) > p.movingRate) out.movingSeconds += kGridDt;
  }
  if (out.movingSeconds < p.minMovingSeconds)
    refuse("too little movement: the arm turned faster than " + fixed1(p.movingRate / kDeg) +
           " deg/s for only " + fixed1(out.movingSeconds) + " s (at least " +
           fixed1(p.minMovingSeconds) +
           " s needed); move the whole arm naturally for 20-60 s (shoulder and elbow, turning "
           "the forearm too), with a moment of rest");
  differentiate(g);

  // Prior lever arms, in the model IMU frames (the sensor's axes if mounted as the sidecar says).
  const ArmPose pose = forwardKinematics(prior, JointVector::Zero());
  const Mat3 ru = pose.upperImu.topLeftCorner<3, 3>(), rf = pose.forearmImu.topLeftCorner<3, 3>();
  const Vec3 pu = pose.upperImu.topRightCorner<3, 1>(), pf = pose.forearmImu.topRightCorner<3, 1>();
  const Vec3 r1Prior = ru.transpose() * pu;
  const Vec3 e1Prior = ru.transpose() * (pu - pose.elbow);
  const Vec3 e2Prior = rf.transpose() * (pf - pose.elbow);

  // Joint positions: the shoulder (a fixed point) and the elbow centre.
  const double accelStd = 0.3;
  double r1[3] = {r1Prior(0), r1Prior(1), r1Prior(2)};
  double e1[3] = {e1Prior(0), e1Prior(1), e1Prior(2)};
  double e2[3] = {e2Prior(0), e2Prior(1), e2Prior(2)};
  // Per-axis accelerometer scale errors (a few per cent on real sensors), seen because the arm
  // takes many orientations: |specific force at the shoulder| = g whatever the orientation.
  double scale1[6] = {0, 0, 0, 0, 0, 0}, scale2[6] = {0, 0, 0, 0, 0, 0};
  Eigen::Matrix<double, 6, 1> sensorPrior;
  sensorPrior << 0.05, 0.05, 0.05, 0.5, 0.5, 0.5;  // scale (relative), bias (m/s^2)
  SmallFit shoulderFit, elbowFit;
  {
    ceres::Problem problem;
    int m = 0;
    for (std::size_t i = 1; i + 1 < g.t.size(); ++i, ++m)
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<ShoulderCost, 1, 3, 6>(
              new ShoulderCost(g.a1[i], g.w1[i], g.wd1[i], gNominal, accelStd)),
          new ceres::HuberLoss(1.0), r1, scale1);
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<VectorPrior, 3, 3>(
                                 new VectorPrior(r1Prior, p.positionPriorStd)),
                             nullptr, r1);
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<SensorPrior, 6, 6>(new SensorPrior(sensorPrior)), nullptr,
        scale1);
    shoulderFit = solveSmall(problem, {r1}, 3, accelStd, m);
  }
  {
    ceres::Problem problem;
    int m = 0;
    for (std::size_t i = 1; i + 1 < g.t.size(); ++i, ++m)
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<ElbowCost, 1, 3, 3, 6, 6>(new ElbowCost(g, i, accelStd)),
          new ceres::HuberLoss(1.0), e1, e2, scale1, scale2);
    problem.SetParameterBlockConstant(scale1);
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<SensorPrior, 6, 6>(new SensorPrior(sensorPrior)), nullptr,
        scale2);
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<VectorPrior, 3, 3>(
                                 new VectorPrior(e1Prior, p.positionPriorStd)),
                             nullptr, e1);
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<VectorPrior, 3, 3>(
                                 new VectorPrior(e2Prior, p.positionPriorStd)),
                             nullptr, e2);
    elbowFit = solveSmall(problem, {e1, e2}, 6, accelStd, m);
  }
  out.leverResidualRms = elbowFit.rms;
  for (std::size_t i = 0; i < g.t.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      g.a1[i](k) = (g.a1[i](k) - scale1[3 + k]) / (1.0 + scale1[k]);
      g.a2[i](k) = (g.a2[i](k) - scale2[3 + k]) / (1.0 + scale2[k]);
    }
  }
  Eigen::VectorXd xs = Eigen::Map<Vec3>(r1), xe(6);
  xe << e1[0], e1[1], e1[2], e2[0], e2[1], e2[2];
  Eigen::VectorXd xe0(6);
  xe0 << e1Prior, e2Prior;
  const int shoulderUnexcited =
      fallBack(xs, r1Prior, shoulderFit.cov, p.positionPriorStd, p.excitedFraction);
  const int elbowUnexcited = fallBack(xe, xe0, elbowFit.cov, p.positionPriorStd, p.excitedFraction);
  const Vec3 vr1 = xs, ve1 = xe.head<3>(), ve2 = xe.tail<3>();

  // The elbow's axes from the relative motion of the two IMUs.
  AxesInput in;
  in.model = relativeModel(prior);
  in.dt = kAxesStride * kGridDt;
  in.accelStd = accelStd;
  in.priorStd = p.rotationPriorStd;
  in.maxIterations = p.maxIterations;
  const Vec3 arm = vr1 - ve1;  // shoulder to elbow, upper-arm IMU axes
  in.longAxis1 = arm.normalized();
  {
    const Mat3 c = shoulderFit.cov + elbowFit.cov.topLeftCorner<3, 3>();
    const Mat3 perp = Mat3::Identity() - in.longAxis1 * in.longAxis1.transpose();
    in.longAxisStd = std::max(
        0.5 * kDeg, std::sqrt(std::max(0.0, (perp * c * perp).trace() / 2.0)) / arm.norm());
  }
  if (p.restPose) {
    // Gravity at rest, against the model's at the given pose: the upper arm's inclination.
    const ArmPose atRest = forwardKinematics(prior, *p.restPose);
    in.gravityModel1 = atRest.upperImu.topLeftCorner<3, 3>().transpose() * rec.meta.up.normalized();
    in.gravity1 = meanOf(g.a1, *rest).normalized();
    in.longAxisStd = std::max(in.longAxisStd, 5.0 * kDeg);
  }
  std::size_t restIndex = 0;
  const std::size_t restMid = (rest->from + rest->to) / 2;
  for (std::size_t i = 1; i + 1 < g.t.size(); i += kAxesStride) {
    if (!in.ae1.empty()) {
      Mat3 d1 = Mat3::Identity(), d2 = Mat3::Identity();
      for (std::size_t j = i - kAxesStride; j < i; ++j) {
        d1 = d1 * expRotation(0.5 * (g.w1[j] + g.w1[j + 1]) * kGridDt);
        d2 = d2 * expRotation(0.5 * (g.w2[j] + g.w2[j + 1]) * kGridDt);
      }
      in.inc1.push_back(d1);
      in.inc2.push_back(d2);
    }
    if (i <= restMid) restIndex = in.ae1.size();
    in.ae1.push_back(g.a1[i] - tangential<double>(g.w1[i], g.wd1[i], ve1));
    in.ae2.push_back(g.a2[i] - tangential<double>(g.w2[i], g.wd2[i], ve2));
    in.w1.push_back(g.w1[i]);
    in.w2.push_back(g.w2[i]);
  }
  const AxesResult axes = fitAxes(in);
  out.axisResidualRms = axes.gyroRms;
  Eigen::VectorXd xw(5), xw0 = Eigen::VectorXd::Zero(5);
  xw << axes.w1, axes.w2;
  Eigen::MatrixXd covW = axes.cov;
  fallBack(xw, xw0, covW, p.rotationPriorStd, p.excitedFraction);
  Mat3 m1 = expRotation(xw.head<3>());
  Mat3 m2 = forearmTilt(xw.tail<2>());
  double roll = 0.0, rollSd = 0.0;
  if (p.restPose) {
    roll = axes.theta[restIndex](1) - (*p.restPose)(4);
    rollSd = std::sqrt(std::max(0.0, covW(3, 3)));
    m2 = Eigen::AngleAxisd(roll, Vec3::UnitY()).toRotationMatrix() * m2;
    out.rollFromPose = true;
  } else if (p.expectedRestPose) {
    // The rests that look like the pose the user was told to rest in: their forearm gravity.
    const PoseRoll pr = rollFromRestPose(g, findRests(g, p, gNominal), axes.theta, kAxesStride, m1,
                                         m2, prior, rec.meta.up, *p.expectedRestPose, p);
    out.rests = pr.rests;
    if (pr.roll) {
      out.poseRests = pr.agreeing;
      roll = *pr.roll;
      rollSd = pr.sd;
      m2 = Eigen::AngleAxisd(roll, Vec3::UnitY()).toRotationMatrix() * m2;
      out.rollFromPose = true;
    } else {
      out.warnings.push_back(
          "the forearm sensor's roll about the forearm was not observable: " + pr.why +
          " (upper arm hanging, elbow at a right angle, thumb up); the sidecar's is kept");
    }
  }
  out.upperMounting = m1;
  out.forearmMounting = m2;

  // Lever arms in the segments' frames, and the whole as the model's geometry.
  const Mat3 r3 = upperImuInFrame3(prior.thu4) * m1;
  const Mat3 r6 = forearmImuInFrame6(prior.thf7) * m2;
  out.upperLever = r3 * vr1;
  out.forearmLever = r6 * ve2;
  // A lever arm no real arm has (the fit pulled by what the model leaves out): the sidecar's.
  const Vec3 upperPrior(prior.lu5 * std::sin(prior.thu4), -prior.lu5 * std::cos(prior.thu4),
                        prior.lu3);
  const Vec3 forearmPrior(prior.lf8 * std::cos(prior.thf7), prior.lf8 * std::sin(prior.thf7),
                          prior.lf6);
  bool upperImplausible = false, forearmImplausible = false;
  if (!(out.upperLever.z() > 0.0 && out.upperLever.z() < prior.l3 + MetaLimits::kStrapMargin &&
        out.upperLever.head<2>().norm() < 0.1)) {
    out.upperLever = upperPrior;
    upperImplausible = true;
    out.warnings.push_back(
        "the upper-arm sensor's position came out where no sensor can sit: "
        "the sidecar's is kept");
  }
  if (!(out.forearmLever.z() > 0.0 && out.forearmLever.z() < prior.l6 + MetaLimits::kStrapMargin &&
        out.forearmLever.head<2>().norm() < 0.1)) {
    out.forearmLever = forearmPrior;
    forearmImplausible = true;
    out.warnings.push_back(
        "the forearm sensor's position came out where no sensor can sit: "
        "the sidecar's is kept");
  }
  Calibration& c = out.calibration;
  c.side = Side::Right;
  c.geometry = prior;
  ArmGeometry& geo = c.geometry;
  geo.lu3 = out.upperLever.z();
  geo.lu5 = std::hypot(out.upperLever.x(), out.upperLever.y());
  geo.thu4 = std::atan2(out.upperLever.x(), -out.upperLever.y());
  geo.lf6 = out.forearmLever.z();
  geo.lf8 = std::hypot(out.forearmLever.x(), out.forearmLever.y());
  geo.thf7 = std::atan2(out.forearmLever.y(), out.forearmLever.x());
  const Mat3 upperCov = upperImplausible
                            ? Mat3::Identity() * (p.positionPriorStd * p.positionPriorStd)
                            : Mat3(r3 * shoulderFit.cov * r3.transpose());
  const Mat3 foreCov = forearmImplausible
                           ? Mat3::Identity() * (p.positionPriorStd * p.positionPriorStd)
                           : Mat3(r6 * elbowFit.cov.bottomRightCorner<3, 3>() * r6.transpose());
  const double l3Sd = std::sqrt(std::max(
      0.0,
      in.longAxis1.dot((shoulderFit.cov + elbowFit.cov.topLeftCorner<3, 3>()) * in.longAxis1)));
  const bool l3Known = l3Sd < 0.015 && arm.norm() > 0.1 && arm.norm() < 0.6;
  if (l3Known) geo.l3 = arm.norm();
  c.upperArm.rotation =
      Eigen::AngleAxisd(prior.thu4 - geo.thu4, Vec3::UnitY()).toRotationMatrix() * m1;
  c.forearm.rotation =
      Eigen::AngleAxisd(prior.thf7 - geo.thf7, Vec3::UnitY()).toRotationMatrix() * m2;
  c.upperArm.gyroBias = bias1;
  c.forearm.gyroBias = bias2;
  c.opticalUsed = false;
  c.headingFromStartPoseOnly = false;
  c.estimated = {"lu3",
                 "lu5",
                 "thu4",
                 "lf6",
                 "lf8",
                 "upperArm.rotation",
                 "forearm.rotation",
                 "upperArm.gyroBias",
                 "forearm.gyroBias"};
  if (l3Known) c.estimated.push_back("l3");
  c.heldFixed = {"l6"};
  if (!l3Known) c.heldFixed.push_back("l3");
  if (p.restPose)
    c.fromStartPose = {"thf7 (the forearm's roll, from the pronation at rest)"};
  else if (out.rollFromPose)
    c.fromStartPose = {"thf7 (the forearm's roll, from gravity at the rests in the start pose)"};
  else
    c.heldFixed.push_back("thf7 (the forearm's roll about its axis: the sidecar's)");

  // The parameters, in the report's units.
  const double fr = p.excitedFraction;
  const double rp = p.rotationPriorStd / kDeg, pp = p.positionPriorStd * 100.0;
  const auto sdW = [&](int i) { return std::sqrt(std::max(0.0, covW(i, i))) / kDeg; };
  const auto sdP = [](const Mat3& cov, const Vec3& dir) {
    return std::sqrt(std::max(0.0, dir.dot(cov * dir))) * 100.0;
  };
  std::vector<MovementParameter>& ps = out.parameters;
  ps.push_back(
      param("upper-arm strap turn about the arm", xw(1) / kDeg, 0.0, sdW(1), "deg", rp, fr));
  ps.push_back(
      param("upper-arm sensor tilt about its x axis", xw(0) / kDeg, 0.0, sdW(0), "deg", rp, fr));
  ps.push_back(
      param("upper-arm sensor tilt about its z axis", xw(2) / kDeg, 0.0, sdW(2), "deg", rp, fr));
  const Vec3 radialU = Vec3(out.upperLever.x(), out.upperLever.y(), 0.0).normalized();
  ps.push_back(param("upper-arm sensor distance from the shoulder", geo.lu3 * 100.0,
                     prior.lu3 * 100.0, sdP(upperCov, Vec3::UnitZ()), "cm", pp, fr));
  ps.push_back(param("upper-arm sensor distance from the arm's axis", geo.lu5 * 100.0,
                     prior.lu5 * 100.0, sdP(upperCov, radialU), "cm", pp, fr));
  ps.push_back(
      param("upper-arm length", arm.norm() * 100.0, prior.l3 * 100.0, l3Sd * 100.0, "cm", pp, fr));
  ps.push_back(
      param("forearm sensor tilt about its x axis", xw(3) / kDeg, 0.0, sdW(3), "deg", rp, fr));
  ps.push_back(
      param("forearm sensor tilt about its z axis", xw(4) / kDeg, 0.0, sdW(4), "deg", rp, fr));
  {
    MovementParameter r;
    r.name = "forearm sensor roll about the forearm";
    r.value = roll / kDeg;
    r.unit = "deg";
    r.sd = rollSd / kDeg;
    r.excited = out.rollFromPose;
    r.observable = out.rollFromPose;
    ps.push_back(r);
  }
  const Vec3 radialF = Vec3(out.forearmLever.x(), out.forearmLever.y(), 0.0).normalized();
  ps.push_back(param("forearm sensor distance from the elbow", geo.lf6 * 100.0, prior.lf6 * 100.0,
                     sdP(foreCov, Vec3::UnitZ()), "cm", pp, fr));
  ps.push_back(param("forearm sensor distance from the forearm's axis", geo.lf8 * 100.0,
                     prior.lf8 * 100.0, sdP(foreCov, radialF), "cm", pp, fr));
  out.upperLeverExcited = shoulderUnexcited == 0 && !upperImplausible;
  out.forearmLeverExcited = elbowUnexcited == 0 && !forearmImplausible;
  if (shoulderUnexcited > 0)
    out.warnings.push_back(
        "the movement did not turn the upper arm enough to place the shoulder in " +
        std::to_string(shoulderUnexcited) + " direction(s): the sidecar's kept there");
  if (elbowUnexcited > 0)
    out.warnings.push_back("the movement did not place the elbow centre in " +
                           std::to_string(elbowUnexcited) +
                           " direction(s): the sidecar's kept there");
  if (!axes.converged) out.warnings.push_back("the elbow-axis fit stopped at its iteration limit");
  return out;
}

}  // namespace

MovementCalibration calibrateFromMovement(const Recording& recording,
                                          const MovementCalibrationParams& params) {
  const bool left = recording.meta.side == Side::Left;
  Recording twin;
  const Recording* use = &recording;
  if (left) {
    twin.meta = recording.meta;
    twin.samples.reserve(recording.samples.size());
    for (const ArmSample& s : recording.samples) twin.samples.push_back(mirrorSample(s));
    use = &twin;
  }
  QuietGlog quiet;
  MovementCalibration m = calibrateMovementRight(*use, params);
  m.calibration.side = recording.meta.side;
  if (left) {
    m.calibration.upperArm = mirrorImuCalibration(m.calibration.upperArm);
    m.calibration.forearm = mirrorImuCalibration(m.calibration.forearm);
  }
  if (const std::string problem = calibrationProblem(m.calibration); !problem.empty())
    refuse("the calibration from this movement is impossible (" + problem +
           "); record again with livelier movement of the whole arm");
  return m;
}

std::optional<MovementCalibration> tryCalibrateFromMovement(const Recording& recording,
                                                            const MovementCalibrationParams& params,
                                                            std::string* why) {
  try {
    return calibrateFromMovement(recording, params);
  } catch (const std::exception& e) {
    if (why) *why = e.what();
    return std::nullopt;
  }
}

}  // namespace armtrack
