#include "core/metrics/ExerciseFeedback.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace armtrack {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSpeedSmoothingSeconds = 0.1;  // the rate is smoothed again before judging it
constexpr double kMinAttemptRad = 5.0 * kDegToRad;

RepetitionParams counterParams(const ExerciseSpec& s) {
  RepetitionParams p;
  p.primaryAngle = s.primaryAngle;
  p.target = s.target;
  p.direction = s.direction == ExcursionDirection::Negative ? ExcursionDirection::Negative
                                                            : ExcursionDirection::Positive;
  return p;
}

const ExerciseSpec& checked(const ExerciseSpec& s) {
  const auto angleOk = [](int a) { return a >= 0 && a <= 4; };
  if (!angleOk(s.primaryAngle))
    throw std::invalid_argument("exercise feedback: the angle must be a clinical angle index 0-4");
  if (s.stillAngles)
    for (int a : *s.stillAngles)
      if (!angleOk(a) || a == s.primaryAngle)
        throw std::invalid_argument(
            "exercise feedback: a still angle must be another clinical angle index 0-4");
  if (!(std::isfinite(s.target.minRad) && std::isfinite(s.target.maxRad) &&
        s.target.maxRad > s.target.minRad))
    throw std::invalid_argument("exercise feedback: the target needs finite min < max");
  if (!(s.reachToleranceRad > 0) || !(s.maxSpeedRadPerS > 0) || !(s.compensationRad > 0) ||
      !std::isfinite(s.reachToleranceRad) || !std::isfinite(s.maxSpeedRadPerS) ||
      !std::isfinite(s.compensationRad))
    throw std::invalid_argument(
        "exercise feedback: the tolerance, speed and compensation limits must be > 0");
  return s;
}

}  // namespace

std::vector<int> ExerciseFeedback::defaultStillAngles(int primaryAngle) {
  if (primaryAngle <= 2) return {3};
  return {0, 1};
}

ExerciseFeedback::ExerciseFeedback(const ExerciseSpec& spec)
    : m_spec(checked(spec)),
      m_counter(counterParams(spec), spec.smoothingSeconds),
      m_tau(spec.smoothingSeconds) {
  if (!m_spec.stillAngles) m_spec.stillAngles = defaultStillAngles(m_spec.primaryAngle);
  reset();
}

void ExerciseFeedback::reset() {
  m_counter.reset();
  m_started = false;
  m_moving = false;
  m_speed = 0;
  m_reached = m_short = m_fast = m_compensated = 0;
  m_events.clear();
  m_ignored = 0;
}

std::vector<FeedbackEvent> ExerciseFeedback::takeEvents() {
  return std::exchange(m_events, {});
}

