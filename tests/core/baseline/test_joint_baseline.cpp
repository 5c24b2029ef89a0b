// The complementary baseline (core/baseline/JointBaseline.h) against analytic cases: its model
// against the arm model's forward kinematics, a constant-rate hinge, a static pose, the
// lever-arm compensation in a known circular motion, its Jacobian against finite differences,
// and hostile input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/baseline/BaselineStudy.h"
#include "core/baseline/JointBaseline.h"
#include "core/kinematics/ArmModel.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
const Eigen::Vector3d kGUp(-9.81, 0.0, 0.0);

JointVector pose(double th0, double th1, double th2, double th4, double th5) {
  JointVector th;
  th << th0, th1, th2, th4, th5;
  return th;
}

/// The arm model's readings for a motion, as a simulator makes them.
ArmSample sampleAt(double t, const JointVector& th, const JointVector& thd = JointVector::Zero(),
                   const JointVector& thdd = JointVector::Zero(),
                   const ArmGeometry& geo = ArmGeometry{}) {
  const ArmPrediction p = predictSensors(geo, th, thd, thdd, kGUp);
  ArmSample s;
  s.t = t;
  s.upperArm = ImuReading{p.upper.gyr, p.upper.acc};
  s.forearm = ImuReading{p.forearm.gyr, p.forearm.acc};
  s.trueAngles = th;
  return s;
}

BaselineParams params() {
  BaselineParams p;
  p.gUp = kGUp;
  return p;
}

TEST(JointBaseline, ElbowModelMatchesTheArmModelsForwardKinematics) {
  const ArmGeometry geo;
  const ElbowModel m(geo);
  for (const JointVector& th : {pose(0.3, -0.2, 0.5, -1.1, 0.7), pose(-0.4, 0.9, -0.8, 0.2, -2.5),
                                pose(1.2, 0.1, 0.0, -2.0, 1.5)}) {
    const ArmPose fk = forwardKinematics(geo, th);
    const Eigen::Matrix3d ru = fk.upperImu.topLeftCorner<3, 3>();
    const Eigen::Matrix3d rf = fk.forearmImu.topLeftCorner<3, 3>();
    const Eigen::Vector3d pu = fk.upperImu.topRightCorner<3, 1>();
    const Eigen::Vector3d pf = fk.forearmImu.topRightCorner<3, 1>();
    EXPECT_LT((m.relative(th(3), th(4)) - ru.transpose() * rf).norm(), 1e-12);
    EXPECT_LT((m.elbowFromUpper - ru.transpose() * (fk.elbow - pu)).norm(), 1e-12);
    EXPECT_LT((m.elbowFromFore - rf.transpose() * (fk.elbow - pf)).norm(), 1e-12);
    EXPECT_LT((m.shoulderFromUpper - ru.transpose() * (-pu)).norm(), 1e-12);
    EXPECT_LT((m.humerus - ru.transpose() * fk.elbow.normalized()).norm(), 1e-12);
  }
}

TEST(JointBaseline, ConstantRateHingeIsIntegratedExactly) {
  // The upper arm still, the elbow turning at 1 rad/s. After the first row the accelerometers
  // read nothing (zero), so only the relative gyroscope rate moves the angle.
  JointBaseline b(params());
  BaselineRow row;
  const double rate = 1.0, th40 = -0.3, th5 = 0.4;
  const double dt = 0.001;
  for (int i = 0; i <= 1000; ++i) {
    const double t = i * dt;
    ArmSample s = sampleAt(t, pose(0.2, 0.1, 0.3, th40 - rate * t, th5), pose(0, 0, 0, -rate, 0));
    if (i > 0) {
      s.upperArm->acc.setZero();
      s.forearm->acc.setZero();
    }
    ASSERT_TRUE(b.push(s, row));
    EXPECT_NEAR(row.flexion, th40 - rate * t, 1e-9) << "t = " << t;
    EXPECT_NEAR(row.pronation, th5, 1e-9);
  }
  // The first zero reading is refused (no specific force); the rest repeat it and are stale.
  EXPECT_EQ(b.counters().accelSkipped, 1u);
  EXPECT_EQ(b.counters().repeatedAccel, 2 * 999u);
}

TEST(JointBaseline, StaticPoseGivesTheGravityInclinationExactly) {
  for (const JointVector& th : {pose(0.7, 0.3, 0.2, -1.0, 0.4), pose(-0.3, 0.8, -0.6, -0.5, -1.2),
                                pose(1.9, 0.2, 0.4, -1.6, 0.9)}) {
    JointBaseline b(params());
    BaselineRow row;
    for (int i = 0; i < 50; ++i) ASSERT_TRUE(b.push(sampleAt(0.01 * i, th), row));
    EXPECT_NEAR(row.elevation, humerusElevation(th, kGUp.normalized()), 1e-9);
    EXPECT_NEAR(row.flexion, th(3), 1e-7);
    EXPECT_NEAR(row.pronation, th(4), 1e-7);
  }
}

