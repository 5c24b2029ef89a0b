#include "core/calibration/CalibrationCosts.h"

#include <ceres/normal_prior.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <numbers>

namespace armtrack::calib {

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

ceres::CostFunction* normalPrior(const Eigen::VectorXd& mean, const Eigen::VectorXd& std) {
  const Eigen::MatrixXd a = std.cwiseInverse().asDiagonal();
  return new ceres::NormalPrior(a, mean);
}

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

}  // namespace armtrack::calib
