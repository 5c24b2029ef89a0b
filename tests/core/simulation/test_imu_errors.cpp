// The error model of a real IMU (core/simulation/ImuErrors.h), each error against a truth worked
// out independently: the analytic reading for a known rotation, the random walk's variance law,
// the held samples, the converter's range and LSB, the wobble's damped envelope, the jitter's
// statistics, and the parameters it refuses.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/simulation/ImuErrors.h"
#include "core/simulation/SensorSimulator.h"

namespace armtrack {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// An IMU with the error model on and nothing else: no noise, no bias, every error zero.
ImuSimParams bare(double rateHz) {
  ImuSimParams p;
  p.rateHz = rateHz;
  p.errors.enabled = true;
  return p;
}

ImuErrorModel::TruthFn constant(const Eigen::Vector3d& gyr, const Eigen::Vector3d& acc) {
  return [gyr, acc](double) { return ImuTruth{gyr, acc, Eigen::Vector3d::Zero()}; };
}

// Every value of the truth is the time itself: a reading shows when it was sampled.
ImuTruth ramp(double t) {
  return {Eigen::Vector3d::Constant(t), Eigen::Vector3d::Constant(t), Eigen::Vector3d::Zero()};
}

TEST(ImuErrors, ScaleCrossAxisAndMountingGiveTheAnalyticReading) {
  ImuSimParams p = bare(100.0);
  p.misalignment =
      Eigen::AngleAxisd(10 * kDeg, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  p.errors.gyroScale = {0.02, -0.01, 0.03};
  p.errors.accelScale = {-0.03, 0.015, 0.0};
  p.errors.gyroCrossAxis << 0, 0.01, -0.02,  //
      0.015, 0, 0.005,                       //
      -0.01, 0.02, 0;
  p.errors.accelCrossAxis << 0, -0.02, 0.01,  //
      0.005, 0, 0.0,                          //
      0.02, -0.015, 0;
  p.errors.gyroGSensitivity = Eigen::Matrix3d::Identity() * (0.1 * kDeg / 9.81);
  const Eigen::Vector3d w(0.5, -1.2, 2.0), f(3.0, -9.0, 1.5);
  ImuErrorModel model(p, 1, 1);
  const ImuReading r = model.reading(0.3, constant(w, f));
  // The sensor's axes are the model's turned by the mounting: it sees M^T w and M^T f.
  const Eigen::Matrix3d M = p.misalignment;
  const Eigen::Vector3d wSensor = M.transpose() * w, fSensor = M.transpose() * f;
  Eigen::Vector3d gyr, acc;
  for (int i = 0; i < 3; ++i) {
    gyr[i] = (1 + p.errors.gyroScale[i]) * wSensor[i] + 0.1 * kDeg / 9.81 * fSensor[i];
    acc[i] = (1 + p.errors.accelScale[i]) * fSensor[i];
    for (int j = 0; j < 3; ++j) {
      if (i == j) continue;
      gyr[i] += p.errors.gyroCrossAxis(i, j) * wSensor[j];
      acc[i] += p.errors.accelCrossAxis(i, j) * fSensor[j];
    }
  }
  EXPECT_LT((r.gyr - gyr).norm(), 1e-12);
  EXPECT_LT((r.acc - acc).norm(), 1e-12);
}

// With the model on and every error zero, the readings are the ideal simulator's (its truth comes
// from the same kinematics), for both sides, a moving trunk and the sternum IMU; the true angles
// are the segment's, untouched.
TEST(ImuErrors, WithEveryErrorZeroTheReadingsAreTheIdealOnes) {
  for (const Side side : {Side::Right, Side::Left}) {
    SimulationParams ideal = defaultSimulation();
    ideal.duration = 3.0;
    ideal.side = side;
    ideal.trunkImu.enabled = true;
    ideal.trunk.enabled = true;
    ideal.trunk.leanDeg = 15.0;
    for (ImuSimParams* imu : {&ideal.upperArm, &ideal.forearm, &ideal.trunkImu}) {
      imu->rateHz = 200.0;
      imu->gyroNoiseStd = imu->accelNoiseStd = 0.0;
    }
    SimulationParams errors = ideal;
    for (ImuSimParams* imu : {&errors.upperArm, &errors.forearm, &errors.trunkImu})
      imu->errors.enabled = true;
    const auto traj = makeTrajectory("reaching", TrajectoryOptions{});
    const Recording a = simulateRecording(*traj, ideal), b = simulateRecording(*traj, errors);
    ASSERT_EQ(a.samples.size(), b.samples.size());
    for (std::size_t i = 0; i < a.samples.size(); ++i) {
      const ArmSample &x = a.samples[i], &y = b.samples[i];
      ASSERT_EQ(x.t, y.t);
      ASSERT_EQ(x.upperArm.has_value(), y.upperArm.has_value());
      if (x.upperArm) {
        EXPECT_LT((x.upperArm->gyr - y.upperArm->gyr).norm(), 1e-9) << x.t;
        EXPECT_LT((x.upperArm->acc - y.upperArm->acc).norm(), 1e-9) << x.t;
        EXPECT_LT((x.forearm->gyr - y.forearm->gyr).norm(), 1e-9) << x.t;
        EXPECT_LT((x.forearm->acc - y.forearm->acc).norm(), 1e-9) << x.t;
        EXPECT_LT((x.trunk->gyr - y.trunk->gyr).norm(), 1e-9) << x.t;
        EXPECT_LT((x.trunk->acc - y.trunk->acc).norm(), 1e-9) << x.t;
        ASSERT_TRUE(y.trueAngles.has_value());
        EXPECT_EQ(*x.trueAngles, *y.trueAngles);
      }
    }
  }
}

// The rate random walk: Var(b(t)) = walk^2 t. Over n = 3 axes x 400 seeds the sample variance has
// a relative standard error of sqrt(2 / (n - 1)) = 0.041; the test allows 4 of them.
TEST(ImuErrors, BiasRandomWalkVarianceGrowsLinearlyAtTheStatedRate) {
  const double walk = 0.01;  // rad/s per sqrt(s)
  const std::vector<double> times = {1.0, 4.0, 16.0};
  std::vector<std::vector<double>> values(times.size());
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    ImuSimParams p = bare(50.0);
    p.errors.gyroBiasWalk = walk;
    p.errors.accelBiasWalk = 2 * walk;
    ImuErrorModel model(p, seed, 1);
    for (std::size_t k = 0; k < times.size(); ++k) {
      const ImuReading r = model.reading(times[k], constant({0, 0, 0}, {0, 0, 0}));
      for (int a = 0; a < 3; ++a) {
        values[k].push_back(r.gyr[a]);
        EXPECT_EQ(r.acc[a] == 0.0, false);  // the accelerometer walks too
      }
    }
  }
  for (std::size_t k = 0; k < times.size(); ++k) {
    const std::vector<double>& v = values[k];
    const double n = static_cast<double>(v.size());
    const double mean = std::accumulate(v.begin(), v.end(), 0.0) / n;
    double var = 0.0;
    for (double x : v) var += (x - mean) * (x - mean);
    var /= n - 1;
    const double expected = walk * walk * times[k];
    EXPECT_NEAR(mean, 0.0, 4 * std::sqrt(expected / n)) << times[k];
    EXPECT_NEAR(var / expected, 1.0, 4 * std::sqrt(2 / (n - 1))) << times[k];
  }
}

TEST(ImuErrors, TemperatureDriftFollowsTheWarmUpCurve) {
  ImuSimParams p = bare(100.0);
  p.gyroBias = {0.01, 0.0, -0.02};
  p.accelBias = {0.1, 0.0, 0.0};
  p.errors.temperatureRiseK = 8.0;
  p.errors.temperatureTauS = 200.0;
  p.errors.gyroBiasPerK = {0.05 * kDeg, -0.03 * kDeg, 0.0};
  p.errors.accelBiasPerK = {0.0, 0.01, -0.005};
  ImuErrorModel model(p, 3, 1);
  for (const double t : {0.0, 10.0, 100.0, 400.0, 1200.0}) {
    const ImuReading r = model.reading(t, constant({0, 0, 0}, {0, 0, 0}));
    const double dT = 8.0 * (1.0 - std::exp(-t / 200.0));
    EXPECT_LT((r.gyr - (p.gyroBias + p.errors.gyroBiasPerK * dT)).norm(), 1e-12) << t;
    EXPECT_LT((r.acc - (p.accelBias + p.errors.accelBiasPerK * dT)).norm(), 1e-12) << t;
  }
}

// A 50 Hz gyroscope and a 25 Hz accelerometer on a 90 Hz clock: each row holds the last internal
// sample (its time, read off the ramp), and the share of repeated rows is 1 - internal / output.
TEST(ImuErrors, SampleAndHoldRepeatsTheLastInternalSample) {
  ImuSimParams p = bare(90.0);
  p.errors.gyroRateHz = 50.0;
  p.errors.accelRateHz = 25.0;
  ImuErrorModel model(p, 1, 1);
  const int rows = 900;  // 10 s
  int gyroRepeats = 0, accelRepeats = 0;
  ImuReading prev;
  for (int i = 0; i <= rows; ++i) {
    const double t = static_cast<double>(i) / 90.0;
    const ImuReading r = model.reading(t, ramp);
    EXPECT_EQ(r.gyr.x(), std::floor(t * 50.0 + 1e-9) / 50.0) << t;
    EXPECT_EQ(r.acc.x(), std::floor(t * 25.0 + 1e-9) / 25.0) << t;
    if (i > 0) {
      gyroRepeats += r.gyr == prev.gyr;
      accelRepeats += r.acc == prev.acc;
    }
    prev = r;
  }
  EXPECT_NEAR(gyroRepeats / double(rows), 1.0 - 50.0 / 90.0, 1.5 / rows);
  EXPECT_NEAR(accelRepeats / double(rows), 1.0 - 25.0 / 90.0, 1.5 / rows);
  EXPECT_EQ(model.gyroSamples(), 501u);
  EXPECT_EQ(model.accelSamples(), 251u);
}

TEST(ImuErrors, SaturationClampsAtTheRange) {
  ImuSimParams p = bare(100.0);
  p.errors.gyroRange = 2000 * kDeg;
  p.errors.accelRange = 16 * 9.80665;
  ImuErrorModel model(p, 1, 1);
  const ImuReading r = model.reading(0.0, constant({100.0, -100.0, 1.0}, {-400.0, 5.0, 400.0}));
  EXPECT_EQ(r.gyr.x(), 2000 * kDeg);
  EXPECT_EQ(r.gyr.y(), -2000 * kDeg);
  EXPECT_EQ(r.gyr.z(), 1.0);
  EXPECT_EQ(r.acc.x(), -16 * 9.80665);
  EXPECT_EQ(r.acc.y(), 5.0);
  EXPECT_EQ(r.acc.z(), 16 * 9.80665);
}

// The same sensor with and without its converter's LSB (the same seed: the same noise): every
// value lies on the lattice, within half an LSB of the unquantised one.
TEST(ImuErrors, QuantisationErrorIsAtMostHalfAnLsb) {
  ImuSimParams p = bare(200.0);
  p.gyroNoiseStd = 0.3;
  p.accelNoiseStd = 2.0;
  ImuSimParams q = p;
  q.errors.gyroLsb = kDeg / 16.4;
  q.errors.accelLsb = 9.80665 / 2048.0;
  ImuErrorModel fine(p, 5, 1), coarse(q, 5, 1);
  const auto truth = [](double t) {
    return ImuTruth{Eigen::Vector3d(std::sin(7 * t), 2 * std::cos(3 * t), t),
                    Eigen::Vector3d(9.81 * std::sin(t), 3 * t, -1.0), Eigen::Vector3d::Zero()};
  };
  for (int i = 0; i < 2000; ++i) {
    const double t = i / 200.0;
    const ImuReading a = fine.reading(t, truth), b = coarse.reading(t, truth);
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(std::abs(b.gyr[k] - a.gyr[k]), q.errors.gyroLsb / 2 * (1 + 1e-9));
      EXPECT_LE(std::abs(b.acc[k] - a.acc[k]), q.errors.accelLsb / 2 * (1 + 1e-9));
      const double counts = b.gyr[k] / q.errors.gyroLsb;
      EXPECT_NEAR(counts, std::round(counts), 1e-6);
    }
  }
}

