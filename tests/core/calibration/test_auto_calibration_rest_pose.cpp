// The automatic calibration's rest pose (issue 27, acceptance 1; docs/calibration.md, "The rest
// pose"): the forearm sensor's roll about the forearm, which no movement can tell from a
// pronation offset, from the rests in the start pose the patient is told to take (upper arm
// hanging, elbow at a right angle, thumb up). Against simulated truth: a patient's session
// (SessionTrajectory, resting in that pose with a patient's scatter of up to 3 deg per joint),
// the realistic sensor preset (docs/simulation.md), both straps turned at random by up to 30 deg
// about every axis, the sidecar's lever arms off by up to 5 cm, 75 s, default settings, no
// calibration file. Each case is run with the rest pose and without it (the automatic path
// before it): without, the forearm's roll stays the sidecar's and pronation is off by the strap's
// roll. A rest with the arm raised, or with the hand flat (palm down), is not taken for the pose.
// Seeds 2701-2705 were not used while choosing the tolerances (they were set beforehand).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include "core/calibration/AutoCalibration.h"
#include "core/calibration/MovementCalibration.h"
#include "core/estimation/ArmFilter.h"
#include "core/metrics/Accuracy.h"
#include "core/simulation/ImuErrors.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "tests/support/StrapsAndRests.h"

