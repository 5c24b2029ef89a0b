// The trunk limit cue against analytic flexion series whose crossings are known: noise about the
// limit does not flicker, a lean past it for 0.2 s does not fire, a sustained one does (and goes
// off again), absent or NaN flexion never fires, and the repetitions made with compensation are
// counted exactly, by span and by end time.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include "core/metrics/TrunkLimitCue.h"

using namespace armtrack;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kDt = 0.01;  // 100 Hz

TrunkLimitCueParams limit(double deg) {
  TrunkLimitCueParams p;
  p.limitDeg = deg;
  return p;
}

/// Feeds flexionDeg(t) from t0 to t1 at 100 Hz; counts the changes of cueShown() and returns
/// the first time it showed (or -1).
template <class F>
double feed(TrunkLimitCue& cue, double t0, double t1, F flexionDeg, int* changes = nullptr) {
  double first = -1;
  bool was = cue.cueShown();
  for (int i = 0; t0 + i * kDt <= t1 + 1e-9; ++i) {
    const double t = t0 + i * kDt;
    cue.add(t, flexionDeg(t) * kDeg);
    if (cue.cueShown() != was && changes) ++*changes;
    was = cue.cueShown();
    if (was && first < 0) first = t;
  }
  return first;
}

/// A lean from 0 to peakDeg and back, raised-cosine, over [start, start + duration].
double lean(double t, double start, double duration, double peakDeg) {
  if (t < start || t > start + duration) return 0;
  return peakDeg * 0.5 * (1 - std::cos(2 * std::numbers::pi * (t - start) / duration));
}

}  // namespace

TEST(TrunkLimitCue, NoiseAboutTheLimitDoesNotFlicker) {
  // Sustained 1 deg above the limit with +-1.5 deg of white noise: comes on once, never off.
  TrunkLimitCue cue(limit(15));
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1.5);
  int changes = 0;
  feed(
      cue, 0, 2, [](double) { return 0.0; }, &changes);
  EXPECT_EQ(changes, 0);
  const double on = feed(
      cue, 2.01, 30, [&](double) { return 16.0 + noise(rng); }, &changes);
  EXPECT_GT(on, 2.3);
  EXPECT_LT(on, 3.0);
  EXPECT_EQ(changes, 1);
  EXPECT_EQ(cue.cues(), 1u);
  // Then exactly at the limit with the same noise: it stays on (inside the margin).
  feed(
      cue, 30.01, 60, [&](double) { return 15.0 + noise(rng); }, &changes);
  EXPECT_EQ(changes, 1);
  EXPECT_TRUE(cue.cueShown());
  // And 1 deg below it (still within the 2 deg margin): no flicker either.
  feed(
      cue, 60.01, 90, [&](double) { return 14.0 + noise(rng); }, &changes);
  EXPECT_EQ(changes, 1);
  EXPECT_EQ(cue.cues(), 1u);
}

TEST(TrunkLimitCue, NoiseJustBelowTheLimitNeverFires) {
  TrunkLimitCue cue(limit(15));
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  int changes = 0;
  feed(
      cue, 0, 120, [&](double) { return 13.5 + noise(rng); }, &changes);
  EXPECT_EQ(changes, 0);
  EXPECT_EQ(cue.cues(), 0u);
}

TEST(TrunkLimitCue, ABriefLeanDoesNotFire) {
  // 25 deg for 0.2 s (a step): well past the limit, but too short.
  TrunkLimitCue cue(limit(15));
  feed(cue, 0, 1, [](double) { return 0.0; });
  const double on = feed(cue, 1.01, 4, [](double t) { return t >= 2.0 && t < 2.2 ? 25.0 : 0.0; });
  EXPECT_LT(on, 0);
  EXPECT_EQ(cue.cues(), 0u);
  EXPECT_GT(*cue.maxFlexionDeg(), 15.0);  // it was past the limit, and the record says so
}

