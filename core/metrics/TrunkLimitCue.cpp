#include "core/metrics/TrunkLimitCue.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace armtrack {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

bool nonNegative(double v) {
  return std::isfinite(v) && v >= 0;
}

}  // namespace

TrunkLimitCue::TrunkLimitCue(const TrunkLimitCueParams& params) : m_p(params) {
  if (!(std::isfinite(m_p.limitDeg) && m_p.limitDeg > 0 && m_p.limitDeg <= 90))
    throw std::invalid_argument("the trunk limit must be above 0 and at most 90 deg");
  if (!(nonNegative(m_p.onAfterS) && nonNegative(m_p.offAfterS) && nonNegative(m_p.offMarginDeg) &&
        nonNegative(m_p.smoothingS) && nonNegative(m_p.maxGapS) && nonNegative(m_p.movedHoldS)))
    throw std::invalid_argument("the trunk cue's times and margin must be finite and >= 0");
}

void TrunkLimitCue::reset() {
  *this = TrunkLimitCue(m_p);
}

void TrunkLimitCue::add(double t, std::optional<double> flexionRad, bool trunkMoved) {
  if (!std::isfinite(t) || (m_started && t <= m_lastT)) return;
  if (!m_started && !m_repStart) m_repStart = t;
  m_started = true;
  m_lastT = t;
  if (trunkMoved) m_movedAt = t;

  // A flexion past half a turn is no trunk's: taken as no flexion.
  const bool measured =
      flexionRad && std::isfinite(*flexionRad) && std::abs(*flexionRad) <= std::numbers::pi;
  if (!measured) {
    if (m_value && t - m_lastFlexionT > m_p.maxGapS) {
      m_value.reset();
      m_shown = false;
      m_aboveSince = m_belowSince = -1;
    }
    return;
  }
  const double deg = *flexionRad * kRadToDeg;
  if (m_value && t - m_lastFlexionT <= m_p.maxGapS) {
    const double alpha =
        m_p.smoothingS > 0 ? 1.0 - std::exp(-(t - m_lastFlexionT) / m_p.smoothingS) : 1.0;
    *m_value += alpha * (deg - *m_value);
  } else {
    m_value = deg;
    m_shown = false;
    m_aboveSince = m_belowSince = -1;
  }
  m_lastFlexionT = t;

  const double size = std::abs(*m_value);
  m_history.push_back({t, size});
  while (!m_history.empty() && m_history.front().t < t - kHistoryS) m_history.pop_front();
  if (!m_maxDeg || size > *m_maxDeg) m_maxDeg = size;

  if (size > m_p.limitDeg) {
    m_belowSince = -1;
    if (m_aboveSince < 0) m_aboveSince = t;
    if (!m_shown && t - m_aboveSince >= m_p.onAfterS) {
      m_shown = true;
      ++m_cues;
    }
  } else if (size < m_p.limitDeg - m_p.offMarginDeg) {
    m_aboveSince = -1;
    if (m_belowSince < 0) m_belowSince = t;
    if (m_shown && t - m_belowSince >= m_p.offAfterS) m_shown = false;
  } else {  // between the two: the cue stays as it is
    m_aboveSince = m_belowSince = -1;
  }
}

bool TrunkLimitCue::trunkMovedShown() const {
  return m_movedAt >= 0 && m_lastT - m_movedAt <= m_p.movedHoldS;
}

std::optional<double> TrunkLimitCue::flexionDeg() const {
  if (!m_value || m_lastT - m_lastFlexionT > m_p.maxGapS) return std::nullopt;
  return m_value;
}

bool TrunkLimitCue::addRepetition(double startS, double endS) {
  if (!std::isfinite(endS) || std::isnan(startS) || endS < startS) return false;
  ++m_repetitions;
  bool over = false;
  for (const Sample& s : m_history)
    if (s.t >= startS && s.t <= endS && s.absDeg > m_p.limitDeg) {
      over = true;
      break;
    }
  if (over) ++m_compensated;
  return over;
}

bool TrunkLimitCue::repetitionEnded(double endS) {
  const double start = m_repStart.value_or(-std::numeric_limits<double>::infinity());
  const bool over = addRepetition(start, endS);
  if (std::isfinite(endS) && endS >= start) m_repStart = endS;
  return over;
}

void TrunkLimitCue::startRepetitions(double t) {
  if (std::isfinite(t)) m_repStart = t;
}

}  // namespace armtrack
