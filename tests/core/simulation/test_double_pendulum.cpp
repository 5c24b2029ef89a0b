// The double pendulum (core/simulation/DoublePendulum.h): its integration conserves energy
// without damping and loses it with damping, its accelerations are the derivatives of its rates,
// its recording carries the rods' rates in its gyroscopes, holds slow sensors' readings, and
// reads as the project's own simulator would read the same motion; hostile parameters are
// refused. And the baseline on it (core/baseline/BaselineStudy.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <set>
#include <stdexcept>

#include "core/baseline/BaselineStudy.h"
#include "core/simulation/DoublePendulum.h"
#include "core/simulation/SensorSimulator.h"

namespace armtrack {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

TEST(DoublePendulum, ConservesEnergyWithoutDamping) {
  PendulumParams p;
  p.pivotDamping = p.hingeDamping = 0.0;
  const DoublePendulum d(p, 20.0);
  const double e0 = d.energy(0.0);
  double worst = 0.0;
  for (double t = 0.0; t <= 20.0; t += 0.0137) worst = std::max(worst, std::abs(d.energy(t) - e0));
  // The swing's energy scale is m g l ~ 2 J: RK4 at 0.1 ms keeps it to far better than 1e-6.
  EXPECT_LT(worst, 1e-7);
}

TEST(DoublePendulum, LosesEnergyWithDamping) {
  PendulumParams p;
  p.pivotDamping = 0.01;
  p.hingeDamping = 0.005;
  const DoublePendulum d(p, 20.0);
  double last = d.energy(0.0);
  for (double t = 0.05; t <= 20.0; t += 0.05) {
    const double e = d.energy(t);
    EXPECT_LE(e, last + 1e-9) << "t = " << t;
    last = e;
  }
  EXPECT_LT(d.energy(20.0), d.energy(0.0) - 0.5);
}

TEST(DoublePendulum, AccelerationsAreTheRatesDerivatives) {
  const DoublePendulum d(PendulumParams{}, 10.0);
  for (double t : {1.5, 3.21, 7.77}) {
    const double h = 1e-5;
    const auto a = d.at(t + h), b = d.at(t - h), s = d.at(t);
    EXPECT_NEAR((a.swingRate - b.swingRate) / (2 * h), s.swingAccel, 1e-4);
    EXPECT_NEAR((a.hingeRate - b.hingeRate) / (2 * h), s.hingeAccel, 1e-4);
    EXPECT_NEAR((a.swing - b.swing) / (2 * h), s.swingRate, 1e-6);
  }
}

TEST(DoublePendulum, HingeBendsBothWaysThroughStraight) {
  const DoublePendulum d(PendulumParams{}, 30.0);
  double lo = 0, hi = 0;
  for (double t = 0; t <= 30.0; t += 0.01) {
    lo = std::min(lo, d.at(t).hinge);
    hi = std::max(hi, d.at(t).hinge);
  }
  EXPECT_LT(lo, -20 * kDegree);
  EXPECT_GT(hi, 20 * kDegree);
}

TEST(DoublePendulum, GyroscopesReadTheRodsRates) {
  PendulumSimParams p;
  p.duration = 5.0;
  const Recording rec = simulatePendulum(p);
  const DoublePendulum d(p.pendulum, p.duration);
  const ElbowModel m(rec.meta.geometry);
  for (const ArmSample& s : rec.samples) {
    const DoublePendulum::State st = d.at(s.t);
    // A planar chain: each rod turns about the one axis normal to the plane.
    EXPECT_NEAR(s.upperArm->gyr.norm(), std::abs(st.swingRate), 1e-9);
    EXPECT_NEAR(s.forearm->gyr.norm(), std::abs(st.swingRate + st.hingeRate), 1e-9);
    // The relative rate about the elbow's axis is the hinge rate (th4 = -hinge).
    const Eigen::Matrix3d r = m.relative(s.trueAngles->coeff(3), 0.0);
    const Eigen::Vector3d rel = s.forearm->gyr - r.transpose() * s.upperArm->gyr;
    EXPECT_NEAR(rel.dot(r.transpose() * m.flexionAxis()), -st.hingeRate, 1e-9);
    EXPECT_NEAR(s.trueAngles->coeff(0), wrapAngle(st.swing), 1e-12);
  }
  // Held still before the release: the accelerometers read g.
  EXPECT_NEAR(rec.samples.front().upperArm->acc.norm(), 9.81, 1e-9);
  EXPECT_NEAR(rec.samples.front().forearm->acc.norm(), 9.81, 1e-9);
}

TEST(DoublePendulum, ReadsAsTheProjectsSimulatorReadsTheSameMotion) {
  PendulumSimParams p;
  p.duration = 4.0;
  p.outputRateHz = 1000.0;
  const Recording mine = simulatePendulum(p);
  const DoublePendulum d(p.pendulum, p.duration);
  SimulationParams sim = defaultSimulation();
  sim.duration = p.duration;
  sim.geometry = pendulumGeometry(p.pendulum);
  sim.kinect.enabled = false;
  for (ImuSimParams* imu : {&sim.upperArm, &sim.forearm})
    imu->gyroNoiseStd = imu->accelNoiseStd = 0;
  const Recording theirs = simulateRecording(PendulumTrajectory(d, 0.0), sim);
  ASSERT_EQ(mine.samples.size(), theirs.samples.size());
  for (std::size_t i = 0; i < mine.samples.size(); ++i) {
    EXPECT_LT((mine.samples[i].upperArm->acc - theirs.samples[i].upperArm->acc).norm(), 1e-9);
    EXPECT_LT((mine.samples[i].forearm->acc - theirs.samples[i].forearm->acc).norm(), 1e-9);
    EXPECT_LT((mine.samples[i].forearm->gyr - theirs.samples[i].forearm->gyr).norm(), 1e-9);
  }
}

TEST(DoublePendulum, SlowSensorsAreHeldOnTheOutputClock) {
  PendulumSimParams p;
  p.duration = 10.0;
  p.outputRateHz = 90.0;
  p.gyroRateHz = 50.0;
  p.accelRateHz = 25.0;
  const Recording rec = simulatePendulum(p);
  ASSERT_EQ(rec.samples.size(), 901u);
  std::set<double> gyros, accels;
  for (const ArmSample& s : rec.samples) {
    gyros.insert(s.forearm->gyr.x());
    accels.insert(s.forearm->acc.x());
  }
  // 9 s of free swing after 1 s held (one reading): 50 and 25 new readings a second.
  EXPECT_NEAR(static_cast<double>(gyros.size()), 9 * 50 + 1, 2);
  EXPECT_NEAR(static_cast<double>(accels.size()), 9 * 25 + 1, 2);
}

TEST(DoublePendulum, ZeroPlacementTurnsOnlyTheModelsAngle) {
  PendulumSimParams p;
  p.duration = 3.0;
  const Recording a = simulatePendulum(p);
  p.zeroOffset = 35 * kDegree;
  const Recording b = simulatePendulum(p);
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    EXPECT_NEAR(wrapAngle(b.samples[i].trueAngles->coeff(3) - a.samples[i].trueAngles->coeff(3)),
                -35 * kDegree, 1e-12);
    // The same rods, the same gyroscopes; gravity and the rods' accelerations only turned.
    EXPECT_LT((a.samples[i].forearm->gyr - b.samples[i].forearm->gyr).norm(), 1e-9);
    EXPECT_NEAR(a.samples[i].forearm->acc.norm(), b.samples[i].forearm->acc.norm(), 1e-9);
  }
}

