// Calibration from ordinary movement (core/calibration/MovementCalibration.h) against simulated
// truth: straps turned at random by up to 30 deg about every axis, lever arms off by up to 5 cm,
// ideal and realistic sensors; planar movement; hostile input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include "core/calibration/Calibrator.h"
#include "core/calibration/MovementCalibration.h"
#include "core/calibration/MovementFit.h"
#include "core/simulation/DoublePendulum.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "tests/support/StrapsAndRests.h"

namespace armtrack {
namespace {

struct Case {
  Recording rec;
  Eigen::Matrix3d rotUa, rotFa;
  Eigen::Vector3d leverUa, leverFa;  // truth, segment frames (m)
};

Case makeCase(const Trajectory& motion, std::uint64_t seed, bool realistic, double seconds = 60.0,
              Side side = Side::Right) {
  std::mt19937_64 rng(seed * 7919 + 3);
  std::uniform_real_distribution<double> off(-0.05, 0.05), radius(0.005, 0.04);
  Case c;
  SimulationParams sim = defaultSimulation();
  sim.kinect.enabled = false;
  sim.duration = seconds;
  sim.seed = seed;
  sim.side = side;
  sim.upperArm.rateHz = sim.forearm.rateHz = 100.0;
  ArmGeometry truth;
  truth.lu3 += off(rng);
  truth.lf6 = 0.17 + off(rng) * 0.6;  // within the forearm
  truth.lu5 = radius(rng);
  truth.lf8 = radius(rng);
  sim.geometry = truth;
  c.rotUa = test::strapTurn(rng, 30.0 * kDeg);
  c.rotFa = test::strapTurn(rng, 30.0 * kDeg);
  sim.upperArm.misalignment = c.rotUa;
  sim.forearm.misalignment = c.rotFa;
  sim.upperArm.gyroBias = Eigen::Vector3d(0.5, -0.3, 0.2) * kDeg;
  sim.forearm.gyroBias = Eigen::Vector3d(-0.4, 0.2, 0.6) * kDeg;
  if (realistic) applySensorModel(SensorModel::Realistic, sim);
  const test::RestThenMove traj(motion, protocolStartPose(), 3.0);
  c.rec = simulateRecording(traj, sim);
  c.rec.meta.geometry = ArmGeometry{};  // the sidecar says nominal
  c.leverUa = Eigen::Vector3d(truth.lu5 * std::sin(truth.thu4), -truth.lu5 * std::cos(truth.thu4),
                              truth.lu3);
  c.leverFa = Eigen::Vector3d(truth.lf8 * std::cos(truth.thf7), truth.lf8 * std::sin(truth.thf7),
                              truth.lf6);
  return c;
}

double angleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle() / kDeg;
}

struct Errors {
  double rotUa, rotFa, levUa, levFa;  // deg, deg, cm, cm
};

Errors errorsOf(const Case& c, const MovementCalibration& m) {
  return {angleDeg(m.upperMounting, c.rotUa), angleDeg(m.forearmMounting, c.rotFa),
          (m.upperLever - c.leverUa).norm() * 100.0, (m.forearmLever - c.leverFa).norm() * 100.0};
}

MovementCalibrationParams withRestPose() {
  MovementCalibrationParams p;
  p.restPose = protocolStartPose();  // the rest is the protocol's start pose
  return p;
}

// The model's relative rotation between the two IMU frames matches the forward kinematics.
TEST(MovementCalibration, RelativeModelMatchesForwardKinematics) {
  ArmGeometry g;
  g.thu4 = 1.1;
  g.thf7 = 0.4;
  const movecal::RelativeModel m = movecal::relativeModel(g);
  JointVector th;
  th << 0.3, 0.2, -0.4, -1.1, 0.7;
  const ArmPose pose = forwardKinematics(g, th);
  const Eigen::Matrix3d expected =
      pose.upperImu.topLeftCorner<3, 3>().transpose() * pose.forearmImu.topLeftCorner<3, 3>();
  EXPECT_LT((movecal::relativeRotation(m, th(3), th(4)) - expected).norm(), 1e-12);
}

// Strap rotation (deg) and lever arms (cm, only where the movement placed the sensor in every
// direction) against the truth, over seeds and the reaching and multi-joint movements.
void sweep(bool realistic, std::uint64_t seeds, double strapLimitDeg) {
  double worst[4] = {0, 0, 0, 0};
  int leversNotExcited = 0;
  for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
    for (int kind = 0; kind < 2; ++kind) {
      const ReachingTrajectory reach(seed, 2.0, 8.0, 70.0);
      const MultiJointTrajectory multi(seed);
      const Trajectory& motion = kind == 0 ? static_cast<const Trajectory&>(reach) : multi;
      const Case c = makeCase(motion, seed, realistic);
      const MovementCalibration m = calibrateFromMovement(c.rec, withRestPose());
      const Errors e = errorsOf(c, m);
      std::cout << "| " << (realistic ? "realistic" : "ideal") << " | "
                << (kind == 0 ? "reaching" : "multi-joint") << " | " << seed << " | " << e.rotUa
                << " | " << e.rotFa << " | " << e.levUa << (m.upperLeverExcited ? "" : " (prior)")
                << " | " << e.levFa << (m.forearmLeverExcited ? "" : " (prior)") << " |\n";
      for (const std::string& w : m.warnings) std::cout << "  note: " << w << "\n";
      worst[0] = std::max(worst[0], e.rotUa);
      worst[1] = std::max(worst[1], e.rotFa);
      if (m.upperLeverExcited) worst[2] = std::max(worst[2], e.levUa);
      if (m.forearmLeverExcited) worst[3] = std::max(worst[3], e.levFa);
      leversNotExcited += !m.upperLeverExcited + !m.forearmLeverExcited;
    }
  }
  std::cout << "worst: strap ua " << worst[0] << " fa " << worst[1] << " deg; lever (excited) ua "
            << worst[2] << " fa " << worst[3] << " cm; " << leversNotExcited
            << " lever arm(s) left at the prior\n";
  EXPECT_LT(worst[0], strapLimitDeg);
  EXPECT_LT(worst[1], strapLimitDeg);
  EXPECT_LT(worst[2], 2.0);
  EXPECT_LT(worst[3], 2.0);
  EXPECT_LE(leversNotExcited, 2);
}