// A step in the segment's acceleration along x rings the sensor about y (n x a, n = z): the tilt
// settles at -k a, and the distance from it decays as exp(-zeta w t) at the damped frequency.
// The envelope is fitted to the ringing's extremes by least squares on their logarithms.
TEST(ImuErrors, WobbleRingsDownAtTheStatedDampingAfterAStep) {
  ImuSimParams p = bare(2000.0);
  p.errors.wobbleFrequencyHz = 12.0;
  p.errors.wobbleDamping = 0.25;
  p.errors.wobbleTiltPerAccel = 0.1 * kDeg;  // per m/s^2
  p.errors.wobbleTranslationGain = 0.3;
  const double step = 0.2, a = 15.0;
  const auto truth = [&](double t) {
    const Eigen::Vector3d lin = t >= step ? Eigen::Vector3d(a, 0, 0) : Eigen::Vector3d::Zero();
    return ImuTruth{Eigen::Vector3d::Zero(), lin, lin};
  };
  ImuErrorModel model(p, 1, 1);
  const double settled = -p.errors.wobbleTiltPerAccel * a;
  std::vector<double> ts, dev;
  double largest = 0.0;
  for (int i = 0; i <= 2000; ++i) {
    const double t = i / 2000.0;
    model.reading(t, truth);
    const Eigen::Vector3d tilt = model.wobbleTilt();
    EXPECT_NEAR(tilt.x(), 0.0, 1e-15);
    EXPECT_NEAR(tilt.z(), 0.0, 1e-15);
    largest = std::max(largest, std::abs(tilt.y()));
    if (t > step) {
      ts.push_back(t - step);
      dev.push_back(tilt.y() - settled);
    }
  }
  // Bounded: no more than the settled tilt plus the first overshoot (at most the full step again).
  EXPECT_LT(largest, 2.0 * std::abs(settled));
  // Extremes of the ringing.
  std::vector<double> peakT, peakLog;
  for (std::size_t i = 1; i + 1 < dev.size(); ++i) {
    const double m = std::abs(dev[i]);
    if (m > std::abs(dev[i - 1]) && m >= std::abs(dev[i + 1]) && m > 1e-4 * std::abs(settled)) {
      peakT.push_back(ts[i]);
      peakLog.push_back(std::log(m));
    }
  }
  ASSERT_GE(peakT.size(), 5u);
  const double n = static_cast<double>(peakT.size());
  const double mt = std::accumulate(peakT.begin(), peakT.end(), 0.0) / n;
  const double ml = std::accumulate(peakLog.begin(), peakLog.end(), 0.0) / n;
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < peakT.size(); ++i) {
    sxy += (peakT[i] - mt) * (peakLog[i] - ml);
    sxx += (peakT[i] - mt) * (peakT[i] - mt);
  }
  const double w = 2 * std::numbers::pi * 12.0;
  EXPECT_NEAR(-sxy / sxx, 0.25 * w, 0.03 * 0.25 * w);
  // Half a damped period between successive extremes.
  const double wd = w * std::sqrt(1 - 0.25 * 0.25);
  EXPECT_NEAR((peakT.back() - peakT.front()) / (n - 1), std::numbers::pi / wd, 1e-3);
  // The translation settles where the spring holds the sensor against the acceleration.
  EXPECT_NEAR(model.wobbleShift().x(), -0.3 * a / (w * w), 1e-6);
}