TEST(DoublePendulum, HostileParametersAreRefused) {
  PendulumParams p;
  p.upperLength = 0.0;
  EXPECT_THROW(DoublePendulum(p, 1.0), std::invalid_argument);
  p = PendulumParams{};
  p.step = 0.0;
  EXPECT_THROW(DoublePendulum(p, 1.0), std::invalid_argument);
  p = PendulumParams{};
  p.hingeDamping = -1.0;
  EXPECT_THROW(DoublePendulum(p, 1.0), std::invalid_argument);
  EXPECT_THROW(DoublePendulum(PendulumParams{}, std::numeric_limits<double>::infinity()),
               std::invalid_argument);
  PendulumSimParams s;
  s.outputRateHz = 0.0;
  EXPECT_THROW(simulatePendulum(s), std::invalid_argument);
  s = PendulumSimParams{};
  s.gyroRateHz = std::nan("");
  EXPECT_THROW(simulatePendulum(s), std::invalid_argument);
  s = PendulumSimParams{};
  s.duration = -1.0;
  EXPECT_THROW(simulatePendulum(s), std::invalid_argument);
}

TEST(BaselineOnThePendulum, TracksTheHingeAndSwingWithIdealSensors) {
  PendulumSimParams p;
  p.duration = 20.0;
  p.outputRateHz = 1000.0;
  const Recording rec = simulatePendulum(p);
  const BaselineRun run = runBaseline(rec, baselineParamsFor(rec.meta));
  EXPECT_GT(run.errors.hinge.count, 18000u);
  EXPECT_LT(run.errors.hinge.rmseDeg(), 0.5);
  EXPECT_LT(run.errors.swing.rmseDeg(), 0.5);
  EXPECT_LT(run.errors.pronation.peakDeg(), 0.01);
}

