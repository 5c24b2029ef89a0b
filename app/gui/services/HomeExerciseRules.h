// The home window's rules for one exercise, without widgets: when a shoulder angle stops being
// trusted (its heading has rested on the start pose alone for a while) and what each set adds to
// the exercise's tally. ExerciseScreen shows what these decide;
// tests/app/gui/services/test_home_exercise_rules.cpp checks them on known rows.
#pragma once

#include "app/gui/services/HomeRecords.h"
#include "core/metrics/ExerciseFeedback.h"
#include "core/session/Session.h"

namespace armtrack::gui {

/// Whether an exercise's angle can be shown and counted. An angle that needs optical data (a
/// shoulder angle) is distrusted once the heading has rested on the start pose alone for longer
/// than blindLimitS; any optical fix trusts it again.
class HeadingTrust {
 public:
  static constexpr double kDefaultBlindLimitS = 3.0;

  explicit HeadingTrust(int angle, double blindLimitS = kDefaultBlindLimitS);

  /// Feeds one estimate row (rows in time order).
  void add(const session::EstimateRow& row);
  /// The heading has rested on the start pose alone for longer than the limit at time t (s).
  /// Always false for an angle that does not need optical data.
  bool blind(double t) const;
  /// Whether row's value of the angle may be shown: not blind and its uncertainty small
  /// (angleTrustworthy()).
  bool shown(const session::EstimateRow& row) const;

 private:
  int m_angle;
  double m_limit;
  double m_blindSince = -1;  // session time the heading began resting on the start pose
};

/// A new exercise's result before any set: its name, angle, plan and target.
HomeExerciseResult plannedResult(const HomeExercise& exercise, bool measured);

/// Adds one finished set's counts to result; the range reached widens only when the angle was
/// measured and at least one repetition counted. setsDone goes up by one.
void addSet(HomeExerciseResult& result, const ExerciseFeedback& set, bool measured);

}  // namespace armtrack::gui
