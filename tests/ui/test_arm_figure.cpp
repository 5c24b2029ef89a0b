// The arm figure the 3D view draws, against the arm model's own forward kinematics and the
// mirror rule of docs/arm-model.md.
#include <gtest/gtest.h>

#include <numbers>

#include "ui/ArmFigure.h"

namespace armtrack::ui {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

JointVector somePose() {
  JointVector th;
  th << 40 * kDeg, 25 * kDeg, -15 * kDeg, -70 * kDeg, 30 * kDeg;
  return th;
}

TEST(ArmFigure, RightArmIsTheModelsForwardKinematics) {
  const ArmGeometry geo;
  const ArmPose pose = forwardKinematics(geo, somePose());
  const ArmFigure f = armFigure(geo, somePose(), Side::Right);
  EXPECT_TRUE(f.shoulder.isZero());
  EXPECT_TRUE(f.elbow.isApprox(pose.elbow, 1e-12));
  EXPECT_TRUE(f.wrist.isApprox(pose.wrist, 1e-12));
  EXPECT_TRUE(f.upperImu.matrix().isApprox(pose.upperImu, 1e-12));
  EXPECT_TRUE(f.forearmImu.matrix().isApprox(pose.forearmImu, 1e-12));
  EXPECT_NEAR(f.elbow.norm(), geo.l3, 1e-12);
  EXPECT_NEAR((f.wrist - f.elbow).norm(), geo.l6, 1e-12);
  // The straps sit on the segments, at the model's distances.
  EXPECT_NEAR(f.upperStrap.norm(), geo.lu3, 1e-12);
  EXPECT_NEAR((f.forearmStrap - f.elbow).norm(), geo.lf6, 1e-12);
  EXPECT_NEAR((f.upperImu.translation() - f.upperStrap).norm(), geo.lu5, 1e-12);
}

TEST(ArmFigure, ZeroPoseHangsDownWithThePalmTowardsTheBody) {
  const ArmGeometry geo;
  const ArmFigure f = armFigure(geo, JointVector::Zero(), Side::Right);
  EXPECT_TRUE(f.elbow.isApprox(Eigen::Vector3d(geo.l3, 0, 0), 1e-12));
  EXPECT_TRUE(f.wrist.isApprox(Eigen::Vector3d(geo.l3 + geo.l6, 0, 0), 1e-12));
  EXPECT_TRUE(f.hand.col(0).isApprox(Eigen::Vector3d::UnitX(), 1e-12));
  // Thumb forward: the palm's normal is medial-lateral (z0), its width forward (y0).
  EXPECT_NEAR(std::abs(f.hand.col(2).z()), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(f.hand.col(1).y()), 1.0, 1e-12);
  EXPECT_NEAR(f.hand.determinant(), 1.0, 1e-12);
}

TEST(ArmFigure, PronationTurnsTheHand) {
  const ArmGeometry geo;
  JointVector th = JointVector::Zero();
  th(4) = -90 * kDeg;  // pronation 90 deg: the palm now faces backwards or forwards
  const ArmFigure f = armFigure(geo, th, Side::Right);
  EXPECT_NEAR(std::abs(f.hand.col(2).y()), 1.0, 1e-9);
}

TEST(ArmFigure, LeftArmIsTheMirrorImage) {
  const ArmGeometry geo;
  const ArmFigure r = armFigure(geo, somePose(), Side::Right);
  const ArmFigure l = armFigure(geo, somePose(), Side::Left);
  const Eigen::Matrix3d s = Eigen::Vector3d(1, 1, -1).asDiagonal();
  EXPECT_TRUE(l.elbow.isApprox(s * r.elbow, 1e-12));
  EXPECT_TRUE(l.wrist.isApprox(s * r.wrist, 1e-12));
  EXPECT_TRUE(l.upperImu.linear().isApprox(s * r.upperImu.linear() * s, 1e-12));
  EXPECT_NEAR(l.upperImu.linear().determinant(), 1.0, 1e-12);
  EXPECT_NEAR(l.forearmImu.linear().determinant(), 1.0, 1e-12);
  EXPECT_NEAR(l.hand.determinant(), 1.0, 1e-12);
  // Abduction takes each arm away from the body: lateral is -medial.
  JointVector abducted = JointVector::Zero();
  abducted(1) = 80 * kDeg;
  EXPECT_LT(armFigure(geo, abducted, Side::Right).wrist.dot(medialDirection(Side::Right)), -0.3);
  EXPECT_LT(armFigure(geo, abducted, Side::Left).wrist.dot(medialDirection(Side::Left)), -0.3);
}

}  // namespace
}  // namespace armtrack::ui
