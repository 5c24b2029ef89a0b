// The 6D orientation filter: BROAD real-data accuracy against VQF's published figures, and
// synthetic checks of convergence, bias estimation, gyroscope integration and input rejection.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/orientation/OrientationFilter.h"

namespace armtrack {
namespace {

constexpr double kToRad = std::numbers::pi / 180.0;
constexpr double kG = 9.81;

// ---------------------------------------------------------------------------------------------
// BROAD

// A numeric CSV with one header line; "nan" cells read as NaN.
std::vector<std::vector<double>> readCsv(const std::string& path, std::size_t columns) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::vector<std::vector<double>> rows;
  std::size_t pos = text.find('\n');
  if (pos == std::string::npos) throw std::runtime_error(path + ": no header");
  ++pos;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::vector<double> row;
    const char* p = text.data() + pos;
    const char* const e = text.data() + end;
    while (p < e && row.size() < columns) {
      double v = 0.0;
      const auto r = std::from_chars(p, e, v);
      if (r.ec != std::errc()) throw std::runtime_error(path + ": bad number");
      row.push_back(v);
      p = r.ptr;
      if (p < e && *p == ',') ++p;
    }
    if (row.size() == columns) rows.push_back(std::move(row));
    pos = end + 1;
  }
  return rows;
}

// Inclination RMSE (deg) of the filter with default parameters over the trial's movement samples.
// A trial file (tests/data/broad/README.md, unpacked by the build) has one row per sample:
// t, gyr xyz, acc xyz, the reference quaternion (w, x, y, z) and the movement flag.
double broadInclinationRmse(const std::string& trial) {
  const auto rows = readCsv(ARMTRACK_BROAD_DIR "/" + trial + ".csv", 12);
  EXPECT_GT(rows.size(), 1000u);
  OrientationFilter filter;
  double sumSq = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    const double dt = i == 0 ? rows[1][0] - rows[0][0] : r[0] - rows[i - 1][0];
    filter.update({r[1], r[2], r[3]}, {r[4], r[5], r[6]}, dt);
    if (r[11] != 1.0 || !std::isfinite(r[7] + r[8] + r[9] + r[10])) continue;
    const double err = inclinationError(filter.orientation(), {r[7], r[8], r[9], r[10]});
    sumSq += err * err;
    ++count;
  }
  EXPECT_GT(count, 1000u);
  EXPECT_EQ(filter.state().rejected, 0u);
  return std::sqrt(sumSq / static_cast<double>(count)) / kToRad;
}

struct BroadCase {
  const char* trial;
  double vqfDeg;  // VQF (6D, default parameters), published
};

class Broad : public ::testing::TestWithParam<BroadCase> {};

TEST_P(Broad, InclinationWithinTwentyPercentOfVqf) {
  const BroadCase& c = GetParam();
  const double rmse = broadInclinationRmse(c.trial);
  const double limit = 1.2 * c.vqfDeg;
  std::printf("BROAD %s: inclination RMSE %.3f deg (VQF %.2f, limit %.3f)\n", c.trial, rmse,
              c.vqfDeg, limit);
  EXPECT_LE(rmse, limit);
}

INSTANTIATE_TEST_SUITE_P(Trials, Broad,
                         ::testing::Values(BroadCase{"02_undisturbed_slow_rotation_B", 0.43},
                                           BroadCase{"07_undisturbed_fast_rotation_B", 1.02},
                                           BroadCase{"16_undisturbed_fast_translation_B", 0.54}),
                         [](const auto& info) { return std::string(info.param.trial, 2); });

// ---------------------------------------------------------------------------------------------
// Synthetic data

// Integrates a body-frame rate over dt exactly (constant rate).
Eigen::Quaterniond rotateBody(const Eigen::Quaterniond& q, const Eigen::Vector3d& w, double dt) {
  const double n = w.norm();
  if (n == 0.0) return q;
  return (q * Eigen::Quaterniond(Eigen::AngleAxisd(n * dt, w / n))).normalized();
}

Eigen::Vector3d gravityInSensor(const Eigen::Quaterniond& q) {
  return q.conjugate() * Eigen::Vector3d(0.0, 0.0, kG);
}

