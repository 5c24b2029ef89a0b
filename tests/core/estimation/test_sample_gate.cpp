// Plausibility at the door: each kind of impossible reading is refused, counted by block and
// reason, and everything else in the sample passes untouched.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "core/estimation/SampleGate.h"

namespace armtrack {
namespace {

ImuReading reading(double gyr, double acc) {
  ImuReading r;
  r.gyr = Eigen::Vector3d(gyr, -0.5 * gyr, 0.1);
  r.acc = Eigen::Vector3d(acc, 0.3, -0.2);
  return r;
}

ArmSample sample(double t) {
  ArmSample s;
  s.t = t;
  s.upperArm = reading(0.5 + 1e-3 * t, 9.8);
  s.forearm = reading(-0.7 + 1e-3 * t, 9.7);
  s.elbow = Eigen::Vector3d(0.2, 0.05, 0.0);
  s.wrist = Eigen::Vector3d(0.3, 0.2, 0.0);
  s.camWrist = Eigen::Vector2d(320, 240);
  s.trueAngles = JointVector::Constant(0.1);
  return s;
}

TEST(SampleGate, PassesGoodSamplesUntouched) {
  SampleGate gate;
  for (int i = 0; i < 200; ++i) {
    const ArmSample s = sample(i * 1e-3);
    const ArmSample out = gate.check(s);
    ASSERT_TRUE(out.upperArm && out.forearm && out.elbow && out.wrist && out.camWrist);
    EXPECT_EQ(out.upperArm->gyr, s.upperArm->gyr);
    EXPECT_EQ(out.forearm->acc, s.forearm->acc);
    EXPECT_EQ(*out.wrist, *s.wrist);
    EXPECT_FALSE(gate.lastRefused());
  }
  EXPECT_EQ(gate.counters().total(), 0u);
  EXPECT_EQ(gate.counters().summary(), "");
}

TEST(SampleGate, RefusesAbsurdButFiniteValuesAndKeepsTheRest) {
  for (double spike : {1e6, 1e38, 6e36, 1e308, 35.0 /* rad/s, just beyond 2000 deg/s */}) {
    SampleGate gate;
    ArmSample s = sample(1.0);
    s.upperArm->gyr(1) = spike;
    const ArmSample out = gate.check(s);
    EXPECT_FALSE(out.upperArm) << spike;
    ASSERT_TRUE(out.forearm);
    EXPECT_EQ(out.forearm->gyr, s.forearm->gyr);
    EXPECT_TRUE(out.elbow && out.wrist && out.camWrist && out.trueAngles);
    EXPECT_EQ(gate.counters().refused[0][static_cast<int>(Implausible::BeyondRange)], 1u);
    EXPECT_EQ(gate.counters().total(), 1u);
    EXPECT_DOUBLE_EQ(gate.counters().firstT, 1.0);
  }
  SampleGate gate;
  ArmSample s = sample(2.0);
  s.forearm->acc(2) = -1e6;
  EXPECT_FALSE(gate.check(s).forearm);
  EXPECT_EQ(gate.counters().byReason(Implausible::BeyondRange), 1u);
  EXPECT_EQ(gate.counters().byBlock(SensorBlock::Forearm), 1u);
}

TEST(SampleGate, RefusesSaturatedReadingsAtFullScale) {
  SampleGate gate;
  const double gyroFull = 2000.0 * std::acos(-1.0) / 180.0, accFull = 16 * 9.80665;
  ArmSample s = sample(3.0);
  s.upperArm->gyr(0) = gyroFull;  // exactly at full scale: clipped
  s.forearm->acc(0) = accFull;
  const ArmSample out = gate.check(s);
  EXPECT_FALSE(out.upperArm);
  EXPECT_FALSE(out.forearm);
  EXPECT_EQ(gate.counters().byReason(Implausible::Saturated), 2u);
  // Fast but real: 1500 deg/s and 12 g pass.
  s = sample(3.001);
  s.upperArm->gyr(0) = 0.75 * gyroFull;
  s.forearm->acc(0) = 0.75 * accFull;
  const ArmSample fine = gate.check(s);
  EXPECT_TRUE(fine.upperArm && fine.forearm);
  EXPECT_EQ(gate.counters().total(), 2u);
}

TEST(SampleGate, RefusesAllZeroAccelerometerButNotZeroGyro) {
  SampleGate gate;
  ArmSample s = sample(4.0);
  s.upperArm->acc.setZero();
  s.upperArm->gyr.setZero();
  s.forearm->gyr.setZero();  // an arm at rest: the gyroscope may well read zero
  const ArmSample out = gate.check(s);
  EXPECT_FALSE(out.upperArm);
  EXPECT_TRUE(out.forearm);
  EXPECT_EQ(gate.counters().byReason(Implausible::AllZero), 1u);
  // A link sending zeros for the optics too.
  s = sample(4.001);
  s.elbow->setZero();
  s.camWrist->setZero();
  const ArmSample optics = gate.check(s);
  EXPECT_FALSE(optics.elbow);
  EXPECT_FALSE(optics.camWrist);
  EXPECT_TRUE(optics.wrist && optics.upperArm);
  EXPECT_EQ(gate.counters().byReason(Implausible::AllZero), 3u);
}

TEST(SampleGate, RefusesAFrozenSensorOnlyAfterManyIdenticalRepeats) {
  PlausibilityLimits limits;
  limits.stuckSamples = 10;
  SampleGate gate(limits);
  const ArmSample frozen = sample(0.0);
  int refusedFrom = -1;
  for (int i = 0; i < 30; ++i) {
    ArmSample s = frozen;
    s.t = i * 1e-3;
    s.forearm = reading(-0.7 + 1e-3 * i, 9.7);  // the forearm keeps changing
    const ArmSample out = gate.check(s);
    EXPECT_TRUE(out.forearm);
    if (!out.upperArm && refusedFrom < 0) refusedFrom = i;
    if (refusedFrom >= 0) {
      EXPECT_FALSE(out.upperArm) << i;
    }
  }
  EXPECT_EQ(refusedFrom, 9);  // the tenth identical reading in a row
  EXPECT_EQ(gate.counters().byReason(Implausible::Stuck), 21u);
  // A change of one bit ends it.
  ArmSample s = frozen;
  s.upperArm->acc(0) = std::nextafter(s.upperArm->acc(0), 100.0);
  EXPECT_TRUE(gate.check(s).upperArm);
}

TEST(SampleGate, RefusesOpticalPointsOffTheArmAndPixelsOutsideAnyImage) {
  SampleGate gate(PlausibilityLimits::forGeometry(0.3, 0.25));  // reach 1.025 m
  ArmSample s = sample(5.0);
  s.elbow = Eigen::Vector3d(0.9, 0.4, 0.0);  // 0.98 m: farther than any elbow, but let through
  s.wrist = Eigen::Vector3d(1e6, 0.0, 0.0);
  s.camWrist = Eigen::Vector2d(3e38, 1.0);
  s.camElbow = Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(), 1.0);
  const ArmSample out = gate.check(s);
  EXPECT_TRUE(out.elbow);
  EXPECT_FALSE(out.wrist);
  EXPECT_FALSE(out.camWrist);
  EXPECT_FALSE(out.camElbow);
  EXPECT_TRUE(out.upperArm && out.forearm);
  EXPECT_EQ(gate.counters().byBlock(SensorBlock::Wrist), 1u);
  EXPECT_EQ(gate.counters().byReason(Implausible::NonFinite), 1u);
  EXPECT_EQ(gate.counters().byReason(Implausible::BeyondRange), 2u);
  EXPECT_EQ(gate.counters().samplesWithRefusal, 1u);
}

TEST(SampleGate, SummarySaysWhatWhereAndWhen) {
  SampleGate gate;
  for (int i = 0; i < 100; ++i) {
    ArmSample s = sample(5.0 + i * 1e-3);
    s.upperArm->gyr(0) = 40.0;  // beyond 2000 deg/s
    s.forearm->acc.setZero();
    gate.check(s);
  }
  const std::string text = gate.counters().summary();
  EXPECT_NE(text.find("refused 200 implausible readings"), std::string::npos) << text;
  EXPECT_NE(text.find("beyond the sensor's range 100: upper-arm IMU 100"), std::string::npos)
      << text;
  EXPECT_NE(text.find("all zero 100: forearm IMU 100"), std::string::npos) << text;
  EXPECT_NE(text.find("between 5.000 s and 5.099 s"), std::string::npos) << text;
}

}  // namespace
}  // namespace armtrack

