#include "core/metrics/Smoothing.h"

#include <Eigen/Cholesky>
#include <algorithm>

namespace armtrack {

std::vector<Segment> splitAtGaps(const std::vector<double>& t, double maxGapSeconds) {
  std::vector<Segment> segments;
  if (t.empty()) return segments;
  std::size_t begin = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i] - t[i - 1] > maxGapSeconds) {
      segments.push_back({begin, i});
      begin = i;
    }
  }
  segments.push_back({begin, t.size()});
  return segments;
}

void fitWindow(const std::vector<double>& t, const Eigen::MatrixXd& values, std::size_t lo,
               std::size_t hi, double tc, double h, int maxOrder, Eigen::RowVectorXd& value,
               Eigen::RowVectorXd& rate) {
  const Eigen::Index k = values.cols();
  const int order = std::min(maxOrder, static_cast<int>(hi - lo) - 1);
  // Polynomial in u = (t_j - tc) / h, which keeps the normal equations well scaled.
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4>;
  Small normal = Small::Zero(order + 1, order + 1);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(order + 1, k);
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 4, 1> basis(order + 1);
  for (std::size_t j = lo; j < hi; ++j) {
    const double u = (t[j] - tc) / h;
    basis(0) = 1.0;
    for (int d = 1; d <= order; ++d) basis(d) = basis(d - 1) * u;
    normal.noalias() += basis * basis.transpose();
    rhs.noalias() += basis * values.row(static_cast<Eigen::Index>(j));
  }
  const Eigen::MatrixXd coef = normal.ldlt().solve(rhs);
  value = coef.row(0);
  rate = order >= 1 ? Eigen::RowVectorXd(coef.row(1) / h) : Eigen::RowVectorXd::Zero(k);
}

void smoothWithDerivative(const std::vector<double>& t, const Eigen::MatrixXd& values,
                          const SmoothingParams& params, Eigen::MatrixXd& smoothed,
                          Eigen::MatrixXd& derivative) {
  const Eigen::Index n = values.rows(), k = values.cols();
  smoothed = values;
  derivative = Eigen::MatrixXd::Zero(n, k);
  const double h = params.halfWindowSeconds;
  for (const Segment& seg : splitAtGaps(t, params.maxGapSeconds)) {
    std::size_t lo = seg.begin, hi = seg.begin;  // window [lo, hi)
    for (std::size_t i = seg.begin; i < seg.end; ++i) {
      while (t[i] - t[lo] > h) ++lo;
      while (hi < seg.end && t[hi] - t[i] <= h) ++hi;
      const std::size_t m = hi - lo;
      if (m < 2) continue;  // lone sample: value as measured, rate unknown (0)
      Eigen::RowVectorXd value, rate;
      fitWindow(t, values, lo, hi, t[i], h, params.polynomialOrder, value, rate);
      smoothed.row(static_cast<Eigen::Index>(i)) = value;
      derivative.row(static_cast<Eigen::Index>(i)) = rate;
    }
  }
}

std::vector<double> sampleWeights(const std::vector<double>& t,
                                  const std::vector<Segment>& segments) {
  std::vector<double> w(t.size(), 0.0);
  for (const Segment& seg : segments) {
    for (std::size_t i = seg.begin; i + 1 < seg.end; ++i) {
      const double half = 0.5 * (t[i + 1] - t[i]);
      w[i] += half;
      w[i + 1] += half;
    }
  }
  return w;
}

}  // namespace armtrack
