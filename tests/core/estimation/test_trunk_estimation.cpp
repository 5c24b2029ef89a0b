// The estimator with a sternum IMU, against the simulator's known trunk and arm angles
// (core/simulation: the trunk leans and turns about the hip following the reaches). What the
// simulation leaves out: a trunk that is not one rigid body turning about a fixed point
// (scapular motion, a spine that bends along its length), straps that slide, sensor bias.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "core/estimation/ArmFilter.h"
#include "core/estimation/RecordingEstimator.h"
#include "core/estimation/TrunkTracker.h"
#include "core/kinematics/Trunk.h"
#include "core/metrics/Accuracy.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

using namespace armtrack;

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

enum class Optics { Kinect, Webcam, None };

std::unique_ptr<Trajectory> reaching(std::uint64_t seed, double peakRateDeg = 90.0) {
  TrajectoryOptions to;
  to.seed = seed;
  to.peakRate = peakRateDeg * kDegree;
  to.peakAccel = 300.0 * kDegree;
  return makeTrajectory("reaching", to);
}

// A leaning patient with a sternum IMU, the IMUs at 200 Hz.
SimulationParams leaningParams(std::uint64_t seed, Side side, Optics optics, double leanDeg) {
  SimulationParams p = defaultSimulation();
  p.duration = 20.0;
  p.seed = seed;
  p.side = side;
  p.upperArm.rateHz = p.forearm.rateHz = 200.0;
  p.trunk.enabled = true;
  p.trunk.leanDeg = leanDeg;
  p.trunkImu.enabled = true;
  p.trunkImu.rateHz = 200.0;
  p.kinect.enabled = optics == Optics::Kinect;
  if (optics == Optics::Webcam) p.webcam.enabled = true;
  return p;
}

Recording leaningSession(std::uint64_t seed, Side side, Optics optics, double leanDeg,
                         double peakRateDeg = 90.0) {
  return simulateRecording(*reaching(seed, peakRateDeg),
                           leaningParams(seed, side, optics, leanDeg));
}

EstimateStats estimateIt(const Recording& rec) {
  return estimateRecording(rec, estimatorParamsFor(rec.meta, EstimateOptions{}));
}

}  // namespace

// Trunk angles under 1 deg RMSE with every optical set-up and both sides (acceptance 1's trunk
// part); measured 0.03-0.15 deg on these seeds.
TEST(TrunkEstimation, TrunkAnglesFollowTheSimulatedLean) {
  for (const Side side : {Side::Right, Side::Left}) {
    for (const Optics optics : {Optics::Kinect, Optics::Webcam, Optics::None}) {
      const Recording rec = leaningSession(61, side, optics, 20.0);
      const EstimateStats st = estimateIt(rec);
      ASSERT_GT(st.trunkTruthCount, 3000u);
      for (int i = 0; i < 3; ++i)
        EXPECT_LT(st.trunkRmseDeg(i), 1.0)
            << "angle " << i << " side " << sideName(side) << " optics " << int(optics);
    }
  }
}

// A slow reach with the trunk leaning 20 deg forward (10 deg sideways and axially): with the
// sternum IMU and a Kinect, every arm angle relative to the thorax within 1 deg RMSE; the same
// recording without the sternum IMU reads the lean as shoulder motion, several degrees off.
TEST(TrunkEstimation, SternumImuKeepsTheArmRelativeToTheThorax) {
  const Recording rec = leaningSession(41, Side::Right, Optics::Kinect, 20.0);
  const EstimateStats with = estimateIt(rec);
  ASSERT_GT(with.truthCount, 3000u);
  for (int j = 0; j < kNumJoints; ++j) EXPECT_LT(with.rmseDeg(j), 1.0) << "joint " << j;

  Recording without = rec;
  without.meta.trunk.reset();
  for (ArmSample& s : without.samples) s.trunk.reset();
  const EstimateStats blind = estimateIt(without);
  EXPECT_GT(blind.rmseDeg.head<3>().maxCoeff(), 3.0);
}

