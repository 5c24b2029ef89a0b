// Trunk compensation metrics against analytic series whose maxima are known, and hostile input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include "core/metrics/TrunkCompensation.h"

using namespace armtrack;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
const Eigen::Vector3d kHip{0.47, 0.0, -0.12};  // below and medial of a right shoulder (frame 0)

Eigen::Vector3d shoulderAt(const TrunkAngles& a) {
  return kHip - trunkRotation(a) * kHip;
}

/// Rows at 100 Hz with trunk angles, and every third row also a shoulder position (a 33 Hz
/// camera), from `angles(t)`; the shoulder follows the hip model.
template <class F>
std::vector<TrunkRow> rowsOf(F angles, double durationS) {
  std::vector<TrunkRow> rows;
  for (int i = 0; i <= static_cast<int>(durationS * 100); ++i) {
    TrunkRow r;
    r.t = i / 100.0;
    r.angle = angles(r.t);
    if (i % 3 == 0) r.shoulder = shoulderAt(*r.angle);
    rows.push_back(r);
  }
  return rows;
}

/// Upright and still for 1 s, then leaning forward and back (15 deg), bending to the left (8 deg)
/// and turning (0 to 5 deg) with a period of 4 s.
TrunkAngles sessionAngles(double t) {
  if (t < 1.0) return TrunkAngles::Zero();
  const double w = 2 * std::numbers::pi * 0.25;
  return {15 * kDeg * std::sin(w * (t - 1)), -8 * kDeg * std::sin(w * (t - 1)),
          5 * kDeg * 0.5 * (1 - std::cos(w * (t - 1)))};
}

/// Four reaches of 2 s each, starting every 3 s from t = 1, leaning forward by `peaks` (deg) in
/// a raised cosine, with half as much lateral bending and a third as much axial rotation.
const std::vector<double> kPeaks{5.0, 12.0, 18.0, 9.0};
TrunkAngles reachAngles(double t) {
  for (std::size_t k = 0; k < kPeaks.size(); ++k) {
    const double u = t - (1.0 + 3.0 * static_cast<double>(k));
    if (u >= 0 && u <= 2.0) {
      const double f = kPeaks[k] * kDeg * 0.5 * (1 - std::cos(std::numbers::pi * u));
      return {f, 0.5 * f, -f / 3.0};
    }
  }
  return TrunkAngles::Zero();
}
std::vector<TimeSpan> reachSpans() {
  std::vector<TimeSpan> s;
  for (std::size_t k = 0; k < kPeaks.size(); ++k) s.push_back({1.0 + 3.0 * k, 3.0 + 3.0 * k});
  return s;
}

/// The largest |s_W - s_W(start)| (cm) over [a, b] on a fine grid.
template <class F>
double trueDisplacementCm(F angles, double a, double b) {
  double m = 0;
  for (double t = a; t <= b; t += 1e-3) {
    m = std::max(m, 100 * (shoulderAt(angles(t)) - shoulderAt(angles(0.0))).norm());
  }
  return m;
}
}  // namespace

TEST(TrunkCompensation, SessionMaximaOfAnalyticSeries) {
  const auto rows = rowsOf(sessionAngles, 20.0);
  const TrunkCompensation c = computeTrunkCompensation(rows);
  ASSERT_TRUE(c.session.maxFlexionDeg && c.session.maxLateralDeg && c.session.maxRotationDeg);
  EXPECT_NEAR(*c.session.maxFlexionDeg, 15.0, 0.05);
  EXPECT_NEAR(*c.session.maxLateralDeg, 8.0, 0.05);  // a negative bend: its magnitude
  EXPECT_NEAR(*c.session.maxRotationDeg, 5.0, 0.05);
  ASSERT_TRUE(c.session.maxShoulderDisplacementCm);
  EXPECT_NEAR(*c.session.maxShoulderDisplacementCm, trueDisplacementCm(sessionAngles, 0, 20), 0.1);
  EXPECT_FALSE(c.session.compensated);  // no limit
  EXPECT_FALSE(c.repetitionsWithCompensation);
  EXPECT_EQ(c.inputRows, rows.size());
  EXPECT_EQ(c.refusedNonFinite + c.refusedImplausible + c.refusedOutOfOrder + c.leftOut, 0u);
}