// Acceptance 4 of issue 27 asks 3 deg; with ideal sensors that holds.
TEST(MovementCalibration, IdealSensors) {
  sweep(false, 2, 3.0);
}
// With the realistic preset the worst strap error measured 3.8 deg (the gyroscopes' 3 % scale and
// 2 % cross-axis errors bend the relative rotation the fit sees; docs/calibration.md).
TEST(MovementCalibration, RealisticSensors) {
  sweep(true, 5, 4.5);
}

// Elbow flexion only: the upper arm never turns (the shoulder cannot be placed) and the forearm
// never pronates (its pronation axis cannot be told within the flexion plane): those fall back to
// the sidecar's values and the report says so.
TEST(MovementCalibration, PlanarMovementFallsBackToThePrior) {
  SinusoidTrajectory flex;
  flex.offset = protocolStartPose();
  flex.amplitude(3) = 45.0 * kDeg;
  flex.frequency(3) = 0.5;
  flex.phase(3) = 0.0;
  const Case c = makeCase(flex, 11, false, 30.0);
  const MovementCalibration m = calibrateFromMovement(c.rec, withRestPose());
  const std::string report = formatMovementReport(m);
  std::cout << report;
  int unexcited = 0;
  for (const MovementParameter& p : m.parameters) {
    if (!p.excited && p.observable) {
      ++unexcited;
      EXPECT_EQ(p.value, p.prior) << p.name;
    }
  }
  EXPECT_GE(unexcited, 2);
  const auto find = [&](const std::string& name) {
    for (const MovementParameter& p : m.parameters)
      if (p.name == name) return p;
    ADD_FAILURE() << name;
    return MovementParameter{};
  };
  EXPECT_FALSE(find("upper-arm sensor distance from the shoulder").excited);
  EXPECT_NE(report.find("did not show it"), std::string::npos);
  // The elbow's axis in the upper-arm sensor, which flexion does show: measured 6.4 deg off (the
  // elbow centre, not placed, biases the accelerometer residual; docs/calibration.md), so this
  // only guards against worse.
  const Eigen::Vector3d flexModel = movecal::relativeModel(ArmGeometry{}).flexionInUpper;
  const Eigen::Vector3d flexTrue = c.rotUa.transpose() * flexModel;
  const Eigen::Vector3d flexEst = m.upperMounting.transpose() * flexModel;
  const double flexErrDeg = std::acos(std::min(1.0, std::abs(flexTrue.dot(flexEst)))) / kDeg;
  std::cout << "flexion axis in the upper-arm sensor: " << flexErrDeg << " deg off\n";
  EXPECT_LT(flexErrDeg, 10.0);
}

// A double pendulum (a planar two-segment chain on a fixed pivot): pronation is never excited.
TEST(MovementCalibration, DoublePendulumSaysWhatItCouldNotSee) {
  PendulumSimParams p;
  p.duration = 30.0;
  p.pendulum.holdSeconds = 2.0;
  p.gyroNoiseStd = 0.005;
  p.accelNoiseStd = 0.05;
  const Recording rec = simulatePendulum(p);
  const MovementCalibration m = calibrateFromMovement(rec);
  std::cout << formatMovementReport(m);
  bool forearmTiltUnexcited = false;
  for (const MovementParameter& q : m.parameters)
    if (q.name.rfind("forearm sensor tilt", 0) == 0 && !q.excited) forearmTiltUnexcited = true;
  EXPECT_TRUE(forearmTiltUnexcited);
  EXPECT_TRUE(calibrationProblem(m.calibration).empty());
}

