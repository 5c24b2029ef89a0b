// The elbow's two axes from the relative motion of the two arm IMUs (docs/calibration.md,
// "Calibration from movement"): a batch fit of the two mountings and the elbow angles per instant.
#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <numbers>

#include "core/calibration/MovementFit.h"

namespace armtrack::movecal {

namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

template <typename T>
using M3 = Eigen::Matrix<T, 3, 3>;
template <typename T>
using V3 = Eigen::Matrix<T, 3, 1>;

template <typename T>
M3<T> rz(const T& a) {
  using std::cos;
  using std::sin;
  M3<T> r;
  r << cos(a), -sin(a), T(0), sin(a), cos(a), T(0), T(0), T(0), T(1);
  return r;
}

/// Sensor mountings as matrices (sensor axes -> model IMU frame).
template <typename T>
void mountings(const T* w1, const T* w2, M3<T>& m1, M3<T>& m2) {
  ceres::AngleAxisToRotationMatrix(w1, m1.data());
  const T w2full[3] = {w2[0], T(0), w2[1]};
  ceres::AngleAxisToRotationMatrix(w2full, m2.data());
}

/// The relative rotation of the two sensors: forearm-sensor axes -> upper-arm-sensor axes.
template <typename T>
M3<T> sensorRelative(const RelativeModel& m, const T* th, const M3<T>& m1, const M3<T>& m2) {
  const M3<T> a = m.c.cast<T>() * rz<T>(th[0]) * m.d.cast<T>() * rz<T>(th[1]) * m.e.cast<T>();
  return m1.transpose() * a * m2;
}

struct AccelCost {
  AccelCost(const RelativeModel& m, const Vec3& ae1, const Vec3& ae2, double std)
      : m_m(m), m_ae1(ae1), m_ae2(ae2), m_w(1.0 / std) {}
  template <typename T>
  bool operator()(const T* th, const T* w1, const T* w2, T* r) const {
    M3<T> m1, m2;
    mountings(w1, w2, m1, m2);
    const V3<T> p = sensorRelative(m_m, th, m1, m2) * m_ae2.cast<T>();
    for (int i = 0; i < 3; ++i) r[i] = (p(i) - T(m_ae1(i))) * m_w;
    return true;
  }
  RelativeModel m_m;
  Vec3 m_ae1, m_ae2;
  double m_w;
};

/// A(k+1) must equal inc1^T A(k) inc2: the relative rotation carried by the two gyroscopes.
struct GyroCost {
  GyroCost(const RelativeModel& m, const Mat3& inc1, const Mat3& inc2, double dt, double std)
      : m_m(m), m_inc1(inc1), m_inc2(inc2), m_w(1.0 / (dt * std)) {}
  template <typename T>
  bool operator()(const T* th0, const T* th1, const T* w1, const T* w2, T* r) const {
    M3<T> m1, m2;
    mountings(w1, w2, m1, m2);
    const M3<T> a0 = sensorRelative(m_m, th0, m1, m2);
    const M3<T> a1 = sensorRelative(m_m, th1, m1, m2);
    const M3<T> p = a1.transpose() * m_inc1.transpose().cast<T>() * a0 * m_inc2.cast<T>();
    r[0] = T(0.5) * (p(2, 1) - p(1, 2)) * m_w;
    r[1] = T(0.5) * (p(0, 2) - p(2, 0)) * m_w;
    r[2] = T(0.5) * (p(1, 0) - p(0, 1)) * m_w;
    return true;
  }
  RelativeModel m_m;
  Mat3 m_inc1, m_inc2;
  double m_w;
};

/// The upper arm's long axis (shoulder to elbow) must be the model IMU frame's y axis.
struct LongAxisCost {
  LongAxisCost(const Vec3& axis, double std) : m_axis(axis), m_w(1.0 / std) {}
  template <typename T>
  bool operator()(const T* w1, T* r) const {
    const T a[3] = {T(m_axis(0)), T(m_axis(1)), T(m_axis(2))};
    T p[3];
    ceres::AngleAxisRotatePoint(w1, a, p);
    r[0] = p[0] * m_w;
    r[1] = (p[1] - T(1)) * m_w;
    r[2] = p[2] * m_w;
    return true;
  }
  Vec3 m_axis;
  double m_w;
};

/// The mounting must take a direction seen in the sensor's axes to the model's.
struct DirectionCost {
  DirectionCost(const Vec3& seen, const Vec3& model, double std)
      : m_seen(seen), m_model(model), m_w(1.0 / std) {}
  template <typename T>
  bool operator()(const T* w1, T* r) const {
    const T a[3] = {T(m_seen(0)), T(m_seen(1)), T(m_seen(2))};
    T q[3];
    ceres::AngleAxisRotatePoint(w1, a, q);
    for (int i = 0; i < 3; ++i) r[i] = (q[i] - T(m_model(i))) * m_w;
    return true;
  }
  Vec3 m_seen, m_model;
  double m_w;
};

struct PriorCost {
  PriorCost(int n, double std) : m_n(n), m_w(1.0 / std) {}
  template <typename T>
  bool operator()(const T* x, T* r) const {
    for (int i = 0; i < m_n; ++i) r[i] = x[i] * m_w;
    return true;
  }
  int m_n;
  double m_w;
};

/// Per instant, the (th4, th5) on a 10 deg grid that best explains the elbow's specific force and
/// the two gyroscopes (the joint rates solved by least squares) at the given mountings.
Eigen::Vector2d gridStart(const AxesInput& in, std::size_t k, const Mat3& m1, const Mat3& m2) {
  double best = 1e300;
  Eigen::Vector2d arg(-kHalfPi, 0.0);
  const Vec3 b5 = m2.transpose() * Vec3::UnitY();
  for (int i4 = -17; i4 <= 2; ++i4) {
    for (int i5 = -18; i5 < 18; ++i5) {
      const double th4 = i4 * 10.0 * std::numbers::pi / 180.0;
      const double th5 = i5 * 10.0 * std::numbers::pi / 180.0;
      const Mat3 a = m1.transpose() * relativeRotation(in.model, th4, th5) * m2;
      const Vec3 ea = in.ae1[k] - a * in.ae2[k];
      const Vec3 rel = in.w2[k] - a.transpose() * in.w1[k];
      Eigen::Matrix<double, 3, 2> b;
      b.col(0) = a.transpose() * m1.transpose() * in.model.flexionInUpper;
      b.col(1) = b5;
      const Eigen::Vector2d rates = (b.transpose() * b).ldlt().solve(b.transpose() * rel);
      const Vec3 er = rel - b * rates;
      const double cost = ea.squaredNorm() / (in.accelStd * in.accelStd) +
                          er.squaredNorm() / (in.gyroStd * in.gyroStd);
      if (cost < best) {
        best = cost;
        arg = {th4, th5};
      }
    }
  }
  return arg;
}

/// Marginal covariance of the last `g` parameters of the whole problem (the per-instant angles
/// eliminated): S = Hgg - Hgl Hll^-1 Hlg, returned S^-1.
Eigen::MatrixXd marginalCovariance(ceres::Problem& problem, const std::vector<double*>& blocks,
                                   int g) {
  ceres::Problem::EvaluateOptions eo;
  eo.parameter_blocks = blocks;
  ceres::CRSMatrix crs;
  problem.Evaluate(eo, nullptr, nullptr, nullptr, &crs);
  Eigen::SparseMatrix<double, Eigen::RowMajor> j(crs.num_rows, crs.num_cols);
  std::vector<Eigen::Triplet<double>> trip;
  for (int r = 0; r < crs.num_rows; ++r)
    for (int p = crs.rows[r]; p < crs.rows[r + 1]; ++p)
      trip.emplace_back(r, crs.cols[p], crs.values[p]);
  j.setFromTriplets(trip.begin(), trip.end());
  const Eigen::SparseMatrix<double> h = Eigen::SparseMatrix<double>(j.transpose() * j);
  const int n = crs.num_cols, l = n - g;
  const Eigen::SparseMatrix<double> hll = h.topLeftCorner(l, l);
  const Eigen::MatrixXd hlg = Eigen::MatrixXd(h.topRightCorner(l, g));
  const Eigen::MatrixXd hgg = Eigen::MatrixXd(h.bottomRightCorner(g, g));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(hll);
  Eigen::MatrixXd s = hgg;
  if (ldlt.info() == Eigen::Success) s -= hlg.transpose() * ldlt.solve(hlg);
  return s.inverse();
}

}  // namespace