namespace armtrack {
namespace {

// A logger's 90 Hz clock with a 50 Hz gyroscope and a 25 Hz accelerometer: a row repeats a
// sensor's previous value when no new sample came. Every repeat, and only the repeats, is marked
// held and counted; nothing is refused.
TEST(SampleGateHeld, MarksExactlyTheRepeatsOfALoggerClock) {
  SampleGate gate;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0.0, 0.01);
  ImuReading latest = reading(0.2, 9.8);
  int lastGyr = -1, lastAcc = -1;
  std::uint64_t repeatsGyr = 0, repeatsAcc = 0;
  for (int row = 0; row < 900; ++row) {
    const double t = row / 90.0;
    const int g = static_cast<int>(std::floor(t * 50.0)),
              a = static_cast<int>(std::floor(t * 25.0));
    const bool freshGyr = g != lastGyr, freshAcc = a != lastAcc;
    if (freshGyr) latest.gyr += Eigen::Vector3d(n(rng), n(rng), n(rng));
    if (freshAcc) latest.acc += Eigen::Vector3d(n(rng), n(rng), n(rng));
    lastGyr = g;
    lastAcc = a;
    repeatsGyr += !freshGyr;
    repeatsAcc += !freshAcc;
    ArmSample s;
    s.t = t;
    s.upperArm = latest;
    const ArmSample out = gate.check(s);
    ASSERT_TRUE(out.upperArm) << row;
    EXPECT_EQ(out.upperArm->gyrHeld, !freshGyr) << row;
    EXPECT_EQ(out.upperArm->accHeld, !freshAcc) << row;
    EXPECT_EQ(out.upperArm->gyr, latest.gyr);
  }
  ASSERT_GT(repeatsGyr, 300u);  // 4 of every 9 rows
  ASSERT_GT(repeatsAcc, 600u);  // 13 of every 18
  EXPECT_EQ(gate.counters().held[0], repeatsGyr);
  EXPECT_EQ(gate.counters().held[1], repeatsAcc);
  EXPECT_EQ(gate.counters().held[2] + gate.counters().held[3], 0u);
  EXPECT_EQ(gate.counters().total(), 0u);  // held is not refused
  EXPECT_EQ(gate.counters().heldSummary(),
            "took " + std::to_string(repeatsGyr + repeatsAcc) +
                " repeated (held) readings as absent: upper-arm gyroscope " +
                std::to_string(repeatsGyr) + ", upper-arm accelerometer " +
                std::to_string(repeatsAcc));
}

// A value that stays the same for longer than any internal sample period is a constant signal
// (an ideal simulation at rest), not a held one: only its first heldSeconds are marked.
TEST(SampleGateHeld, AConstantSignalIsHeldOnlyForHeldSeconds) {
  PlausibilityLimits limits;
  limits.stuckSamples = 0;
  SampleGate gate(limits);
  const ImuReading constant = reading(0.3, 9.8);
  int held = 0;
  for (int i = 0; i < 200; ++i) {  // 1 s at 200 Hz
    ArmSample s;
    s.t = i / 200.0;
    s.forearm = constant;
    const ArmSample out = gate.check(s);
    ASSERT_TRUE(out.forearm);
    held += out.forearm->gyrHeld;
    if (i > 12) {
      EXPECT_FALSE(out.forearm->gyrHeld) << i;
    }
  }
  EXPECT_EQ(held, 10);  // 5 ms to 50 ms after the value last changed
  // Off: nothing is marked.
  limits.heldSeconds = 0.0;
  SampleGate off(limits);
  for (int i = 0; i < 20; ++i) {
    ArmSample s;
    s.t = i / 200.0;
    s.forearm = constant;
    const ArmSample out = off.check(s);
    EXPECT_FALSE(out.forearm->gyrHeld || out.forearm->accHeld);
  }
  EXPECT_EQ(off.counters().totalHeld(), 0u);
}

}  // namespace
}  // namespace armtrack