// On a fast reaching movement the preset's stiffest excitation keeps the wobble to a few degrees.
TEST(ImuErrors, WobbleStaysBoundedOnAFastReach) {
  const auto traj = makeTrajectory("reaching", TrajectoryOptions{});
  const ArmGeometry geo;
  const Eigen::Vector3d gUp(-9.81, 0, 0);
  const auto truth = [&](double t) {
    const JointMotion m = traj->at(t);
    const auto k = armKinematics<double>(geo, m.th, m.thd, m.thdd, gUp);
    return ImuTruth{k.forearmImu.omega, k.forearmImu.up + k.forearmImu.accel, k.forearmImu.accel};
  };
  ImuSimParams p = bare(100.0);
  p.errors.wobbleFrequencyHz = RealisticBounds::kWobbleMinHz;
  p.errors.wobbleDamping = RealisticBounds::kWobbleDampingMin;
  p.errors.wobbleTiltPerAccel = RealisticBounds::kTiltPerAccelMax;
  p.errors.wobbleTranslationGain = RealisticBounds::kTranslationGainMax;
  ImuErrorModel model(p, 1, 1);
  double largest = 0.0, shift = 0.0;
  for (int i = 0; i <= 3000; ++i) {
    model.reading(i / 100.0, truth);
    largest = std::max(largest, model.wobbleTilt().norm());
    shift = std::max(shift, model.wobbleShift().norm());
  }
  EXPECT_GT(largest, 0.1 * kDeg);  // it does wobble
  EXPECT_LT(largest, 5.0 * kDeg);
  EXPECT_LT(shift, 0.01);  // m
}

