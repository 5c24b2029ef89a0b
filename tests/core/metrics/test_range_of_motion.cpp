// Range of motion, angular velocity and movement time against analytic truth, and what the
// metrics do with hostile input (docs/metrics.md).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "core/kinematics/ClinicalAngles.h"
#include "core/metrics/RangeOfMotion.h"

namespace armtrack {
namespace {

constexpr double kPi = std::numbers::pi;

/// Every angle a[k] * sin(2 pi f t) + offset[k], sampled at `rate` Hz for `seconds`, with a
/// uniform jitter of +-jitter s on the time stamps.
AngleSeries sinusoid(double rate, double seconds, double f, const ClinicalRow& amp,
                     const ClinicalRow& offset, double jitter = 0, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  AngleSeries s;
  const int n = static_cast<int>(seconds * rate) + 1;
  for (int i = 0; i < n; ++i) {
    const double t = i / rate + (i > 0 && i + 1 < n ? u(rng) : 0.0);
    ClinicalRow row;
    for (int a = 0; a < kNumClinicalAngles; ++a)
      row[a] = offset[a] + amp[a] * std::sin(2 * kPi * f * t);
    s.t.push_back(t);
    s.angle.push_back(row);
  }
  return s;
}

const ClinicalRow kAmp{1.0, 0.5, 0.3, 0.8, 0.2};      // rad
const ClinicalRow kOffset{0.5, 0.2, 0.0, 1.0, -0.1};  // rad

// theta = A sin(w t): ROM 2A, peak rate A w, mean |rate| over whole periods 2 A w / pi, and
// |rate| >= c for the fraction 1 - (2/pi) asin(c / (A w)) of the time.
void expectAnalytic(const IntervalMetrics& m, double f, double seconds, double threshold,
                    double tolRel) {
  const double w = 2 * kPi * f;
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    SCOPED_TRACE(a);
    const AngleMetrics& g = m.angle[a];
    const double A = kAmp[a];
    EXPECT_NEAR(g.minRad, kOffset[a] - A, 5e-4 * A);
    EXPECT_NEAR(g.maxRad, kOffset[a] + A, 5e-4 * A);
    EXPECT_NEAR(g.romRad, 2 * A, 1e-3 * A);
    EXPECT_NEAR(g.peakVelocityRadPerS, A * w, tolRel * A * w);
    EXPECT_NEAR(g.meanVelocityRadPerS, 2 * A * w / kPi, tolRel * A * w);
    const double moving =
        threshold < A * w ? seconds * (1 - 2 / kPi * std::asin(threshold / (A * w))) : 0.0;
    EXPECT_NEAR(g.movementTimeS, moving, 0.01 * seconds);
  }
}

TEST(RangeOfMotion, SinusoidMatchesAnalyticValues) {
  const double f = 0.5, seconds = 10.0;  // five whole periods
  const PreparedSeries p = prepareSeries(sinusoid(100, seconds, f, kAmp, kOffset));
  const IntervalMetrics m = intervalMetrics(p, 0, p.size());
  EXPECT_NEAR(m.coveredTimeS, seconds, 1e-9);
  expectAnalytic(m, f, seconds, p.params.movingThresholdRadPerS, 0.004);
  const AngleMetricsDeg d = inDegrees(m.angle[0]);
  EXPECT_NEAR(d.romDeg, 2 * kAmp[0] * 180 / kPi, 0.02);
  std::printf(
      "sinusoid 0.5 Hz, A = 1 rad: ROM %.4f rad (true %.4f), peak %.4f rad/s (true %.4f),"
      " mean %.4f rad/s (true %.4f)\n",
      m.angle[0].romRad, 2.0, m.angle[0].peakVelocityRadPerS, 2 * kPi * f,
      m.angle[0].meanVelocityRadPerS, 4 * f);
}

TEST(RangeOfMotion, NonUniformTimeStampsGiveTheSameValues) {
  const double f = 0.5, seconds = 10.0;
  const PreparedSeries p = prepareSeries(sinusoid(100, seconds, f, kAmp, kOffset, 0.004, 7));
  expectAnalytic(intervalMetrics(p, 0, p.size()), f, seconds, p.params.movingThresholdRadPerS,
                 0.015);
}

TEST(RangeOfMotion, DenseSamplingIsThinnedWithoutLosingAccuracy) {
  // 1 kHz: 301 samples per window, thinned to every 4th (maxSamplesPerFit = 100).
  const double f = 0.5, seconds = 10.0;
  const PreparedSeries p = prepareSeries(sinusoid(1000, seconds, f, kAmp, kOffset, 0.0002, 9));
  expectAnalytic(intervalMetrics(p, 0, p.size()), f, seconds, p.params.movingThresholdRadPerS,
                 0.004);
  MotionParams unthinned;
  unthinned.smoothing.maxSamplesPerFit = 0;
  const PreparedSeries q =
      prepareSeries(sinusoid(1000, seconds, f, kAmp, kOffset, 0.0002, 9), unthinned);
  EXPECT_LT((p.rate - q.rate).cwiseAbs().maxCoeff(), 1e-3);
  MotionParams tooFew;
  tooFew.smoothing.maxSamplesPerFit = 3;
  EXPECT_THROW(prepareSeries(sinusoid(100, 1, f, kAmp, kOffset), tooFew), std::invalid_argument);
}

TEST(RangeOfMotion, HigherThresholdShortensMovementTime) {
  MotionParams params;
  params.movingThresholdRadPerS = 1.5;  // below A w for angle 0 (pi), above it for angle 2
  const PreparedSeries p = prepareSeries(sinusoid(200, 10.0, 0.5, kAmp, kOffset), params);
  expectAnalytic(intervalMetrics(p, 0, p.size()), 0.5, 10.0, 1.5, 0.012);
}

TEST(RangeOfMotion, NoiseDoesNotInflateTheRange) {
  // 0.5 deg white noise at 100 Hz: the smoothed extremes stay within 1 deg of the true range.
  AngleSeries s = sinusoid(100, 20.0, 0.25, kAmp, kOffset);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.5 * kDegToRad);
  for (ClinicalRow& row : s.angle)
    for (double& a : row) a += noise(rng);
  const PreparedSeries p = prepareSeries(s);
  const IntervalMetrics m = intervalMetrics(p, 0, p.size());
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    const double errDeg = (m.angle[a].romRad - 2 * kAmp[a]) * kRadToDeg;
    EXPECT_LT(std::abs(errDeg), 1.0) << a;
    std::printf("noisy sinusoid angle %d: ROM error %.3f deg\n", a, errDeg);
  }
}