TEST(JointBaseline, LeverArmCompensationRemovesTheCentripetalTerm) {
  // Shoulder flexion at a constant 3 rad/s: the upper-arm IMU goes round a circle about the
  // shoulder and reads a centripetal acceleration of w^2 r beside gravity.
  const ArmGeometry geo;
  const ElbowModel m(geo);
  const double w = 3.0;
  for (double t : {0.0, 0.4, 1.1}) {
    const JointVector th = pose(w * t, 0.2, 0.0, -0.8, 0.0);
    const JointVector thd = pose(w, 0, 0, 0, 0);
    const ArmSample s = sampleAt(t, th, thd, JointVector::Zero(), geo);
    const Eigen::Matrix3d ru = forwardKinematics(geo, th).upperImu.topLeftCorner<3, 3>();
    const Eigen::Vector3d gravity = ru.transpose() * kGUp;
    // Raw, the accelerometer is off gravity by the centripetal term ...
    EXPECT_GT((s.upperArm->acc - gravity).norm(), 0.5 * w * w * geo.lu3);
    // ... and carried to the shoulder's centre (a fixed point) it reads gravity alone.
    const Eigen::Vector3d atShoulder = leverArmShift(s.upperArm->acc, s.upperArm->gyr,
                                                     Eigen::Vector3d::Zero(), m.shoulderFromUpper);
    EXPECT_LT((atShoulder - gravity).norm(), 1e-9);
  }
  // And the baseline's elevation follows the circle.
  JointBaseline b(params());
  BaselineRow row;
  double worst = 0.0;
  for (int i = 0; i <= 3000; ++i) {
    const double t = 0.001 * i;
    const JointVector th = pose(w * t, 0.2, 0.0, -0.8, 0.0);
    ASSERT_TRUE(b.push(sampleAt(t, th, pose(w, 0, 0, 0, 0)), row));
    worst = std::max(worst, std::abs(row.elevation - humerusElevation(th, kGUp.normalized())));
  }
  EXPECT_LT(worst, 0.05 * kDegree);
}

TEST(JointBaseline, AccelStepJacobianMatchesFiniteDifferences) {
  const ElbowModel m{ArmGeometry{}};
  const Eigen::Vector3d fu(0.3, -9.0, 2.0), ff(-4.0, 1.0, 8.5);
  for (const Eigen::Vector2d& th : {Eigen::Vector2d(-0.7, 0.3), Eigen::Vector2d(0.2, -1.9)}) {
    const ElbowAccelStep s = elbowAccelStep(m, th(0), th(1), fu, ff, 1e-3);
    const double h = 1e-6;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d a = th, b = th;
      a(k) += h;
      b(k) -= h;
      const Eigen::Vector3d fd =
          (m.relative(a(0), a(1)) * ff.normalized() - m.relative(b(0), b(1)) * ff.normalized()) /
          (2 * h);
      EXPECT_LT((fd - s.jacobian.col(k)).norm(), 1e-8) << "column " << k;
    }
  }
}

TEST(JointBaseline, FollowsTheArmModelsOwnMotion) {
  // Ideal readings of a smooth five-joint motion: the baseline's angles stay close to the truth.
  JointBaseline b(params());
  BaselineRow row;
  double worstFlex = 0.0, worstElev = 0.0;
  for (int i = 0; i <= 10000; ++i) {
    const double t = 0.001 * i;
    const double c = std::cos(t), s = std::sin(t);
    const JointVector th = pose(0.5 + 0.4 * s, 0.3 + 0.2 * s, 0.2 * s, -1.0 + 0.5 * s, 0.3 * s);
    const JointVector thd = pose(0.4 * c, 0.2 * c, 0.2 * c, 0.5 * c, 0.3 * c);
    const JointVector thdd = -pose(0.4 * s, 0.2 * s, 0.2 * s, 0.5 * s, 0.3 * s);
    ASSERT_TRUE(b.push(sampleAt(t, th, thd, thdd), row));
    worstFlex = std::max(worstFlex, std::abs(row.flexion - th(3)));
    worstElev = std::max(worstElev,
                         std::abs(row.elevation - humerusElevation(th, Eigen::Vector3d(-1, 0, 0))));
  }
  EXPECT_LT(worstFlex, 0.1 * kDegree);
  EXPECT_LT(worstElev, 0.1 * kDegree);
}