TEST(OrientationFilter, StaticTiltConvergesQuickly) {
  const Eigen::Quaterniond truth(
      Eigen::AngleAxisd(35.0 * kToRad, Eigen::Vector3d(1, 2, 0.5).normalized()));
  std::mt19937 rng(3);
  std::normal_distribution<double> gyrNoise(0.0, 0.005), accNoise(0.0, 0.05);
  OrientationFilter f;
  const double dt = 0.01;
  for (int k = 0; k < 500; ++k) {
    const Eigen::Vector3d gyr(gyrNoise(rng), gyrNoise(rng), gyrNoise(rng));
    const Eigen::Vector3d acc =
        gravityInSensor(truth) + Eigen::Vector3d(accNoise(rng), accNoise(rng), accNoise(rng));
    ASSERT_TRUE(f.update(gyr, acc, dt));
    if (k == 100) {
      EXPECT_LT(inclinationError(f.orientation(), truth), 1.0 * kToRad);
    }  // 1 s
  }
  EXPECT_LT(inclinationError(f.orientation(), truth), 0.2 * kToRad);
  EXPECT_TRUE(f.restDetected());
}

// 10 s rest, 30 s of motion, 10 s rest, 30 s of motion, 5 s rest with a gyroscope bias of
// 0.01 rad/s (0.57 deg/s) on every axis. Returns the worst inclination error (deg) from 10 s on,
// i.e. once the first rest phase is over.
double biasedRestAndMotionRun(OrientationFilter& f, const Eigen::Vector3d& bias) {
  const double dt = 0.01;
  std::mt19937 rng(5);
  std::normal_distribution<double> gyrNoise(0.0, 0.003), accNoise(0.0, 0.03);
  Eigen::Quaterniond truth(Eigen::AngleAxisd(20.0 * kToRad, Eigen::Vector3d::UnitY()));
  double worstDeg = 0.0;
  const auto moving = [](double t) { return (t >= 10 && t < 40) || (t >= 50 && t < 80); };
  for (int k = 0; k < 8500; ++k) {
    const double t = k * dt;
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    if (moving(t)) {
      w = Eigen::Vector3d(0.8 * std::sin(1.3 * t), 0.6 * std::sin(0.7 * t + 1.0),
                          1.0 * std::cos(0.9 * t));
    }
    truth = rotateBody(truth, w, dt);
    const Eigen::Vector3d gyr =
        w + bias + Eigen::Vector3d(gyrNoise(rng), gyrNoise(rng), gyrNoise(rng));
    const Eigen::Vector3d acc =
        gravityInSensor(truth) + Eigen::Vector3d(accNoise(rng), accNoise(rng), accNoise(rng));
    EXPECT_TRUE(f.update(gyr, acc, dt));
    if (t >= 10.0) worstDeg = std::max(worstDeg, inclinationError(f.orientation(), truth) / kToRad);
    if (k == 999 && f.params().restBiasEstEnabled) {
      EXPECT_TRUE(f.restDetected());
      EXPECT_LT((f.bias() - bias).norm(), 0.05 * kToRad) << f.bias().transpose();
    }
  }
  return worstDeg;
}

TEST(OrientationFilter, ConstantBiasIsEstimatedAndInclinationStaysAccurate) {
  const Eigen::Vector3d bias = Eigen::Vector3d::Constant(0.01);
  OrientationFilter f;
  const double worst = biasedRestAndMotionRun(f, bias);
  OrientationParams off;
  off.restBiasEstEnabled = false;
  off.motionBiasEstEnabled = false;
  OrientationFilter g(off);
  const double worstOff = biasedRestAndMotionRun(g, bias);
  std::printf(
      "bias estimate (deg/s): %.4f %.4f %.4f (true %.4f), sigma %.4f; worst inclination error "
      "after 10 s: %.3f deg (%.3f without bias estimation)\n",
      f.bias().x() / kToRad, f.bias().y() / kToRad, f.bias().z() / kToRad, bias.x() / kToRad,
      f.biasSigma() / kToRad, worst, worstOff);
  EXPECT_TRUE(f.restDetected());
  EXPECT_LT((f.bias() - bias).norm(), 0.05 * kToRad);
  EXPECT_LT(worst, 0.25);
  EXPECT_LT(worst, 0.25 * worstOff);
}

