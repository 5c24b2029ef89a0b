// The live repetition counter against the offline detector (detectRepetitions) on the same
// simulated exercises: same counts, same partial ones, peaks at the same times; and against what
// a live stream throws at it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/metrics/RepetitionCounter.h"
#include "core/metrics/Repetitions.h"

namespace armtrack {
namespace {

constexpr double kDeg = kDegToRad;

/// One angle (deg) over time: rest, then raised-cosine excursions to each peak and back, with
/// holds and pauses of varying length; Gaussian noise; 100 Hz.
struct Exercise {
  std::vector<double> t, deg, truePeakS;
};

Exercise makeExercise(double restDeg, const std::vector<double>& peaksDeg, double noiseDeg,
                      unsigned seed = 3) {
  Exercise e;
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, noiseDeg);
  const double rises[] = {1.2, 1.6, 0.9, 1.4, 1.1};
  const double holds[] = {0.4, 0.1, 0.8, 0.3, 0.6};
  const double pauses[] = {1.0, 2.5, 0.6, 1.8, 1.2};
  struct Move {
    double t0, t1, from, to;
  };
  std::vector<Move> moves;
  double t = 2.0;
  for (std::size_t r = 0; r < peaksDeg.size(); ++r) {
    const double rise = rises[r % 5], hold = holds[r % 5], pause = pauses[r % 5];
    moves.push_back({t, t + rise, restDeg, peaksDeg[r]});
    e.truePeakS.push_back(t + rise + hold / 2);
    moves.push_back({t + rise + hold, t + 2 * rise + hold, peaksDeg[r], restDeg});
    t += 2 * rise + hold + pause;
  }
  const double end = t + 2.0;
  for (int k = 0; k <= static_cast<int>(end * 100); ++k) {
    const double tk = k / 100.0;
    double v = restDeg;
    for (const Move& m : moves) {
      if (tk >= m.t0 && tk <= m.t1) {
        const double s = (tk - m.t0) / (m.t1 - m.t0);
        v = m.from + (m.to - m.from) * (1 - std::cos(s * std::numbers::pi)) / 2;
      } else if (tk > m.t1) {
        v = m.to;
      }
    }
    e.t.push_back(tk);
    e.deg.push_back(v + noise(rng));
  }
  return e;
}

RepetitionResult offline(const Exercise& e, const RepetitionParams& p) {
  AngleSeries s;
  s.t = e.t;
  for (double d : e.deg) {
    ClinicalRow row{};
    row[static_cast<std::size_t>(p.primaryAngle.value_or(0))] = d * kDeg;
    s.angle.push_back(row);
  }
  return detectRepetitions(prepareSeries(s), p);
}

RepetitionCounter online(const Exercise& e, const RepetitionParams& p) {
  RepetitionCounter c(p);
  for (std::size_t i = 0; i < e.t.size(); ++i) c.add(e.t[i], e.deg[i] * kDeg);
  return c;
}

void expectSameAsOffline(const Exercise& e, const RepetitionParams& p) {
  const RepetitionResult ref = offline(e, p);
  const RepetitionCounter c = online(e, p);
  ASSERT_EQ(c.count(), ref.repetitions.size());
  EXPECT_EQ(c.fullCount(), ref.fullCount);
  EXPECT_EQ(c.partialCount(), ref.partialCount);
  for (std::size_t i = 0; i < c.count(); ++i) {
    EXPECT_EQ(c.repetitions()[i].partial, ref.repetitions[i].partial) << "repetition " << i;
    EXPECT_NEAR(c.repetitions()[i].peakS, ref.repetitions[i].peakS, 0.5) << "repetition " << i;
    EXPECT_NEAR(c.repetitions()[i].excursionRad, ref.repetitions[i].excursionRad, 3 * kDeg);
  }
}

const std::vector<double> kPeaks{100, 95, 100, 45, 100, 98, 100, 100};  // the fourth is partial

TEST(RepetitionCounter, CountsAsTheOfflineDetectorWithoutATarget) {
  const Exercise e = makeExercise(10, kPeaks, 0.5);
  RepetitionParams p;
  p.primaryAngle = 0;
  const RepetitionResult ref = offline(e, p);
  ASSERT_EQ(ref.repetitions.size(), 8u);
  EXPECT_EQ(ref.partialCount, 1u);
  expectSameAsOffline(e, p);
}

TEST(RepetitionCounter, CountsAsTheOfflineDetectorWithATarget) {
  const Exercise e = makeExercise(10, kPeaks, 0.5, 5);
  RepetitionParams p;
  p.primaryAngle = 0;
  p.target = TargetRange{10 * kDeg, 100 * kDeg};
  const RepetitionCounter c = online(e, p);
  EXPECT_EQ(c.count(), 8u);
  EXPECT_EQ(c.partialCount(), 1u);
  EXPECT_TRUE(c.repetitions()[3].partial);
  expectSameAsOffline(e, p);
}

TEST(RepetitionCounter, ExcursionsDownwardsFromARaisedRest) {
  // Rest high (e.g. an elbow held flexed, extended repeatedly): Automatic finds the direction.
  const Exercise e = makeExercise(120, {20, 25, 20, 22, 20}, 0.5, 9);
  RepetitionParams p;
  p.primaryAngle = 3;
  const RepetitionCounter c = online(e, p);
  EXPECT_EQ(c.count(), 5u);
  EXPECT_LT(c.enterLevelRad(), c.exitLevelRad());  // falling through enter below exit
  expectSameAsOffline(e, p);
  for (std::size_t i = 0; i < c.count(); ++i)
    EXPECT_NEAR(c.repetitions()[i].peakS, e.truePeakS[i], 0.5);
}

TEST(RepetitionCounter, StillnessNoiseAndFidgetingAreNotRepetitions) {
  RepetitionParams p;
  p.primaryAngle = 1;
  EXPECT_EQ(online(makeExercise(30, {}, 0.0), p).count(), 0u);
  EXPECT_EQ(online(makeExercise(30, {}, 1.5), p).count(), 0u);
  EXPECT_EQ(online(makeExercise(30, {33, 32, 34, 33}, 0.5), p).count(), 0u);  // 3 deg wiggles
}

TEST(RepetitionCounter, HostileSamplesAreIgnoredAndCounted) {
  const Exercise e = makeExercise(10, {90, 90, 90}, 0.3);
  RepetitionParams p;
  p.primaryAngle = 0;
  RepetitionCounter c(p);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < e.t.size(); ++i) {
    c.add(e.t[i], e.deg[i] * kDeg);
    if (i == 100) c.add(e.t[i] + 0.001, nan);
    if (i == 200) c.add(e.t[i], e.deg[i] * kDeg);  // same time again
    if (i == 300) c.add(std::numeric_limits<double>::infinity(), 0.0);
    if (i == 400) c.add(e.t[i] + 0.005, 1e6);  // one absurd spike, clamped and smoothed
  }
  EXPECT_EQ(c.ignored(), 3u);
  EXPECT_EQ(c.count(), 3u);
  c.reset();
  EXPECT_EQ(c.count(), 0u);
  EXPECT_EQ(c.ignored(), 0u);
}

TEST(RepetitionCounter, RefusesWhatTheOfflineDetectorRefuses) {
  RepetitionParams p;
  p.primaryAngle = 7;
  EXPECT_THROW(RepetitionCounter{p}, std::invalid_argument);
  p.primaryAngle = 0;
  p.enterFraction = 0.1;
  p.exitFraction = 0.2;
  EXPECT_THROW(RepetitionCounter{p}, std::invalid_argument);
  p = {};
  p.target = TargetRange{1.0, 0.5};
  EXPECT_THROW(RepetitionCounter{p}, std::invalid_argument);
  EXPECT_THROW(RepetitionCounter({}, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace armtrack