namespace armtrack {
namespace {

constexpr double kDuration = 75.0;  // s
constexpr double kFrom = 30.0;      // s: errors are tallied from here on

struct Case {
  Recording withKinect, imusOnly;
  Eigen::Matrix3d upperTurn, forearmTurn;
};

/// A recording of `traj` with realistic sensors, straps turned up to 30 deg, the sidecar's lever
/// arms off by up to 5 cm along the segments and 2 cm across.
Case makeCase(const Trajectory& traj, std::uint64_t seed, Side side = Side::Right) {
  SimulationParams sp = defaultSimulation();
  sp.duration = kDuration;
  sp.seed = seed;
  sp.side = side;
  sp.kinect.enabled = true;
  applySensorModel(SensorModel::Realistic, sp);
  std::mt19937_64 rng(seed * 7919 + 29);
  Case c;
  c.upperTurn = test::strapTurn(rng, 30 * kDeg);
  c.forearmTurn = test::strapTurn(rng, 30 * kDeg);
  sp.upperArm.misalignment = c.upperTurn;
  sp.forearm.misalignment = c.forearmTurn;
  c.withKinect = simulateRecording(traj, sp);
  std::uniform_real_distribution<double> along(-0.05, 0.05), across(-0.02, 0.02);
  ArmGeometry& g = c.withKinect.meta.geometry;
  g.lu3 += along(rng);
  g.lu5 = std::max(0.005, g.lu5 + across(rng));
  g.lf6 += along(rng);
  g.lf8 = std::max(0.005, g.lf8 + across(rng));
  c.imusOnly = c.withKinect;
  for (ArmSample& s : c.imusOnly.samples) {
    s.elbow.reset();
    s.wrist.reset();
    s.shoulder.reset();
  }
  return c;
}

constexpr std::uint64_t kFirstSeed = 2701, kLastSeed = 2705;

/// The sessions of the seeds, simulated once for both tests.
const Case& sessionCase(std::uint64_t seed) {
  static std::map<std::uint64_t, Case> cases;
  auto it = cases.find(seed);
  if (it == cases.end()) {
    const SessionTrajectory traj(seed, 150 * kDeg, 1500 * kDeg, kDuration);
    it = cases.emplace(seed, makeCase(traj, seed)).first;
  }
  return it->second;
}

double angleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle() / kDeg;
}

/// The forearm strap's roll about the forearm (the model IMU's y axis) left after the fit (deg).
double rollLeftDeg(const Eigen::Matrix3d& fitted, const Eigen::Matrix3d& truth) {
  const Eigen::Matrix3d d = fitted * truth.transpose();
  return std::atan2(d(0, 2) - d(2, 0), d(0, 0) + d(2, 2)) / kDeg;
}

const MovementParameter* roll(const MovementCalibration& m) {
  for (const MovementParameter& p : m.parameters)
    if (p.name == "forearm sensor roll about the forearm") return &p;
  return nullptr;
}

/// RMSE per joint after kFrom (deg), estimating with `calibration` applied (when given).
JointVector rmseWith(const Recording& rec, const std::optional<Calibration>& calibration) {
  Recording used = rec;
  if (calibration) applyCalibration(*calibration, used);
  auto f = makeEstimator(recordingParams(used.meta));
  ErrorAccumulator err;
  for (const ArmSample& s : used.samples) {
    const UpdateResult r = f->update(s);
    if (hasEstimate(r) && s.trueAngles && s.t >= kFrom) err.add(f->estimate().th, *s.trueAngles);
  }
  EXPECT_GT(err.count(), 2000u);
  return err.rmse() / kDeg;
}

// The forearm strap's roll from the rests in the start pose: the whole forearm strap rotation
// within 3 deg; without the rest pose the roll is the strap's own (up to 30 deg) and named not
// observable.
TEST(AutoCalibrationRestPose, RecoversTheForearmRollFromTheStartPose) {
  double worstRollWithout = 0.0;
  for (std::uint64_t seed = kFirstSeed; seed <= kLastSeed; ++seed) {
    SCOPED_TRACE(seed);
    const Case& c = sessionCase(seed);
    Recording window = c.imusOnly;
    std::erase_if(window.samples, [](const ArmSample& s) { return s.t > 60.0; });
    MovementCalibrationParams with, without;
    with.expectedRestPose = protocolStartPose();
    const MovementCalibration a = calibrateFromMovement(window, with);
    const MovementCalibration b = calibrateFromMovement(window, without);
    const double rollWith = rollLeftDeg(a.forearmMounting, c.forearmTurn);
    const double rollWithout = rollLeftDeg(b.forearmMounting, c.forearmTurn);
    std::printf(
        "[ measured ] seed %llu forearm strap: roll left %.1f deg with the rest pose (%d of %d "
        "rests taken; whole turn left %.1f), %.1f without (whole %.1f); upper-arm strap %.1f\n",
        static_cast<unsigned long long>(seed), rollWith, a.poseRests, a.rests,
        angleDeg(a.forearmMounting, c.forearmTurn), rollWithout,
        angleDeg(b.forearmMounting, c.forearmTurn), angleDeg(a.upperMounting, c.upperTurn));
    EXPECT_TRUE(a.rollFromPose);
    EXPECT_GE(a.poseRests, 3);
    EXPECT_LT(std::abs(rollWith), 3.0);
    ASSERT_NE(roll(a), nullptr);
    EXPECT_TRUE(roll(a)->observable);
    EXPECT_TRUE(roll(a)->excited);
    EXPECT_GT(roll(a)->sd, 0.0);
    EXPECT_LT(roll(a)->sd, 3.0);
    EXPECT_NE(formatMovementReport(a).find("rest(s) in the start pose"), std::string::npos);
    ASSERT_NE(roll(b), nullptr);
    EXPECT_FALSE(b.rollFromPose);
    EXPECT_FALSE(roll(b)->observable);
    worstRollWithout = std::max(worstRollWithout, std::abs(rollWithout));
  }
  EXPECT_GT(worstRollWithout, 10.0);  // the straps' rolls are large enough to matter here
}

// Estimating with the automatic calibration (fitted on the IMUs, as the live session does): the
// joints after 30 s, with a Kinect and IMUs only, against the same automatic path without the
// rest pose. Pronation: within 3 deg on every seed (1.2-2.5 measured; 3.5-31 without), a third of
// the error without it at most over the seeds; the other joints as without it (the roll moves
// pronation only). Issue 27's 2 deg is not met on every seed: what is left is the forearm
// sensor's tilt and the realistic sensors' errors, not the roll.
TEST(AutoCalibrationRestPose, PronationFollowsWithTheForearmRoll) {
  const FilterParamsFor paramsFor = [](const RecordingMeta& m) { return recordingParams(m); };
  for (const bool kinect : {true, false}) {
    double sumWith = 0.0, sumWithout = 0.0;
    for (std::uint64_t seed = kFirstSeed; seed <= kLastSeed; ++seed) {
      SCOPED_TRACE(::testing::Message() << "seed " << seed << (kinect ? ", Kinect" : ", IMUs"));
      const Case& c = sessionCase(seed);
      AutoCalibrationParams with, without;
      without.expectedRestPose.reset();
      static std::map<std::uint64_t, std::pair<AutoCalibrationResult, AutoCalibrationResult>> fits;
      if (!fits.contains(seed))
        fits[seed] = {autoCalibrate(c.imusOnly, paramsFor, with),
                      autoCalibrate(c.imusOnly, paramsFor, without)};
      const auto& [rw, ro] = fits[seed];
      const Recording& rec = kinect ? c.withKinect : c.imusOnly;
      const JointVector ew = rmseWith(rec, rw.calibration), eo = rmseWith(rec, ro.calibration);
      std::printf(
          "[ measured ] seed %llu %-9s RMSE after 30 s (deg, th0 th1 th2 th4 th5): with the rest "
          "pose %.1f %.1f %.1f %.1f %.1f | without %.1f %.1f %.1f %.1f %.1f\n",
          static_cast<unsigned long long>(seed), kinect ? "Kinect" : "IMUs only", ew(0), ew(1),
          ew(2), ew(3), ew(4), eo(0), eo(1), eo(2), eo(3), eo(4));
      if (kinect) std::printf("  %s\n", rw.line.c_str());
      EXPECT_EQ(rw.outcome, AutoCalibrationResult::Outcome::Applied) << rw.line;
      EXPECT_TRUE(rw.forearmRollSeen);
      EXPECT_FALSE(ro.forearmRollSeen);
      EXPECT_NE(rw.line.find("rest(s) in the start pose"), std::string::npos) << rw.line;
      EXPECT_EQ(ro.line.find("rest(s) in the start pose"), std::string::npos) << ro.line;
      EXPECT_LT(ew(4), 3.0);
      for (int j = 0; j < 4; ++j) EXPECT_LT(ew(j), eo(j) + 0.3) << "joint " << j;
      sumWith += ew(4);
      sumWithout += eo(4);
    }
    EXPECT_LT(sumWith, sumWithout / 3.0) << (kinect ? "Kinect" : "IMUs only");
  }
}

// A rest in another pose is not taken for the start pose: the arm raised forward 60 deg (elbow
// at a right angle, thumb up), and the hand flat, palm down (forearm turned 80 deg from thumb
// up). The roll stays the sidecar's and the report says it was not observable.
TEST(AutoCalibrationRestPose, ARestInAnotherPoseIsNotTakenForIt) {
  const ReachingTrajectory reaches(2711, 150 * kDeg, 1500 * kDeg, kDuration);
  JointVector raised = protocolStartPose(), palmDown = protocolStartPose();
  raised(0) = 60 * kDeg;
  palmDown(4) = 80 * kDeg;
  for (const auto& [what, pose] :
       {std::pair{"arm raised", raised}, std::pair{"palm down", palmDown},
        std::pair{"start pose", protocolStartPose()}}) {
    SCOPED_TRACE(what);
    const test::RestThenMove traj(reaches, pose, 4.0);
    const Case c = makeCase(traj, 2711);
    Recording window = c.imusOnly;
    std::erase_if(window.samples, [](const ArmSample& s) { return s.t > 60.0; });
    MovementCalibrationParams p;
    p.expectedRestPose = protocolStartPose();
    const MovementCalibration m = calibrateFromMovement(window, p);
    std::printf("[ measured ] rest %s: %d of %d rests taken, forearm strap error %.1f deg\n", what,
                m.poseRests, m.rests, angleDeg(m.forearmMounting, c.forearmTurn));
    ASSERT_NE(roll(m), nullptr);
    const bool isPose = std::string(what) == "start pose";
    EXPECT_EQ(m.rollFromPose, isPose);
    EXPECT_EQ(roll(m)->observable, isPose);
    if (isPose) {
      EXPECT_LT(angleDeg(m.forearmMounting, c.forearmTurn), 3.0);
      continue;
    }
    bool said = false;
    for (const std::string& w : m.warnings)
      said = said || w.find("roll about the forearm was not observable") != std::string::npos;
    EXPECT_TRUE(said) << formatMovementReport(m);
    EXPECT_NE(formatMovementReport(m).find("no rest was in the start pose"), std::string::npos);
  }
}

// A live refit that did not see the forearm's roll is not applied over a calibration in use that
// has it from the start pose (it would put the sidecar's roll back); the same fit is applied over
// one that does not.
TEST(AutoCalibrationRestPose, ARefitWithoutTheRollDoesNotReplaceOneWithIt) {
  const ReachingTrajectory reaches(2712, 150 * kDeg, 1500 * kDeg, kDuration);
  JointVector raised = protocolStartPose();
  raised(0) = 60 * kDeg;
  const test::RestThenMove traj(reaches, raised, 4.0);
  const Case c = makeCase(traj, 2712);
  Recording window = c.imusOnly;
  std::erase_if(window.samples, [](const ArmSample& s) { return s.t > 60.0; });
  Calibration inUse;  // the sidecar's mounting, as if fitted with the roll
  inUse.geometry = window.meta.geometry;
  const FilterParamsFor paramsFor = [](const RecordingMeta& m) { return recordingParams(m); };
  AutoCalibrationParams seen, notSeen;
  seen.currentRollSeen = true;
  const AutoCalibrationResult kept = autoCalibrate(window, paramsFor, seen, &inUse);
  const AutoCalibrationResult replaced = autoCalibrate(window, paramsFor, notSeen, &inUse);
  std::printf("[ measured ] %s\n", kept.line.c_str());
  EXPECT_FALSE(kept.forearmRollSeen);
  EXPECT_EQ(kept.outcome, AutoCalibrationResult::Outcome::NotApplied) << kept.line;
  EXPECT_FALSE(kept.calibration.has_value());
  EXPECT_NE(kept.line.find("forearm roll not observable"), std::string::npos) << kept.line;
  EXPECT_NE(kept.line.find("has the forearm's roll from the start pose"), std::string::npos)
      << kept.line;
  EXPECT_EQ(replaced.outcome, AutoCalibrationResult::Outcome::Applied) << replaced.line;
}

// A left arm: fitted on its right-arm twin (the readings mirrored), the rests in the start pose
// give its forearm's roll the same way.
TEST(AutoCalibrationRestPose, TheLeftArmsRollToo) {
  const SessionTrajectory traj(2706, 150 * kDeg, 1500 * kDeg, kDuration);
  const Case c = makeCase(traj, 2706, Side::Left);
  Recording window = c.imusOnly;
  std::erase_if(window.samples, [](const ArmSample& s) { return s.t > 60.0; });
  MovementCalibrationParams p;
  p.expectedRestPose = protocolStartPose();
  const MovementCalibration m = calibrateFromMovement(window, p);
  const double left = rollLeftDeg(m.forearmMounting, c.forearmTurn);
  std::printf("[ measured ] left arm: %d of %d rests taken, roll left %.1f deg (whole %.1f)\n",
              m.poseRests, m.rests, left, angleDeg(m.forearmMounting, c.forearmTurn));
  EXPECT_EQ(m.calibration.side, Side::Left);
  EXPECT_TRUE(m.rollFromPose);
  EXPECT_LT(std::abs(left), 3.0);
}

}  // namespace
}  // namespace armtrack