// Continuous motion, no rest: the bias is learnt from the inclination correction alone while the
// sensor turns through many attitudes. Returns the inclination RMSE (deg) after the first 10 s.
double motionOnlyRun(bool motionBias, Eigen::Vector3d* biasError) {
  OrientationParams p;
  p.restBiasEstEnabled = false;
  p.motionBiasEstEnabled = motionBias;
  OrientationFilter f(p);
  const Eigen::Vector3d bias(0.01, -0.008, 0.005);  // rad/s
  const double dt = 0.01;
  Eigen::Quaterniond truth = Eigen::Quaterniond::Identity();
  double sumSq = 0.0;
  int count = 0;
  for (int k = 0; k < 9000; ++k) {
    const double t = k * dt;
    const Eigen::Vector3d w(0.8 * std::sin(1.3 * t), 0.6 * std::sin(0.7 * t + 1.0),
                            1.0 * std::cos(0.9 * t));
    truth = rotateBody(truth, w, dt);
    EXPECT_TRUE(f.update(w + bias, gravityInSensor(truth), dt));
    if (t >= 10.0) {
      const double e = inclinationError(f.orientation(), truth) / kToRad;
      sumSq += e * e;
      ++count;
    }
  }
  *biasError = f.bias() - bias;
  return std::sqrt(sumSq / count);
}

TEST(OrientationFilter, MotionBiasEstimationLearnsBiasWithoutRest) {
  Eigen::Vector3d errOn, errOff;
  const double rmseOn = motionOnlyRun(true, &errOn);
  const double rmseOff = motionOnlyRun(false, &errOff);
  std::printf(
      "motion-only, 90 s: bias error %.3f deg/s (%.3f without motion estimation), "
      "inclination RMSE %.3f deg (%.3f)\n",
      errOn.norm() / kToRad, errOff.norm() / kToRad, rmseOn, rmseOff);
  EXPECT_LT(errOn.norm(), 0.25 * kToRad);  // from 0.79 deg/s
  EXPECT_LT(rmseOn, 0.5 * rmseOff);
}

TEST(OrientationFilter, PureRotationAboutVerticalIntegratesGyroscopeExactly) {
  OrientationFilter f;
  const double rate = 0.7;  // rad/s
  const double dt = 1.0 / 286.0;
  const int n = 2000;
  for (int k = 0; k < n; ++k) ASSERT_TRUE(f.update({0.0, 0.0, rate}, {0.0, 0.0, kG}, dt));
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(rate * n * dt, Eigen::Vector3d::UnitZ()));
  EXPECT_LT(f.orientation().angularDistance(expected), 1e-9);
  EXPECT_LT(f.bias().norm(), 1e-12);
}

TEST(OrientationFilter, FollowsAVaryingSampleInterval) {
  // Rotating sensor, noise-free, sampled with +-30 % jitter, then at half and double the rate:
  // every sample's own dt is used, so the inclination stays accurate.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(0.7, 1.3);
  OrientationFilter f;
  Eigen::Quaterniond truth(Eigen::AngleAxisd(30.0 * kToRad, Eigen::Vector3d::UnitX()));
  double t = 0.0, worst = 0.0;
  while (t < 60.0) {
    double dt = 0.005 * jitter(rng);
    if (t >= 20.0 && t < 40.0) dt = t < 30.0 ? 0.01 : 0.0025;
    t += dt;
    // The rate is held over the interval (zero-order hold), as the filter assumes.
    const Eigen::Vector3d w(0.8 * std::sin(1.3 * t), 0.6 * std::sin(0.7 * t + 1.0),
                            1.0 * std::cos(0.9 * t));
    truth = rotateBody(truth, w, dt);
    ASSERT_TRUE(f.update(w, gravityInSensor(truth), dt));
    if (t > 2.0) worst = std::max(worst, inclinationError(f.orientation(), truth));
  }
  EXPECT_LT(worst, 0.05 * kToRad);
}

TEST(OrientationFilter, NonFiniteSamplesAndBadDtAreRejectedWithoutTouchingTheState) {
  OrientationFilter f;
  for (int k = 0; k < 300; ++k) f.update({0.01, -0.02, 0.03}, {0.5, 0.2, 9.7}, 0.005);
  const OrientationState before = f.state();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(f.update({nan, 0.0, 0.0}, {0.0, 0.0, kG}, 0.005));
  EXPECT_FALSE(
      f.update({0.0, 0.0, 0.0}, {0.0, std::numeric_limits<double>::infinity(), kG}, 0.005));
  EXPECT_FALSE(f.update({0.0, 0.0, 0.0}, {0.0, 0.0, kG}, nan));
  EXPECT_FALSE(f.update({0.0, 0.0, 0.0}, {0.0, 0.0, kG}, 0.0));
  EXPECT_FALSE(f.update({0.0, 0.0, 0.0}, {0.0, 0.0, kG}, -0.005));
  const OrientationState& after = f.state();
  EXPECT_EQ(after.rejected, before.rejected + 5);
  EXPECT_EQ(after.accepted, before.accepted);
  EXPECT_EQ(after.gyrQuat.coeffs(), before.gyrQuat.coeffs());
  EXPECT_EQ(after.accQuat.coeffs(), before.accQuat.coeffs());
  EXPECT_EQ(after.bias, before.bias);
  EXPECT_EQ(after.biasP, before.biasP);
  EXPECT_EQ(after.accLp.y, before.accLp.y);
  EXPECT_EQ(after.accLp.s0, before.accLp.s0);
  EXPECT_EQ(after.restTime, before.restTime);
}

