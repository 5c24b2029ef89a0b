#include "core/metrics/RangeOfMotion.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/kinematics/ClinicalAngles.h"

namespace armtrack {

AngleSeries angleSeriesFromJoints(const std::vector<double>& t,
                                  const std::vector<JointVector>& joints) {
  if (t.size() != joints.size()) {
    throw std::invalid_argument("angleSeriesFromJoints: times and joint vectors differ in length");
  }
  AngleSeries s;
  s.t = t;
  s.angle.reserve(joints.size());
  for (const JointVector& th : joints) {
    const std::array<double, 5> deg = asArray(toClinical(th));
    ClinicalRow row;
    for (int a = 0; a < kNumClinicalAngles; ++a) row[a] = deg[a] * kDegToRad;
    s.angle.push_back(row);
  }
  return s;
}

JointVector jointsFromClinical(const ClinicalRow& r) {
  const ClinicalAngles c{r[0] * kRadToDeg, r[1] * kRadToDeg, r[2] * kRadToDeg, r[3] * kRadToDeg,
                         r[4] * kRadToDeg};
  return fromClinical(c);
}

namespace {
bool positiveFinite(double x) {
  return std::isfinite(x) && x > 0;
}
}  // namespace

PreparedSeries prepareSeries(const AngleSeries& series, const MotionParams& params) {
  if (series.t.size() != series.angle.size()) {
    throw std::invalid_argument("clinical metrics: " + std::to_string(series.t.size()) +
                                " time stamps but " + std::to_string(series.angle.size()) +
                                " rows of angles");
  }
  if (!positiveFinite(params.smoothing.halfWindowSeconds) ||
      !positiveFinite(params.smoothing.maxGapSeconds) || params.smoothing.polynomialOrder < 1 ||
      (params.smoothing.maxSamplesPerFit != 0 && params.smoothing.maxSamplesPerFit < 4) ||
      params.smoothing.polynomialOrder > 3 ||
      !(std::isfinite(params.movingThresholdRadPerS) && params.movingThresholdRadPerS >= 0)) {
    throw std::invalid_argument(
        "clinical metrics: smoothing window and gap must be positive, the polynomial order 1-3, "
        "samples per fit 0 or at least 4, "
        "the moving threshold non-negative, all finite");
  }
  PreparedSeries p;
  p.params = params;
  p.inputRows = series.t.size();
  std::vector<std::size_t> kept;
  kept.reserve(series.t.size());
  for (std::size_t i = 0; i < series.t.size(); ++i) {
    bool finite = std::isfinite(series.t[i]);
    for (double a : series.angle[i]) finite = finite && std::isfinite(a);
    if (!finite) {
      ++p.rejectedNonFinite;
      continue;
    }
    if (!kept.empty() && !(series.t[i] > series.t[kept.back()])) {
      std::ostringstream msg;
      msg.precision(17);
      msg << "clinical metrics: time stamps must increase strictly, but row " << i
          << " (t = " << series.t[i] << " s) does not follow row " << kept.back()
          << " (t = " << series.t[kept.back()] << " s)";
      throw std::invalid_argument(msg.str());
    }
    kept.push_back(i);
  }
  if (kept.empty()) {
    throw std::invalid_argument("clinical metrics: no usable samples (" +
                                std::to_string(p.inputRows) + " rows given, " +
                                std::to_string(p.rejectedNonFinite) + " non-finite)");
  }
  const auto n = static_cast<Eigen::Index>(kept.size());
  Eigen::MatrixXd raw(n, kNumClinicalAngles);
  p.t.reserve(kept.size());
  for (Eigen::Index r = 0; r < n; ++r) {
    const std::size_t i = kept[static_cast<std::size_t>(r)];
    p.t.push_back(series.t[i]);
    for (int a = 0; a < kNumClinicalAngles; ++a) raw(r, a) = series.angle[i][a];
  }
  smoothWithDerivative(p.t, raw, params.smoothing, p.angle, p.rate);
  p.segments = splitAtGaps(p.t, params.smoothing.maxGapSeconds);
  p.weight = sampleWeights(p.t, p.segments);
  return p;
}

AngleMetricsDeg inDegrees(const AngleMetrics& m) {
  return {m.minRad * kRadToDeg,
          m.maxRad * kRadToDeg,
          m.romRad * kRadToDeg,
          m.peakVelocityRadPerS * kRadToDeg,
          m.meanVelocityRadPerS * kRadToDeg,
          m.movementTimeS};
}

IntervalMetrics intervalMetrics(const PreparedSeries& s, std::size_t begin, std::size_t end) {
  if (!(begin < end && end <= s.size())) {
    throw std::out_of_range("intervalMetrics: interval [" + std::to_string(begin) + ", " +
                            std::to_string(end) + ") outside a series of " +
                            std::to_string(s.size()) + " samples");
  }
  IntervalMetrics out;
  out.samples = end - begin;
  // Weights of the end samples count only the half-steps inside the interval.
  auto weightAt = [&](std::size_t i) {
    double w = s.weight[i];
    if (i == begin && i > 0 && w > 0 && s.t[i] - s.t[i - 1] <= s.params.smoothing.maxGapSeconds)
      w -= 0.5 * (s.t[i] - s.t[i - 1]);
    if (i + 1 == end && i + 1 < s.size() && s.t[i + 1] - s.t[i] <= s.params.smoothing.maxGapSeconds)
      w -= 0.5 * (s.t[i + 1] - s.t[i]);
    return std::max(w, 0.0);
  };
  std::vector<double> w(end - begin);
  for (std::size_t i = begin; i < end; ++i) {
    w[i - begin] = weightAt(i);
    out.coveredTimeS += w[i - begin];
  }
  const double threshold = s.params.movingThresholdRadPerS;
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    AngleMetrics m;
    m.minRad = m.maxRad = s.angle(static_cast<Eigen::Index>(begin), a);
    double weighted = 0;
    for (std::size_t i = begin; i < end; ++i) {
      const auto r = static_cast<Eigen::Index>(i);
      const double v = s.angle(r, a), speed = std::abs(s.rate(r, a));
      m.minRad = std::min(m.minRad, v);
      m.maxRad = std::max(m.maxRad, v);
      m.peakVelocityRadPerS = std::max(m.peakVelocityRadPerS, speed);
      weighted += w[i - begin] * speed;
      if (speed >= threshold && speed > 0) m.movementTimeS += w[i - begin];
    }
    m.romRad = m.maxRad - m.minRad;
    m.meanVelocityRadPerS = out.coveredTimeS > 0 ? weighted / out.coveredTimeS : 0.0;
    out.angle[static_cast<std::size_t>(a)] = m;
  }
  return out;
}

}  // namespace armtrack