TEST(TrunkCompensation, PerRepetitionMaximaAndCompensationCount) {
  const auto rows = rowsOf(reachAngles, 14.0);
  TrunkCompensationParams p;
  p.flexionLimitDeg = 10.0;
  const TrunkCompensation c = computeTrunkCompensation(rows, reachSpans(), p);
  ASSERT_EQ(c.repetitions.size(), kPeaks.size());
  for (std::size_t k = 0; k < kPeaks.size(); ++k) {
    const TrunkExtremes& r = c.repetitions[k];
    ASSERT_TRUE(r.maxFlexionDeg && r.maxLateralDeg && r.maxRotationDeg) << k;
    EXPECT_NEAR(*r.maxFlexionDeg, kPeaks[k], 0.05) << k;
    EXPECT_NEAR(*r.maxLateralDeg, kPeaks[k] / 2, 0.05) << k;
    EXPECT_NEAR(*r.maxRotationDeg, kPeaks[k] / 3, 0.05) << k;
    ASSERT_TRUE(r.maxShoulderDisplacementCm) << k;
    const TimeSpan s = reachSpans()[k];
    EXPECT_NEAR(*r.maxShoulderDisplacementCm, trueDisplacementCm(reachAngles, s.startS, s.endS),
                0.1)
        << k;
    ASSERT_TRUE(r.compensated) << k;
    EXPECT_EQ(*r.compensated, kPeaks[k] > 10.0) << k;
  }
  ASSERT_TRUE(c.repetitionsWithCompensation);
  EXPECT_EQ(*c.repetitionsWithCompensation, 2u);  // the 12 and 18 deg reaches
  EXPECT_NEAR(*c.session.maxFlexionDeg, 18.0, 0.05);

  // Without a limit nothing is counted.
  const TrunkCompensation off = computeTrunkCompensation(rows, reachSpans());
  EXPECT_FALSE(off.repetitionsWithCompensation);
  for (const auto& r : off.repetitions) EXPECT_FALSE(r.compensated);
}

TEST(TrunkCompensation, RepetitionSpansComeFromDetectedRepetitions) {
  RepetitionResult result;
  for (const TimeSpan& s : reachSpans()) {
    Repetition r;
    r.startS = s.startS;
    r.endS = s.endS;
    r.peakS = 0.5 * (s.startS + s.endS);
    result.repetitions.push_back(r);
  }
  const auto spans = repetitionSpans(result);
  ASSERT_EQ(spans.size(), kPeaks.size());
  for (std::size_t k = 0; k < spans.size(); ++k) {
    EXPECT_EQ(spans[k].startS, reachSpans()[k].startS);
    EXPECT_EQ(spans[k].endS, reachSpans()[k].endS);
  }
}

TEST(TrunkCompensation, EmptyInputMeasuresNothing) {
  TrunkCompensationParams p;
  p.flexionLimitDeg = 10.0;
  const TrunkCompensation c = computeTrunkCompensation({}, reachSpans(), p);
  EXPECT_FALSE(c.session.maxFlexionDeg || c.session.maxLateralDeg || c.session.maxRotationDeg ||
               c.session.maxShoulderDisplacementCm || c.session.compensated);
  ASSERT_EQ(c.repetitions.size(), kPeaks.size());
  for (const auto& r : c.repetitions) {
    EXPECT_FALSE(r.maxFlexionDeg || r.maxShoulderDisplacementCm || r.compensated);
  }
  EXPECT_FALSE(c.repetitionsWithCompensation);
  EXPECT_EQ(c.inputRows, 0u);
}