// ---------------------------------------------------------------------------------------------
// Hostile input: absurd but finite readings, saturation and gaps in time

// A sensor turned about changing axes with a small body acceleration, gyroscope bias and noise;
// the truth is integrated exactly from the analytic rate.
struct TurningImu {
  Eigen::Quaterniond truth{Eigen::AngleAxisd(25.0 * kToRad, Eigen::Vector3d::UnitX())};
  Eigen::Vector3d bias{0.004, -0.003, 0.002};  // rad/s
  std::mt19937 rng{13};
  std::normal_distribution<double> gyrNoise{0.0, 0.004}, accNoise{0.0, 0.04};

  static Eigen::Vector3d rate(double t) {
    return {0.9 * std::sin(1.1 * t), 0.7 * std::sin(0.6 * t + 1.0), 0.8 * std::cos(0.8 * t)};
  }
  // Advances the truth to t + dt and returns the reading at its end (gyr, acc).
  std::pair<Eigen::Vector3d, Eigen::Vector3d> step(double t, double dt) {
    const Eigen::Vector3d w = rate(t + dt);
    truth = rotateBody(truth, w, dt);
    const Eigen::Vector3d bodyAcc(0.4 * std::sin(2.5 * t), 0.3 * std::cos(1.7 * t), 0.0);
    const Eigen::Vector3d acc = truth.conjugate() * (Eigen::Vector3d(0.0, 0.0, kG) + bodyAcc);
    return {w + bias + Eigen::Vector3d(gyrNoise(rng), gyrNoise(rng), gyrNoise(rng)),
            acc + Eigen::Vector3d(accNoise(rng), accNoise(rng), accNoise(rng))};
  }
};

bool finite(const Eigen::Quaterniond& q) {
  return q.coeffs().allFinite();
}

TEST(OrientationFilter, AbsurdButFiniteReadingsAreRejectedAndTheFilterKeepsTracking) {
  const double saturatedGyr = 2000.0 * kToRad;  // the usual full scale, reached
  const double saturatedAcc = 16.0 * 9.80665;
  struct Spike {
    const char* what;
    Eigen::Vector3d gyr, acc;  // replaces the reading; NaN = keep the true value
  };
  const double keep = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Spike> spikes = {
      {"gyr 1e308", {1e308, 0.0, 0.0}, Eigen::Vector3d::Constant(keep)},
      {"gyr 1e38", {0.0, -1e38, 0.0}, Eigen::Vector3d::Constant(keep)},
      {"gyr 1e6", {0.0, 0.0, 1e6}, Eigen::Vector3d::Constant(keep)},
      {"gyr saturated", {saturatedGyr, 0.1, 0.1}, Eigen::Vector3d::Constant(keep)},
      {"acc 1e38", Eigen::Vector3d::Constant(keep), {1e38, 0.0, 9.81}},
      {"acc saturated", Eigen::Vector3d::Constant(keep), {0.0, 0.0, saturatedAcc}},
  };
  for (const Spike& spike : spikes) {
    SCOPED_TRACE(spike.what);
    TurningImu imu;
    OrientationFilter f;
    const double dt = 0.005;
    double worstAfter = 0.0;
    bool allFinite = true;
    for (int k = 0; k < 6000; ++k) {  // 30 s, the spike at 10 s
      const double t = k * dt;
      auto [gyr, acc] = imu.step(t, dt);
      const bool spiked = k == 2000;
      if (spiked) {
        for (int j = 0; j < 3; ++j) {
          if (!std::isnan(spike.gyr(j))) gyr(j) = spike.gyr(j);
          if (!std::isnan(spike.acc(j))) acc(j) = spike.acc(j);
        }
      }
      EXPECT_EQ(f.update(gyr, acc, dt), !spiked) << "sample " << k;
      allFinite = allFinite && finite(f.orientation()) && f.bias().allFinite();
      if (k > 2000) worstAfter = std::max(worstAfter, inclinationError(f.orientation(), imu.truth));
    }
    EXPECT_TRUE(allFinite);
    EXPECT_EQ(f.state().rejected, 1u);
    EXPECT_LT(worstAfter, 1.0 * kToRad);  // the spike leaves no trace
    EXPECT_LT((f.bias() - imu.bias).norm(), 0.3 * kToRad);
  }
}

