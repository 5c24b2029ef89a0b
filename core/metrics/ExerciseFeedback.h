// Live feedback on one exercise of a home programme, sample by sample: a repetition counted, the
// target reached, the range not reached, too fast, another joint moving instead (the elbow
// bending during a shoulder exercise), and whether an angle can be trusted at all. Plain C++, no
// Qt; the home window turns the events into words, colours and sounds.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/metrics/RepetitionCounter.h"

namespace armtrack {

/// What one exercise asks for, in SI units.
struct ExerciseSpec {
  int primaryAngle = 3;  ///< clinical angle index (clinicalAngleInfo() order)
  /// The range the movement should cover: from min (rest) to max for Positive, from max down to
  /// min for Negative. max > min.
  TargetRange target;
  ExcursionDirection direction = ExcursionDirection::Positive;  ///< Automatic is taken as Positive
  /// A repetition reaches the target when it comes within this of its far end (rad, 5 deg).
  double reachToleranceRad = 5.0 * kDegToRad;
  /// Faster than this at any moment of a repetition is too fast (rad/s, 150 deg/s: a 100 deg
  /// movement done in about 1.2 s).
  double maxSpeedRadPerS = 150.0 * kDegToRad;
  /// Angles that should stay where they are during a repetition; none given: the ones an
  /// exercise of this angle is usually cheated with (ExerciseFeedback::defaultStillAngles); an
  /// empty list watches none (e.g. when they cannot be trusted).
  std::optional<std::vector<int>> stillAngles;
  /// A still angle moving more than this within a repetition is compensation (rad, 20 deg).
  double compensationRad = 20.0 * kDegToRad;
  /// Low-pass time constant of the angles before anything is judged (s).
  double smoothingSeconds = 0.05;
};

enum class FeedbackKind {
  TargetReached,  ///< the repetition came within reach of the target's far end (live, at the top)
  RepetitionCounted,  ///< a repetition ended and was counted
  RangeNotReached,    ///< a counted repetition fell short of the target, or an attempt too small to
                      ///< count
  TooFast,            ///< the repetition went faster than maxSpeedRadPerS
  Compensation,       ///< another angle moved instead (angle says which)
};

struct FeedbackEvent {
  FeedbackKind kind = FeedbackKind::RepetitionCounted;
  double t = 0;        ///< s
  int repetition = 0;  ///< the count after this repetition (1, 2, ...); 0 for an uncounted attempt
  int angle = -1;      ///< the angle concerned (the primary one, or the one that compensated)
  double value = 0;    ///< the repetition's far point (rad), its peak speed (rad/s), or the
                       ///< compensating angle's excursion (rad), as the kind says
  bool partial = false;  ///< RepetitionCounted: judged partial by the counter
};

class ExerciseFeedback {
 public:
  /// Throws std::invalid_argument for an angle outside 0-4 (primary or still), a target whose max
  /// is not above its min, or a non-positive tolerance, speed or compensation limit.
  explicit ExerciseFeedback(const ExerciseSpec& spec);

  /// One estimate: time (s, increasing) and the five clinical angles (rad). Samples with a
  /// non-finite time or primary angle, or a time that does not increase, are ignored and counted.
  void add(double t, const std::array<double, 5>& clinicalRad);
  /// The events since the last call, in time order.
  std::vector<FeedbackEvent> takeEvents();
  /// Forgets everything (a new set keeps counting: call only for a new exercise).
  void reset();

  const ExerciseSpec& spec() const { return m_spec; }
  std::size_t repetitions() const { return m_counter.count(); }
  std::size_t partial() const { return m_counter.partialCount(); }
  std::size_t targetReached() const { return m_reached; }
  std::size_t rangeNotReached() const { return m_short; }
  std::size_t tooFast() const { return m_fast; }
  std::size_t compensations() const { return m_compensated; }  ///< repetitions with compensation
  /// The smoothed primary angle's extremes over the exercise (rad); equal before any sample.
  double rangeMinRad() const { return m_rangeMin; }
  double rangeMaxRad() const { return m_rangeMax; }
  bool inRepetition() const { return m_moving; }
  std::uint64_t ignored() const { return m_ignored; }

  /// The angles an exercise of this one is usually cheated with: the elbow for a shoulder
  /// exercise, shoulder flexion and abduction for an elbow or forearm one.
  static std::vector<int> defaultStillAngles(int primaryAngle);

 private:
  void startWindow();
  void closeWindow(double t, bool counted);

  ExerciseSpec m_spec;
  RepetitionCounter m_counter;
  double m_tau;
  bool m_started = false;
  double m_lastT = 0;
  std::array<double, 5> m_value{};  // smoothed angles (rad)
  double m_speed = 0;               // smoothed rate of the primary angle (rad/s)
  // The movement under way: from the primary angle leaving rest (past the exit level) to its
  // return.
  bool m_moving = false;
  bool m_reachedThisTime = false;
  double m_far = 0;        // the far point of the primary angle (rad)
  double m_peakSpeed = 0;  // rad/s
  std::array<double, 5> m_lo{}, m_hi{};
  double m_rangeMin = 0, m_rangeMax = 0;
  std::size_t m_reached = 0, m_short = 0, m_fast = 0, m_compensated = 0;
  std::vector<FeedbackEvent> m_events;
  std::uint64_t m_ignored = 0;
};

/// Whether a live angle can be shown as a measurement: not a shoulder angle (0-2) while the
/// estimator's heading rests on the start pose alone (no optical data: they drift about the
/// vertical), and not with a 2-sigma uncertainty above maxTwoSigmaRad (10 deg). stdRad: the
/// estimate's standard deviation of that joint.
bool angleTrustworthy(int angle, double stdRad, bool headingFromStartPoseOnly,
                      double maxTwoSigmaRad = 10.0 * kDegToRad);
/// Whether an angle needs optical data (a camera or a Kinect) to be trusted: the shoulder's three.
bool angleNeedsOptics(int angle);

}  // namespace armtrack
