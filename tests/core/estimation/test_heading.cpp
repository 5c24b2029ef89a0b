// The heading turn in joint space against the arm model: turning the joint angles with
// turnAboutVertical must turn every point and frame of the forward kinematics by the same
// rotation about the vertical through the shoulder, whatever the angle; and for a small turn it
// must step along headingGenerator.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "core/estimation/Heading.h"
#include "core/kinematics/ArmModel.h"

namespace armtrack {
namespace {

constexpr double kPi = std::numbers::pi;

JointVector randomAngles(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  JointVector th;
  th << kPi * u(rng), 1.4 * u(rng), kPi * u(rng), kPi * u(rng), kPi * u(rng);
  return th;
}

// Frame 0: x0 down, so the vertical is -x0; a leaning trunk tilts it.
const Eigen::Vector3d kUprightUp(-1.0, 0.0, 0.0);
const Eigen::Vector3d kLeaningUp = Eigen::Vector3d(-1.0, 0.25, -0.15).normalized();

TEST(TurnAboutVertical, TurnsTheWholeArmByTheSameRotation) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  const ArmGeometry geo;
  double worst = 0.0;
  for (const Eigen::Vector3d& up : {kUprightUp, kLeaningUp}) {
    for (int k = 0; k < 300; ++k) {
      const JointVector th = randomAngles(rng);
      const double a = angle(rng);
      const JointVector turned = turnAboutVertical(th, a, up);
      const Eigen::Matrix3d r = Eigen::AngleAxisd(a, up).toRotationMatrix();
      const ArmPose before = forwardKinematics(geo, th);
      const ArmPose after = forwardKinematics(geo, turned);
      const double err = std::max(
          {(after.elbow - r * before.elbow).norm(), (after.wrist - r * before.wrist).norm(),
           (after.forearmImu.topLeftCorner<3, 3>() - r * before.forearmImu.topLeftCorner<3, 3>())
               .norm(),
           (after.upperImu.topLeftCorner<3, 3>() - r * before.upperImu.topLeftCorner<3, 3>())
               .norm()});
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-9) << "th " << th.transpose() << " turn " << a;
      EXPECT_EQ(turned.tail<2>(), th.tail<2>());
      for (int j = 0; j < 3; ++j) EXPECT_LE(std::abs(turned(j)), kPi);
    }
  }
  std::printf("[ measured ] worst pose mismatch after a turn: %.3g\n", worst);
}

TEST(TurnAboutVertical, SmallTurnStepsAlongTheGenerator) {
  std::mt19937_64 rng(7);
  for (int k = 0; k < 100; ++k) {
    const JointVector th = randomAngles(rng);
    if (std::abs(std::cos(th(1))) < 0.2) continue;  // too near the gimbal lock for a 1e-5 step
    const double a = 1e-5;
    const JointVector step = (turnAboutVertical(th, a, kLeaningUp) - th) / a;
    const JointVector h = headingGenerator(th, kLeaningUp);
    EXPECT_LT((step - h).norm(), 1e-4 * (1.0 + h.norm())) << th.transpose();
  }
}

TEST(TurnAboutVertical, ZeroTurnAndFullCircleReturnTheSameArm) {
  std::mt19937_64 rng(11);
  const ArmGeometry geo;
  for (int k = 0; k < 50; ++k) {
    const JointVector th = randomAngles(rng);
    EXPECT_LT((turnAboutVertical(th, 0.0, kUprightUp) - th).norm(), 1e-12);
    const JointVector full = turnAboutVertical(th, 2 * kPi, kUprightUp);
    EXPECT_LT((forwardKinematics(geo, full).wrist - forwardKinematics(geo, th).wrist).norm(), 1e-9);
  }
}

}  // namespace
}  // namespace armtrack
