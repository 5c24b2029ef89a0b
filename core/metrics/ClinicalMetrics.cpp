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

/// The smoothness of the path between two times (s), from the velocity on the path's grid
/// there: only that part is computed.
PathSmoothness smoothnessBetween(const std::vector<double>& t, const Eigen::MatrixXd& path,
                                 const UniformVelocity& grid, double fromS, double toS,
                                 const PathSmoothnessParams& params) {
  const UniformVelocity v = uniformVelocityBetween(t, path, params, grid, fromS, toS);
  return velocitySmoothness(v.velocity, v.sampleRateHz, params);
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
  // The velocity is computed only where it is used, on one grid for the whole session: its
  // memory and time grow with the movements' length, not with the session's span (a day-long
  // gap holds no grid rows).
  const UniformVelocity grid = uniformGrid(s.t, params.smoothness);

  std::vector<SmoothnessValue> sparcs, ldljs;
  for (const Repetition& r : out.repetitions.repetitions) {
    const PathSmoothness p =
        smoothnessBetween(s.t, path, grid, r.startS, r.endS, params.smoothness);
    out.repetitionSmoothness.push_back({p.sparc, p.ldlj});
    sparcs.push_back(p.sparc);
    ldljs.push_back(p.ldlj);
  }
  if (out.repetitions.repetitions.empty()) {
    // No repetition: each gap-free stretch of the path, in pieces of at most
    // kMaxSmoothnessPieceS, and the median of their values (docs/metrics.md).
    for (const Segment& g : s.segments) {
      const double from = s.t[g.begin], to = s.t[g.end - 1];
      const int pieces =
          std::max(1, static_cast<int>(std::ceil((to - from) / kMaxSmoothnessPieceS)));
      const double length = (to - from) / pieces;
      for (int k = 0; k < pieces; ++k) {
        const PathSmoothness p =
            smoothnessBetween(s.t, path, grid, from + k * length,
                              k + 1 == pieces ? to : from + (k + 1) * length, params.smoothness);
        sparcs.push_back(p.sparc);
        ldljs.push_back(p.ldlj);
      }
    }
  }
  out.sparc = medianOf(sparcs);
  out.ldlj = medianOf(ldljs);
  return out;
}

}  // namespace armtrack