Mat3 upperImuInFrame3(double thu4) {
  return rotZ(thu4) * rotX(kHalfPi);
}
Mat3 forearmImuInFrame6(double thf7) {
  return rotZ(thf7 + kHalfPi) * rotX(kHalfPi);
}

RelativeModel relativeModel(const ArmGeometry& geo) {
  const Mat3 r34 = rotZ(kHalfPi) * rotX(-kHalfPi);
  RelativeModel m;
  m.c = upperImuInFrame3(geo.thu4).transpose() * r34;
  m.d = rotX(kHalfPi);
  m.e = forearmImuInFrame6(geo.thf7);
  m.flexionInUpper = m.c * Vec3::UnitZ();
  return m;
}

Mat3 relativeRotation(const RelativeModel& m, double th4, double th5) {
  return m.c * rotZ(th4) * m.d * rotZ(th5) * m.e;
}

Mat3 expRotation(const Vec3& w) {
  const double a = w.norm();
  if (a < 1e-300) return Mat3::Identity();
  return Eigen::AngleAxisd(a, w / a).toRotationMatrix();
}

Mat3 forearmTilt(const Eigen::Vector2d& w2) {
  return expRotation(Vec3(w2(0), 0.0, w2(1)));
}

AxesResult fitAxes(const AxesInput& in) {
  const std::size_t n = in.ae1.size();
  AxesResult out;
  double w1[3] = {0, 0, 0};
  double w2[2] = {0, 0};
  std::vector<double> th(2 * n);
  for (int pass = 0; pass < 2; ++pass) {
    const Mat3 m1 = expRotation(Vec3(w1[0], w1[1], w1[2]));
    const Mat3 m2 = forearmTilt({w2[0], w2[1]});
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Vector2d s = gridStart(in, k, m1, m2);
      th[2 * k] = s(0);
      th[2 * k + 1] = s(1);
    }
    ceres::Problem::Options po;
    ceres::Problem problem(po);
    for (std::size_t k = 0; k < n; ++k) {
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<AccelCost, 3, 2, 3, 2>(
                                   new AccelCost(in.model, in.ae1[k], in.ae2[k], in.accelStd)),
                               new ceres::HuberLoss(2.0), &th[2 * k], w1, w2);
      if (k + 1 < n) {
        problem.AddResidualBlock(
            new ceres::AutoDiffCostFunction<GyroCost, 3, 2, 2, 3, 2>(
                new GyroCost(in.model, in.inc1[k], in.inc2[k], in.dt, in.gyroStd)),
            new ceres::HuberLoss(2.0), &th[2 * k], &th[2 * k + 2], w1, w2);
      }
    }
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<LongAxisCost, 3, 3>(
                                 new LongAxisCost(in.longAxis1, in.longAxisStd)),
                             nullptr, w1);
    if (in.gravity1 && in.gravityModel1) {
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<DirectionCost, 3, 3>(
              new DirectionCost(*in.gravity1, *in.gravityModel1, in.gravityStd)),
          nullptr, w1);
    }
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<PriorCost, 3, 3>(new PriorCost(3, in.priorStd)), nullptr,
        w1);
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<PriorCost, 2, 2>(new PriorCost(2, in.priorStd)), nullptr,
        w2);
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    so.max_num_iterations = in.maxIterations;
    so.num_threads = 2;
    so.logging_type = ceres::SILENT;
    so.minimizer_progress_to_stdout = false;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    out.converged = summary.termination_type == ceres::CONVERGENCE;
    if (pass == 1 || summary.final_cost > 0.8 * summary.initial_cost) {
      // The last pass: the covariance and the residuals.
      std::vector<double*> blocks;
      for (std::size_t k = 0; k < n; ++k) blocks.push_back(&th[2 * k]);
      blocks.push_back(w1);
      blocks.push_back(w2);
      const Eigen::MatrixXd cov = marginalCovariance(problem, blocks, 5);
      const double dof = std::max(1.0, static_cast<double>(summary.num_residuals) -
                                           static_cast<double>(summary.num_parameters));
      const double factor = std::max(1.0, 2.0 * summary.final_cost / dof);
      out.cov = cov * factor;
      break;
    }
  }
  out.w1 = Vec3(w1[0], w1[1], w1[2]);
  out.w2 = Eigen::Vector2d(w2[0], w2[1]);
  out.theta.resize(n);
  for (std::size_t k = 0; k < n; ++k) out.theta[k] = {th[2 * k], th[2 * k + 1]};
  // Unweighted residuals, for the report.
  const Mat3 m1 = expRotation(out.w1), m2 = forearmTilt(out.w2);
  double g2 = 0, a2 = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Mat3 a0 = m1.transpose() * relativeRotation(in.model, th[2 * k], th[2 * k + 1]) * m2;
    a2 += (in.ae1[k] - a0 * in.ae2[k]).squaredNorm();
    if (k + 1 < n) {
      const Mat3 a1 =
          m1.transpose() * relativeRotation(in.model, th[2 * k + 2], th[2 * k + 3]) * m2;
      const Mat3 p = a1.transpose() * in.inc1[k].transpose() * a0 * in.inc2[k];
      const Vec3 v(p(2, 1) - p(1, 2), p(0, 2) - p(2, 0), p(1, 0) - p(0, 1));
      g2 += (0.5 * v / in.dt).squaredNorm();
    }
  }
  out.gyroRms = n > 1 ? std::sqrt(g2 / (3.0 * static_cast<double>(n - 1))) : 0.0;
  out.accelRms = n > 0 ? std::sqrt(a2 / (3.0 * static_cast<double>(n))) : 0.0;
  return out;
}

}  // namespace armtrack::movecal
