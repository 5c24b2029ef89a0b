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
      const int order = std::min(params.polynomialOrder, static_cast<int>(m) - 1);
      // Polynomial in u = (t_j - t_i) / h, which keeps the normal equations well scaled.
      using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4>;
      Small normal = Small::Zero(order + 1, order + 1);
      Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(order + 1, k);
      Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 4, 1> basis(order + 1);
      for (std::size_t j = lo; j < hi; ++j) {
        const double u = (t[j] - t[i]) / h;
        basis(0) = 1.0;
        for (int d = 1; d <= order; ++d) basis(d) = basis(d - 1) * u;
        normal.noalias() += basis * basis.transpose();
        rhs.noalias() += basis * values.row(static_cast<Eigen::Index>(j));
      }
      const Eigen::MatrixXd coef = normal.ldlt().solve(rhs);
      smoothed.row(static_cast<Eigen::Index>(i)) = coef.row(0);
      derivative.row(static_cast<Eigen::Index>(i)) = coef.row(1) / h;
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

Eigen::RowVectorXd interpolateRow(const std::vector<double>& t, const Eigen::MatrixXd& values,
                                  double tq) {
  const auto it = std::upper_bound(t.begin(), t.end(), tq);
  if (it == t.begin()) return values.row(0);
  if (it == t.end()) return values.row(values.rows() - 1);
  const auto b = static_cast<Eigen::Index>(it - t.begin());
  const Eigen::Index a = b - 1;
  const double f = (tq - t[static_cast<std::size_t>(a)]) /
                   (t[static_cast<std::size_t>(b)] - t[static_cast<std::size_t>(a)]);
  return (1.0 - f) * values.row(a) + f * values.row(b);
}

}  // namespace armtrack