// Each sample is taken at stamp + offset + jitter: on the ramp the reading minus its stamp has the
// offset as its mean and the jitter (clipped at 3 sigma) as its spread. n = 10000 samples: the
// tolerances are 4 standard errors.
TEST(ImuErrors, JitterAndClockOffsetHaveTheStatedStatistics) {
  ImuSimParams p = bare(100.0);
  p.errors.clockOffsetS = 0.004;
  p.errors.jitterStdS = 0.0005;
  ImuErrorModel model(p, 11, 1);
  std::vector<double> lag;
  for (int i = 1; i <= 10000; ++i) {
    const double t = i / 100.0;
    lag.push_back(model.reading(t, ramp).gyr.x() - t);
    EXPECT_EQ(model.gyroSampleTime(), model.reading(t, ramp).gyr.x());
  }
  const double n = static_cast<double>(lag.size());
  const double mean = std::accumulate(lag.begin(), lag.end(), 0.0) / n;
  double var = 0.0;
  for (double x : lag) var += (x - mean) * (x - mean);
  var /= n - 1;
  // A standard normal clipped at +-3: E[z^2] = erf(3/sqrt2) - 6 phi(3) + 9 P(|z| > 3).
  const double phi3 = std::exp(-4.5) / std::sqrt(2 * std::numbers::pi);
  const double inside = std::erf(3 / std::sqrt(2.0));
  const double clippedVar = inside - 6 * phi3 + 9 * (1 - inside);
  const double sd = 0.0005 * std::sqrt(clippedVar);
  EXPECT_NEAR(mean, 0.004, 4 * sd / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(var) / sd, 1.0, 4 / std::sqrt(2 * n));
  for (double x : lag) EXPECT_LE(std::abs(x - 0.004), 3 * 0.0005 + 1e-12);
}

