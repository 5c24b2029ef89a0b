// The sternum sensor's mounting from the upright start pose, on a simulated sternum IMU (Table 5
// noise and a gyroscope bias) whose mounting is the simulator's default turned by a known amount:
// the tilt is recovered within 1 deg; a turn about the vertical, which gravity cannot see, is
// left as the mounting started from.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/calibration/TrunkMounting.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

using namespace armtrack;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double angleBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle() / kDeg;
}

// A tilt: a turn about a horizontal axis (no turn about the vertical x0), forwardDeg of it about
// the forward axis y0 and lateralDeg about the lateral axis z0.
Eigen::Matrix3d tilt(double forwardDeg, double lateralDeg) {
  const Eigen::Vector3d v(0.0, forwardDeg, lateralDeg);
  return Eigen::AngleAxisd(v.norm() * kDeg, v.normalized()).toRotationMatrix();
}

std::vector<ArmSample> sternumReadings(Side side, const TrunkMount& mount, std::uint64_t seed) {
  SimulationParams sim = defaultSimulation();
  sim.duration = 3.0;
  sim.side = side;
  sim.seed = seed;
  sim.kinect.enabled = false;
  sim.upperArm.rateHz = sim.forearm.rateHz = sim.trunkImu.rateHz = 200;
  sim.trunkImu.enabled = true;
  sim.trunkImu.gyroBias = Eigen::Vector3d(0.006, -0.008, 0.005);
  sim.trunkMount = mount;
  return simulateRecording(CalibrationProtocolTrajectory(), sim).samples;
}

TEST(TrunkMounting, LevellingANoiseFreeReadingRecoversAHorizontalTiltExactly) {
  const TrunkMount initial = defaultSimulatedTrunkMount(Side::Right);
  TrunkMount truth = initial;
  truth.imuRotation = tilt(14, -9) * initial.imuRotation;
  const Eigen::Vector3d up(-1, 0, 0);
  const Eigen::Vector3d acc = 9.81 * truth.imuRotation.transpose() * up;
  const TrunkMount got = levelTrunkMount(initial, acc, up);
  EXPECT_LT(angleBetween(got.imuRotation, truth.imuRotation), 1e-6);
  EXPECT_TRUE(got.imuPosition.isApprox(initial.imuPosition));
  // Nothing to go by: the mounting stays.
  const TrunkMount same = levelTrunkMount(initial, Eigen::Vector3d::Zero(), up);
  EXPECT_TRUE(same.imuRotation.isApprox(initial.imuRotation));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(levelTrunkMount(initial, Eigen::Vector3d(nan, 1, 0), up)
                  .imuRotation.isApprox(initial.imuRotation));
}

TEST(TrunkMounting, TiltOfASimulatedSternumSensorWithinOneDegreeBothSides) {
  std::uint64_t seed = 41;
  for (Side side : {Side::Right, Side::Left}) {
    for (const auto& [f, l] :
         {std::pair{12.0, 8.0}, std::pair{-20.0, 5.0}, std::pair{3.0, -25.0}}) {
      const TrunkMount initial = defaultSimulatedTrunkMount(side);
      TrunkMount truth = initial;
      truth.imuRotation = tilt(f, l) * initial.imuRotation;
      const std::vector<ArmSample> samples = sternumReadings(side, truth, ++seed);
      TrunkMountingParams p;
      const TrunkMounting got = calibrateTrunkMount(samples, initial, p);
      ASSERT_TRUE(got.mount) << got.problem;
      EXPECT_LT(angleBetween(got.mount->imuRotation, truth.imuRotation), 1.0)
          << sideName(side) << " " << f << " " << l;
      EXPECT_NEAR(got.tiltDeg, angleBetween(initial.imuRotation, truth.imuRotation), 1.0);
      EXPECT_GT(got.stillSeconds, 1.0);
    }
  }
}

TEST(TrunkMounting, HeadingAboutTheVerticalIsLeftAsTheDefault) {
  // Turned 30 deg about the vertical as well as tilted: gravity sees the tilt only, so the result
  // is the default turned by the tilt alone, not the true mounting.
  const TrunkMount initial = defaultSimulatedTrunkMount(Side::Right);
  const Eigen::Matrix3d heading = Eigen::AngleAxisd(30 * kDeg, Eigen::Vector3d::UnitX()).matrix();
  TrunkMount truth = initial;
  truth.imuRotation = heading * tilt(10, 6) * initial.imuRotation;
  const TrunkMounting got =
      calibrateTrunkMount(sternumReadings(Side::Right, truth, 7), initial, {});
  ASSERT_TRUE(got.mount) << got.problem;
  EXPECT_LT(angleBetween(got.mount->imuRotation, tilt(10, 6) * initial.imuRotation), 1.0);
  EXPECT_GT(angleBetween(got.mount->imuRotation, truth.imuRotation), 25.0);
  // Gravity is where the sensor reads it.
  const Eigen::Vector3d up(-1, 0, 0);
  EXPECT_LT(std::acos(std::clamp(
                (got.mount->imuRotation.transpose() * up).dot(truth.imuRotation.transpose() * up),
                -1.0, 1.0)) /
                kDeg,
            1.0);
}

TEST(TrunkMounting, NoStillStartOrNoGravityGivesNoMountAndSaysWhy) {
  const TrunkMount initial = defaultSimulatedTrunkMount(Side::Right);
  EXPECT_FALSE(calibrateTrunkMount({}, initial, {}).mount);
  // No sternum readings at all.
  std::vector<ArmSample> samples = sternumReadings(Side::Right, initial, 3);
  std::vector<ArmSample> none = samples;
  for (ArmSample& s : none) s.trunk.reset();
  TrunkMounting got = calibrateTrunkMount(none, initial, {});
  EXPECT_FALSE(got.mount);
  EXPECT_FALSE(got.problem.empty());
  // The patient moves all the time (the gyroscope never still).
  std::vector<ArmSample> moving = samples;
  for (ArmSample& s : moving)
    if (s.trunk) s.trunk->gyr += Eigen::Vector3d(0.0, 0.6, 0.0);
  got = calibrateTrunkMount(moving, initial, {});
  EXPECT_FALSE(got.mount);
  EXPECT_NE(got.problem.find("still"), std::string::npos);
  // An accelerometer in g, not m/s^2.
  std::vector<ArmSample> inG = samples;
  for (ArmSample& s : inG)
    if (s.trunk) s.trunk->acc /= 9.81;
  got = calibrateTrunkMount(inG, initial, {});
  EXPECT_FALSE(got.mount);
  EXPECT_NE(got.problem.find("gravity"), std::string::npos);
  // Garbage readings among good ones are skipped.
  std::vector<ArmSample> garbage = samples;
  for (std::size_t i = 0; i < garbage.size(); i += 7)
    if (garbage[i].trunk) garbage[i].trunk->acc.x() = std::numeric_limits<double>::infinity();
  got = calibrateTrunkMount(garbage, initial, {});
  ASSERT_TRUE(got.mount);
  EXPECT_LT(angleBetween(got.mount->imuRotation, initial.imuRotation), 1.0);
}

}  // namespace
