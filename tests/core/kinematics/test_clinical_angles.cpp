// The clinical sign conventions of docs/arm-model.md, checked on poses whose meaning is obvious.
#include <gtest/gtest.h>

#include "core/kinematics/ArmModel.h"
#include "core/kinematics/ClinicalAngles.h"

namespace armtrack {
namespace {

// Shoulder frame: x0 down, y0 forward, z0 lateral (right arm).
const Eigen::Vector3d kDown(1, 0, 0), kForward(0, 1, 0), kLateral(0, 0, 1);

TEST(ClinicalAngles, FlexionLiftsTheArmForward) {
  ClinicalAngles c;
  c.shoulderFlexion = 30;
  const ArmPose p = forwardKinematics({}, fromClinical(c));
  EXPECT_GT(p.elbow.dot(kForward), 0.05);
  EXPECT_NEAR(p.elbow.dot(kLateral), 0.0, 1e-12);
}

TEST(ClinicalAngles, AbductionLiftsTheArmSideways) {
  ClinicalAngles c;
  c.shoulderAbduction = 30;
  const ArmPose p = forwardKinematics({}, fromClinical(c));
  EXPECT_GT(p.elbow.dot(kLateral), 0.05);
  EXPECT_NEAR(p.elbow.dot(kForward), 0.0, 1e-12);
}

TEST(ClinicalAngles, ElbowFlexionBringsTheHandForward) {
  ClinicalAngles c;
  c.elbowFlexion = 90;
  const ArmPose p = forwardKinematics({}, fromClinical(c));
  EXPECT_NEAR((p.wrist - p.elbow).normalized().dot(kForward), 1.0, 1e-12);
}

TEST(ClinicalAngles, InternalRotationTurnsTheFlexedForearmInward) {
  ClinicalAngles c;
  c.elbowFlexion = 90;
  c.shoulderInternalRotation = 40;
  const ArmPose p = forwardKinematics({}, fromClinical(c));
  EXPECT_LT((p.wrist - p.elbow).dot(kLateral), -0.05);  // toward the trunk
}

TEST(ClinicalAngles, PronationTurnsTheThumbInward) {
  // th5 = 0: thumb forward. The forearm IMU's x axis lies along the thumb direction at zero
  // (Table 7 mounting); pronation must carry it toward the body's midline (-z0).
  ClinicalAngles c;
  c.forearmPronation = 45;
  const ArmPose p = forwardKinematics({}, fromClinical(c));
  const Eigen::Vector3d thumb = p.forearmImu.block<3, 1>(0, 0);
  EXPECT_LT(thumb.dot(kLateral), -0.5);
  EXPECT_GT(p.wrist.dot(kDown), 0.4);  // the arm still hangs
}

TEST(ClinicalAngles, RoundTripAndWrap) {
  ClinicalAngles c{10, 20, -30, 40, 50};
  const ClinicalAngles back = toClinical(fromClinical(c));
  const auto a = asArray(c), b = asArray(back);
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(a[i], b[i], 1e-9);
  JointVector th = JointVector::Zero();
  th(0) = 2 * std::numbers::pi + 0.1;
  EXPECT_NEAR(toClinical(th).shoulderFlexion, 0.1 * 180 / std::numbers::pi, 1e-9);
  EXPECT_EQ(clinicalAngleInfo().size(), 5u);
  EXPECT_EQ(clinicalAngleInfo()[3].key, "elbow_flexion");
}

}  // namespace
}  // namespace armtrack
