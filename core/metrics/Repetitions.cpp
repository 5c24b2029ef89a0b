#include "core/metrics/Repetitions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace armtrack {
namespace {

/// Time-weighted percentile (0-1) of x.
double weightedPercentile(const std::vector<double>& x, const std::vector<double>& w, double q) {
  std::vector<std::size_t> order(x.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  double total = 0;
  for (double v : w) total += v;
  if (total <= 0) {  // no duration (a single sample): plain order statistics
    const auto k = static_cast<std::size_t>(q * static_cast<double>(x.size() - 1));
    return x[order[k]];
  }
  double acc = 0;
  for (std::size_t i : order) {
    acc += w[i];
    if (acc >= q * total) return x[i];
  }
  return x[order.back()];
}

void validate(const RepetitionParams& p) {
  if (p.primaryAngle && (*p.primaryAngle < 0 || *p.primaryAngle >= kNumClinicalAngles)) {
    throw std::invalid_argument("repetitions: primary angle must be 0-4");
  }
  if (!(p.exitFraction > 0 && p.exitFraction < p.enterFraction && p.enterFraction < 1)) {
    throw std::invalid_argument("repetitions: need 0 < exitFraction < enterFraction < 1");
  }
  if (!(p.partialFraction > 0 && p.partialFraction <= 1)) {
    throw std::invalid_argument("repetitions: partialFraction must be in (0, 1]");
  }
  if (p.target && !(std::isfinite(p.target->minRad) && std::isfinite(p.target->maxRad) &&
                    p.target->maxRad > p.target->minRad)) {
    throw std::invalid_argument("repetitions: target max must be above target min");
  }
  if (!(std::isfinite(p.minDurationS) && p.minDurationS >= 0 && std::isfinite(p.minExcursionRad) &&
        p.minExcursionRad >= 0)) {
    throw std::invalid_argument(
        "repetitions: minimum duration and minimum excursion must be finite, >= 0");
  }
}

}  // namespace

RepetitionResult detectRepetitions(const PreparedSeries& s, const RepetitionParams& p) {
  validate(p);
  RepetitionResult out;
  const std::size_t n = s.size();
  if (n == 0) return out;

  // Primary angle: given, or the one with the largest range of motion.
  if (p.primaryAngle) {
    out.primaryAngle = *p.primaryAngle;
  } else {
    const IntervalMetrics all = intervalMetrics(s, 0, n);
    for (int a = 1; a < kNumClinicalAngles; ++a) {
      if (all.angle[a].romRad > all.angle[out.primaryAngle].romRad) out.primaryAngle = a;
    }
  }
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = s.angle(static_cast<Eigen::Index>(i), out.primaryAngle);

  const double lo = weightedPercentile(x, s.weight, 0.02);
  const double hi = weightedPercentile(x, s.weight, 0.98);
  if (!(hi - lo >= p.minExcursionRad && hi > lo)) return out;  // no excursion worth counting

  // Direction: rest is the end of the range where the angle spends more time.
  bool negative = p.direction == ExcursionDirection::Negative;
  if (p.direction == ExcursionDirection::Automatic) {
    const double median = weightedPercentile(x, s.weight, 0.5);
    negative = median > 0.5 * (lo + hi);
  }
  out.negativeDirection = negative;
  // Work on y, which rises during a repetition; rest near 0, top near 1 x range.
  const double range = hi - lo;
  std::vector<double> y(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = negative ? hi - x[i] : x[i] - lo;
  const double enter = p.enterFraction * range, exit = p.exitFraction * range;
  out.enterLevelRad = negative ? hi - enter : lo + enter;
  out.exitLevelRad = negative ? hi - exit : lo + exit;

  // Hysteresis: armed once at rest; an excursion runs from the enter crossing to the exit one.
  struct Excursion {
    std::size_t up, down;
  };
  std::vector<Excursion> excursions;
  bool armed = false, inside = false;
  std::size_t up = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!inside) {
      if (y[i] <= exit) armed = true;
      if (y[i] >= enter) {
        if (armed) {
          inside = true;
          up = i;
        } else if (i == 0 || y[i - 1] < enter) {
          ++out.truncated;  // the recording starts inside an excursion
        }
        armed = false;
      }
    } else if (y[i] <= exit) {
      excursions.push_back({up, i});
      inside = false;
      armed = true;
    }
  }
  if (inside) ++out.truncated;

  // Boundaries: the movement onset before the enter crossing (the last sample at rest by the
  // rate threshold, then down to the nearest local minimum of y), and the offset after the exit
  // crossing. Without a sample at rest, the lowest point between neighbouring excursions.
  const double still = s.params.movingThresholdRadPerS;
  auto rate = [&](std::size_t i) {
    return std::abs(s.rate(static_cast<Eigen::Index>(i), out.primaryAngle));
  };
  std::size_t previousEnd = 0;
  for (std::size_t e = 0; e < excursions.size(); ++e) {
    const std::size_t before = std::max(e == 0 ? 0 : excursions[e - 1].down, previousEnd);
    const std::size_t after = e + 1 < excursions.size() ? excursions[e + 1].up : n - 1;
    const std::size_t up = excursions[e].up, down = excursions[e].down;
    std::size_t start = up + 1;
    for (std::size_t i = up + 1; i-- > before;) {
      if (rate(i) < still) {
        start = i;
        break;
      }
    }
    if (start > up) {
      start = before;
      for (std::size_t i = before; i <= up; ++i)
        if (y[i] < y[start]) start = i;
    } else {
      while (start > before && y[start - 1] <= y[start]) --start;
    }
    std::size_t end = n;
    for (std::size_t i = down; i <= after; ++i) {
      if (rate(i) < still) {
        end = i;
        break;
      }
    }
    if (end == n) {
      end = down;
      for (std::size_t i = down; i <= after; ++i)
        if (y[i] < y[end]) end = i;
    } else {
      while (end < after && y[end + 1] <= y[end]) ++end;
    }
    if (s.t[end] - s.t[start] < p.minDurationS) continue;
    const IntervalMetrics metrics = intervalMetrics(s, start, end + 1);
    if (metrics.angle[out.primaryAngle].romRad < p.minExcursionRad) continue;
    previousEnd = end;

    Repetition r;
    r.startIndex = start;
    r.endIndex = end;
    r.peakIndex = start;
    for (std::size_t i = start; i <= end; ++i)
      if (y[i] > y[r.peakIndex]) r.peakIndex = i;
    r.startS = s.t[start];
    r.peakS = s.t[r.peakIndex];
    r.endS = s.t[end];
    r.metrics = metrics;
    r.excursionRad = r.metrics.angle[out.primaryAngle].romRad;
    out.repetitions.push_back(r);
  }

  // Partial repetitions: against the target range, else the median repetition.
  if (p.target) {
    out.referenceRad = p.target->maxRad - p.target->minRad;
  } else if (!out.repetitions.empty()) {
    std::vector<double> ex;
    for (const Repetition& r : out.repetitions) ex.push_back(r.excursionRad);
    std::nth_element(ex.begin(), ex.begin() + static_cast<long>(ex.size() / 2), ex.end());
    out.referenceRad = ex[ex.size() / 2];
  }
  for (Repetition& r : out.repetitions) {
    r.partial = r.excursionRad < p.partialFraction * out.referenceRad;
    (r.partial ? out.partialCount : out.fullCount) += 1;
  }
  return out;
}

}  // namespace armtrack
