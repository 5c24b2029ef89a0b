// The gyroscope bias at rest (core/estimation/RestBias.h) against readings made here with a known
// bias: still sensors give it back, moving ones give nothing, a bias that changes is followed,
// and what the rules exclude (slow turns that tilt gravity, rates no bias reaches, held values,
// time going back) is excluded.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "core/estimation/RestBias.h"

namespace armtrack {
namespace {

struct Sensor {
  Eigen::Vector3d bias{0.04, -0.02, 0.03};  // rad/s: 2.3, -1.1, 1.7 deg/s
  double noise = 0.0055;                    // rad/s, Table 5
  std::mt19937_64 rng{7};
  std::normal_distribution<double> n{0.0, 1.0};

  ImuReading still(const Eigen::Vector3d& up = {-9.81, 0.0, 0.0}) {
    ImuReading r;
    r.gyr = bias + noise * Eigen::Vector3d(n(rng), n(rng), n(rng));
    r.acc = -up + 0.1 * Eigen::Vector3d(n(rng), n(rng), n(rng));
    return r;
  }
};

TEST(RestBias, AStillSensorGivesItsBiasBack) {
  Sensor s;
  RestBias rb;
  for (int i = 0; i < 200 * 3; ++i) rb.add(i / 200.0, s.still());  // 3 s at 200 Hz
  ASSERT_GE(rb.windows(), 2u);
  // The mean of 200 readings with 0.0055 rad/s noise: 0.0004 rad/s sd; allow five.
  EXPECT_LT((rb.bias() - s.bias).cwiseAbs().maxCoeff(), 0.002) << rb.bias().transpose();
}

TEST(RestBias, NothingBeforeAWholeStillWindow) {
  Sensor s;
  RestBias rb;
  for (int i = 0; i < 190; ++i) rb.add(i / 200.0, s.still());  // 0.95 s
  EXPECT_EQ(rb.windows(), 0u);
  EXPECT_TRUE(rb.bias().isZero(0.0));
}

TEST(RestBias, AMovingArmIsNotRest) {
  Sensor s;
  RestBias rb;
  for (int i = 0; i < 200 * 5; ++i) {
    const double t = i / 200.0;
    ImuReading r = s.still();
    r.gyr.x() += 1.0 * std::sin(2.0 * std::numbers::pi * 0.5 * t);  // a swing of +-1 rad/s
    rb.add(t, r);
  }
  EXPECT_EQ(rb.windows(), 0u);
  EXPECT_TRUE(rb.bias().isZero(0.0));
}

TEST(RestBias, ASlowSteadyTurnThatTiltsGravityIsNotTakenForBias) {
  Sensor s;
  s.bias.setZero();
  RestBias rb;
  const double rate = 0.05;  // rad/s (2.9 deg/s) about z: gravity turns in the x-y plane
  for (int i = 0; i < 200 * 4; ++i) {
    const double t = i / 200.0;
    const double a = rate * t;
    ImuReading r = s.still(Eigen::Vector3d(-9.81 * std::cos(a), -9.81 * std::sin(a), 0.0));
    r.gyr.z() += rate;
    rb.add(t, r);
  }
  EXPECT_EQ(rb.windows(), 0u) << rb.bias().transpose();
}

TEST(RestBias, RatesBeyondAnyBiasAreNotTaken) {
  Sensor s;
  s.bias = Eigen::Vector3d(0.2, 0.0, 0.0);  // 11.5 deg/s: beyond every datasheet
  RestBias rb;
  for (int i = 0; i < 200 * 3; ++i) rb.add(i / 200.0, s.still());
  EXPECT_EQ(rb.windows(), 0u);
}

TEST(RestBias, ABiasThatChangesIsFollowedAtEachRest) {
  Sensor s;
  RestBias rb;
  double t = 0.0;
  auto rest = [&](double seconds) {
    for (int i = 0; i < int(seconds * 200); ++i, t += 1.0 / 200.0) rb.add(t, s.still());
  };
  rest(2.0);
  const Eigen::Vector3d first = rb.bias();
  s.bias += Eigen::Vector3d(0.01, 0.01, -0.01);  // warmed up by 0.6 deg/s per axis
  rest(6.0);
  EXPECT_LT((first - (s.bias - Eigen::Vector3d(0.01, 0.01, -0.01))).cwiseAbs().maxCoeff(), 0.002);
  EXPECT_LT((rb.bias() - s.bias).cwiseAbs().maxCoeff(), 0.002) << rb.bias().transpose();
}

TEST(RestBias, HeldValuesAreLeftOutOfTheMean) {
  // A logger repeating an old, larger value as held: marked, it must not move the bias.
  Sensor s;
  RestBias rb;
  for (int i = 0; i < 200 * 3; ++i) {
    ImuReading r = s.still();
    if (i % 2) {
      r.gyr = Eigen::Vector3d::Constant(0.09);
      r.gyrHeld = true;
    }
    rb.add(i / 200.0, r);
  }
  ASSERT_GE(rb.windows(), 2u);
  EXPECT_LT((rb.bias() - s.bias).cwiseAbs().maxCoeff(), 0.003);
}

TEST(RestBias, TimeGoingBackOrNotNumbersBreakNothing) {
  Sensor s;
  RestBias rb;
  for (int i = 0; i < 150; ++i) rb.add(i / 200.0, s.still());
  rb.add(0.1, s.still());  // back in time: the window starts again
  ImuReading bad = s.still();
  bad.gyr.x() = std::numeric_limits<double>::quiet_NaN();
  rb.add(0.2, bad);
  rb.add(std::numeric_limits<double>::infinity(), s.still());
  for (int i = 0; i < 150; ++i) rb.add(0.2 + i / 200.0, s.still());
  EXPECT_EQ(rb.windows(), 0u);  // neither stretch was a whole second
  for (int i = 150; i < 400; ++i) rb.add(0.2 + i / 200.0, s.still());
  EXPECT_GE(rb.windows(), 1u);
  EXPECT_TRUE(rb.bias().allFinite());
  EXPECT_LT((rb.bias() - s.bias).cwiseAbs().maxCoeff(), 0.002);
}

}  // namespace
}  // namespace armtrack