TEST(BaselineOnThePendulum, NoJumpAtTheReleaseAfterAStillStart) {
  // A second held still gives a second of repeated readings; the first new ones at the release
  // must neither be differenced over the whole second nor correct for all of it.
  PendulumSimParams p;
  p.duration = 5.0;
  p.outputRateHz = 1000.0;
  p.pendulum.swing0 = 20 * kDegree;
  p.pendulum.hinge0 = -20 * kDegree;
  const Recording rec = simulatePendulum(p);
  const BaselineRun run = runBaseline(rec, baselineParamsFor(rec.meta));
  EXPECT_LT(run.errors.hinge.peakDeg(), 1.5);
  EXPECT_LT(run.errors.swing.peakDeg(), 1.5);
}

TEST(BaselineOnThePendulum, HeldReadingsAreTakenAsStale) {
  PendulumSimParams p;
  p.duration = 20.0;
  p.outputRateHz = 90.0;
  p.gyroRateHz = 50.0;
  p.accelRateHz = 25.0;
  const Recording rec = simulatePendulum(p);
  const BaselineRun stale = runBaseline(rec, baselineParamsFor(rec.meta));
  // 19 s of swing at 90 rows a second: 90 - 25 repeated accelerometer rows a second per IMU
  // (and every row of the still second but the first).
  EXPECT_NEAR(static_cast<double>(stale.counters.repeatedAccel), 2 * (19 * 65 + 89), 10);
  EXPECT_NEAR(static_cast<double>(stale.counters.repeatedGyro), 2 * (19 * 40 + 89), 10);
  BaselineParams asGiven = baselineParamsFor(rec.meta);
  asGiven.repeatsAreStale = false;
  const BaselineRun given = runBaseline(rec, asGiven);
  EXPECT_LT(stale.errors.hinge.rmseDeg(), 3.0);
  EXPECT_LT(stale.errors.hinge.rmseDeg(), 0.8 * given.errors.hinge.rmseDeg());
}

TEST(BaselineOnThePendulum, TheRightLeverArmMakesTheZeroIrrelevant) {
  PendulumSimParams p;
  p.duration = 10.0;
  p.outputRateHz = 500.0;
  const Recording straight = simulatePendulum(p);
  const double reference =
      runBaseline(straight, baselineParamsFor(straight.meta)).errors.hinge.rmseDeg();
  p.zeroOffset = 90 * kDegree;
  const Recording turned = simulatePendulum(p);
  BaselineParams told = baselineParamsFor(turned.meta);
  told.elbowFromForearm = pendulumElbowFromForearm(turned.meta.geometry, p.zeroOffset);
  EXPECT_NEAR(runBaseline(turned, told).errors.hinge.rmseDeg(), reference, 1e-6);
}

