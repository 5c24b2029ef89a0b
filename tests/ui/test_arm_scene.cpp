// The 3D view's scene with a leaning trunk, without a display: where the actors are placed
// against the trunk's pose worked out here by hand (docs/trunk.md: a point p of the trunk's frame
// is at h + R (p - h) in the world, h the hip pivot) and the patient-term signs of
// core/kinematics/Trunk.h.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "core/simulation/TrunkMotion.h"
#include "ui/ArmScene.h"

namespace armtrack::ui {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(ArmScene, UprightTrunkLeavesTheArmAtTheShoulderFrame) {
  ArmScene scene;
  const ArmGeometry geo;
  scene.setArm(geo, Side::Right, -Eigen::Vector3d::UnitX());
  scene.setPose(JointVector::Zero());
  EXPECT_TRUE(scene.trunkPose().matrix().isIdentity(1e-15));
  EXPECT_TRUE(scene.shoulderActorCentre().isZero(1e-15));
  EXPECT_TRUE(scene.figure().elbow.isApprox(Eigen::Vector3d(geo.l3, 0, 0), 1e-12));
}

TEST(ArmScene, HipPivotIsTheSimulatorsDefaultHip) {
  for (Side side : {Side::Right, Side::Left}) {
    ArmScene scene;
    scene.setArm(ArmGeometry{}, side, -Eigen::Vector3d::UnitX());
    EXPECT_TRUE(scene.hipPivot().isApprox(defaultHip(side), 1e-12)) << sideName(side);
  }
}

TEST(ArmScene, ForwardLeanMovesTheShoulderAboutTheHip) {
  ArmScene scene;
  const ArmGeometry geo;
  scene.setArm(geo, Side::Right, -Eigen::Vector3d::UnitX());
  scene.setPose(JointVector::Zero());
  scene.setTrunk(TrunkAngles(20 * kDeg, 0, 0));
  // Flexion turns frame 0 about its z0 (the lateral axis): down (x0) tips backwards, so the
  // shoulder goes forwards (+y0). Worked out by hand for the hip (0.45, 0, -0.15).
  const double c = std::cos(20 * kDeg), s = std::sin(20 * kDeg);
  Eigen::Matrix3d r;
  r << c, s, 0,  //
      -s, c, 0,  //
      0, 0, 1;
  const Eigen::Vector3d hip(0.45, 0.0, -0.15);
  const Eigen::Vector3d shoulder = hip + r * (Eigen::Vector3d::Zero() - hip);
  EXPECT_TRUE(shoulder.isApprox(Eigen::Vector3d(0.45 * (1 - c), 0.45 * s, 0), 1e-12));
  EXPECT_TRUE(scene.shoulderActorCentre().isApprox(shoulder, 1e-12));
  EXPECT_TRUE(scene.figure().shoulder.isApprox(shoulder, 1e-12));
  // The arm hangs from the moving shoulder along the trunk's down axis (zero pose).
  EXPECT_TRUE(scene.figure().elbow.isApprox(shoulder + r * Eigen::Vector3d(geo.l3, 0, 0), 1e-12));
  // The torso's long axis (its second column, drawn along up) leans 20 deg forward.
  const Eigen::Vector3d torsoUp = scene.torsoAxes().col(1);
  EXPECT_NEAR(std::acos(torsoUp.dot(-Eigen::Vector3d::UnitX())), 20 * kDeg, 1e-9);
  EXPECT_GT(torsoUp.y(), 0.3);  // towards the front
  EXPECT_NEAR(torsoUp.z(), 0.0, 1e-12);
  // The head stays as far from the hip and goes forward more than the shoulder.
  ArmScene upright;
  upright.setArm(geo, Side::Right, -Eigen::Vector3d::UnitX());
  EXPECT_NEAR((scene.headCentre() - hip).norm(), (upright.headCentre() - hip).norm(), 1e-12);
  EXPECT_GT(scene.headCentre().y(), shoulder.y());
  EXPECT_TRUE(scene.torsoCentre().isApprox(hip + r * (upright.torsoCentre() - hip), 1e-12));
}

TEST(ArmScene, SidewaysLeanAndTurnInPatientTermsForBothSides) {
  for (Side side : {Side::Right, Side::Left}) {
    // Lateral bending > 0 leans to the patient's right (+z0 for either arm's frame): the head
    // goes that way.
    ArmScene scene;
    scene.setArm(ArmGeometry{}, side, -Eigen::Vector3d::UnitX());
    ArmScene upright;
    upright.setArm(ArmGeometry{}, side, -Eigen::Vector3d::UnitX());
    scene.setTrunk(TrunkAngles(0, 10 * kDeg, 0));
    EXPECT_GT(scene.headCentre().z() - upright.headCentre().z(), 0.05) << sideName(side);
    // Axial rotation > 0 brings the right shoulder forward and the left one back.
    scene.setTrunk(TrunkAngles(0, 0, 10 * kDeg));
    const double forward = scene.shoulderActorCentre().y();
    if (side == Side::Right)
      EXPECT_GT(forward, 0.02);
    else
      EXPECT_LT(forward, -0.02);
    // The trunk turns about the vertical: the shoulder stays at its height.
    EXPECT_NEAR(scene.shoulderActorCentre().x(), 0.0, 1e-12) << sideName(side);
  }
}

TEST(ArmScene, TargetArmHangsFromTheSameMovingShoulder) {
  ArmScene scene;
  scene.setArm(ArmGeometry{}, Side::Left, -Eigen::Vector3d::UnitX());
  scene.setTargetPose(JointVector::Zero());
  scene.setTrunk(TrunkAngles(15 * kDeg, -5 * kDeg, 8 * kDeg));
  const Eigen::Isometry3d pose = scene.trunkPose();
  const Eigen::Matrix3d r = trunkRotation(TrunkAngles(15 * kDeg, -5 * kDeg, 8 * kDeg));
  EXPECT_TRUE(pose.linear().isApprox(r, 1e-12));
  EXPECT_TRUE(
      pose.translation().isApprox(defaultHip(Side::Left) - r * defaultHip(Side::Left), 1e-12));
  EXPECT_TRUE(scene.shoulderActorCentre().isApprox(pose.translation(), 1e-12));
}

TEST(ArmScene, UnsetOrNonFiniteTrunkIsUpright) {
  ArmScene scene;
  scene.setArm(ArmGeometry{}, Side::Right, -Eigen::Vector3d::UnitX());
  scene.setTrunk(TrunkAngles(20 * kDeg, 0, 0));
  scene.setTrunk(std::nullopt);
  EXPECT_TRUE(scene.shoulderActorCentre().isZero(1e-15));
  scene.setTrunk(TrunkAngles(std::nan(""), 0, 0));
  EXPECT_TRUE(scene.shoulderActorCentre().isZero(1e-15));
  EXPECT_TRUE(scene.trunkPose().matrix().isIdentity(1e-15));
}

TEST(ArmScene, SternumImuSitsOnTheChestAndTurnsWithTheTrunk) {
  for (Side side : {Side::Right, Side::Left}) {
    ArmScene scene;
    scene.setArm(ArmGeometry{}, side, -Eigen::Vector3d::UnitX());
    EXPECT_FALSE(scene.sternumImuPose()) << "none until the session has one";
    const TrunkMount mount = defaultTrunkMount(side);
    scene.setSternumImu(mount);
    const auto upright = scene.sternumImuPose();
    ASSERT_TRUE(upright) << sideName(side);
    // At the mounting's height and side (0.10 m below, 0.18 m medial), in front of the shoulder
    // on the torso's front, in the mounting's orientation.
    EXPECT_NEAR(upright->translation().x(), 0.10, 1e-12);
    EXPECT_NEAR(upright->translation().z(), side == Side::Left ? 0.18 : -0.18, 1e-12);
    EXPECT_GT(upright->translation().y(), 0.09);
    EXPECT_LT(upright->translation().y(), 0.12);
    EXPECT_TRUE(upright->linear().isApprox(mount.imuRotation, 1e-9));
    // Leaning, it moves as a point of the trunk: about the hip by the trunk's rotation.
    const TrunkAngles lean(18 * kDeg, 6 * kDeg, -9 * kDeg);
    scene.setTrunk(lean);
    const Eigen::Isometry3d pose = scene.trunkPose();
    const auto leaning = scene.sternumImuPose();
    ASSERT_TRUE(leaning);
    EXPECT_TRUE(leaning->translation().isApprox(pose * upright->translation(), 1e-9));
    EXPECT_TRUE(leaning->linear().isApprox(trunkRotation(lean) * mount.imuRotation, 1e-9));
    // A mounting that is not a rotation is not drawn; none hides it again.
    TrunkMount bad = mount;
    bad.imuRotation(0, 0) = 2.0;
    scene.setSternumImu(bad);
    EXPECT_FALSE(scene.sternumImuPose());
    scene.setSternumImu(mount);
    EXPECT_TRUE(scene.sternumImuPose());
    scene.setSternumImu(std::nullopt);
    EXPECT_FALSE(scene.sternumImuPose());
  }
}

}  // namespace
}  // namespace armtrack::ui