TEST(OrientationFilter, NonFiniteValueOnAnyAxisIsRejected) {
  // Eigen's default maxCoeff() may skip a NaN that is not the first coefficient.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    for (double bad : {nan, -nan, inf, -inf}) {
      OrientationFilter f;
      Eigen::Vector3d gyr = Eigen::Vector3d::Zero(), acc(0.0, 0.0, kG);
      gyr(axis) = bad;
      EXPECT_FALSE(f.update(gyr, acc, 0.01)) << "gyr axis " << axis << " " << bad;
      gyr.setZero();
      acc(axis) = bad;
      EXPECT_FALSE(f.update(gyr, acc, 0.01)) << "acc axis " << axis << " " << bad;
      EXPECT_TRUE(finite(f.orientation()));
      EXPECT_EQ(f.state().rejected, 2u);
      EXPECT_EQ(f.state().outOfRange, 0u);
    }
  }
}

TEST(OrientationFilter, PlausibilityLimitsAreCountedAndReadingsJustInsideAreUsed) {
  OrientationFilter f;
  const double dt = 0.005;
  const Eigen::Vector3d g(0.0, 0.0, kG);
  EXPECT_TRUE(f.update({1999.0 * kToRad, 0.0, 0.0}, g, dt));
  EXPECT_TRUE(f.update({0.0, 0.0, 0.0}, {0.0, -15.9 * 9.80665, 0.0}, dt));
  EXPECT_FALSE(f.update({0.0, -2000.0 * kToRad, 0.0}, g, dt));
  EXPECT_EQ(f.lastStatus(), OrientationStatus::Rejected);
  EXPECT_FALSE(f.update({0.0, 0.0, 0.0}, {0.0, 0.0, 1e6}, dt));
  EXPECT_FALSE(f.update({std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0}, g, dt));
  EXPECT_EQ(f.state().rejected, 3u);
  EXPECT_EQ(f.state().outOfRange, 2u);
  EXPECT_TRUE(f.update({0.0, 0.0, 0.0}, g, dt));
  EXPECT_EQ(f.lastStatus(), OrientationStatus::Accepted);
  // The three refused samples' time is carried over: 4 x 5 ms is not yet a gap.
  EXPECT_EQ(f.state().gaps, 0u);

  OrientationParams p;
  p.gyrMax = 500.0;
  OrientationFilter narrow(p);
  EXPECT_FALSE(narrow.update({0.0, 0.0, 600.0 * kToRad}, g, dt));
  p.gapSeconds = 0.0;
  EXPECT_THROW(OrientationFilter{p}, std::invalid_argument);
}

// The sensor keeps turning through a 5 s gap in the samples (as when a wireless link drops).
// Returns the worst inclination error (deg) from `settle` s after the gap on.
struct GapRun {
  double worstAfterSettleDeg = 0.0;
  double errorJustAfterDeg = 0.0;  // 0.1 s after the gap
  bool allFinite = true;
  Eigen::Vector3d biasError = Eigen::Vector3d::Zero();  // rad/s, at the end
  std::uint64_t gaps = 0;
};

GapRun runWithGap(double gapStart, double gapLength, double settle, double end) {
  TurningImu imu;
  OrientationFilter f;
  const double dt = 0.005;
  GapRun r;
  double tPrev = 0.0;
  for (int k = 1; k * dt <= end; ++k) {
    const double t = k * dt;
    const auto [gyr, acc] = imu.step(t - dt, dt);
    if (t > gapStart && t <= gapStart + gapLength) continue;  // nothing arrives
    EXPECT_TRUE(f.update(gyr, acc, t - tPrev));
    tPrev = t;
    r.allFinite = r.allFinite && finite(f.orientation()) && f.bias().allFinite();
    const double e = inclinationError(f.orientation(), imu.truth) / kToRad;
    if (t > gapStart + gapLength + settle)
      r.worstAfterSettleDeg = std::max(r.worstAfterSettleDeg, e);
    if (std::abs(t - (gapStart + gapLength + 0.1)) < 0.5 * dt) r.errorJustAfterDeg = e;
  }
  r.biasError = f.bias() - imu.bias;
  r.gaps = f.state().gaps;
  return r;
}

