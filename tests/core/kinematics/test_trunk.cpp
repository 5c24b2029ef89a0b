// Trunk angles against their definition in words (core/kinematics/Trunk.h): where the trunk's up
// axis and the right shoulder go when the patient leans or turns.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "core/kinematics/Trunk.h"

using namespace armtrack;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
const Eigen::Vector3d kUp{-1.0, 0.0, 0.0};       // x0 points down
const Eigen::Vector3d kForward{0.0, 1.0, 0.0};   // y0
const Eigen::Vector3d kPatientRight{0, 0, 1.0};  // z0 of a right arm
}  // namespace

TEST(Trunk, UprightIsIdentity) {
  EXPECT_TRUE(trunkRotation(TrunkAngles::Zero()).isApprox(Eigen::Matrix3d::Identity()));
  EXPECT_TRUE(trunkRotation(TrunkAngles::Zero(), Side::Left).isApprox(Eigen::Matrix3d::Identity()));
}

TEST(Trunk, SignsFollowThePatientsWords) {
  // Forward flexion of 20 deg tips the trunk's up axis 20 deg towards forward.
  const Eigen::Vector3d up = trunkRotation({20 * kDeg, 0, 0}) * kUp;
  EXPECT_NEAR(up.dot(kForward), std::sin(20 * kDeg), 1e-12);
  EXPECT_NEAR(up.dot(kUp), std::cos(20 * kDeg), 1e-12);
  // Lateral bending to the right tips it towards the patient's right.
  const Eigen::Vector3d upLat = trunkRotation({0, 10 * kDeg, 0}) * kUp;
  EXPECT_NEAR(upLat.dot(kPatientRight), std::sin(10 * kDeg), 1e-12);
  // Axial rotation brings the right shoulder (lateral, +z0) forward and keeps up up.
  const Eigen::Matrix3d rot = trunkRotation({0, 0, 10 * kDeg});
  EXPECT_NEAR((rot * kPatientRight).dot(kForward), std::sin(10 * kDeg), 1e-12);
  EXPECT_NEAR((rot * kUp).dot(kUp), 1.0, 1e-12);
  // A left arm estimated as its mirror image (z0 reversed): the same words give the mirrored
  // rotation.
  for (const TrunkAngles& a :
       {TrunkAngles(20 * kDeg, 0, 0), TrunkAngles(0, 10 * kDeg, 0), TrunkAngles(0, 0, 10 * kDeg),
        TrunkAngles(15 * kDeg, -8 * kDeg, 6 * kDeg)}) {
    const Eigen::Matrix3d m = Eigen::Vector3d(1, 1, -1).asDiagonal();
    EXPECT_TRUE(trunkRotation(a, Side::Left).isApprox(m * trunkRotation(a) * m, 1e-12));
  }
}

TEST(Trunk, AnglesRoundTripWithinTheTrunksRange) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> flex(-30 * kDeg, 60 * kDeg), side(-40 * kDeg, 40 * kDeg);
  for (int i = 0; i < 500; ++i) {
    const TrunkAngles a(flex(rng), side(rng), side(rng));
    for (Side s : {Side::Right, Side::Left}) {
      const TrunkAngles back = trunkAngles(trunkRotation(a, s), s);
      EXPECT_NEAR((back - a).cwiseAbs().maxCoeff(), 0.0, 1e-12) << i;
    }
  }
}