TEST(JointBaseline, HostileInputIsCountedOrRefused) {
  const JointVector th = pose(0.3, 0.2, 0.1, -0.9, 0.2);
  JointBaseline b(params());
  BaselineRow row;
  ASSERT_TRUE(b.push(sampleAt(0.00, th), row));
  EXPECT_TRUE(row.restarted);
  ASSERT_TRUE(b.push(sampleAt(0.01, th), row));
  EXPECT_FALSE(row.restarted);
  // A NaN in both IMUs: no row, counted.
  ArmSample bad = sampleAt(0.02, th);
  bad.upperArm->gyr.x() = std::numeric_limits<double>::quiet_NaN();
  bad.forearm->acc.z() = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(b.push(bad, row));
  EXPECT_EQ(b.counters().nonFinite, 2u);
  // A time that goes back, or is not a number: refused, counted.
  EXPECT_FALSE(b.push(sampleAt(0.005, th), row));
  ArmSample nanTime = sampleAt(0.0, th);
  nanTime.t = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(b.push(nanTime, row));
  EXPECT_EQ(b.counters().rejectedTime, 2u);
  // A gap longer than maxGap restarts, and the row says so.
  ASSERT_TRUE(b.push(sampleAt(5.0, th), row));
  EXPECT_TRUE(row.restarted);
  EXPECT_EQ(b.counters().restarts, 1u);
  EXPECT_NEAR(row.flexion, th(3), 1e-7);
  // Optical-only rows are not the baseline's business.
  ArmSample optical;
  optical.t = 5.1;
  optical.elbow = Eigen::Vector3d(0.2, 0.0, 0.0);
  EXPECT_FALSE(b.push(optical, row));
  EXPECT_EQ(b.counters().rows, 7u);
}

TEST(JointBaseline, WithoutAForearmIMUOnlyTheElevationIsEstimated) {
  const JointVector th = pose(0.6, 0.1, 0.0, -0.5, 0.0);
  JointBaseline b(params());
  BaselineRow row;
  for (int i = 0; i < 10; ++i) {
    ArmSample s = sampleAt(0.01 * i, th);
    s.forearm.reset();
    ASSERT_TRUE(b.push(s, row));
    EXPECT_TRUE(std::isnan(row.flexion));
    EXPECT_TRUE(std::isnan(row.pronation));
    EXPECT_NEAR(row.elevation, humerusElevation(th, Eigen::Vector3d(-1, 0, 0)), 1e-9);
  }
  EXPECT_EQ(b.counters().withoutForearm, 10u);
  // A forearm alone gives nothing.
  JointBaseline f(params());
  ArmSample s = sampleAt(0.0, th);
  s.upperArm.reset();
  EXPECT_FALSE(f.push(s, row));
  EXPECT_EQ(f.counters().withoutUpper, 1u);
}

TEST(JointBaseline, BadParametersAreRefused) {
  BaselineParams p = params();
  p.timeConstant = 0.0;
  EXPECT_THROW(JointBaseline{p}, std::invalid_argument);
  p = params();
  p.timeConstant = std::numeric_limits<double>::infinity();
  EXPECT_THROW(JointBaseline{p}, std::invalid_argument);
  p = params();
  p.gUp.setZero();
  EXPECT_THROW(JointBaseline{p}, std::invalid_argument);
  p = params();
  p.maxGap = -1.0;
  EXPECT_THROW(JointBaseline{p}, std::invalid_argument);
  p = params();
  p.elbowFromForearm = Eigen::Vector3d(std::nan(""), 0, 0);
  EXPECT_THROW(JointBaseline{p}, std::invalid_argument);
}

TEST(JointBaseline, ALeftArmGivesTheSameAnglesAsItsRightTwin) {
  SimulationParams sim = defaultSimulation();
  sim.duration = 3.0;
  sim.kinect.enabled = false;
  SinusoidTrajectory traj;
  traj.offset = pose(0.4, 0.3, 0.1, -1.0, 0.2);
  traj.amplitude = JointVector::Constant(0.3);
  traj.frequency = JointVector::Constant(0.4);
  const Recording right = simulateRecording(traj, sim);
  sim.side = Side::Left;
  const Recording left = simulateRecording(traj, sim);
  ASSERT_EQ(left.meta.side, Side::Left);
  std::vector<BaselineRow> r, l;
  runBaseline(right, baselineParamsFor(right.meta), [&](const BaselineRow& x) { r.push_back(x); });
  runBaseline(left, baselineParamsFor(left.meta), [&](const BaselineRow& x) { l.push_back(x); });
  ASSERT_EQ(r.size(), l.size());
  ASSERT_GT(r.size(), 2000u);
  for (std::size_t i = 0; i < r.size(); ++i) {
    EXPECT_NEAR(r[i].flexion, l[i].flexion, 1e-9);
    EXPECT_NEAR(r[i].pronation, l[i].pronation, 1e-9);
    EXPECT_NEAR(r[i].elevation, l[i].elevation, 1e-9);
  }
  EXPECT_LT(runBaseline(left, baselineParamsFor(left.meta)).errors.hinge.rmseDeg(), 1.0);
}

TEST(JointBaseline, IsDeterministic) {
  std::vector<BaselineRow> first, second;
  for (auto* rows : {&first, &second}) {
    JointBaseline b(params());
    BaselineRow row;
    for (int i = 0; i < 500; ++i) {
      const double t = 0.002 * i;
      if (b.push(sampleAt(t, pose(std::sin(t), 0.1, 0.2, -1 + 0.3 * std::sin(2 * t), 0.1),
                          pose(std::cos(t), 0, 0, 0.6 * std::cos(2 * t), 0)),
                 row))
        rows->push_back(row);
    }
  }
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].flexion, second[i].flexion);
    EXPECT_EQ(first[i].elevation, second[i].elevation);
  }
}

}  // namespace
}  // namespace armtrack
