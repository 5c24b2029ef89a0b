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

// headingSymmetry's rate and acceleration parts are the exact derivatives Dh th' and
// Dh th'' + D2h[th', th'] of the generator h (normalised by |h|): against central differences of
// headingGenerator along th' and th'', Richardson-extrapolated over two steps. The first
// derivative's differences are good to about 1e-12 here; the second's carry round-off of about
// 1e-16 |h| / step^2, a few 1e-8 at the largest rates, whatever the step.
TEST(HeadingSymmetry, RateAndAccelerationPartsAreTheGeneratorsDerivatives) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> rate(-3.0, 3.0), acc(-30.0, 30.0);
  double worstRate = 0.0, worstAcc = 0.0;
  int checked = 0;
  for (const Eigen::Vector3d& up : {kUprightUp, kLeaningUp}) {
    for (int k = 0; k < 200; ++k) {
      const JointVector th = randomAngles(rng);
      if (std::abs(std::cos(th(1))) < 0.2) continue;  // the damped solve bends near the lock
      JointVector thd, thdd;
      for (int j = 0; j < 5; ++j) thd(j) = rate(rng), thdd(j) = acc(rng);
      Eigen::Matrix<double, 15, 1> x;
      x << thdd, thd, th;
      const JointVector h = headingGenerator(th, up);
      const Eigen::Matrix<double, 15, 1> v = headingSymmetry(x, up) * h.norm();
      // First and second central differences along d with step e.
      auto diff = [&](const JointVector& d, double e, JointVector& d1, JointVector& d2) {
        const JointVector hp = headingGenerator(th + e * d, up);
        const JointVector hm = headingGenerator(th - e * d, up);
        d1 = (hp - hm) / (2 * e);
        d2 = (hp - 2 * h + hm) / (e * e);
      };
      auto extrapolated = [&](const JointVector& d, JointVector& d1, JointVector& d2) {
        const double e = 1e-3 / d.norm();
        JointVector a1, a2, b1, b2;
        diff(d, e, a1, a2);
        diff(d, e / 2, b1, b2);
        d1 = (4 * b1 - a1) / 3;
        d2 = (4 * b2 - a2) / 3;
      };
      JointVector dRate, d2Rate, dAcc, unused;
      extrapolated(thd, dRate, d2Rate);
      extrapolated(thdd, dAcc, unused);
      const JointVector accTruth = dAcc + d2Rate;
      const double errRate = (v.segment<5>(5) - dRate).norm() / (1.0 + dRate.norm());
      const double errAcc = (v.segment<5>(0) - accTruth).norm() / (1.0 + accTruth.norm());
      worstRate = std::max(worstRate, errRate);
      worstAcc = std::max(worstAcc, errAcc);
      EXPECT_LT(errRate, 1e-9) << th.transpose() << " | " << thd.transpose();
      EXPECT_LT(errAcc, 2e-7) << th.transpose() << " | " << thd.transpose();
      EXPECT_EQ(v.segment<2>(3), Eigen::Vector2d::Zero());
      EXPECT_EQ(v.segment<2>(8), Eigen::Vector2d::Zero());
      ++checked;
    }
  }
  EXPECT_GE(checked, 200);
  std::printf("[ measured ] %d states, worst relative mismatch: rates %.3g, accelerations %.3g\n",
              checked, worstRate, worstAcc);
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
