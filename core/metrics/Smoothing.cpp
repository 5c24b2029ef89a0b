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

void localFitWeights(const std::vector<double>& t, std::size_t lo, std::size_t hi, double tc,
                     double h, int maxOrder, int maxSamples, LocalFit& fit) {
  fit.index.clear();
  fit.valueWeight.clear();
  fit.rateWeight.clear();
  const std::size_t m = hi - lo;
  if (m == 0) return;
  // Dense windows are thinned to at most maxSamples, evenly, keeping the sample nearest tc.
  const std::size_t stride =
      maxSamples > 0 ? std::max<std::size_t>(1, (m + static_cast<std::size_t>(maxSamples) - 1) /
                                                    static_cast<std::size_t>(maxSamples))
                     : 1;
  const auto nearest = static_cast<std::size_t>(
      std::lower_bound(t.begin() + static_cast<long>(lo), t.begin() + static_cast<long>(hi), tc) -
      t.begin());
  const std::size_t first = lo + (std::min(nearest, hi - 1) - lo) % stride;
  for (std::size_t j = first; j < hi; j += stride) fit.index.push_back(j);
  const int count = static_cast<int>(fit.index.size());
  const int order = std::min(maxOrder, count - 1);
  if (order < 1) {  // one sample: its value, no rate
    fit.valueWeight.assign(fit.index.size(), 1.0 / count);
    fit.rateWeight.assign(fit.index.size(), 0.0);
    return;
  }
  // Polynomial in u = (t_j - tc) / h, which keeps the normal equations well scaled. The normal
  // matrix holds the moments sum u^(r+c); the value and rate at tc are e0 and e1 of the
  // coefficients, so each sample's weights are e0' N^-1 b_j and e1' N^-1 b_j / h.
  double moment[7] = {0, 0, 0, 0, 0, 0, 0};
  for (std::size_t j : fit.index) {
    const double u = (t[j] - tc) / h;
    double p = 1.0;
    for (int d = 0; d <= 2 * order; ++d) {
      moment[d] += p;
      p *= u;
    }
  }
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4>;
  using SmallVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 4, 1>;
  Small normal(order + 1, order + 1);
  for (int r = 0; r <= order; ++r)
    for (int c = 0; c <= order; ++c) normal(r, c) = moment[r + c];
  const Eigen::LDLT<Small> ldlt(normal);
  const SmallVec a = ldlt.solve(SmallVec::Unit(order + 1, 0));
  const SmallVec b = ldlt.solve(SmallVec::Unit(order + 1, 1));
  for (std::size_t j : fit.index) {
    const double u = (t[j] - tc) / h;
    double p = 1.0, w0 = 0.0, w1 = 0.0;
    for (int d = 0; d <= order; ++d) {
      w0 += a(d) * p;
      w1 += b(d) * p;
      p *= u;
    }
    fit.valueWeight.push_back(w0);
    fit.rateWeight.push_back(w1 / h);
  }
}

void smoothWithDerivative(const std::vector<double>& t, const Eigen::MatrixXd& values,
                          const SmoothingParams& params, Eigen::MatrixXd& smoothed,
                          Eigen::MatrixXd& derivative) {
  const Eigen::Index n = values.rows(), k = values.cols();
  smoothed = values;
  derivative = Eigen::MatrixXd::Zero(n, k);
  const double h = params.halfWindowSeconds;
  LocalFit fit;
  Eigen::RowVectorXd value(k), rate(k);
  // Rows are read one at a time: a row-major copy keeps each row contiguous.
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = values;
  for (const Segment& seg : splitAtGaps(t, params.maxGapSeconds)) {
    std::size_t lo = seg.begin, hi = seg.begin;  // window [lo, hi)
    for (std::size_t i = seg.begin; i < seg.end; ++i) {
      while (t[i] - t[lo] > h) ++lo;
      while (hi < seg.end && t[hi] - t[i] <= h) ++hi;
      if (hi - lo < 2) continue;  // lone sample: value as measured, rate unknown (0)
      localFitWeights(t, lo, hi, t[i], h, params.polynomialOrder, params.maxSamplesPerFit, fit);
      value.setZero();
      rate.setZero();
      for (std::size_t q = 0; q < fit.index.size(); ++q) {
        const auto row = rows.row(static_cast<Eigen::Index>(fit.index[q]));
        value.noalias() += fit.valueWeight[q] * row;
        rate.noalias() += fit.rateWeight[q] * row;
      }
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