TEST(TrunkCompensation, NonFiniteAndImplausibleRowsAreRefusedAndCounted) {
  auto rows = rowsOf(reachAngles, 14.0);
  const TrunkCompensation clean = computeTrunkCompensation(rows, reachSpans());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto insertAfter = [&](double t, TrunkRow r) {
    const auto it =
        std::find_if(rows.begin(), rows.end(), [&](const TrunkRow& x) { return x.t > t; });
    rows.insert(it, r);
  };
  TrunkRow bad;
  bad.t = 2.0005;
  bad.angle = TrunkAngles(nan, 0, 0);
  insertAfter(2.0, bad);
  bad.t = nan;
  bad.angle = TrunkAngles(0.5, 0.5, 0.5);
  insertAfter(4.0, bad);
  bad.t = 4.5005;
  bad.angle = TrunkAngles::Zero();
  bad.shoulder = Eigen::Vector3d(inf, 0, 0);
  insertAfter(4.5, bad);
  bad.t = 7.0005;
  bad.angle = TrunkAngles(4.0, 0, 0);  // 229 deg: no trunk
  bad.shoulder.reset();
  insertAfter(7.0, bad);
  bad.t = 7.5005;
  bad.angle = TrunkAngles::Zero();
  bad.shoulder = Eigen::Vector3d(1e6, 0, 0);
  insertAfter(7.5, bad);
  bad.t = 3.0;  // back in time
  bad.angle = TrunkAngles(1.0, 1.0, 1.0);
  bad.shoulder.reset();
  insertAfter(8.0, bad);
  // Rows the estimator's status leaves out: a wild 40 deg that must not count.
  for (TrunkRow& r : rows) {
    if (r.t > 10.2 && r.t < 10.4) {
      r.angle = TrunkAngles(40 * kDeg, 40 * kDeg, 40 * kDeg);
      r.leaveOut = true;
    }
  }

  const TrunkCompensation c = computeTrunkCompensation(rows, reachSpans());
  EXPECT_EQ(c.refusedNonFinite, 3u);
  EXPECT_EQ(c.refusedImplausible, 2u);
  EXPECT_EQ(c.refusedOutOfOrder, 1u);
  EXPECT_EQ(c.leftOut, 19u);
  EXPECT_EQ(c.inputRows, rows.size());
  // What was kept gives the same numbers as the clean series.
  ASSERT_EQ(c.repetitions.size(), clean.repetitions.size());
  for (std::size_t k = 0; k < c.repetitions.size(); ++k) {
    EXPECT_NEAR(*c.repetitions[k].maxFlexionDeg, *clean.repetitions[k].maxFlexionDeg, 0.05) << k;
    EXPECT_NEAR(*c.repetitions[k].maxLateralDeg, *clean.repetitions[k].maxLateralDeg, 0.05) << k;
    EXPECT_NEAR(*c.repetitions[k].maxShoulderDisplacementCm,
                *clean.repetitions[k].maxShoulderDisplacementCm, 0.05)
        << k;
  }
  EXPECT_NEAR(*c.session.maxFlexionDeg, 18.0, 0.05);
}