// The sidecar's mounting put on the rod (mountingOnRod): the sensor is where the sidecar says,
// so the baseline's errors do not depend on the zero.
TEST(BaselineOnThePendulum, AMountingOnTheRodMakesTheZeroIrrelevant) {
  PendulumSimParams p;
  p.duration = 10.0;
  p.outputRateHz = 500.0;
  const Recording straight = simulatePendulum(p);
  const double reference =
      runBaseline(straight, baselineParamsFor(straight.meta)).errors.hinge.rmseDeg();
  for (double zero : {35.0, 90.0, -60.0}) {
    p.zeroOffset = zero * kDegree;
    p.mountingOnRod = true;
    const Recording onRod = simulatePendulum(p);
    // The sidecar's forearm IMU sits where the model's default one does on the rod.
    const ArmGeometry g = onRod.meta.geometry;
    JointVector th = JointVector::Zero();
    th(3) = -0.3;
    JointVector rod = th;
    rod(3) += p.zeroOffset;
    EXPECT_LT((forwardKinematics(g, th).forearmImu.topRightCorner<3, 1>() -
               forwardKinematics(straight.meta.geometry, rod).forearmImu.topRightCorner<3, 1>())
                  .norm(),
              1e-12)
        << "zero " << zero;
    EXPECT_NEAR(runBaseline(onRod, baselineParamsFor(onRod.meta)).errors.hinge.rmseDeg(), reference,
                0.02)
        << "zero " << zero;
  }
}

// Strap wobble: the sensors rock on their straps about axes across the rods' (a rate off the
// hinge's axis), and without it the readings are exactly the ideal ones.
TEST(DoublePendulum, WobbleTurnsTheSensorsOffTheRodsAxes) {
  PendulumSimParams p;
  p.duration = 10.0;
  p.outputRateHz = 200.0;
  const Recording ideal = simulatePendulum(p);
  p.wobbleTiltPerAccel = 0.08 * kDegree;
  p.wobbleTranslationGain = 0.25;
  const Recording wobbly = simulatePendulum(p);
  ASSERT_EQ(ideal.samples.size(), wobbly.samples.size());
  // The ideal forearm gyroscope turns about one fixed axis: the hinge's.
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  for (const ArmSample& s : ideal.samples)
    if (s.forearm->gyr.norm() > axis.norm()) axis = s.forearm->gyr;
  axis.normalize();
  double offAxis = 0.0, alongError = 0.0;  // sums of squares, (rad/s)^2
  for (std::size_t i = 0; i < ideal.samples.size(); ++i) {
    const Eigen::Vector3d& w = wobbly.samples[i].forearm->gyr;
    const Eigen::Vector3d& w0 = ideal.samples[i].forearm->gyr;
    EXPECT_LT((w0 - axis * axis.dot(w0)).norm(), 1e-9);
    offAxis += (w - axis * axis.dot(w)).squaredNorm();
    alongError += std::pow(axis.dot(w - w0), 2);
  }
  const double n = static_cast<double>(ideal.samples.size());
  std::printf("[ measured ] wobble: off-axis rate RMS %.3f rad/s, along-axis error RMS %.3f\n",
              std::sqrt(offAxis / n), std::sqrt(alongError / n));
  EXPECT_GT(std::sqrt(offAxis / n), 0.01);
  EXPECT_LT(std::sqrt(alongError / n), std::sqrt(offAxis / n));
  p.wobbleTiltPerAccel = -1.0;
  EXPECT_THROW(simulatePendulum(p), std::invalid_argument);
}

}  // namespace
}  // namespace armtrack
