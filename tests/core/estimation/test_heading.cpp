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

// The heading covector against the forward kinematics: for any small change of the angles,
// w . dth is the vertical part of the upper arm's rotation (R' R^T by central differences of the
// upper-arm IMU frame), so it reads 1 along the generator and 0 for a change that only tilts the
// arm. The heading-blind IMU update holds exactly this, not the angles' component along h.
TEST(HeadingCovector, ReadsTheVerticalPartOfTheUpperArmsRotation) {
  std::mt19937_64 rng(17);
  std::normal_distribution<double> n(0.0, 1.0);
  const ArmGeometry geo;
  for (const Eigen::Vector3d& up : {kUprightUp, kLeaningUp}) {
    for (int k = 0; k < 200; ++k) {
      const JointVector th = randomAngles(rng);
      JointVector d;
      d << n(rng), n(rng), n(rng), n(rng), n(rng);
      const double e = 1e-6;
      const Eigen::Matrix3d rp = forwardKinematics(geo, th + e * d).upperImu.topLeftCorner<3, 3>();
      const Eigen::Matrix3d rm = forwardKinematics(geo, th - e * d).upperImu.topLeftCorner<3, 3>();
      const Eigen::Matrix3d r = forwardKinematics(geo, th).upperImu.topLeftCorner<3, 3>();
      const Eigen::Matrix3d skew = (rp - rm) / (2 * e) * r.transpose();
      const Eigen::Vector3d omega(skew(2, 1), skew(0, 2), skew(1, 0));
      const JointVector w = headingCovector(th, up);
      EXPECT_NEAR(w.dot(d), up.dot(omega), 1e-6 * (1.0 + d.norm())) << th.transpose();
      EXPECT_EQ(w.tail<2>(), JointVector::Zero().tail<2>());
      if (std::abs(std::cos(th(1))) > 0.2) {
        EXPECT_NEAR(w.dot(headingGenerator(th, up)), 1.0, 1e-9) << th.transpose();
      }
    }
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

// The mean squared joint change under a random turn, against a dense sum over the normal density
// (2,001 points over +-6 sd, the turn followed in steps of at most 0.24 deg): the independent
// truth the coarser sum must match. Large heading uncertainties (10-40 deg), where the turn bends
// far from its first-order step.
TEST(TurnSecondMoment, MatchesADenseIntegralOverTheTurn) {
  std::mt19937_64 rng(13);
  double worst = 0.0;
  int poses = 0;
  for (int k = 0; k < 60; ++k) {
    const JointVector th = randomAngles(rng);
    // Near the gimbal lock a turn swings flexion and rotation through half a circle within a few
    // degrees, and which way depends on how finely the turn is followed: not compared there.
    // About the upright vertical, a whole turn of the arm at th keeps |sin th1| below
    // sqrt(1 - (cos th0 cos th1)^2), so this keeps every turn 30 deg or more from the lock.
    if (std::abs(std::cos(th(0)) * std::cos(th(1))) < 0.5) continue;
    ++poses;
    for (const double sdDeg : {10.0, 25.0, 40.0}) {
      const double sd = sdDeg * kPi / 180.0;
      // Out to 6 sd each way (half a circle at most), in steps of 1/1000 of that, each turning
      // the last point on: the continuous turn, followed finely.
      JointVector dense = JointVector::Zero();
      double weights = 1.0;
      const double reach = std::min(6.0 * sd, kPi);
      for (const double sign : {-1.0, 1.0}) {
        JointVector turned = th;
        for (int i = 1; i <= 1000; ++i) {
          turned = turnAboutVertical(turned, sign * reach / 1000.0, kUprightUp);
          const double z = reach * i / 1000.0 / sd;
          const double w = std::exp(-0.5 * z * z);
          for (int j = 0; j < 3; ++j) dense(j) += w * std::pow(wrapAngle(turned(j) - th(j)), 2);
          weights += w;
        }
      }
      dense /= weights;
      const JointVector gh = turnSecondMoment(th, sd, kUprightUp);
      EXPECT_EQ(gh.tail<2>(), JointVector::Zero().tail<2>());
      for (int j = 0; j < 3; ++j) {
        // Relative to the joint's root mean square change, plus a floor for joints a turn hardly
        // moves; quadrature error grows where wrapping makes the change non-smooth.
        const double err = std::abs(std::sqrt(gh(j)) - std::sqrt(dense(j)));
        worst = std::max(worst, err / (std::sqrt(dense(j)) + 0.01));
        EXPECT_LT(err, 0.1 * std::sqrt(dense(j)) + 0.5 * kPi / 180.0)
            << "joint " << j << ", sd " << sdDeg << " deg, th " << th.transpose();
      }
    }
  }
  EXPECT_GE(poses, 10);
  std::printf("[ measured ] %d poses, worst relative rms mismatch of the sum: %.3g\n", poses,
              worst);
}

TEST(TurnSecondMoment, SmallTurnIsTheFirstOrderVariance) {
  std::mt19937_64 rng(17);
  for (int k = 0; k < 50; ++k) {
    const JointVector th = randomAngles(rng);
    if (std::abs(std::cos(th(1))) < 0.2) continue;  // near the gimbal lock nothing is small
    const double sd = 1e-3;
    const JointVector h = headingGenerator(th, kLeaningUp);
    const JointVector m = turnSecondMoment(th, sd, kLeaningUp);
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(m(j), sd * sd * h(j) * h(j), 1e-3 * sd * sd * (1.0 + h.squaredNorm()));
  }
}

}  // namespace
}  // namespace armtrack