// Two IMUs with their own clock offsets in one simulation: the forearm's samples lag the upper
// arm's by the difference, seen on a still-moving shoulder-wheel as the readings' lead.
TEST(ImuErrors, ClockOffsetBetweenImusInTheSimulator) {
  SimulationParams sim = defaultSimulation();
  sim.duration = 2.0;
  sim.kinect.enabled = false;
  for (ImuSimParams* imu : {&sim.upperArm, &sim.forearm}) {
    imu->rateHz = 200.0;
    imu->gyroNoiseStd = imu->accelNoiseStd = 0.0;
  }
  SimulationParams late = sim;
  late.forearm.errors.enabled = true;
  late.forearm.errors.clockOffsetS = 0.01;
  const auto traj = makeTrajectory("multi-joint", TrajectoryOptions{});
  const Recording a = simulateRecording(*traj, sim), b = simulateRecording(*traj, late);
  // b's forearm at stamp t is a's forearm 10 ms (2 rows) later; the upper arm is unchanged.
  for (std::size_t i = 0; i + 2 < a.samples.size(); ++i) {
    EXPECT_LT((b.samples[i].forearm->gyr - a.samples[i + 2].forearm->gyr).norm(), 1e-9);
    EXPECT_EQ(b.samples[i].upperArm->gyr, a.samples[i].upperArm->gyr);
  }
}

TEST(ImuErrors, SlipCreepsAboutTheLongAxis) {
  ImuSimParams p = bare(50.0);
  p.errors.slipMaxRad = 4 * kDeg;
  p.errors.slipTauS = 100.0;
  ImuErrorModel model(p, 1, 1);
  const Eigen::Vector3d f(0, 0, 9.81);  // gravity along the skin's normal, across the long axis y
  for (const double t : {0.0, 50.0, 100.0, 600.0}) {
    const ImuReading r = model.reading(t, constant({0, 0, 0}, f));
    const double psi = 4 * kDeg * (1 - std::exp(-t / 100.0));
    // The sensor turned by psi about y sees the normal tipped towards its x axis.
    EXPECT_NEAR(r.acc.x(), -9.81 * std::sin(psi), 1e-9) << t;
    EXPECT_NEAR(r.acc.z(), 9.81 * std::cos(psi), 1e-9) << t;
    EXPECT_NEAR(r.acc.y(), 0.0, 1e-12);
  }
}