void ExerciseFeedback::add(double t, const std::array<double, 5>& clinicalRad) {
  const int primary = m_spec.primaryAngle;
  const double x = clinicalRad[static_cast<std::size_t>(primary)];
  if (!std::isfinite(t) || !std::isfinite(x) || (m_started && t <= m_lastT)) {
    ++m_ignored;
    return;
  }
  const std::size_t before = m_counter.count();
  m_counter.add(t, x);
  // The same low-pass as the counter's, on every angle (a non-finite other angle holds).
  if (!m_started) {
    for (std::size_t a = 0; a < 5; ++a)
      m_value[a] = std::isfinite(clinicalRad[a]) ? std::clamp(clinicalRad[a], -kPi, kPi) : 0.0;
    m_rangeMin = m_rangeMax = m_value[static_cast<std::size_t>(primary)];
    m_started = true;
  } else {
    const double dt = t - m_lastT;
    const double a = m_tau > 0 ? 1.0 - std::exp(-dt / m_tau) : 1.0;
    const double previous = m_value[static_cast<std::size_t>(primary)];
    for (std::size_t j = 0; j < 5; ++j)
      if (std::isfinite(clinicalRad[j]))
        m_value[j] += a * (std::clamp(clinicalRad[j], -kPi, kPi) - m_value[j]);
    const double rate = (m_value[static_cast<std::size_t>(primary)] - previous) / dt;
    m_speed += (1.0 - std::exp(-dt / kSpeedSmoothingSeconds)) * (rate - m_speed);
  }
  m_lastT = t;
  const double v = m_value[static_cast<std::size_t>(primary)];
  m_rangeMin = std::min(m_rangeMin, v);
  m_rangeMax = std::max(m_rangeMax, v);

  const bool negative = m_spec.direction == ExcursionDirection::Negative;
  const double sign = negative ? -1.0 : 1.0;
  const double y = sign * v;
  const double exit = sign * m_counter.exitLevelRad();
  const double reach = negative ? -(m_spec.target.minRad + m_spec.reachToleranceRad)
                                : m_spec.target.maxRad - m_spec.reachToleranceRad;
  if (!m_moving && y > exit) startWindow();
  if (m_moving) {
    m_far = std::max(m_far, y);
    m_peakSpeed = std::max(m_peakSpeed, std::abs(m_speed));
    for (std::size_t j = 0; j < 5; ++j) {
      m_lo[j] = std::min(m_lo[j], m_value[j]);
      m_hi[j] = std::max(m_hi[j], m_value[j]);
    }
    if (!m_reachedThisTime && m_far >= reach) {
      m_reachedThisTime = true;
      m_events.push_back({FeedbackKind::TargetReached, t, static_cast<int>(before) + 1, primary,
                          sign * m_far, false});
    }
  }
  if (m_counter.count() > before)
    closeWindow(t, true);
  else if (m_moving && y <= exit)
    closeWindow(t, false);
}

void ExerciseFeedback::startWindow() {
  m_moving = true;
  m_reachedThisTime = false;
  m_far = -std::numeric_limits<double>::infinity();
  m_peakSpeed = 0;
  m_lo = m_value;
  m_hi = m_value;
}

void ExerciseFeedback::closeWindow(double t, bool counted) {
  const int primary = m_spec.primaryAngle;
  const bool negative = m_spec.direction == ExcursionDirection::Negative;
  const double sign = negative ? -1.0 : 1.0;
  const double far = m_moving ? m_far : sign * m_value[static_cast<std::size_t>(primary)];
  m_moving = false;
  if (!counted) {
    // An attempt that left rest but never got far enough to count.
    if (far - sign * m_counter.exitLevelRad() >= kMinAttemptRad) {
      ++m_short;
      m_events.push_back({FeedbackKind::RangeNotReached, t, 0, primary, sign * far, false});
    }
    return;
  }
  const int n = static_cast<int>(m_counter.count());
  const bool partial = m_counter.repetitions().back().partial;
  m_events.push_back({FeedbackKind::RepetitionCounted, t, n, primary, sign * far, partial});
  if (m_reachedThisTime) {
    ++m_reached;
  } else {
    ++m_short;
    m_events.push_back({FeedbackKind::RangeNotReached, t, n, primary, sign * far, partial});
  }
  if (m_peakSpeed > m_spec.maxSpeedRadPerS) {
    ++m_fast;
    m_events.push_back({FeedbackKind::TooFast, t, n, primary, m_peakSpeed, false});
  }
  bool compensated = false;
  for (int a : *m_spec.stillAngles) {
    const double moved = m_hi[static_cast<std::size_t>(a)] - m_lo[static_cast<std::size_t>(a)];
    if (moved > m_spec.compensationRad) {
      compensated = true;
      m_events.push_back({FeedbackKind::Compensation, t, n, a, moved, false});
    }
  }
  if (compensated) ++m_compensated;
}

bool angleTrustworthy(int angle, double stdRad, bool headingFromStartPoseOnly,
                      double maxTwoSigmaRad) {
  if (angleNeedsOptics(angle) && headingFromStartPoseOnly) return false;
  return std::isfinite(stdRad) && 2.0 * stdRad <= maxTwoSigmaRad;
}

bool angleNeedsOptics(int angle) {
  return angle >= 0 && angle <= 2;
}

}  // namespace armtrack
