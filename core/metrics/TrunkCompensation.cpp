#include "core/metrics/TrunkCompensation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace armtrack {
namespace {

constexpr double kToDeg = 180.0 / std::numbers::pi;
constexpr double kMaxShoulderM = 2.0;

/// A smoothed track: times and one value per row (columns as given).
struct Track {
  std::vector<double> t;
  Eigen::MatrixXd value;
  bool empty() const { return t.empty(); }
};

Track smoothed(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& raw,
               const SmoothingParams& params, bool medianFirst,
               Eigen::MatrixXd* filtered = nullptr) {
  Track out;
  out.t = t;
  Eigen::MatrixXd values(static_cast<Eigen::Index>(t.size()), 3);
  for (std::size_t i = 0; i < t.size(); ++i) values.row(static_cast<Eigen::Index>(i)) = raw[i];
  if (t.empty()) {
    out.value = values;
    return out;
  }
  if (medianFirst) {
    // A running median of 5 within each gap-free run: a single or double wild frame never
    // reaches the fit.
    Eigen::MatrixXd med = values;
    for (const Segment& seg : splitAtGaps(t, params.maxGapSeconds)) {
      for (std::size_t i = seg.begin; i < seg.end; ++i) {
        const std::size_t lo = std::max(seg.begin, i >= 2 ? i - 2 : 0);
        const std::size_t hi = std::min(seg.end, i + 3);
        for (Eigen::Index k = 0; k < 3; ++k) {
          std::vector<double> w;
          for (std::size_t j = lo; j < hi; ++j)
            w.push_back(values(static_cast<Eigen::Index>(j), k));
          std::nth_element(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(w.size() / 2),
                           w.end());
          med(static_cast<Eigen::Index>(i), k) = w[w.size() / 2];
        }
      }
    }
    values = med;
  }
  if (filtered) *filtered = values;
  Eigen::MatrixXd derivative;
  smoothWithDerivative(t, values, params, out.value, derivative);
  if (medianFirst && params.polynomialOrder > 1) {
    // Within a half window of a run's ends the fit is one-sided, where a quadratic's value is
    // about three times as noisy as in the middle; a straight line there halves that.
    SmoothingParams line = params;
    line.polynomialOrder = 1;
    Eigen::MatrixXd linear;
    smoothWithDerivative(t, values, line, linear, derivative);
    for (const Segment& seg : splitAtGaps(t, params.maxGapSeconds)) {
      for (std::size_t i = seg.begin; i < seg.end; ++i) {
        if (t[i] - t[seg.begin] < params.halfWindowSeconds ||
            t[seg.end - 1] - t[i] < params.halfWindowSeconds) {
          out.value.row(static_cast<Eigen::Index>(i)) = linear.row(static_cast<Eigen::Index>(i));
        }
      }
    }
  }
  return out;
}

/// Indices [begin, end) of the samples with startS <= t <= endS.
std::pair<std::size_t, std::size_t> inside(const std::vector<double>& t, double startS,
                                           double endS) {
  const auto b = std::lower_bound(t.begin(), t.end(), startS);
  const auto e = std::upper_bound(b, t.end(), endS);
  return {static_cast<std::size_t>(b - t.begin()), static_cast<std::size_t>(e - t.begin())};
}

std::optional<double> largestAbs(const Eigen::VectorXd& v, std::size_t b, std::size_t e) {
  if (b >= e) return std::nullopt;
  return v.segment(static_cast<Eigen::Index>(b), static_cast<Eigen::Index>(e - b))
      .cwiseAbs()
      .maxCoeff();
}

TrunkExtremes extremes(const Track& angles, const Eigen::VectorXd& displacementCm,
                       const std::vector<double>& shoulderT, double startS, double endS,
                       const std::optional<double>& limitDeg) {
  TrunkExtremes x;
  const auto [ab, ae] = inside(angles.t, startS, endS);
  if (ab < ae) {
    x.maxFlexionDeg = *largestAbs(angles.value.col(0), ab, ae) * kToDeg;
    x.maxLateralDeg = *largestAbs(angles.value.col(1), ab, ae) * kToDeg;
    x.maxRotationDeg = *largestAbs(angles.value.col(2), ab, ae) * kToDeg;
    if (limitDeg) x.compensated = *x.maxFlexionDeg > *limitDeg;
  }
  const auto [sb, se] = inside(shoulderT, startS, endS);
  x.maxShoulderDisplacementCm = largestAbs(displacementCm, sb, se);
  return x;
}

}  // namespace

