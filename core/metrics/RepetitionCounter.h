// Repetitions counted while a session runs: the hysteresis of detectRepetitions()
// (core/metrics/Repetitions.h) applied sample by sample to one clinical angle, so a live screen
// can show "7 of 10" without re-analysing the session. Plain C++, no Qt.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/metrics/Repetitions.h"

namespace armtrack {

/// A repetition as the counter saw it (times in s, angles in rad).
struct CountedRepetition {
  double enterS = 0, peakS = 0, exitS = 0;  ///< crossings of the levels, and the peak between
  double excursionRad = 0;                  ///< from the rest before it to its peak
  bool partial = false;
};

/// Counts as detectRepetitions() does on the same angle, with what is known so far:
/// - levels: the target's range when given (its enter/exit fractions of max - min), else the
///   robust range (2nd to 98th percentile, time-weighted) of the samples seen so far, so early
///   counts use the range the first movements reveal;
/// - direction: as given, or Automatic: rest is the end of the range where the angle has spent
///   more time so far (re-judged only between repetitions);
/// - a repetition counts when its crossings are at least minDurationS apart and its excursion
///   at least minExcursionRad; it is partial below partialFraction of the target's range, or of
///   the median excursion counted so far.
/// The angle is smoothed by a first-order low-pass (smoothingSeconds) first. Offline analysis
/// (detectRepetitions) remains the reference for reports; tests hold the two to the same counts.
class RepetitionCounter {
 public:
  /// params.primaryAngle says which clinical angle the caller feeds (0-4; default 0); the other
  /// parameters mean what they mean for detectRepetitions(). Throws std::invalid_argument for
  /// the same invalid values.
  explicit RepetitionCounter(const RepetitionParams& params = {}, double smoothingSeconds = 0.05);

  /// One sample of the primary angle: time (s, increasing) and angle (rad). A non-finite value
  /// or a time that does not increase is ignored and counted in ignored().
  void add(double t, double angleRad);
  /// Forgets everything (a new session).
  void reset();

  int primaryAngle() const { return m_primary; }
  std::size_t count() const { return m_reps.size(); }
  std::size_t fullCount() const { return count() - partialCount(); }
  std::size_t partialCount() const;
  /// True while the angle is past the enter level and not yet back below the exit level.
  bool inRepetition() const { return m_inside; }
  const std::vector<CountedRepetition>& repetitions() const { return m_reps; }
  std::uint64_t ignored() const { return m_ignored; }
  /// The levels in use (rad, signed angle); equal until a range is known.
  double enterLevelRad() const { return m_enterLevel; }
  double exitLevelRad() const { return m_exitLevel; }

 private:
  void updateLevels();
  double percentile(double q) const;
  void classify();

  RepetitionParams m_params;
  int m_primary = 0;
  double m_tau;
  // Time-weighted histogram of the smoothed angle, 0.25 deg bins over +-pi.
  static constexpr int kBins = 1440;
  std::array<double, kBins> m_hist{};
  double m_histTotal = 0;
  double m_lastT = 0, m_value = 0;
  bool m_started = false;
  double m_enterLevel = 0, m_exitLevel = 0;
  bool m_negative = false;
  bool m_levelsKnown = false;
  bool m_inside = false;
  double m_enterT = 0, m_peakT = 0;
  double m_restLo = 0, m_restHi = 0;  // raw angle range at rest since the last repetition
  double m_peakLo = 0, m_peakHi = 0;  // raw angle range during the current one
  double m_sinceLevels = 0;
  std::vector<CountedRepetition> m_reps;
  std::uint64_t m_ignored = 0;
};

}  // namespace armtrack