TEST(OrientationFilter, FiveSecondGapWhileTurningRecoversWithinTwoSeconds) {
  const GapRun r = runWithGap(20.0, 5.0, 2.0, 40.0);
  std::printf(
      "5 s gap while turning: inclination error 0.1 s after the gap %.2f deg, worst from 2 s "
      "after %.3f deg; bias error at the end %.3f deg/s\n",
      r.errorJustAfterDeg, r.worstAfterSettleDeg, r.biasError.norm() / kToRad);
  EXPECT_TRUE(r.allFinite);
  EXPECT_LT(r.worstAfterSettleDeg, 2.0);
  // The gap must not be taken for a gyroscope bias.
  EXPECT_LT(r.biasError.norm(), 0.3 * kToRad);
}

TEST(OrientationFilter, GapsAreCountedAndMarkedAndShortStepsAreNotGaps) {
  const GapRun r = runWithGap(20.0, 5.0, 2.0, 30.0);
  EXPECT_EQ(r.gaps, 1u);
  OrientationFilter f;
  const Eigen::Vector3d g(0.0, 0.0, kG);
  for (int k = 0; k < 100; ++k) ASSERT_TRUE(f.update({0.0, 0.0, 0.0}, g, 0.01));
  ASSERT_TRUE(f.update({0.0, 0.0, 0.0}, g, 0.09));  // a late sample, not a gap
  EXPECT_EQ(f.lastStatus(), OrientationStatus::Accepted);
  ASSERT_TRUE(f.update({0.0, 0.0, 0.0}, g, 0.5));
  EXPECT_EQ(f.lastStatus(), OrientationStatus::AfterGap);
  EXPECT_EQ(f.state().gaps, 1u);
  EXPECT_DOUBLE_EQ(f.state().gapTime, 0.5);
  // 30 refused samples of 10 ms in a row are a gap too.
  for (int k = 0; k < 30; ++k) ASSERT_FALSE(f.update({1e6, 0.0, 0.0}, g, 0.01));
  ASSERT_TRUE(f.update({0.0, 0.0, 0.0}, g, 0.01));
  EXPECT_EQ(f.lastStatus(), OrientationStatus::AfterGap);
  EXPECT_EQ(f.state().gaps, 2u);
}

TEST(OrientationFilter, BatchMatchesSampleBySample) {
  const int n = 1000;
  std::vector<double> gyr(3 * n), acc(3 * n), dt(n), out(4 * n);
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.3);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < 3; ++j) {
      gyr[3 * i + j] = noise(rng);
      acc[3 * i + j] = (j == 2 ? kG : 0.0) + noise(rng);
    }
    dt[i] = 0.0035 + (i % 7) * 1e-5;
  }
  gyr[3 * 500] = std::numeric_limits<double>::quiet_NaN();
  OrientationFilter batch, single;
  std::vector<OrientationStatus> status(n);
  EXPECT_EQ(batch.updateBatch(gyr, acc, dt, out, status), std::size_t(n - 1));
  EXPECT_EQ(status[500], OrientationStatus::Rejected);
  EXPECT_EQ(status[501], OrientationStatus::Accepted);
  for (int i = 0; i < n; ++i) {
    single.update({gyr[3 * i], gyr[3 * i + 1], gyr[3 * i + 2]},
                  {acc[3 * i], acc[3 * i + 1], acc[3 * i + 2]}, dt[i]);
    const Eigen::Quaterniond q = single.orientation();
    ASSERT_EQ(out[4 * i], q.w());
    ASSERT_EQ(out[4 * i + 3], q.z());
  }
  EXPECT_EQ(batch.state().rejected, 1u);
  EXPECT_THROW(batch.updateBatch(gyr, acc, std::span(dt).first(10), {}), std::invalid_argument);
}

TEST(OrientationFilter, InclinationErrorIgnoresHeading) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -1, 0.3).normalized()));
  const Eigen::Quaterniond turned = Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitZ()) * q;
  EXPECT_NEAR(inclinationError(turned, q), 0.0, 1e-12);
  const Eigen::Quaterniond tilted = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()) * q;
  EXPECT_NEAR(inclinationError(tilted, q), 0.1, 1e-12);
}

TEST(OrientationFilter, RejectsBadParameters) {
  OrientationParams p;
  p.tauAcc = 0.0;
  EXPECT_THROW(OrientationFilter{p}, std::invalid_argument);
  p = {};
  p.restThAcc = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(OrientationFilter{p}, std::invalid_argument);
}

}  // namespace
}  // namespace armtrack
