// Repetition detection on one clinical angle: hysteresis on the excursion from the rest posture
// (docs/metrics.md). Works on a PreparedSeries (smoothed, SI units).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/metrics/RangeOfMotion.h"

namespace armtrack {

/// Which way the exercise moves the angle away from rest.
enum class ExcursionDirection {
  Automatic,  ///< rest is the end of the range where the angle spends more of the time
  Positive,   ///< rest low, repetitions rise (e.g. flexion from the arm hanging)
  Negative,   ///< rest high, repetitions fall
};

/// The protocol's target for the primary angle (rad).
struct TargetRange {
  double minRad = 0;
  double maxRad = 0;
};

/// The clinical angle a session's repetitions are counted on, live and in its analysis
/// (docs/metrics.md, "Repetitions"): the protocol's primary angle (clinicalAngleInfo() index),
/// or shoulder flexion without a protocol. One rule, so that the live counter, the review and the
/// report count the same session on the same angle.
inline constexpr int kDefaultRepetitionAngle = 0;  // shoulder flexion
inline int repetitionAngle(std::optional<int> protocolAngle) {
  return protocolAngle && *protocolAngle >= 0 && *protocolAngle < kNumClinicalAngles
             ? *protocolAngle
             : kDefaultRepetitionAngle;
}

struct RepetitionParams {
  /// Angle to count on (index in clinicalAngleInfo() order); empty = the angle with the largest
  /// range of motion over the session.
  std::optional<int> primaryAngle;
  /// The protocol's target range; empty = judge partial repetitions against the median
  /// repetition.
  std::optional<TargetRange> target;
  ExcursionDirection direction = ExcursionDirection::Automatic;
  /// Start and end: the movement onset before the excursion (the last sample whose rate is
  /// below MotionParams::movingThresholdRadPerS, then back to the nearest local minimum of the
  /// angle) and the matching offset after it; so a pause at rest is not part of a repetition.
  /// Hysteresis levels as fractions of the session's robust range of the primary angle (2nd to
  /// 98th percentile, in the excursion's direction): a repetition begins when the angle rises
  /// above `enterFraction` after having been below `exitFraction`, and ends when it falls back
  /// below `exitFraction`. Excursions that never reach enterFraction are not counted at all.
  double enterFraction = 0.35;
  double exitFraction = 0.15;
  /// A repetition whose range on the primary angle is below this fraction of the reference
  /// (target max - min, or the median repetition) is partial. Default 0.8.
  double partialFraction = 0.8;
  /// Excursions shorter than this (s), start to end, are ignored as glitches.
  double minDurationS = 0.3;
  /// Excursions smaller than this (rad) on the primary angle are not repetitions, and a session
  /// whose robust range is smaller has none: noise and fidgeting are not counted. 5 deg.
  double minExcursionRad = 5.0 * kDegToRad;
};

struct Repetition {
  std::size_t startIndex = 0, peakIndex = 0, endIndex = 0;  ///< samples in the PreparedSeries
  double startS = 0, peakS = 0, endS = 0;                   ///< times (s)
  double excursionRad = 0;  ///< range of motion of the primary angle in this repetition
  bool partial = false;
  IntervalMetrics metrics;  ///< all five angles over [startIndex, endIndex]
};

struct RepetitionResult {
  int primaryAngle = 0;            ///< the angle counted on
  bool negativeDirection = false;  ///< true when repetitions move the angle down from rest
  double referenceRad = 0;         ///< what partial repetitions are judged against
  double enterLevelRad = 0, exitLevelRad = 0;  ///< the hysteresis levels used (signed angle)
  std::vector<Repetition> repetitions;
  std::size_t fullCount = 0, partialCount = 0;
  /// Excursions cut by the start or end of the recording (not counted).
  std::size_t truncated = 0;
};

/// Finds repetitions on the primary angle. Throws std::invalid_argument for a primary angle
/// outside 0-4, fractions outside 0 < exit < enter < 1 or partialFraction outside (0, 1], or a
/// target whose max is not above its min. A series with no excursion (e.g. constant) gives no
/// repetitions.
RepetitionResult detectRepetitions(const PreparedSeries& series,
                                   const RepetitionParams& params = {});

}  // namespace armtrack
