// The sensor check before a home session, on simulated check movements (the arm hangs still,
// then the elbow bends three times) with the paper's noise and gyroscope biases, the sensors worn
// right, swapped (the two readings exchanged), upside down (the simulator's misalignment turns a
// sensor end over end), tilted, on a left arm, and with what a home set-up can get wrong besides.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/calibration/SensorCheck.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

using namespace armtrack;

namespace {

constexpr double kPi = std::numbers::pi;

// A sensor turned end over end on its strap: half a turn about the axis through the strap (the
// sensor's z, normal to the long axis y of both segments' sensor frames in the default mounting).
Eigen::Matrix3d upsideDown() {
  return Eigen::AngleAxisd(kPi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

struct Wearing {
  Side side = Side::Right;
  Eigen::Matrix3d upperMount = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d foreMount = Eigen::Matrix3d::Identity();
  bool swapped = false;
  std::uint64_t seed = 3;
};

std::vector<ArmSample> simulateCheck(const Wearing& w, const Trajectory& trajectory,
                                     double seconds = SensorCheckTrajectory::duration()) {
  SimulationParams sim = defaultSimulation();
  sim.duration = seconds;
  sim.side = w.side;
  sim.seed = w.seed;
  sim.kinect.enabled = false;
  sim.upperArm.rateHz = sim.forearm.rateHz = 200;
  // Gyroscope biases of a cheap IMU, about 0.5 deg/s per axis.
  sim.upperArm.gyroBias = Eigen::Vector3d(0.008, -0.006, 0.009);
  sim.forearm.gyroBias = Eigen::Vector3d(-0.007, 0.009, 0.004);
  sim.upperArm.misalignment = w.upperMount;
  sim.forearm.misalignment = w.foreMount;
  std::vector<ArmSample> samples = simulateRecording(trajectory, sim).samples;
  if (w.swapped)
    for (ArmSample& s : samples) std::swap(s.upperArm, s.forearm);
  return samples;
}

SensorCheckResult check(const Wearing& w) {
  const SensorCheckTrajectory trajectory;
  SensorCheckParams p;
  p.side = w.side;
  return checkSensors(simulateCheck(w, trajectory), p);
}

std::vector<SensorFinding> findings(std::initializer_list<SensorFinding> f) {
  return f;
}

}  // namespace

TEST(SensorCheck, WornRightPassesOnBothArms) {
  for (Side side : {Side::Right, Side::Left}) {
    Wearing w;
    w.side = side;
    const SensorCheckResult r = check(w);
    SCOPED_TRACE(sideName(side) + ": " + r.explanation);
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.status, SensorCheckStatus::Judged);
    // Three bends of 100 deg in 1.5 s each: the forearm turns at about 1.4 rad/s RMS, the upper
    // arm only reads its noise.
    EXPECT_GT(r.forearmMotionRadS, 0.8);
    EXPECT_LT(r.upperMotionRadS, 0.05);
    EXPECT_GT(r.upperCos, 0.99);
    EXPECT_GT(r.forearmCos, 0.99);
    EXPECT_GT(r.restSeconds, 2.5);
  }
}

TEST(SensorCheck, SwappedSensorsAreFoundOnBothArms) {
  for (Side side : {Side::Right, Side::Left}) {
    Wearing w;
    w.side = side;
    w.swapped = true;
    const SensorCheckResult r = check(w);
    SCOPED_TRACE(r.explanation);
    EXPECT_EQ(r.status, SensorCheckStatus::Judged);
    EXPECT_EQ(r.findings, findings({SensorFinding::Swapped}));
    EXPECT_GT(r.upperMotionRadS, 0.8);  // the sensor plugged in as the upper arm's turned
  }
}

TEST(SensorCheck, AnUpsideDownSensorIsFoundOnItsSegment) {
  Wearing w;
  w.upperMount = upsideDown();
  SensorCheckResult r = check(w);
  EXPECT_EQ(r.findings, findings({SensorFinding::UpperArmUpsideDown})) << r.explanation;
  EXPECT_LT(r.upperCos, -0.99);
  w = {};
  w.foreMount = upsideDown();
  r = check(w);
  EXPECT_EQ(r.findings, findings({SensorFinding::ForearmUpsideDown})) << r.explanation;
  w.upperMount = upsideDown();
  r = check(w);
  EXPECT_EQ(r.findings,
            findings({SensorFinding::UpperArmUpsideDown, SensorFinding::ForearmUpsideDown}));
  // Swapped as well: the finding names the segment the upside-down sensor is really on. The
  // sensor on the forearm (plugged in as the upper arm's) is upside down.
  w = {};
  w.foreMount = upsideDown();
  w.swapped = true;
  r = check(w);
  EXPECT_EQ(r.findings, findings({SensorFinding::Swapped, SensorFinding::ForearmUpsideDown}))
      << r.explanation;
  w.foreMount = Eigen::Matrix3d::Identity();
  w.upperMount = upsideDown();
  r = check(w);
  EXPECT_EQ(r.findings, findings({SensorFinding::Swapped, SensorFinding::UpperArmUpsideDown}))
      << r.explanation;
  // Left arm.
  w = {};
  w.side = Side::Left;
  w.foreMount = upsideDown();
  r = check(w);
  EXPECT_EQ(r.findings, findings({SensorFinding::ForearmUpsideDown})) << r.explanation;
}

// The strap's angle around the arm is the calibration's business, and a small misalignment is
// normal: neither makes the check fail. A quarter turn end over end is a tilt.
TEST(SensorCheck, StrapAngleAroundTheArmIsFineAQuarterTurnIsATilt) {
  Wearing w;
  w.upperMount = Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  w.foreMount = randomMisalignment(15 * kPi / 180, 9);
  SensorCheckResult r = check(w);
  EXPECT_TRUE(r.ok()) << r.explanation;
  w.foreMount = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  r = check(w);
  EXPECT_EQ(r.findings, findings({SensorFinding::ForearmTilted})) << r.explanation;
  EXPECT_LT(std::abs(r.forearmCos), 0.1);
}

TEST(SensorCheck, SaysWhenItCannotJudge) {
  const SensorCheckTrajectory trajectory;
  SensorCheckParams p;
  Wearing w;
  std::vector<ArmSample> samples = simulateCheck(w, trajectory);

  EXPECT_EQ(checkSensors({}, p).status, SensorCheckStatus::MissingUpperArm);
  std::vector<ArmSample> noFore = samples;
  for (ArmSample& s : noFore) s.forearm.reset();
  EXPECT_EQ(checkSensors(noFore, p).status, SensorCheckStatus::MissingForearm);

  // Both sensors on the forearm: they turn alike.
  std::vector<ArmSample> both = samples;
  for (ArmSample& s : both) s.upperArm = s.forearm;
  EXPECT_EQ(checkSensors(both, p).status, SensorCheckStatus::BothMoved);

  // The arm kept still all along: nothing to judge the swap by.
  SinusoidTrajectory still;
  EXPECT_EQ(checkSensors(simulateCheck(w, still), p).status, SensorCheckStatus::NoMovement);

  // Moving from the start: no still hang.
  const MultiJointTrajectory moving(4);
  EXPECT_EQ(checkSensors(simulateCheck(w, moving), p).status, SensorCheckStatus::NotStill);

  // Accelerometers read in g instead of m/s^2 (an unconverted sensor).
  std::vector<ArmSample> inG = samples;
  for (ArmSample& s : inG) {
    if (s.upperArm) s.upperArm->acc /= 9.81;
    if (s.forearm) s.forearm->acc /= 9.81;
  }
  EXPECT_EQ(checkSensors(inG, p).status, SensorCheckStatus::ImplausibleReadings);
}

TEST(SensorCheck, GarbageIsSkippedNotTrusted) {
  const SensorCheckTrajectory trajectory;
  Wearing w;
  w.swapped = true;
  std::vector<ArmSample> samples = simulateCheck(w, trajectory);
  // Every fifth reading ruined: NaN, infinity, a NaN time.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < samples.size(); i += 5) {
    if (samples[i].upperArm) samples[i].upperArm->gyr.x() = nan;
    if (samples[i].forearm) samples[i].forearm->acc.y() = std::numeric_limits<double>::infinity();
    if (i % 15 == 0) samples[i].t = nan;
  }
  SensorCheckParams p;
  const SensorCheckResult r = checkSensors(samples, p);
  EXPECT_EQ(r.findings, findings({SensorFinding::Swapped})) << r.explanation;
  EXPECT_TRUE(std::isfinite(r.upperMotionRadS));
}