TEST(RangeOfMotion, GapIsNeitherMovingNorBridged) {
  AngleSeries s = sinusoid(100, 10.0, 0.5, kAmp, kOffset);
  AngleSeries holed;
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    if (s.t[i] > 4.0 && s.t[i] < 5.0) continue;  // one second missing
    holed.t.push_back(s.t[i]);
    holed.angle.push_back(s.angle[i]);
  }
  const PreparedSeries p = prepareSeries(holed);
  EXPECT_EQ(p.segments.size(), 2u);
  const IntervalMetrics m = intervalMetrics(p, 0, p.size());
  EXPECT_NEAR(m.coveredTimeS, 9.0, 1e-6);  // samples at 4.00 and 5.00 s are kept
  // One full period missing: the analytic values over the remaining 9 s still hold.
  EXPECT_NEAR(m.angle[0].peakVelocityRadPerS, kPi, 0.012 * kPi);
  EXPECT_NEAR(m.angle[0].meanVelocityRadPerS, 2.0, 0.03);
}

TEST(RangeOfMotion, IntervalMetricsCoverOnlyTheInterval) {
  const PreparedSeries p = prepareSeries(sinusoid(100, 10.0, 0.5, kAmp, kOffset));
  // Samples 0..50 cover t in [0, 0.5] s: the first quarter period, angle rises from offset to
  // offset + A.
  const IntervalMetrics m = intervalMetrics(p, 0, 51);
  EXPECT_NEAR(m.coveredTimeS, 0.5, 1e-9);
  EXPECT_NEAR(m.angle[0].minRad, kOffset[0], 2e-3);
  EXPECT_NEAR(m.angle[0].maxRad, kOffset[0] + kAmp[0], 1e-3);
  EXPECT_THROW(intervalMetrics(p, 5, 5), std::out_of_range);
  EXPECT_THROW(intervalMetrics(p, 0, p.size() + 1), std::out_of_range);
}

TEST(RangeOfMotion, JointVectorsMapToClinicalRadians) {
  JointVector th;
  th << 0.3, 0.2, 0.1, -0.4, 0.5;
  const AngleSeries s = angleSeriesFromJoints({0.0}, {th});
  const ClinicalAngles c = toClinical(th);
  EXPECT_NEAR(s.angle[0][0], c.shoulderFlexion * kDegToRad, 1e-12);
  EXPECT_NEAR(s.angle[0][3], c.elbowFlexion * kDegToRad, 1e-12);
  EXPECT_NEAR(s.angle[0][3], 0.4, 1e-12);  // elbow flexion = -th4
  EXPECT_TRUE(jointsFromClinical(s.angle[0]).isApprox(th, 1e-12));
}

// ---- Hostile input ----------------------------------------------------------------------------

TEST(RangeOfMotionHostile, EmptySeriesIsAClearError) {
  try {
    prepareSeries({});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no usable samples"), std::string::npos) << e.what();
  }
}

TEST(RangeOfMotionHostile, MismatchedColumnsAreAnError) {
  AngleSeries s;
  s.t = {0.0, 0.1};
  s.angle.resize(1);
  EXPECT_THROW(prepareSeries(s), std::invalid_argument);
}

