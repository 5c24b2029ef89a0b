// One call for a session's clinical metrics (docs/metrics.md): range of motion, velocities and
// movement time of the five clinical angles for the session and each repetition, the
// repetitions, and the smoothness of the wrist path. Qt-free; SI units.
#pragma once

#include <optional>
#include <vector>

#include "core/kinematics/ArmModel.h"
#include "core/metrics/RangeOfMotion.h"
#include "core/metrics/Repetitions.h"
#include "core/metrics/Smoothness.h"

namespace armtrack {

/// PathSmoothnessParams with a 0.15 s half-width for the wrist path (see below).
inline PathSmoothnessParams clinicalPathSmoothness() {
  PathSmoothnessParams p;
  p.smoothing.halfWindowSeconds = 0.15;
  return p;
}

/// A session without repetitions has its smoothness taken over pieces of its path no longer
/// than this (s), and the median of theirs: SPARC and LDLJ are defined for movements, and a
/// spectrum of a whole hour would take hundreds of megabytes for a number with no meaning.
inline constexpr double kMaxSmoothnessPieceS = 600.0;

struct ClinicalMetricsParams {
  MotionParams motion;
  RepetitionParams repetitions;
  /// Wrist path differentiation: a 0.15 s half-width, wider than pathSmoothness()'s default,
  /// because the path comes from estimated angles whose residual noise the jerk (a third
  /// derivative) amplifies: with 0.5 deg of angle noise it moves LDLJ by about 0.7 and SPARC by
  /// under 0.02 (tests/core/metrics/test_repetitions.cpp).
  PathSmoothnessParams smoothness = clinicalPathSmoothness();
  /// Segment lengths for the wrist path; empty = no smoothness metrics.
  std::optional<ArmGeometry> geometry = ArmGeometry{};
};

struct RepetitionSmoothness {
  SmoothnessValue sparc, ldlj;
};

struct SessionMetrics {
  IntervalMetrics session;                                 ///< whole recording
  RepetitionResult repetitions;                            ///< with per-repetition metrics
  std::vector<RepetitionSmoothness> repetitionSmoothness;  ///< one per repetition
  /// Session smoothness: the median over the repetitions that have a value, or, with no
  /// repetition, the whole wrist path (status TooShort etc. when undefined).
  SmoothnessValue sparc, ldlj;
  double durationS = 0;               ///< last time minus first time (s), gaps included
  std::size_t samples = 0;            ///< rows used
  std::size_t rejectedNonFinite = 0;  ///< rows dropped
  std::size_t gaps = 0;               ///< number of gaps (segments - 1)
};

/// Everything above for one session. Throws std::invalid_argument as prepareSeries() and
/// detectRepetitions() do (mismatched sizes, no usable row, times not increasing, bad params).
SessionMetrics computeSessionMetrics(const AngleSeries& series,
                                     const ClinicalMetricsParams& params = {});

}  // namespace armtrack