TEST(RealisticSensors, PresetIsDeterministicPerSeedAndInsideItsBounds) {
  using B = RealisticBounds;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    for (int sensor = 0; sensor < 3; ++sensor) {
      Eigen::Vector3d bg, ba, bg2, ba2;
      const ImuErrorParams p = realisticImuErrors(seed, sensor, 90.0, &bg, &ba);
      const ImuErrorParams q = realisticImuErrors(seed, sensor, 90.0, &bg2, &ba2);
      EXPECT_EQ(p.gyroScale, q.gyroScale);
      EXPECT_EQ(p.accelCrossAxis, q.accelCrossAxis);
      EXPECT_EQ(p.wobbleFrequencyHz, q.wobbleFrequencyHz);
      EXPECT_EQ(p.slipMaxRad, q.slipMaxRad);
      EXPECT_EQ(bg, bg2);
      EXPECT_EQ(ba, ba2);
      EXPECT_TRUE(p.enabled);
      EXPECT_NO_THROW(checkImuErrors(p, 90.0, "preset"));
      EXPECT_LE(p.gyroScale.cwiseAbs().maxCoeff(), B::kGyroScale);
      EXPECT_LE(p.accelScale.cwiseAbs().maxCoeff(), B::kAccelScale);
      EXPECT_LE(p.gyroCrossAxis.cwiseAbs().maxCoeff(), B::kGyroCrossAxis);
      EXPECT_LE(p.accelCrossAxis.cwiseAbs().maxCoeff(), B::kAccelCrossAxis);
      EXPECT_LE(p.gyroGSensitivity.cwiseAbs().maxCoeff(), B::kGyroGSensitivity);
      EXPECT_LE(bg.cwiseAbs().maxCoeff(), B::kGyroBias);
      EXPECT_LE(ba.cwiseAbs().maxCoeff(), B::kAccelBias);
      EXPECT_LE(p.gyroBiasPerK.cwiseAbs().maxCoeff(), B::kGyroBiasPerK);
      EXPECT_LE(p.accelBiasPerK.cwiseAbs().maxCoeff(), B::kAccelBiasPerK);
      EXPECT_TRUE(p.gyroBiasWalk >= B::kGyroWalkMin && p.gyroBiasWalk <= B::kGyroWalkMax);
      EXPECT_TRUE(p.accelBiasWalk >= B::kAccelWalkMin && p.accelBiasWalk <= B::kAccelWalkMax);
      EXPECT_TRUE(p.temperatureRiseK >= B::kRiseMinK && p.temperatureRiseK <= B::kRiseMaxK);
      EXPECT_TRUE(p.temperatureTauS >= B::kTempTauMinS && p.temperatureTauS <= B::kTempTauMaxS);
      EXPECT_DOUBLE_EQ(*p.gyroRateHz, 50.0);
      EXPECT_DOUBLE_EQ(*p.accelRateHz, 25.0);
      EXPECT_TRUE(p.jitterStdS >= B::kJitterMinS && p.jitterStdS <= B::kJitterMaxS);
      EXPECT_LE(std::abs(p.clockOffsetS), B::kClockOffsetS);
      EXPECT_EQ(p.gyroRange, B::kGyroRange);
      EXPECT_EQ(p.accelRange, B::kAccelRange);
      EXPECT_EQ(p.gyroLsb, B::kGyroLsb);
      EXPECT_EQ(p.accelLsb, B::kAccelLsb);
      EXPECT_TRUE(p.wobbleFrequencyHz >= B::kWobbleMinHz && p.wobbleFrequencyHz <= B::kWobbleMaxHz);
      EXPECT_TRUE(p.wobbleDamping >= B::kWobbleDampingMin &&
                  p.wobbleDamping <= B::kWobbleDampingMax);
      EXPECT_TRUE(p.wobbleTiltPerAccel >= B::kTiltPerAccelMin &&
                  p.wobbleTiltPerAccel <= B::kTiltPerAccelMax);
      EXPECT_TRUE(p.wobbleTranslationGain >= B::kTranslationGainMin &&
                  p.wobbleTranslationGain <= B::kTranslationGainMax);
      EXPECT_TRUE(std::abs(p.slipMaxRad) >= B::kSlipMinRad &&
                  std::abs(p.slipMaxRad) <= B::kSlipMaxRad);
      EXPECT_TRUE(p.slipTauS >= B::kSlipTauMinS && p.slipTauS <= B::kSlipTauMaxS);
    }
    // Different sensors and seeds draw differently.
    EXPECT_NE(realisticImuErrors(seed, 0, 90.0).gyroScale,
              realisticImuErrors(seed, 1, 90.0).gyroScale);
    EXPECT_NE(realisticImuErrors(seed, 0, 90.0).gyroScale,
              realisticImuErrors(seed + 1, 0, 90.0).gyroScale);
  }
}