// A filter that has lost the arm starts again from a fit of the last quarter second. While the
// patient leans, that fit has to predict each reading from the trunk's motion as it was then:
// gravity tilted with the lean, the trunk's own rates and the shoulder's acceleration. Fitted in
// the upright frame, the arm came out tilted by the lean: on seed 505 of the acceptance set (IMUs
// only, 420 deg/s, recoveries with the trunk 19 deg forward) the elbow went from 0.2 deg to 10 and
// 17 deg RMSE. These seeds (not that set) recover with the trunk 16-19 deg forward, once with
// the sternum IMU from the first row and once with it silent for the first 0.3 s (the window
// then holds samples fused for a still trunk before the trunk's).
TEST(TrunkEstimation, ARecoveryWhileLeaningFitsTheArmInTheLeaningFrame) {
  int leaningRecoveries = 0;
  for (const double silentSeconds : {0.0, 0.3})
    for (const std::uint64_t seed : {86u, 88u}) {
      const ReachingTrajectory traj(seed, 420.0 * kDegree, 4000.0 * kDegree, 20.0);
      Recording rec = simulateRecording(traj, leaningParams(seed, Side::Right, Optics::None, 20.0));
      for (ArmSample& s : rec.samples)
        if (s.t < silentSeconds) s.trunk.reset();
      auto filter = makeEstimator(recordingParams(rec.meta));
      double sq = 0.0;
      int count = 0;
      for (const ArmSample& s : rec.samples) {
        const UpdateResult r = filter->update(s);
        if (r == UpdateResult::Recovered && s.trueTrunk && (*s.trueTrunk)(0) > 10.0 * kDegree &&
            s.t > 1.0)
          ++leaningRecoveries;
        if (!s.trueAngles || s.t < 1.0 || !filter->initialised()) continue;
        const JointVector e = filter->estimate().th;
        for (int j = 3; j < kNumJoints; ++j) {
          const double d = wrapAngle(e(j) - (*s.trueAngles)(j));
          sq += d * d;
        }
        count += 2;
      }
      ASSERT_GT(count, 6000);
      const double rmse = std::sqrt(sq / count) / kDegree;
      std::printf(
          "[ measured ] seed %lu, sternum silent %.1f s: elbow and pronation RMSE %.2f deg\n",
          static_cast<unsigned long>(seed), silentSeconds, rmse);
      EXPECT_LT(rmse, 0.5) << "seed " << seed;
    }
  EXPECT_GE(leaningRecoveries, 4);  // the case this test is about did happen
}

// Patients' hips are not where the estimator's prior puts them. With the trunk turning about a
// hip 4 cm away from the prior and no optical shoulder (a webcam, or a Kinect whose skeleton
// shoulder is not used), the hip is fitted from the arm's own optical points: the arm stays under
// 1 deg RMSE. With the hip left at its prior the webcam lost the arm (12-17 deg on seeds
// 501-510); measured now 0.3-0.5 deg on seeds 501-510 (none of these seeds).
TEST(TrunkEstimation, AHipAwayFromThePriorIsFittedFromTheArmsPoints) {
  for (const Side side : {Side::Right, Side::Left}) {
    for (const Optics optics : {Optics::Webcam, Optics::Kinect}) {
      for (const std::uint64_t seed : {521u, 522u}) {
        SimulationParams p = leaningParams(seed, side, optics, 20.0);
        p.trunk.swaySeed = seed;
        // 4 cm from the prior, in a different direction for each seed.
        const Eigen::Vector3d away =
            Eigen::Vector3d(1.0, seed == 521u ? 1.0 : -1.0, seed == 521u ? -1.0 : 1.0).normalized();
        p.trunk.hip = defaultHip(side) + 0.04 * away;
        p.kinect.shoulder = false;
        const EstimateStats st = estimateIt(simulateRecording(*reaching(seed), p));
        ASSERT_GT(st.truthCount, 3000u);
        for (int j = 0; j < kNumJoints; ++j)
          EXPECT_LT(st.rmseDeg(j), 1.0)
              << sideName(side) << (optics == Optics::Webcam ? " webcam" : " Kinect") << " seed "
              << seed << " joint " << j;
      }
    }
  }
}