std::vector<TimeSpan> repetitionSpans(const RepetitionResult& result) {
  std::vector<TimeSpan> spans;
  spans.reserve(result.repetitions.size());
  for (const Repetition& r : result.repetitions) spans.push_back({r.startS, r.endS});
  return spans;
}

TrunkCompensation computeTrunkCompensation(const std::vector<TrunkRow>& rows,
                                           const std::vector<TimeSpan>& repetitions,
                                           const TrunkCompensationParams& params) {
  if (params.flexionLimitDeg &&
      !(std::isfinite(*params.flexionLimitDeg) && *params.flexionLimitDeg > 0)) {
    throw std::invalid_argument("the trunk flexion limit must be a positive number of degrees");
  }
  TrunkCompensation out;
  out.inputRows = rows.size();

  std::vector<double> angleT, shoulderT;
  std::vector<Eigen::Vector3d> angleRaw, shoulderRaw;
  std::optional<double> lastT;
  for (const TrunkRow& row : rows) {
    if (row.leaveOut) {
      ++out.leftOut;
      continue;
    }
    if (!std::isfinite(row.t) || (row.angle && !row.angle->allFinite()) ||
        (row.shoulder && !row.shoulder->allFinite())) {
      ++out.refusedNonFinite;
      continue;
    }
    if ((row.angle && row.angle->cwiseAbs().maxCoeff() > std::numbers::pi) ||
        (row.shoulder && row.shoulder->norm() > kMaxShoulderM)) {
      ++out.refusedImplausible;
      continue;
    }
    if (lastT && row.t <= *lastT) {
      ++out.refusedOutOfOrder;
      continue;
    }
    if (!row.angle && !row.shoulder) continue;  // nothing to measure, but its time is fine
    lastT = row.t;
    if (row.angle) {
      angleT.push_back(row.t);
      angleRaw.push_back(*row.angle);
    }
    if (row.shoulder) {
      shoulderT.push_back(row.t);
      shoulderRaw.push_back(*row.shoulder);
    }
  }

  const Track angles = smoothed(angleT, angleRaw, params.angleSmoothing, false);
  Eigen::MatrixXd shoulderFiltered;
  const Track shoulder =
      smoothed(shoulderT, shoulderRaw, params.shoulderSmoothing, true, &shoulderFiltered);
  Eigen::VectorXd displacementCm(static_cast<Eigen::Index>(shoulder.t.size()));
  if (!shoulder.empty()) {
    // The start position: the mean of the median-filtered positions over the first
    // shoulderReferenceSeconds (the smoothed ones are one-sided fits there, and noisier).
    const auto [b, e] = inside(shoulder.t, shoulder.t.front(),
                               shoulder.t.front() + std::max(0.0, params.shoulderReferenceSeconds));
    const Eigen::Vector3d start =
        shoulderFiltered.middleRows(static_cast<Eigen::Index>(b), static_cast<Eigen::Index>(e - b))
            .colwise()
            .mean()
            .transpose();
    for (Eigen::Index i = 0; i < displacementCm.size(); ++i) {
      displacementCm(i) = 100.0 * (shoulder.value.row(i).transpose() - start).norm();
    }
  }

  const double inf = std::numeric_limits<double>::infinity();
  out.session = extremes(angles, displacementCm, shoulder.t, -inf, inf, params.flexionLimitDeg);
  std::size_t compensated = 0;
  for (const TimeSpan& span : repetitions) {
    if (!std::isfinite(span.startS) || !std::isfinite(span.endS) || span.endS < span.startS) {
      ++out.invalidSpans;
      out.repetitions.emplace_back();
      continue;
    }
    out.repetitions.push_back(extremes(angles, displacementCm, shoulder.t, span.startS, span.endS,
                                       params.flexionLimitDeg));
    compensated += out.repetitions.back().compensated.value_or(false) ? 1 : 0;
  }
  if (params.flexionLimitDeg && !angles.empty()) out.repetitionsWithCompensation = compensated;
  return out;
}

}  // namespace armtrack