TEST(RangeOfMotionHostile, OneSampleGivesItsAngleAndNoMotion) {
  AngleSeries s;
  s.t = {3.0};
  s.angle = {{0.1, 0.2, 0.3, 0.4, 0.5}};
  const PreparedSeries p = prepareSeries(s);
  const IntervalMetrics m = intervalMetrics(p, 0, 1);
  EXPECT_EQ(m.coveredTimeS, 0.0);
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    EXPECT_EQ(m.angle[a].minRad, s.angle[0][a]);
    EXPECT_EQ(m.angle[a].maxRad, s.angle[0][a]);
    EXPECT_EQ(m.angle[a].romRad, 0.0);
    EXPECT_EQ(m.angle[a].peakVelocityRadPerS, 0.0);
    EXPECT_EQ(m.angle[a].meanVelocityRadPerS, 0.0);
    EXPECT_EQ(m.angle[a].movementTimeS, 0.0);
  }
}

TEST(RangeOfMotionHostile, NonFiniteRowsAreDroppedAndCounted) {
  AngleSeries s = sinusoid(100, 10.0, 0.5, kAmp, kOffset);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  s.angle[100][2] = nan;
  s.angle[200][0] = std::numeric_limits<double>::infinity();
  s.t[300] = nan;
  const PreparedSeries p = prepareSeries(s);
  EXPECT_EQ(p.rejectedNonFinite, 3u);
  EXPECT_EQ(p.size(), s.t.size() - 3);
  EXPECT_TRUE(p.angle.allFinite());
  EXPECT_TRUE(p.rate.allFinite());
  const IntervalMetrics m = intervalMetrics(p, 0, p.size());
  EXPECT_NEAR(m.angle[0].romRad, 2 * kAmp[0], 1e-3);

  AngleSeries allNan;
  allNan.t = {0.0, 0.01};
  allNan.angle = {{nan, 0, 0, 0, 0}, {0, nan, 0, 0, 0}};
  EXPECT_THROW(prepareSeries(allNan), std::invalid_argument);
}

TEST(RangeOfMotionHostile, ConstantSignalHasNoMotion) {
  AngleSeries s;
  for (int i = 0; i < 500; ++i) {
    s.t.push_back(i * 0.01);
    s.angle.push_back({0.7, -0.2, 0.1, 1.2, 0.0});
  }
  const PreparedSeries p = prepareSeries(s);
  const IntervalMetrics m = intervalMetrics(p, 0, p.size());
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    EXPECT_NEAR(m.angle[a].romRad, 0.0, 1e-12);
    EXPECT_NEAR(m.angle[a].peakVelocityRadPerS, 0.0, 1e-9);
    EXPECT_EQ(m.angle[a].movementTimeS, 0.0);
    EXPECT_TRUE(std::isfinite(m.angle[a].meanVelocityRadPerS));
  }
}

TEST(RangeOfMotionHostile, TimeGoingBackOrRepeatingIsAnErrorNamingTheRow) {
  AngleSeries s = sinusoid(100, 1.0, 0.5, kAmp, kOffset);
  AngleSeries back = s;
  back.t[40] = back.t[38];
  try {
    prepareSeries(back);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("row 40"), std::string::npos) << e.what();
  }
  AngleSeries repeat = s;
  repeat.t[10] = repeat.t[9];
  EXPECT_THROW(prepareSeries(repeat), std::invalid_argument);
}

TEST(RangeOfMotionHostile, BadParametersAreRejected) {
  const AngleSeries s = sinusoid(100, 1.0, 0.5, kAmp, kOffset);
  MotionParams p;
  p.smoothing.halfWindowSeconds = 0;
  EXPECT_THROW(prepareSeries(s, p), std::invalid_argument);
  p = {};
  p.smoothing.maxGapSeconds = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(prepareSeries(s, p), std::invalid_argument);
  p = {};
  p.movingThresholdRadPerS = -1;
  EXPECT_THROW(prepareSeries(s, p), std::invalid_argument);
}

TEST(RangeOfMotionHostile, AbsurdButFiniteValuesStayFinite) {
  AngleSeries s;
  for (int i = 0; i < 100; ++i) {
    s.t.push_back(1e6 + i * 0.01);  // a clock far from zero
    const double big = (i % 2 ? 1e6 : -1e6);
    s.angle.push_back({big, 0, 0, 0, 0});
  }
  const PreparedSeries p = prepareSeries(s);
  const IntervalMetrics m = intervalMetrics(p, 0, p.size());
  EXPECT_TRUE(std::isfinite(m.angle[0].romRad));
  EXPECT_TRUE(std::isfinite(m.angle[0].peakVelocityRadPerS));
  EXPECT_NEAR(m.coveredTimeS, 0.99, 1e-6);
}

}  // namespace
}  // namespace armtrack