TEST(TrunkCompensation, SingleSampleAndEmptyRepetitions) {
  const auto rows = rowsOf(sessionAngles, 20.0);
  std::vector<TimeSpan> spans{
      {5.0, 5.0},      // exactly one sample (t = 5.00)
      {5.001, 5.009},  // between two samples: nothing inside
      {6.0, 5.0},      // end before start
      {std::numeric_limits<double>::quiet_NaN(), 7.0},
      {25.0, 30.0},  // after the session
  };
  TrunkCompensationParams p;
  p.flexionLimitDeg = 1.0;
  const TrunkCompensation c = computeTrunkCompensation(rows, spans, p);
  ASSERT_EQ(c.repetitions.size(), spans.size());
  const TrunkAngles at5 = sessionAngles(5.0);
  ASSERT_TRUE(c.repetitions[0].maxFlexionDeg);
  EXPECT_NEAR(*c.repetitions[0].maxFlexionDeg, std::abs(at5(0)) / kDeg, 0.05);
  EXPECT_NEAR(*c.repetitions[0].maxLateralDeg, std::abs(at5(1)) / kDeg, 0.05);
  EXPECT_NEAR(*c.repetitions[0].maxRotationDeg, std::abs(at5(2)) / kDeg, 0.05);
  EXPECT_EQ(c.repetitions[0].compensated, std::optional<bool>(std::abs(at5(0)) / kDeg > 1.0));
  // No shoulder frame at t = 5.00? Rows 0, 3, 6... carry one: row 500 does not.
  EXPECT_FALSE(c.repetitions[0].maxShoulderDisplacementCm);
  for (std::size_t k = 1; k < spans.size(); ++k) {
    EXPECT_FALSE(c.repetitions[k].maxFlexionDeg) << k;
    EXPECT_FALSE(c.repetitions[k].maxShoulderDisplacementCm) << k;
    EXPECT_FALSE(c.repetitions[k].compensated) << k;
  }
  EXPECT_EQ(c.invalidSpans, 2u);
  ASSERT_TRUE(c.repetitionsWithCompensation);
  EXPECT_EQ(*c.repetitionsWithCompensation, std::abs(at5(0)) / kDeg > 1.0 ? 1u : 0u);

  // A session of one row: its own values, exactly.
  TrunkRow one;
  one.t = 3.0;
  one.angle = TrunkAngles(-7 * kDeg, 2 * kDeg, -3 * kDeg);
  const TrunkCompensation single = computeTrunkCompensation({one}, {{3.0, 3.0}});
  EXPECT_NEAR(*single.session.maxFlexionDeg, 7.0, 1e-9);
  EXPECT_NEAR(*single.repetitions[0].maxLateralDeg, 2.0, 1e-9);
  EXPECT_NEAR(*single.repetitions[0].maxRotationDeg, 3.0, 1e-9);
}

TEST(TrunkCompensation, NoisyShoulderWithWildFrames) {
  // A Kinect shoulder (1 cm noise per axis, 30 Hz) with one frame 30 cm off every 2 s: the
  // displacement stays within a centimetre of the truth, and a still trunk shows its noise
  // floor, 1 to 1.5 cm (docs/metrics.md), never the 30 cm frames.
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.01);
    for (bool still : {true, false}) {
      std::vector<TrunkRow> rows;
      for (int i = 0; i < 14 * 30; ++i) {
        TrunkRow r;
        r.t = i / 30.0;
        const TrunkAngles a = still ? TrunkAngles::Zero() : reachAngles(r.t);
        r.shoulder = shoulderAt(a) + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
        if (i % 60 == 17) r.shoulder->y() += 0.3;
        rows.push_back(r);
      }
      const TrunkCompensation c = computeTrunkCompensation(rows, reachSpans());
      EXPECT_FALSE(c.session.maxFlexionDeg);  // no angles: not measurable
      ASSERT_TRUE(c.session.maxShoulderDisplacementCm);
      if (still) {
        EXPECT_LT(*c.session.maxShoulderDisplacementCm, 2.0) << seed;
        continue;
      }
      for (std::size_t k = 0; k < kPeaks.size(); ++k) {
        const TimeSpan s = reachSpans()[k];
        EXPECT_NEAR(*c.repetitions[k].maxShoulderDisplacementCm,
                    trueDisplacementCm(reachAngles, s.startS, s.endS), 1.0)
            << "seed " << seed << ", repetition " << k;
      }
    }
  }
}

TEST(TrunkCompensation, ALimitMustBeAPositiveNumber) {
  for (double bad : {0.0, -5.0, std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::infinity()}) {
    TrunkCompensationParams p;
    p.flexionLimitDeg = bad;
    EXPECT_THROW(computeTrunkCompensation({}, {}, p), std::invalid_argument) << bad;
  }
}
