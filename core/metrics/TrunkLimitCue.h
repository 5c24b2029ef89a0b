// The trunk limit cue (docs/trunk.md, "The trunk limit"): while a session runs, whether to tell
// the patient "Keep your back against the chair", and how many repetitions were made leaning past
// the limit a protocol or home exercise sets. Fed each live estimate; plain C++, no Qt. The live
// screen and the home window's exercise screen show what it decides.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>

namespace armtrack {

struct TrunkLimitCueParams {
  /// The limit: |trunk flexion| above it (deg) is compensation, leaning forward or back, as
  /// computeTrunkCompensation() counts it. Positive and finite (the constructor checks).
  double limitDeg = 15.0;
  /// The cue comes on once the flexion has stayed above the limit this long (s): a brief lean,
  /// e.g. to reach a little further once, is not cued.
  double onAfterS = 0.3;
  /// The cue goes off once the flexion has stayed below limit - offMarginDeg this long (s), so
  /// noise about the limit does not make it flicker.
  double offMarginDeg = 2.0;
  double offAfterS = 0.5;
  /// Low-pass time constant of the flexion before anything is judged (s); a gap in the flexion
  /// over maxGapS starts the filter again.
  double smoothingS = 0.1;
  /// No flexion for longer than this (s; an absent or non-finite value) turns the cue off: it
  /// never shows on data it no longer has.
  double maxGapS = 0.5;
  /// The note that the trunk moved unmeasured (an estimate's trunkMoved) stays this long (s)
  /// after the last such estimate.
  double movedHoldS = 1.0;
};

class TrunkLimitCue {
 public:
  /// Throws std::invalid_argument for a limit outside (0, 90] deg or a non-finite, negative
  /// time or margin.
  explicit TrunkLimitCue(const TrunkLimitCueParams& params = {});

  /// One estimate: time (s, increasing; a time that does not increase is ignored), the trunk's
  /// flexion (rad, positive forward; empty or non-finite when the estimate has none: no trunk
  /// IMU) and whether the trunk moved with nothing to measure it (EstimateRow::trunkMoved).
  void add(double t, std::optional<double> flexionRad, bool trunkMoved = false);

  /// Whether the cue is to be shown now.
  bool cueShown() const { return m_shown; }
  /// How many times the cue came on.
  std::size_t cues() const { return m_cues; }
  /// Whether to show that the trunk moved unmeasured (the shoulder angles include the lean).
  bool trunkMovedShown() const;

  /// A repetition spanned [startS, endS] (s, the estimates' clock): counted as made with
  /// compensation when the smoothed |flexion| went above the limit at a sample inside the span.
  /// Spans are judged on the estimates of the last kHistoryS seconds; give them once the
  /// estimates up to endS have been added. Returns whether it was compensated; a span with a
  /// non-finite end or end < start counts nothing and returns false.
  bool addRepetition(double startS, double endS);
  /// A repetition ended at endS; it began when the previous one ended (or at the first estimate
  /// after reset()/startRepetitions()): for counters that tell only the end.
  bool repetitionEnded(double endS);
  /// Repetitions told since reset() begin at t (e.g. a set starts): the next repetitionEnded()
  /// spans from here.
  void startRepetitions(double t);

  std::size_t repetitions() const { return m_repetitions; }
  std::size_t compensated() const { return m_compensated; }
  /// The largest smoothed |flexion| so far (deg); empty before any flexion.
  std::optional<double> maxFlexionDeg() const { return m_maxDeg; }
  /// The smoothed flexion now (deg, signed); empty without a recent flexion.
  std::optional<double> flexionDeg() const;
  const TrunkLimitCueParams& params() const { return m_p; }

  /// Forgets everything (a new session).
  void reset();

  static constexpr double kHistoryS = 120.0;

 private:
  struct Sample {
    double t;
    double absDeg;  // smoothed |flexion|
  };

  TrunkLimitCueParams m_p;
  bool m_started = false;
  double m_lastT = 0;
  std::optional<double> m_value;  // smoothed flexion (deg)
  double m_lastFlexionT = 0;
  double m_aboveSince = -1, m_belowSince = -1;
  bool m_shown = false;
  std::size_t m_cues = 0;
  double m_movedAt = -1;
  std::deque<Sample> m_history;
  std::optional<double> m_maxDeg;
  std::optional<double> m_repStart;
  std::size_t m_repetitions = 0, m_compensated = 0;
};

}  // namespace armtrack