TEST(TrunkLimitCue, ASustainedLeanFiresAndGoesOff) {
  // Step to 20 deg at t = 2 s, back to 5 deg at t = 6 s. The smoothed value (tau 0.1 s) passes
  // 15 deg at 2 + 0.1 ln 4 = 2.139 s; 0.3 s later the cue is on. Back at 5 deg it falls below
  // 13 deg at 6 + 0.1 ln(15/8) = 6.063 s; 0.5 s later it is off.
  TrunkLimitCue cue(limit(15));
  feed(cue, 0, 2, [](double) { return 0.0; });
  const double on = feed(cue, 2.01, 5.99, [](double) { return 20.0; });
  EXPECT_NEAR(on, 2.139 + 0.3, 0.02);
  EXPECT_TRUE(cue.cueShown());
  double off = -1;
  for (double t = 6.0; t < 8.0; t += kDt) {
    cue.add(t, 5.0 * kDeg);
    if (!cue.cueShown() && off < 0) off = t;
  }
  EXPECT_NEAR(off, 6.063 + 0.5, 0.02);
  EXPECT_EQ(cue.cues(), 1u);
  ASSERT_TRUE(cue.flexionDeg());
  EXPECT_NEAR(*cue.flexionDeg(), 5.0, 0.01);
}

TEST(TrunkLimitCue, LeaningBackCountsAsFlexionDoes) {
  TrunkLimitCue cue(limit(10));
  const double on = feed(cue, 0, 3, [](double t) { return t > 1 ? -14.0 : 0.0; });
  EXPECT_GT(on, 1.0);
  EXPECT_TRUE(cue.cueShown());
}

TEST(TrunkLimitCue, AbsentOrNaNFlexionNeverFires) {
  TrunkLimitCue cue(limit(10));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 2000; ++i) {
    const double t = i * kDt;
    switch (i % 4) {
      case 0:
        cue.add(t, std::nullopt);
        break;
      case 1:
        cue.add(t, nan);
        break;
      case 2:
        cue.add(t, inf);
        break;
      default:
        cue.add(t, 4.0);  // 229 deg: no trunk leans so far
    }
    EXPECT_FALSE(cue.cueShown());
  }
  EXPECT_FALSE(cue.maxFlexionDeg());
  EXPECT_FALSE(cue.flexionDeg());
  EXPECT_FALSE(cue.addRepetition(0, 20));
  EXPECT_EQ(cue.compensated(), 0u);
  EXPECT_EQ(cue.repetitions(), 1u);
}

TEST(TrunkLimitCue, FlexionThatStopsTurnsTheCueOff) {
  TrunkLimitCue cue(limit(10));
  feed(cue, 0, 2, [](double) { return 20.0; });
  ASSERT_TRUE(cue.cueShown());
  // The trunk sensor drops out: no flexion. Off once the gap passes 0.5 s, not before.
  for (double t = 2.01; t < 2.4; t += kDt) cue.add(t, std::nullopt);
  EXPECT_TRUE(cue.cueShown());
  for (double t = 2.4; t < 2.6; t += kDt) cue.add(t, std::nullopt);
  EXPECT_FALSE(cue.cueShown());
  EXPECT_FALSE(cue.flexionDeg());
}

TEST(TrunkLimitCue, TimesThatDoNotIncreaseAreIgnored) {
  TrunkLimitCue cue(limit(10));
  cue.add(1.0, 0.0);
  cue.add(1.0, 40 * kDeg);
  cue.add(0.5, 40 * kDeg);
  cue.add(std::numeric_limits<double>::quiet_NaN(), 40 * kDeg);
  EXPECT_NEAR(*cue.maxFlexionDeg(), 0.0, 1e-12);
}