// The preset in a whole simulation: the same seed, the same recording; the rows on the 90 Hz
// clock repeat as the internal rates say; the true angles and the Kinect are the ideal run's.
TEST(RealisticSensors, SimulationIsDeterministicHoldsSamplesAndKeepsTheTruth) {
  SimulationParams ideal = defaultSimulation();
  ideal.duration = 20.0;
  ideal.seed = 4;
  for (ImuSimParams* imu : {&ideal.upperArm, &ideal.forearm}) imu->rateHz = 90.0;
  SimulationParams real = ideal;
  applySensorModel(SensorModel::Realistic, real);
  EXPECT_EQ(real.upperArm.rateHz, 90.0);
  EXPECT_TRUE(real.upperArm.errors.enabled && real.forearm.errors.enabled);
  EXPECT_FALSE(real.trunkImu.enabled);
  TrajectoryOptions o;
  o.seed = 4;
  const auto traj = makeTrajectory("multi-joint", o);
  const Recording a = simulateRecording(*traj, ideal), b = simulateRecording(*traj, real),
                  c = simulateRecording(*traj, real);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  ASSERT_EQ(b.samples.size(), c.samples.size());
  int rows = 0, gyroRepeats = 0, accelRepeats = 0;
  const ArmSample* prev = nullptr;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    const ArmSample &x = a.samples[i], &y = b.samples[i], &z = c.samples[i];
    ASSERT_EQ(x.t, y.t);
    EXPECT_EQ(x.trueAngles.has_value(), y.trueAngles.has_value());
    if (x.trueAngles) {
      EXPECT_EQ(*x.trueAngles, *y.trueAngles);
    }
    EXPECT_EQ(x.elbow.has_value(), y.elbow.has_value());
    if (x.elbow) {
      EXPECT_EQ(*x.elbow, *y.elbow);
    }
    if (!y.upperArm) continue;
    EXPECT_EQ(y.upperArm->gyr, z.upperArm->gyr);
    EXPECT_EQ(y.forearm->acc, z.forearm->acc);
    if (prev) {
      ++rows;
      gyroRepeats += y.upperArm->gyr == prev->upperArm->gyr;
      accelRepeats += y.upperArm->acc == prev->upperArm->acc;
    }
    prev = &y;
  }
  EXPECT_NEAR(gyroRepeats / double(rows), 1.0 - 50.0 / 90.0, 0.005);
  EXPECT_NEAR(accelRepeats / double(rows), 1.0 - 25.0 / 90.0, 0.005);
  // A given output rate keeps the ratios: 200 Hz -> 111 Hz gyroscope, 55.6 Hz accelerometer.
  SimulationParams fast = ideal;
  applySensorModel(SensorModel::Realistic, fast, 200.0);
  EXPECT_EQ(fast.forearm.rateHz, 200.0);
  EXPECT_NEAR(*fast.forearm.errors.gyroRateHz, 200.0 * 50 / 90, 1e-9);
  // Ideal leaves everything as it was.
  SimulationParams same = ideal;
  applySensorModel(SensorModel::Ideal, same);
  EXPECT_FALSE(same.upperArm.errors.enabled);
  EXPECT_EQ(same.upperArm.rateHz, 90.0);
}

// A live source joining a shared time base late (SensorStream::skipTo): its first rows already
// hold readings (an accelerometer that has not sampled yet used to read exactly zero).
TEST(RealisticSensors, AStreamThatSkipsAheadHoldsRealReadingsFromItsFirstRow) {
  SimulationParams sim = defaultSimulation();
  sim.duration = 20.0;
  sim.kinect.enabled = false;
  applySensorModel(SensorModel::Realistic, sim);
  const auto traj = makeTrajectory("multi-joint", TrajectoryOptions{});
  SensorStream stream(*traj, sim);
  stream.skipTo(10.013);
  for (int i = 0; i < 10; ++i) {
    const std::optional<ArmSample> row = stream.next();
    ASSERT_TRUE(row && row->upperArm && row->forearm);
    EXPECT_GE(row->t, 10.013);
    // At rest or moving gently, the specific force is near g; a missing sample would read 0.
    EXPECT_NEAR(row->upperArm->acc.norm(), 9.81, 2.0) << row->t;
    EXPECT_NEAR(row->forearm->acc.norm(), 9.81, 2.0) << row->t;
    EXPECT_GT(row->upperArm->gyr.norm(), 0.0) << row->t;
  }
}

TEST(RealisticSensors, ParsesTheModelAndRefusesOthers) {
  EXPECT_EQ(parseSensorModel("ideal"), SensorModel::Ideal);
  EXPECT_EQ(parseSensorModel("realistic"), SensorModel::Realistic);
  for (const char* bad : {"", "Realistic", "bogus", "real"}) {
    try {
      parseSensorModel(bad);
      ADD_FAILURE() << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("'" + std::string(bad) + "'"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("ideal or realistic"), std::string::npos);
    }
  }
}

