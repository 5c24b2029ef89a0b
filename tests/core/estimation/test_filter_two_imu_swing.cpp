// The paper's body-acceleration case (section 3.3, Table 6: 90 deg shoulder flexion at 1 Hz,
// Table 5 noise, 1 kHz) on the whole arm: both IMUs, all five joints free, elbow straight, no
// optical data, default settings. Table 6 was simulated on one segment; here the elbow and the
// shoulder's other two joints can take up what the accelerometer model gets wrong, and the
// forearm strap, 0.42 m from the shoulder, reads 4 g of centripetal acceleration.
// - Every method stays on the arm (no joint off by a mirrored branch) and A < B < C on shoulder
//   flexion. Method B is within twice the paper's 2.51 deg, Method C within a factor of two of
//   its 7.39 deg (from 3.7 to 14.8 deg).
// - Every method never reports a joint outside the anatomical limits.
// Noise seeds 4 and 5 were not used when the defaults were chosen; Methods B and C's kinematic
// start-up was developed on 4-9 and is checked on 14 and 15 as well. Truth: the simulation.
#include <gtest/gtest.h>

#include <cstdio>

#include "core/estimation/ArmFilter.h"
#include "core/metrics/Accuracy.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

struct SwingResult {
  JointVector rmse = JointVector::Zero();  // deg, from 1 s
  int outsideLimits = 0;                   // estimates outside the anatomical limits
};

SwingResult swing(MeasurementModel model, FilterKind kind, std::uint64_t seed) {
  SinusoidTrajectory traj;
  traj.amplitude(0) = 90 * kDeg;
  traj.frequency.setZero();
  traj.frequency(0) = 1.0;
  SimulationParams sim = defaultSimulation();
  sim.duration = 10.0;
  sim.seed = seed;
  sim.upperArm.rateHz = sim.forearm.rateHz = 1000.0;
  sim.kinect.enabled = false;
  sim.webcam.enabled = false;
  const Recording rec = simulateRecording(traj, sim);
  EstimatorParams p = recordingParams(rec.meta);
  p.model = model;
  p.filter = kind;
  auto filter = makeEstimator(p);
  ErrorAccumulator acc;
  SwingResult r;
  for (const ArmSample& s : rec.samples) {
    if (!hasEstimate(filter->update(s))) continue;
    const JointVector th = filter->estimate().th;
    for (int j = 0; j < kNumJoints; ++j)
      if (th(j) < p.jointLower(j) - 1e-9 || th(j) > p.jointUpper(j) + 1e-9) ++r.outsideLimits;
    if (s.trueAngles && s.t >= 1.0) acc.add(th, *s.trueAngles);
  }
  r.rmse = acc.rmse() / kDeg;
  return r;
}

class TwoImuSwing : public testing::TestWithParam<FilterKind> {};

TEST_P(TwoImuSwing, EveryMethodStaysOnTheArmAndAIsBestCWorst) {
  for (std::uint64_t seed : {4u, 5u, 14u, 15u}) {
    const SwingResult a = swing(MeasurementModel::AccelGyro, GetParam(), seed);
    const SwingResult b = swing(MeasurementModel::AugmentedBodyAccel, GetParam(), seed);
    const SwingResult c = swing(MeasurementModel::InclinometerGyro, GetParam(), seed);
    std::printf(
        "[ measured ] seed %lu, flexion RMSE (worst joint) in deg: A %.2f (%.2f), B %.2f (%.2f), "
        "C %.2f (%.2f)\n",
        static_cast<unsigned long>(seed), a.rmse(0), a.rmse.maxCoeff(), b.rmse(0),
        b.rmse.maxCoeff(), c.rmse(0), c.rmse.maxCoeff());
    EXPECT_LT(a.rmse(0), b.rmse(0)) << "seed " << seed;
    EXPECT_LT(b.rmse(0), c.rmse(0)) << "seed " << seed;
    EXPECT_LT(b.rmse(0), 2.0 * 2.51) << "Method B, seed " << seed << ": " << b.rmse.transpose();
    EXPECT_GT(c.rmse(0), 7.39 / 2.0) << "Method C, seed " << seed << ": " << c.rmse.transpose();
    EXPECT_LT(c.rmse(0), 2.0 * 7.39) << "Method C, seed " << seed << ": " << c.rmse.transpose();
    // A mirrored branch is tens of degrees off on several joints. C's elbow takes up the forearm's
    // unmodelled body acceleration: about 6.6 deg.
    EXPECT_LT(a.rmse.maxCoeff(), 2.0) << "Method A, seed " << seed << ": " << a.rmse.transpose();
    EXPECT_LT(b.rmse.maxCoeff(), 3.0) << "Method B, seed " << seed << ": " << b.rmse.transpose();
    EXPECT_LT(c.rmse.maxCoeff(), 9.0) << "Method C, seed " << seed << ": " << c.rmse.transpose();
  }
}

TEST_P(TwoImuSwing, NoMethodLeavesTheAnatomicalRange) {
  for (MeasurementModel m : {MeasurementModel::AccelGyro, MeasurementModel::AugmentedBodyAccel,
                             MeasurementModel::InclinometerGyro}) {
    const SwingResult r = swing(m, GetParam(), 4);
    EXPECT_EQ(r.outsideLimits, 0) << methodName(m);
  }
}

INSTANTIATE_TEST_SUITE_P(Filters, TwoImuSwing, testing::Values(FilterKind::Ekf, FilterKind::Ukf),
                         [](const testing::TestParamInfo<FilterKind>& i) {
                           return std::string(i.param == FilterKind::Ekf ? "Ekf" : "Ukf");
                         });

}  // namespace
}  // namespace armtrack
