// The estimator on sensors as real ones are (issue 27), against simulated truth on a patient's
// session (SessionTrajectory: 3 s still, then reaches from a resting hand and back with 1-3 s
// rests), Kinect at 30 Hz, default settings:
// - a gyroscope bias of 3 deg/s per axis, as MEMS parts have at switch-on, is found at the rests
//   and removed: the angles come back to what an unbiased sensor gives, where the bias left in
//   costs degrees;
// - a logger that repeats each sensor's last sample (a 50 Hz gyroscope and a 25 Hz
//   accelerometer on a 90 Hz clock) is not taken for new measurements.
// Each compares the default filter with the same filter with the feature off, on the same data.
// The simulation leaves out every other real-sensor error (docs/simulation.md's preset has them;
// docs/estimator.md gives the figures with all of them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "core/estimation/ArmFilter.h"
#include "core/metrics/Accuracy.h"
#include "core/simulation/ImuErrors.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

constexpr double kFrom = 10.0;  // s: errors are tallied from here on
// The sessions these figures were measured on (and docs/estimator.md's): resting with the hand on
// the lap. In the start pose (SessionTrajectory's default rest since the automatic calibration
// asks for it) seed 714's humeral rotation came out 0.46 deg with the repeated samples left out
// against 0.26 deg fused as new.
const SessionRest kRest = SessionRest::handOnLap();

SimulationParams session(std::uint64_t seed, double duration, double imuRate) {
  SimulationParams sp = defaultSimulation();
  sp.duration = duration;
  sp.seed = seed;
  sp.upperArm.rateHz = sp.forearm.rateHz = imuRate;
  sp.kinect.enabled = true;
  return sp;
}

struct Result {
  JointVector rmse = JointVector::Zero();  // deg
  EstimatorCounters counters;
};

Result run(const Recording& rec, const EstimatorParams& p) {
  auto f = makeEstimator(p);
  ErrorAccumulator err;
  for (const ArmSample& s : rec.samples) {
    f->update(s);
    if (s.trueAngles && s.t >= kFrom && f->initialised()) err.add(f->estimate().th, *s.trueAngles);
  }
  return {err.rmse() / kDeg, f->counters()};
}

TEST(RealSensors, AGyroscopeBiasIsFoundAtRestAndRemoved) {
  for (std::uint64_t seed : {711u, 712u}) {
    SCOPED_TRACE(seed);
    const SessionTrajectory traj(seed, 150 * kDeg, 1500 * kDeg, 40.0, 3.0, kRest);
    SimulationParams sp = session(seed, 40.0, 200.0);
    const Recording clean = simulateRecording(traj, sp);
    const Eigen::Vector3d biasUa(3 * kDeg, -3 * kDeg, 3 * kDeg),
        biasFa(-3 * kDeg, 3 * kDeg, 3 * kDeg);
    sp.upperArm.gyroBias = biasUa;
    sp.forearm.gyroBias = biasFa;
    const Recording biased = simulateRecording(traj, sp);

    const EstimatorParams p = recordingParams(biased.meta);
    EstimatorParams off = p;
    off.gyroBiasAtRest = false;
    const Result truth = run(clean, p), on = run(biased, p), left = run(biased, off);
    std::printf(
        "seed %llu RMSE (deg): unbiased %.2f %.2f %.2f %.2f %.2f | removed %.2f %.2f %.2f "
        "%.2f %.2f | left in %.2f %.2f %.2f %.2f %.2f\n",
        static_cast<unsigned long long>(seed), truth.rmse(0), truth.rmse(1), truth.rmse(2),
        truth.rmse(3), truth.rmse(4), on.rmse(0), on.rmse(1), on.rmse(2), on.rmse(3), on.rmse(4),
        left.rmse(0), left.rmse(1), left.rmse(2), left.rmse(3), left.rmse(4));
    // The bias found: within 0.1 deg/s of the simulated one on every axis.
    ASSERT_GT(on.counters.restWindows[0], 5u);
    ASSERT_GT(on.counters.restWindows[1], 5u);
    EXPECT_LT((on.counters.restBias[0] - biasUa).cwiseAbs().maxCoeff(), 0.1 * kDeg);
    EXPECT_LT((on.counters.restBias[1] - biasFa).cwiseAbs().maxCoeff(), 0.1 * kDeg);
    for (int j = 0; j < kNumJoints; ++j) {
      // Removed: within 0.3 deg of the unbiased sensor's error; left in: at least twice as far.
      EXPECT_LT(on.rmse(j), truth.rmse(j) + 0.3) << "joint " << j;
      EXPECT_GT(left.rmse(j) - truth.rmse(j), 2.0 * std::max(0.0, on.rmse(j) - truth.rmse(j)))
          << "joint " << j;
    }
    EXPECT_GT(left.rmse.maxCoeff(), 1.0);  // the bias left in costs degrees
  }
}

TEST(RealSensors, ALoggersRepeatedSamplesAreNotTakenForNewOnes) {
  for (std::uint64_t seed : {713u, 714u}) {
    SCOPED_TRACE(seed);
    const SessionTrajectory traj(seed, 150 * kDeg, 1500 * kDeg, 40.0, 3.0, kRest);
    SimulationParams sp = session(seed, 40.0, 90.0);
    for (ImuSimParams* imu : {&sp.upperArm, &sp.forearm}) {
      imu->errors.enabled = true;
      imu->errors.gyroRateHz = 50.0;
      imu->errors.accelRateHz = 25.0;
    }
    const Recording rec = simulateRecording(traj, sp);
    const EstimatorParams p = recordingParams(rec.meta);
    EstimatorParams asNew = p;
    asNew.plausibility.heldSeconds = 0.0;
    const Result held = run(rec, p), fused = run(rec, asNew);
    std::printf(
        "seed %llu RMSE (deg): held left out %.2f %.2f %.2f %.2f %.2f | fused as new "
        "%.2f %.2f %.2f %.2f %.2f\n",
        static_cast<unsigned long long>(seed), held.rmse(0), held.rmse(1), held.rmse(2),
        held.rmse(3), held.rmse(4), fused.rmse(0), fused.rmse(1), fused.rmse(2), fused.rmse(3),
        fused.rmse(4));
    // 4 of every 9 gyroscope rows and 13 of every 18 accelerometer rows repeat.
    const GateCounters& g = held.counters.implausible;
    const double rows = static_cast<double>(rec.samples.size());
    EXPECT_NEAR(static_cast<double>(g.held[0]) / rows, 4.0 / 9.0, 0.02);
    EXPECT_NEAR(static_cast<double>(g.held[1]) / rows, 13.0 / 18.0, 0.02);
    EXPECT_EQ(g.total(), 0u);
    // Summed over the joints, a quarter less error at least (about half on seeds 701-703); no
    // joint worse. (The shoulder's rotation, th2, rests mostly on the Kinect and gains least.)
    EXPECT_LT(held.rmse.sum(), 0.75 * fused.rmse.sum());
    for (int j = 0; j < kNumJoints; ++j) {
      EXPECT_LT(held.rmse(j), fused.rmse(j) + 0.02) << "joint " << j;
      EXPECT_LT(held.rmse(j), 0.4) << "joint " << j;
    }
  }
}

}  // namespace
}  // namespace armtrack
