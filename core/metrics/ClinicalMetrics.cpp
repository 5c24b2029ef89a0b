#include "core/metrics/ClinicalMetrics.h"

#include <algorithm>
#include <cmath>

namespace armtrack {
namespace {

/// Median of the values with status Ok; the first failure's status when none is Ok.
SmoothnessValue medianOf(const std::vector<SmoothnessValue>& values) {
  std::vector<double> ok;
  for (const SmoothnessValue& v : values)
    if (v.ok()) ok.push_back(v.value);
  if (ok.empty()) return values.empty() ? SmoothnessValue{} : values.front();
  std::sort(ok.begin(), ok.end());
  const std::size_t m = ok.size() / 2;
  const double median = ok.size() % 2 ? ok[m] : 0.5 * (ok[m - 1] + ok[m]);
  return {median, SmoothnessStatus::Ok};
}

/// The part of a uniformly sampled velocity between two times (s).
PathSmoothness smoothnessBetween(const UniformVelocity& v, double fromS, double toS,
                                 const PathSmoothnessParams& params) {
  const Eigen::Index rows = v.velocity.rows();
  const auto first = std::clamp<Eigen::Index>(
      static_cast<Eigen::Index>(std::ceil((fromS - v.t0) * v.sampleRateHz - 1e-9)), 0, rows);
  const auto last = std::clamp<Eigen::Index>(
      static_cast<Eigen::Index>(std::floor((toS - v.t0) * v.sampleRateHz + 1e-9)), -1, rows - 1);
  const Eigen::Index count = std::max<Eigen::Index>(last - first + 1, 0);
  return velocitySmoothness(v.velocity.middleRows(first, count), v.sampleRateHz, params);
}

}  // namespace

SessionMetrics computeSessionMetrics(const AngleSeries& series,
                                     const ClinicalMetricsParams& params) {
  const PreparedSeries s = prepareSeries(series, params.motion);
  SessionMetrics out;
  out.samples = s.size();
  out.rejectedNonFinite = s.rejectedNonFinite;
  out.gaps = s.segments.size() - 1;
  out.durationS = s.t.back() - s.t.front();
  out.session = intervalMetrics(s, 0, s.size());
  out.repetitions = detectRepetitions(s, params.repetitions);
  if (!params.geometry) return out;

  // The wrist path of the smoothed angles. Jerk is a third derivative: from the raw angles,
  // 0.5 deg of noise on a 0.42 m arm (4 mm at the wrist) swamps it. The angle smoothing keeps
  // the spectrum of arm movements (below about 4 Hz) and the path's own fit only differentiates.
  Eigen::MatrixXd path;
  {
    std::vector<ClinicalRow> rows(s.size());
    for (std::size_t i = 0; i < s.size(); ++i)
      for (int a = 0; a < kNumClinicalAngles; ++a)
        rows[i][a] = s.angle(static_cast<Eigen::Index>(i), a);
    path = wristPath(rows, *params.geometry);
  }  // the rows are freed before the velocity is resampled: 40 bytes a sample less at the peak
  const UniformVelocity velocity = uniformVelocity(s.t, path, params.smoothness);

  std::vector<SmoothnessValue> sparcs, ldljs;
  for (const Repetition& r : out.repetitions.repetitions) {
    const PathSmoothness p = smoothnessBetween(velocity, r.startS, r.endS, params.smoothness);
    out.repetitionSmoothness.push_back({p.sparc, p.ldlj});
    sparcs.push_back(p.sparc);
    ldljs.push_back(p.ldlj);
  }
  if (out.repetitions.repetitions.empty()) {
    const PathSmoothness p =
        smoothnessBetween(velocity, s.t.front(), s.t.back(), params.smoothness);
    out.sparc = p.sparc;
    out.ldlj = p.ldlj;
  } else {
    out.sparc = medianOf(sparcs);
    out.ldlj = medianOf(ldljs);
  }
  return out;
}

}  // namespace armtrack