// The tracker alone, against analytic cases: a sternum IMU at rest on a trunk leaning 15 deg
// forward reads gravity tilted by the lean, and the tracker finds the lean from it; a constant
// turn about the vertical is integrated exactly.
TEST(TrunkEstimation, TrackerFindsAStaticLeanAndIntegratesATurn) {
  detail::TrunkTrackerParams p;
  p.mount.imuPosition = {0.10, 0.08, -0.18};
  p.mount.imuRotation << -1, 0, 0, 0, 0, 1, 0, 1, 0;
  {
    detail::TrunkTracker tracker(p);
    const Eigen::Matrix3d r = trunkRotation({15.0 * kDegree, 0.0, 0.0});
    ImuReading at;
    // Specific force at rest: g up, in the IMU's axes, with the trunk leaning.
    at.acc = (r * p.mount.imuRotation).transpose() * p.gUp;
    for (int k = 0; k < 20000; ++k) tracker.addImu(k * 0.005, at);
    const Eigen::Vector3d a = tracker.angles();
    // Gravity cannot tell the lean from the start pose's heading: flexion and lateral bending
    // come out, axial rotation stays where it started.
    EXPECT_NEAR(a(0), 15.0 * kDegree, 0.05 * kDegree);
    EXPECT_NEAR(a(1), 0.0, 0.05 * kDegree);
    EXPECT_NEAR(a(2), 0.0, 0.05 * kDegree);
  }
  {
    detail::TrunkTracker tracker(p);
    ImuReading turning;
    const Eigen::Vector3d omega0 = Eigen::Vector3d(-1.0, 0.0, 0.0) * (10.0 * kDegree);  // about up
    turning.gyr = p.mount.imuRotation.transpose() * omega0;
    turning.acc = p.mount.imuRotation.transpose() * p.gUp;
    // The sternum's centripetal acceleration at 10 deg/s (under 0.01 m/s^2) is left out.
    for (int k = 0; k <= 400; ++k) tracker.addImu(k * 0.005, turning);  // 2 s: 20 deg
    // A right-handed turn about up (-x0) brings z0, the right shoulder, forward: +20 deg of axial
    // rotation in the patient's terms.
    EXPECT_NEAR(tracker.angles()(2), 20.0 * kDegree, 0.1 * kDegree);
    EXPECT_NEAR(tracker.angles()(0), 0.0, 0.1 * kDegree);
  }
}

// The estimate's output carries the trunk only for recordings that have one.
TEST(TrunkEstimation, RowsCarryTrunkAnglesOnlyWithATrunkImu) {
  const Recording rec = leaningSession(43, Side::Right, Optics::Kinect, 10.0);
  EstimateCallbacks cb;
  int withTrunk = 0, rows = 0;
  cb.row = [&](const EstimateRow& r) {
    ++rows;
    withTrunk += std::isfinite(r.trunk(0)) && std::isfinite(r.trunkSd(0));
  };
  estimateRecording(rec, estimatorParamsFor(rec.meta, EstimateOptions{}), cb);
  EXPECT_EQ(withTrunk, rows);

  Recording still = rec;
  still.meta.trunk.reset();
  for (ArmSample& s : still.samples) s.trunk.reset(), s.shoulder.reset();
  withTrunk = rows = 0;
  estimateRecording(still, estimatorParamsFor(still.meta, EstimateOptions{}), cb);
  EXPECT_GT(rows, 0);
  EXPECT_EQ(withTrunk, 0);
}

// Without a sternum IMU, a Kinect that reports the shoulder: the moving trunk is reported
// (status 4) on at least 90 % of the rows where it is more than 5 deg from upright, and never on
// a still trunk (acceptance 2, the estimate's part).
TEST(TrunkEstimation, AMovingTrunkWithoutASternumImuIsReported) {
  for (const std::uint64_t seed : {71u, 72u, 73u}) {
    for (const double lean : {0.0, 8.0, 20.0}) {
      const auto traj = reaching(seed);
      SimulationParams p = defaultSimulation();
      p.duration = 20.0;
      p.seed = seed;
      p.upperArm.rateHz = p.forearm.rateHz = 200.0;
      p.trunk.enabled = lean > 0.0;
      p.trunk.leanDeg = lean;
      p.kinect.shoulder = true;
      const Recording rec = simulateRecording(*traj, p);
      std::size_t beyond = 0, reported = 0, flagged = 0, rows = 0;
      std::size_t i = 0;
      EstimateCallbacks cb;
      // Rows come in sample order; find each row's sample by time to read its true trunk.
      cb.row = [&](const EstimateRow& r) {
        while (i < rec.samples.size() && rec.samples[i].t < r.t) ++i;
        ++rows;
        flagged += r.status == kStatusTrunkMoved;
        const ArmSample& s = rec.samples[i];
        if (s.trueTrunk && s.trueTrunk->cwiseAbs().maxCoeff() > 5.0 * kDegree && r.t > 1.0) {
          ++beyond;
          reported += r.status == kStatusTrunkMoved;
        }
      };
      const EstimateStats st =
          estimateRecording(rec, estimatorParamsFor(rec.meta, EstimateOptions{}), cb);
      ASSERT_GT(rows, 3000u);
      if (lean == 0.0) {
        EXPECT_EQ(flagged, 0u) << "seed " << seed;
        EXPECT_TRUE(st.trunkMovedSpans.empty());
      } else {
        ASSERT_GT(beyond, 200u) << "seed " << seed << " lean " << lean;
        EXPECT_GE(double(reported), 0.9 * double(beyond)) << "seed " << seed << " lean " << lean;
        EXPECT_FALSE(st.trunkMovedSpans.empty());
      }
    }
  }
}