namespace {

// The check with a sternum sensor worn as `worn` (frame 0 axes) while the check expects the
// simulator's default mounting.
SensorCheckResult checkWithSternum(Side side, const Eigen::Matrix3d& turn, bool send = true) {
  SimulationParams sim = defaultSimulation();
  sim.duration = SensorCheckTrajectory::duration();
  sim.side = side;
  sim.seed = 11;
  sim.kinect.enabled = false;
  sim.upperArm.rateHz = sim.forearm.rateHz = sim.trunkImu.rateHz = 200;
  sim.trunkImu.enabled = send;
  sim.trunkImu.gyroBias = Eigen::Vector3d(0.006, -0.008, 0.005);
  const TrunkMount expected = defaultSimulatedTrunkMount(side);
  TrunkMount worn = expected;
  worn.imuRotation = turn * expected.imuRotation;
  sim.trunkMount = worn;
  SensorCheckParams p;
  p.side = side;
  p.trunk = expected;
  return checkSensors(simulateRecording(SensorCheckTrajectory(), sim).samples, p);
}

Eigen::Matrix3d aboutForward(double deg) {
  return Eigen::AngleAxisd(deg * kPi / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

}  // namespace

TEST(SensorCheck, SternumSensorWornRightPassesOnBothArms) {
  for (Side side : {Side::Right, Side::Left}) {
    const SensorCheckResult r = checkWithSternum(side, Eigen::Matrix3d::Identity());
    SCOPED_TRACE(sideName(side) + ": " + r.explanation);
    EXPECT_TRUE(r.ok());
    EXPECT_LT(r.trunkAngleDeg, 3.0);
    // A little crooked (15 deg) is within the tolerance.
    const SensorCheckResult crooked = checkWithSternum(side, aboutForward(15));
    EXPECT_TRUE(crooked.ok()) << crooked.explanation;
    EXPECT_NEAR(crooked.trunkAngleDeg, 15.0, 2.0);
  }
}

TEST(SensorCheck, SternumSensorUpsideDownOrTurnedIsFound) {
  for (Side side : {Side::Right, Side::Left}) {
    SensorCheckResult r = checkWithSternum(side, aboutForward(180));
    EXPECT_EQ(r.findings, findings({SensorFinding::TrunkUpsideDown})) << r.explanation;
    EXPECT_GT(r.trunkAngleDeg, 170.0);
    r = checkWithSternum(side, aboutForward(40));
    EXPECT_EQ(r.findings, findings({SensorFinding::TrunkTurned})) << r.explanation;
    EXPECT_NEAR(r.trunkAngleDeg, 40.0, 2.0);
    // Turned 90 deg about the vertical: gravity still reads along the same axis.
    r = checkWithSternum(side, Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()).matrix());
    EXPECT_TRUE(r.ok()) << r.explanation;
  }
}

TEST(SensorCheck, SternumSensorExpectedButSilentOrNotExpected) {
  SensorCheckResult r = checkWithSternum(Side::Right, Eigen::Matrix3d::Identity(), false);
  EXPECT_EQ(r.status, SensorCheckStatus::MissingTrunk);
  EXPECT_FALSE(r.ok());
  // Without an expected mounting the sternum readings are not judged (an arm-only check).
  Wearing w;
  r = check(w);
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(std::isnan(r.trunkAngleDeg));
}