// A left arm is fitted on its right-arm twin and given back in the real sensors' axes: the
// rotation mirror-conjugated, the bias -D b (as the protocol calibration does).
TEST(MovementCalibration, LeftArm) {
  const ReachingTrajectory reach(2, 2.0, 8.0, 70.0);
  const Case c = makeCase(reach, 2, false, 40.0, Side::Left);
  const MovementCalibration m = calibrateFromMovement(c.rec, withRestPose());
  EXPECT_EQ(m.calibration.side, Side::Left);
  const Errors e = errorsOf(c, m);
  std::cout << "left arm: strap ua " << e.rotUa << " fa " << e.rotFa << " deg; lever ua " << e.levUa
            << " fa " << e.levFa << " cm\n";
  EXPECT_LT(e.rotUa, 3.0);
  EXPECT_LT(e.rotFa, 3.0);
  const Eigen::Matrix3d d = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();
  EXPECT_LT((m.calibration.upperArm.gyroBias + d * Eigen::Vector3d(0.5, -0.3, 0.2) * kDeg).norm(),
            0.05 * kDeg);
  // The real sensor's rotation, mirrored back to the twin, gives the twin's whole mounting.
  const Eigen::Matrix3d twin = d * m.calibration.upperArm.rotation * d;
  EXPECT_LT(
      angleDeg(mountingRotation(m.calibration.geometry.thu4, ArmGeometry{}.thu4, twin), c.rotUa),
      3.0);
}

Recording shortStill(double seconds) {
  SinusoidTrajectory still;
  still.offset = protocolStartPose();
  SimulationParams sim = defaultSimulation();
  sim.kinect.enabled = false;
  sim.duration = seconds;
  sim.upperArm.rateHz = sim.forearm.rateHz = 100.0;
  return simulateRecording(still, sim);
}

void expectRefusal(const Recording& rec, const std::string& words) {
  std::string why;
  EXPECT_FALSE(tryCalibrateFromMovement(rec, {}, &why).has_value()) << words;
  EXPECT_NE(why.find(words), std::string::npos) << why;
  EXPECT_THROW(calibrateFromMovement(rec), std::invalid_argument);
}

TEST(MovementCalibration, HostileInput) {
  expectRefusal(shortStill(2.0), "only 2.0 s");
  expectRefusal(shortStill(20.0), "too little movement");
  {
    Recording rec = shortStill(20.0);
    for (ArmSample& s : rec.samples) s.forearm.reset();
    expectRefusal(rec, "no forearm IMU");
  }
  {
    Recording rec;
    expectRefusal(rec, "no upper-arm IMU");
  }
  const MultiJointTrajectory multi(3);
  {
    // No rest anywhere.
    SimulationParams sim = defaultSimulation();
    sim.kinect.enabled = false;
    sim.duration = 20.0;
    sim.upperArm.rateHz = sim.forearm.rateHz = 100.0;
    expectRefusal(simulateRecording(multi, sim), "no moment of rest");
  }
  {
    // Saturated: the upper-arm gyroscope clipped at +-0.6 rad/s.
    Case c = makeCase(multi, 3, false, 20.0);
    for (ArmSample& s : c.rec.samples)
      if (s.upperArm) s.upperArm->gyr = s.upperArm->gyr.cwiseMax(-0.6).cwiseMin(0.6);
    expectRefusal(c.rec, "saturated");
  }
  {
    // Mostly not numbers.
    Case c = makeCase(multi, 3, false, 20.0);
    for (ArmSample& s : c.rec.samples)
      if (s.forearm) s.forearm->acc.x() = std::numeric_limits<double>::quiet_NaN();
    expectRefusal(c.rec, "not numbers");
  }
}

// One NaN row is left out and said; the calibration is still made.
TEST(MovementCalibration, OneNanRowIsLeftOut) {
  const MultiJointTrajectory multi(4);
  Case c = makeCase(multi, 4, false, 25.0);
  for (ArmSample& s : c.rec.samples) {
    if (s.t > 10.0 && s.upperArm) {
      s.upperArm->gyr.y() = std::numeric_limits<double>::quiet_NaN();
      break;
    }
  }
  const MovementCalibration m = calibrateFromMovement(c.rec, withRestPose());
  bool said = false;
  for (const std::string& w : m.warnings) said = said || w.find("not numbers") != std::string::npos;
  EXPECT_TRUE(said);
  EXPECT_LT(errorsOf(c, m).rotFa, 5.0);
}

}  // namespace
}  // namespace armtrack