// Bad parameters are refused by the model and by the simulator, the message naming the parameter.
TEST(ImuErrors, RefusesBadParametersNamingThem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    const char* name;
    void (*set)(ImuErrorParams&, double);
    double value;
  };
  const Case cases[] = {
      {"gyroRateHz", [](ImuErrorParams& e, double v) { e.gyroRateHz = v; }, 0.0},
      {"gyroRateHz", [](ImuErrorParams& e, double v) { e.gyroRateHz = v; }, -5.0},
      {"gyroRateHz", [](ImuErrorParams& e, double v) { e.gyroRateHz = v; }, 120.0},
      {"accelRateHz", [](ImuErrorParams& e, double v) { e.accelRateHz = v; }, nan},
      {"accelRateHz", [](ImuErrorParams& e, double v) { e.accelRateHz = v; }, 90.5},
      {"gyroScale", [](ImuErrorParams& e, double v) { e.gyroScale.y() = v; }, nan},
      {"accelScale", [](ImuErrorParams& e, double v) { e.accelScale.x() = v; }, -2.0},
      {"gyroCrossAxis", [](ImuErrorParams& e, double v) { e.gyroCrossAxis(1, 1) = v; }, 0.01},
      {"accelCrossAxis", [](ImuErrorParams& e, double v) { e.accelCrossAxis(0, 2) = v; }, nan},
      {"gyroGSensitivity", [](ImuErrorParams& e, double v) { e.gyroGSensitivity(2, 0) = v; }, nan},
      {"gyroBiasWalk", [](ImuErrorParams& e, double v) { e.gyroBiasWalk = v; }, -1e-3},
      {"accelBiasWalk", [](ImuErrorParams& e, double v) { e.accelBiasWalk = v; }, nan},
      {"temperatureTauS", [](ImuErrorParams& e, double v) { e.temperatureTauS = v; }, 0.0},
      {"temperatureRiseK", [](ImuErrorParams& e, double v) { e.temperatureRiseK = v; }, nan},
      {"gyroBiasPerK", [](ImuErrorParams& e, double v) { e.gyroBiasPerK.z() = v; }, nan},
      {"jitterStdS", [](ImuErrorParams& e, double v) { e.jitterStdS = v; }, -0.001},
      {"jitterStdS", [](ImuErrorParams& e, double v) { e.jitterStdS = v; }, 0.01},
      {"clockOffsetS", [](ImuErrorParams& e, double v) { e.clockOffsetS = v; }, nan},
      {"gyroRange", [](ImuErrorParams& e, double v) { e.gyroRange = v; }, -1.0},
      {"accelLsb", [](ImuErrorParams& e, double v) { e.accelLsb = v; }, nan},
      {"gyroLsb", [](ImuErrorParams& e, double v) { e.gyroLsb = v; }, -0.001},
      {"wobbleFrequencyHz", [](ImuErrorParams& e, double v) { e.wobbleFrequencyHz = v; }, 0.0},
      {"wobbleDamping", [](ImuErrorParams& e, double v) { e.wobbleDamping = v; }, nan},
      {"wobbleTiltPerAccel", [](ImuErrorParams& e, double v) { e.wobbleTiltPerAccel = v; }, -1.0},
      {"wobbleTranslationGain", [](ImuErrorParams& e, double v) { e.wobbleTranslationGain = v; },
       1.5},
      {"skinNormal", [](ImuErrorParams& e, double v) { e.skinNormal.setConstant(v); }, 0.0},
      {"slipAxis", [](ImuErrorParams& e, double v) { e.slipAxis.x() = v; }, nan},
      {"slipMaxRad", [](ImuErrorParams& e, double v) { e.slipMaxRad = v; }, nan},
      {"slipTauS", [](ImuErrorParams& e, double v) { e.slipTauS = v; }, -10.0},
  };
  const auto traj = makeTrajectory("sinusoid", TrajectoryOptions{});
  for (const Case& c : cases) {
    ImuSimParams imu = bare(90.0);
    c.set(imu.errors, c.value);
    const std::string what = std::string("errors.") + c.name;
    try {
      ImuErrorModel model(imu, 1, 1, "forearm IMU");
      ADD_FAILURE() << c.name << " = " << c.value << " accepted by the model";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("forearm IMU"), std::string::npos) << e.what();
    }
    SimulationParams sim = defaultSimulation();
    sim.duration = 1.0;
    sim.forearm = imu;
    try {
      simulateRecording(*traj, sim);
      ADD_FAILURE() << c.name << " = " << c.value << " accepted by the simulator";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  }
  // A disabled model's parameters are not looked at (the default simulation is untouched).
  SimulationParams sim = defaultSimulation();
  sim.duration = 0.1;
  sim.forearm.errors.gyroRateHz = -1.0;
  EXPECT_NO_THROW(simulateRecording(*traj, sim));
}

}  // namespace
}  // namespace armtrack