TEST(TrunkLimitCue, CountsTheRepetitionsMadeWithCompensation) {
  // Ten repetitions of 4 s; in repetitions 2, 5, 6 and 9 (0-based) the trunk leans 20 deg
  // (peak) inside the repetition, in 3 it leans 12 deg (below the 15 deg limit), in the others
  // it stays upright; 1.5 deg of noise on all.
  TrunkLimitCue byEnd(limit(15));
  TrunkLimitCue bySpan(limit(15));
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.5);
  const auto peak = [](int rep) {
    return (rep == 2 || rep == 5 || rep == 6 || rep == 9) ? 20.0 : rep == 3 ? 12.0 : 0.0;
  };
  for (int rep = 0; rep < 10; ++rep) {
    const double start = rep * 4.0;
    for (int i = 0; i < 400; ++i) {
      const double t = start + i * kDt;
      const double f = lean(t, start + 1.0, 2.0, peak(rep)) + noise(rng);
      byEnd.add(t, f * kDeg);
      bySpan.add(t, f * kDeg);
    }
    byEnd.repetitionEnded(start + 3.99);
    EXPECT_EQ(bySpan.addRepetition(start + 0.5, start + 3.5), peak(rep) > 15);
  }
  EXPECT_EQ(byEnd.repetitions(), 10u);
  EXPECT_EQ(byEnd.compensated(), 4u);
  EXPECT_EQ(bySpan.compensated(), 4u);
  // A span outside the leans counts none; a bad span counts nothing.
  EXPECT_FALSE(bySpan.addRepetition(8.0, 8.5));
  EXPECT_FALSE(bySpan.addRepetition(5.0, 4.0));
  EXPECT_FALSE(bySpan.addRepetition(0.0, std::numeric_limits<double>::quiet_NaN()));
  EXPECT_EQ(bySpan.repetitions(), 11u);
  EXPECT_EQ(bySpan.compensated(), 4u);
}

TEST(TrunkLimitCue, AStartGivenBoundsTheNextRepetition) {
  TrunkLimitCue cue(limit(15));
  feed(cue, 0, 3, [](double t) { return lean(t, 0.5, 1.0, 25.0); });  // a lean before the set
  cue.startRepetitions(3.0);
  feed(cue, 3.01, 6, [](double) { return 0.0; });
  EXPECT_FALSE(cue.repetitionEnded(6.0));
  EXPECT_EQ(cue.compensated(), 0u);
}

TEST(TrunkLimitCue, TheTrunkMovedNoteHoldsASecond) {
  TrunkLimitCue cue(limit(15));
  cue.add(0.0, std::nullopt, false);
  EXPECT_FALSE(cue.trunkMovedShown());
  cue.add(1.0, std::nullopt, true);
  EXPECT_TRUE(cue.trunkMovedShown());
  cue.add(1.9, std::nullopt, false);
  EXPECT_TRUE(cue.trunkMovedShown());
  cue.add(2.1, std::nullopt, false);
  EXPECT_FALSE(cue.trunkMovedShown());
  EXPECT_FALSE(cue.cueShown());  // the flag alone never cues: it says nothing of the limit
}

TEST(TrunkLimitCue, RefusesLimitsThatMeanNothing) {
  for (double bad : {0.0, -5.0, 91.0, std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::infinity()})
    EXPECT_THROW(TrunkLimitCue{limit(bad)}, std::invalid_argument) << bad;
  TrunkLimitCueParams p = limit(10);
  p.onAfterS = -1;
  EXPECT_THROW(TrunkLimitCue{p}, std::invalid_argument);
  EXPECT_NO_THROW(TrunkLimitCue{limit(90)});
}

TEST(TrunkLimitCue, ResetForgetsEverything) {
  TrunkLimitCue cue(limit(10));
  feed(cue, 0, 2, [](double) { return 20.0; });
  cue.repetitionEnded(2.0);
  cue.reset();
  EXPECT_FALSE(cue.cueShown());
  EXPECT_EQ(cue.cues(), 0u);
  EXPECT_EQ(cue.repetitions(), 0u);
  EXPECT_FALSE(cue.maxFlexionDeg());
  EXPECT_EQ(cue.params().limitDeg, 10.0);
}
