#include "core/metrics/RepetitionCounter.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace armtrack {

namespace {
constexpr double kPi = std::numbers::pi;
}

RepetitionCounter::RepetitionCounter(const RepetitionParams& params, double smoothingSeconds)
    : m_params(params), m_tau(smoothingSeconds) {
  // The same checks as detectRepetitions().
  detectRepetitions(PreparedSeries{}, params);
  m_primary = params.primaryAngle.value_or(0);
  if (!(smoothingSeconds >= 0.0) || !std::isfinite(smoothingSeconds))
    throw std::invalid_argument("repetition counter: smoothing must be a finite time >= 0 s");
  reset();
}

void RepetitionCounter::reset() {
  m_hist.fill(0.0);
  m_histTotal = 0;
  m_started = false;
  m_levelsKnown = false;
  m_inside = false;
  m_negative = m_params.direction == ExcursionDirection::Negative;
  m_reps.clear();
  m_ignored = 0;
  m_sinceLevels = 0;
  if (m_params.target) {
    const double lo = m_params.target->minRad, hi = m_params.target->maxRad;
    const double range = hi - lo;
    // With a target and no direction given, repetitions rise towards the target's max.
    m_enterLevel =
        m_negative ? hi - m_params.enterFraction * range : lo + m_params.enterFraction * range;
    m_exitLevel =
        m_negative ? hi - m_params.exitFraction * range : lo + m_params.exitFraction * range;
    m_levelsKnown = range >= m_params.minExcursionRad;
  }
}

double RepetitionCounter::percentile(double q) const {
  const double want = q * m_histTotal;
  double sum = 0;
  for (int b = 0; b < kBins; ++b) {
    sum += m_hist[static_cast<std::size_t>(b)];
    if (sum >= want) return -kPi + (b + 0.5) * (2 * kPi / kBins);
  }
  return kPi;
}

void RepetitionCounter::updateLevels() {
  if (m_params.target || m_histTotal <= 0) return;
  const double lo = percentile(0.02), hi = percentile(0.98);
  if (!(hi - lo >= m_params.minExcursionRad)) return;
  if (!m_inside && m_params.direction == ExcursionDirection::Automatic)
    m_negative = percentile(0.5) > 0.5 * (lo + hi);
  const double range = hi - lo;
  m_enterLevel =
      m_negative ? hi - m_params.enterFraction * range : lo + m_params.enterFraction * range;
  m_exitLevel =
      m_negative ? hi - m_params.exitFraction * range : lo + m_params.exitFraction * range;
  m_levelsKnown = true;
}

void RepetitionCounter::add(double t, double angleRad) {
  if (!std::isfinite(t) || !std::isfinite(angleRad) || (m_started && t <= m_lastT)) {
    ++m_ignored;
    return;
  }
  const double x = std::clamp(angleRad, -kPi, kPi);
  double dt = 0;
  if (!m_started) {
    m_value = x;
    m_started = true;
    m_restLo = m_restHi = x;
  } else {
    dt = t - m_lastT;
    const double a = m_tau > 0 ? 1.0 - std::exp(-dt / m_tau) : 1.0;
    m_value += a * (x - m_value);
  }
  m_lastT = t;
  // Weigh each sample by the time it stands for (at most 0.25 s: a gap is not a posture).
  const int bin = std::clamp(static_cast<int>((m_value + kPi) / (2 * kPi) * kBins), 0, kBins - 1);
  const double w = m_histTotal == 0 ? 1e-3 : std::min(dt, 0.25);
  m_hist[static_cast<std::size_t>(bin)] += w;
  m_histTotal += w;
  m_sinceLevels += dt;
  if (m_sinceLevels >= 0.05 || !m_levelsKnown) {
    updateLevels();
    m_sinceLevels = 0;
  }
  if (!m_levelsKnown) return;

  // y rises during a repetition, as in detectRepetitions().
  const double y = m_negative ? -m_value : m_value;
  const double enter = m_negative ? -m_enterLevel : m_enterLevel;
  const double exit = m_negative ? -m_exitLevel : m_exitLevel;
  if (!m_inside) {
    m_restLo = std::min(m_restLo, m_value);
    m_restHi = std::max(m_restHi, m_value);
    // Armed once the angle has been back at rest (at or below the exit level) since the last
    // excursion. Judged on the range seen at rest, so rest that came before the levels were
    // known (the first seconds of a session without a target) arms the first repetition.
    const bool armed = m_negative ? m_restHi >= m_exitLevel : m_restLo <= m_exitLevel;
    if (y >= enter) {
      if (armed) {
        m_inside = true;
        m_enterT = m_peakT = t;
        m_peakLo = m_peakHi = m_value;
      } else {
        m_restLo = m_restHi = m_value;  // began inside an excursion: not counted
      }
    }
    return;
  }
  if ((m_negative && m_value < m_peakLo) || (!m_negative && m_value > m_peakHi)) m_peakT = t;
  m_peakLo = std::min(m_peakLo, m_value);
  m_peakHi = std::max(m_peakHi, m_value);
  if (y > exit) return;
  m_inside = false;
  const double excursion = m_negative ? m_restHi - m_peakLo : m_peakHi - m_restLo;
  if (t - m_enterT >= m_params.minDurationS && excursion >= m_params.minExcursionRad) {
    CountedRepetition r;
    r.enterS = m_enterT;
    r.peakS = m_peakT;
    r.exitS = t;
    r.excursionRad = excursion;
    m_reps.push_back(r);
    classify();
  }
  m_restLo = m_restHi = m_value;
}

void RepetitionCounter::classify() {
  double reference = 0;
  if (m_params.target) {
    reference = m_params.target->maxRad - m_params.target->minRad;
  } else {
    std::vector<double> ex;
    for (const CountedRepetition& r : m_reps) ex.push_back(r.excursionRad);
    std::nth_element(ex.begin(), ex.begin() + static_cast<long>(ex.size() / 2), ex.end());
    reference = ex[ex.size() / 2];
  }
  for (CountedRepetition& r : m_reps)
    r.partial = r.excursionRad < m_params.partialFraction * reference;
}

std::size_t RepetitionCounter::partialCount() const {
  return static_cast<std::size_t>(std::count_if(
      m_reps.begin(), m_reps.end(), [](const CountedRepetition& r) { return r.partial; }));
}

}  // namespace armtrack
