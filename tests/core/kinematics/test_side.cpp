// The left arm as the mirror image of the right: physical meaning, the sensor mapping checked
// against numerical differentiation of the left sensor frames, and estimation accuracy.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/ArmSample.h"
#include "core/estimation/ArmFilter.h"
#include "core/io/Recording.h"
#include "core/kinematics/Side.h"
#include "core/metrics/Accuracy.h"
#include "core/simulation/SensorSimulator.h"

namespace armtrack {
namespace {

const Eigen::Matrix3d kS = Eigen::Vector3d(1, 1, -1).asDiagonal();  // sagittal mirror
const Eigen::Matrix3d kD = Eigen::Vector3d(1, 1, -1).asDiagonal();  // sensor z reversed

SimulationParams noiseFree(Side side) {
  SimulationParams p;
  p.duration = 0.5;
  p.side = side;
  p.kinect.noiseStd = 0.0;
  return p;
}

TEST(Side, LeftArmPosesMeanWhatTheySay) {
  // Left shoulder frame: x0 down, y0 forward, z0 to the patient's right (medial for this arm).
  SinusoidTrajectory flex;
  flex.offset(0) = 30 * kDeg;
  Recording r = simulateRecording(flex, noiseFree(Side::Left));
  ASSERT_TRUE(r.samples[0].elbow);
  EXPECT_GT(r.samples[0].elbow->y(), 0.05);  // flexion: forward
  EXPECT_NEAR(r.samples[0].elbow->z(), 0.0, 1e-12);

  SinusoidTrajectory abd;
  abd.offset(1) = 30 * kDeg;
  r = simulateRecording(abd, noiseFree(Side::Left));
  EXPECT_LT(r.samples[0].elbow->z(), -0.05);  // abduction: out to the patient's left
  EXPECT_EQ(r.meta.side, Side::Left);
  // At rest the accelerometers read g.
  EXPECT_NEAR(r.samples[0].upperArm->acc.norm(), 9.81, 1e-9);
  EXPECT_NEAR(r.samples[0].forearm->acc.norm(), 9.81, 1e-9);
}

TEST(Side, MirrorIsAnExactInvolution) {
  ArmSample s;
  s.t = 1.5;
  s.upperArm = ImuReading{{0.1, -0.2, 0.3}, {1.0, 2.0, -9.0}};
  s.forearm = ImuReading{{-0.4, 0.5, 0.6}, {-3.0, 0.5, 8.0}};
  s.elbow = Eigen::Vector3d(0.2, 0.05, -0.03);
  s.wrist = Eigen::Vector3d(0.3, 0.2, 0.1);
  const ArmSample back = mirrorSample(mirrorSample(s));
  EXPECT_EQ(back.upperArm->gyr, s.upperArm->gyr);
  EXPECT_EQ(back.upperArm->acc, s.upperArm->acc);
  EXPECT_EQ(back.forearm->gyr, s.forearm->gyr);
  EXPECT_EQ(*back.elbow, *s.elbow);
  EXPECT_EQ(*back.wrist, *s.wrist);
}

Eigen::Vector3d vee(const Eigen::Matrix3d& m) {
  return {0.5 * (m(2, 1) - m(1, 2)), 0.5 * (m(0, 2) - m(2, 0)), 0.5 * (m(1, 0) - m(0, 1))};
}

// The left sensor frame is S F_R D (mirror image, z reversed): a proper rotation. What a sensor
// in that frame reads follows from differentiating its pose, independently of mirrorImu.
TEST(Side, LeftImuReadingsMatchDifferentiatedLeftFrames) {
  SinusoidTrajectory traj;
  traj.offset << 0.4, 0.3, -0.2, -0.9, 0.3;
  traj.amplitude << 0.6, 0.4, 0.5, 0.7, 0.8;
  traj.frequency << 0.7, 0.9, 1.1, 0.8, 1.3;
  SimulationParams p = noiseFree(Side::Left);
  p.kinect.enabled = false;
  p.duration = 1.0;
  const Recording rec = simulateRecording(traj, p);
  const ArmGeometry geo;
  const Eigen::Vector3d gUpLeft = p.g * p.up;
  auto frame = [&](double t, bool upper) -> Eigen::Matrix4d {
    const ArmPose pose = forwardKinematics(geo, traj.at(t).th);
    const Eigen::Matrix4d h = upper ? pose.upperImu : pose.forearmImu;
    Eigen::Matrix4d l = Eigen::Matrix4d::Identity();
    l.topLeftCorner<3, 3>() = kS * h.topLeftCorner<3, 3>() * kD;
    l.topRightCorner<3, 1>() = kS * h.topRightCorner<3, 1>();
    return l;
  };
  const double dt = 1e-3;  // five-point stencils: truncation ~dt^4
  for (const ArmSample& s : rec.samples) {
    if (s.t < 0.1 || s.t > 0.9 || std::fmod(s.t, 0.1) > 1e-9) continue;
    for (bool upper : {true, false}) {
      auto rot = [&](double t) -> Eigen::Matrix3d { return frame(t, upper).topLeftCorner<3, 3>(); };
      auto pos = [&](double t) -> Eigen::Vector3d {
        return frame(t, upper).topRightCorner<3, 1>();
      };
      const Eigen::Matrix3d r = rot(s.t);
      ASSERT_NEAR(r.determinant(), 1.0, 1e-12);
      const double t = s.t;
      const Eigen::Matrix3d rd =
          (rot(t - 2 * dt) - 8 * rot(t - dt) + 8 * rot(t + dt) - rot(t + 2 * dt)) / (12 * dt);
      const Eigen::Vector3d gyr = r.transpose() * vee(rd * r.transpose());
      const Eigen::Vector3d pdd =
          (-pos(t - 2 * dt) + 16 * pos(t - dt) - 30 * pos(t) + 16 * pos(t + dt) - pos(t + 2 * dt)) /
          (12 * dt * dt);
      const Eigen::Vector3d acc = r.transpose() * (pdd + gUpLeft);
      const ImuReading& got = upper ? *s.upperArm : *s.forearm;
      EXPECT_LT((got.gyr - gyr).norm(), 1e-6) << "t = " << s.t << (upper ? " upper" : " forearm");
      EXPECT_LT((got.acc - acc).norm(), 1e-6) << "t = " << s.t << (upper ? " upper" : " forearm");
    }
  }
}

JointVector runRmse(const Recording& rec, Side side) {
  EstimatorParams p;
  p.side = side;
  p.gUp = rec.meta.gUp();
  p.jointAccelVariance = (10 * kDeg) * (10 * kDeg);
  auto f = makeEstimator(p);
  ErrorAccumulator acc;
  for (const ArmSample& s : rec.samples) {
    f->update(s);
    if (s.trueAngles && s.t >= 1.0) acc.add(f->estimate().th, *s.trueAngles);
  }
  return acc.rmse() / kDeg;
}

TEST(Side, LeftArmIsEstimatedAsWellAsTheRight) {
  const MultiJointTrajectory traj(5);
  SimulationParams p = defaultSimulation();
  p.duration = 15.0;
  p.seed = 5;
  const Recording right = simulateRecording(traj, p);
  p.side = Side::Left;
  const Recording left = simulateRecording(traj, p);
  const JointVector r = runRmse(right, Side::Right);
  const JointVector l = runRmse(left, Side::Left);
  for (int j = 0; j < kNumJoints; ++j) {
    EXPECT_LE(l(j), 1.0) << "joint " << j;
    EXPECT_NEAR(l(j), r(j), 0.05) << "joint " << j;
  }
  // Declaring the wrong side spoils it: the side is not cosmetic.
  EXPECT_GT(runRmse(left, Side::Right).maxCoeff(), 5.0);
}

TEST(Side, SidecarCarriesTheSide) {
  const auto dir = std::filesystem::temp_directory_path() / "armtrack_test_side";
  std::filesystem::create_directories(dir);
  Recording rec;
  rec.meta.side = Side::Left;
  ArmSample s;
  s.t = 0.0;
  s.elbow = Eigen::Vector3d(0.2, 0.0, 0.0);
  rec.samples.push_back(s);
  writeRecording(dir / "left.csv", rec);
  EXPECT_EQ(readRecording(dir / "left.csv").meta.side, Side::Left);
  {
    std::ofstream bad(dir / "bad.json");
    bad << R"({"format": "armtrack-recording", "version": 1, "side": "middle"})";
  }
  EXPECT_THROW(readSidecar(dir / "bad.json"), RecordingError);
  EXPECT_EQ(parseSide("LEFT"), Side::Left);
  EXPECT_THROW(parseSide("both"), std::invalid_argument);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace armtrack
