// The DH model against hand-computed poses, and the rigid-body recursion (eqs. 11-18) against
// numerical differentiation of the forward kinematics.
#include <gtest/gtest.h>

#include <cmath>

#include <random>

#include "core/kinematics/ArmModel.h"

namespace armtrack {
namespace {

constexpr double kPi = std::numbers::pi;

JointVector joints(double a, double b, double c, double d, double e) {
  JointVector th;
  th << a, b, c, d, e;
  return th;
}

void expectNear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tol) {
  EXPECT_LT((a - b).norm(), tol) << "got " << a.transpose() << ", expected " << b.transpose();
}

// Poses worked out by hand from Tables 1-4 with x0 down, y0 forward, z0 lateral.
TEST(ArmModel, ZeroPoseHangsStraightDown) {
  const ArmGeometry g;
  const ArmPose p = forwardKinematics(g, JointVector::Zero());
  expectNear(p.elbow, {g.l3, 0, 0}, 1e-12);
  expectNear(p.wrist, {g.l3 + g.l6, 0, 0}, 1e-12);
  // Upper-arm IMU: lu3 down the arm, lu5 out along z0 (thu4 = pi/2), its z axis lateral.
  expectNear(p.upperImu.block<3, 1>(0, 3), {g.lu3, 0, g.lu5}, 1e-12);
  Eigen::Matrix3d ru;
  ru << 0, 1, 0, -1, 0, 0, 0, 0, 1;
  EXPECT_LT((p.upperImu.topLeftCorner<3, 3>() - ru).norm(), 1e-12);
  // Forearm IMU: lf6 beyond the elbow, lf8 medial (thf7 = pi/2), its x axis forward.
  expectNear(p.forearmImu.block<3, 1>(0, 3), {g.l3 + g.lf6, 0, -g.lf8}, 1e-12);
  Eigen::Matrix3d rf;
  rf << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  EXPECT_LT((p.forearmImu.topLeftCorner<3, 3>() - rf).norm(), 1e-12);
}

TEST(ArmModel, SingleJointPoses) {
  const ArmGeometry g;
  // 90 deg flexion: the straight arm points forward.
  ArmPose p = forwardKinematics(g, joints(kPi / 2, 0, 0, 0, 0));
  expectNear(p.elbow, {0, g.l3, 0}, 1e-12);
  expectNear(p.wrist, {0, g.l3 + g.l6, 0}, 1e-12);
  // 90 deg abduction: the arm points sideways.
  p = forwardKinematics(g, joints(0, kPi / 2, 0, 0, 0));
  expectNear(p.elbow, {0, 0, g.l3}, 1e-12);
  // Elbow flexed 90 deg (th4 = -90 deg): forearm forward.
  p = forwardKinematics(g, joints(0, 0, 0, -kPi / 2, 0));
  expectNear(p.elbow, {g.l3, 0, 0}, 1e-12);
  expectNear(p.wrist, {g.l3, g.l6, 0}, 1e-12);
  // ... then 90 deg external rotation (th2 = +90 deg) swings the forearm outward.
  p = forwardKinematics(g, joints(0, 0, kPi / 2, -kPi / 2, 0));
  expectNear(p.wrist, {g.l3, 0, g.l6}, 1e-12);
  // Pronation/supination turns the forearm IMU about the forearm axis but leaves the wrist.
  const ArmPose a = forwardKinematics(g, joints(0.3, 0.2, 0.1, -1.0, 0.0));
  const ArmPose b = forwardKinematics(g, joints(0.3, 0.2, 0.1, -1.0, 0.8));
  expectNear(a.wrist, b.wrist, 1e-12);
  EXPECT_GT((a.forearmImu.block<3, 1>(0, 3) - b.forearmImu.block<3, 1>(0, 3)).norm(), 1e-3);
}

TEST(ArmModel, SegmentLengthsArePreservedEverywhere) {
  const ArmGeometry g;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-kPi, kPi);
  for (int i = 0; i < 200; ++i) {
    const JointVector th = joints(u(rng), u(rng), u(rng), u(rng), u(rng));
    const ArmPose p = forwardKinematics(g, th);
    EXPECT_NEAR(p.elbow.norm(), g.l3, 1e-12);
    EXPECT_NEAR((p.wrist - p.elbow).norm(), g.l6, 1e-12);
    const Eigen::Matrix3d r = p.upperImu.topLeftCorner<3, 3>();
    EXPECT_LT((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  }
}

TEST(ArmModel, RecursionPositionsMatchTheTables) {
  const ArmGeometry g;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-kPi, kPi);
  const JointVector zero = JointVector::Zero();
  for (int i = 0; i < 50; ++i) {
    const JointVector th = joints(u(rng), u(rng), u(rng), u(rng), u(rng));
    const ArmPose p = forwardKinematics(g, th);
    const ArmKinematics<double> k = armKinematics<double>(g, th, zero, zero, {-9.81, 0, 0});
    expectNear(k.elbow, p.elbow, 1e-12);
    expectNear(k.wrist, p.wrist, 1e-12);
    // Gravity carried down the recursion equals the tables' rotation applied to g * up.
    const Eigen::Vector3d gUp(-9.81, 0, 0);
    expectNear(k.upperImu.up, p.upperImu.topLeftCorner<3, 3>().transpose() * gUp, 1e-12);
    expectNear(k.forearmImu.up, p.forearmImu.topLeftCorner<3, 3>().transpose() * gUp, 1e-12);
  }
}

// A smooth random joint trajectory with analytic derivatives.
struct Wave {
  JointVector a, b, w, phi;
  JointVector th(double t) const {
    return a + b.cwiseProduct((w * t + phi).array().sin().matrix());
  }
  JointVector thd(double t) const {
    return b.cwiseProduct(w).cwiseProduct((w * t + phi).array().cos().matrix());
  }
  JointVector thdd(double t) const {
    return -b.cwiseProduct(w).cwiseProduct(w).cwiseProduct((w * t + phi).array().sin().matrix());
  }
};

Eigen::Vector3d vee(const Eigen::Matrix3d& s) {
  return {0.5 * (s(2, 1) - s(1, 2)), 0.5 * (s(0, 2) - s(2, 0)), 0.5 * (s(1, 0) - s(0, 1))};
}

// Five-point central differences of a function of time.
template <typename F>
auto d1(F f, double t, double h) {
  return ((f(t - 2 * h) - 8 * f(t - h) + 8 * f(t + h) - f(t + 2 * h)) / (12 * h)).eval();
}
template <typename F>
auto d2(F f, double t, double h) {
  return ((-f(t - 2 * h) + 16 * f(t - h) - 30 * f(t) + 16 * f(t + h) - f(t + 2 * h)) / (12 * h * h))
      .eval();
}

double relErr(const Eigen::Vector3d& got, const Eigen::Vector3d& ref) {
  return (got - ref).norm() / std::max(ref.norm(), 1e-3);
}

TEST(ArmModel, RecursionMatchesNumericalDifferentiation) {
  ArmGeometry g;
  g.thu4 = 1.1;  // off the default so no term hides behind a zero
  g.thf7 = 0.4;
  const Eigen::Vector3d gUp(-9.81, 0, 0);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> amp(0.2, 1.2), freq(1.0, 8.0), ph(-kPi, kPi);
  const double h = 1e-3;
  double worst = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Wave wave;
    for (int j = 0; j < 5; ++j) {
      wave.a(j) = ph(rng) * 0.5;
      wave.b(j) = amp(rng);
      wave.w(j) = freq(rng);
      wave.phi(j) = ph(rng);
    }
    const double t = std::uniform_real_distribution<double>(0.0, 3.0)(rng);
    const ArmKinematics<double> k =
        armKinematics<double>(g, wave.th(t), wave.thd(t), wave.thdd(t), gUp);

    for (int which = 0; which < 2; ++which) {
      auto rot = [&](double s) -> Eigen::Matrix3d {
        const ArmPose p = forwardKinematics(g, wave.th(s));
        return (which == 0 ? p.upperImu : p.forearmImu).topLeftCorner<3, 3>();
      };
      auto pos = [&](double s) -> Eigen::Vector3d {
        const ArmPose p = forwardKinematics(g, wave.th(s));
        return (which == 0 ? p.upperImu : p.forearmImu).block<3, 1>(0, 3);
      };
      // Spatial angular velocity from R' R^T; its derivative equals R * (body omega').
      auto omegaSpatial = [&](double s) -> Eigen::Vector3d {
        return vee(d1(rot, s, h) * rot(s).transpose());
      };
      const FrameState<double>& f = which == 0 ? k.upperImu : k.forearmImu;
      const Eigen::Matrix3d r = rot(t);
      const Eigen::Vector3d omegaRef = r.transpose() * omegaSpatial(t);
      const Eigen::Vector3d omegaDotRef = r.transpose() * d1(omegaSpatial, t, h);
      const Eigen::Vector3d accRef = r.transpose() * d2(pos, t, h);
      const Eigen::Vector3d upRef = r.transpose() * gUp;
      worst = std::max({worst, relErr(f.omega, omegaRef), relErr(f.omegaDot, omegaDotRef),
                        relErr(f.accel, accRef), relErr(f.up, upRef)});
      EXPECT_LE(relErr(f.omega, omegaRef), 1e-6) << "omega, trial " << trial;
      EXPECT_LE(relErr(f.omegaDot, omegaDotRef), 1e-6) << "omega', trial " << trial;
      EXPECT_LE(relErr(f.accel, accRef), 1e-6) << "p'', trial " << trial;
      EXPECT_LE(relErr(f.up, upRef), 1e-12) << "gravity, trial " << trial;
    }
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

// With delta != 0 a row's origin moves inside the previous frame; the extra terms must hold.
TEST(ArmModel, PropagateHandlesLinkOffsets) {
  const double delta = 0.3, lambda = 0.1, beta = 0.7;
  auto pose = [&](double s) -> Eigen::Matrix4d {
    return dhTransform<double>(std::sin(2 * s), 0.2, 0.4, 0.0) *
           dhTransform<double>(1.5 * s * s, lambda, beta, delta);
  };
  auto pos = [&](double s) -> Eigen::Vector3d { return pose(s).block<3, 1>(0, 3); };
  const double t = 0.37, hh = 1e-3;
  FrameState<double> f0;
  const FrameState<double> f1 = propagateJoint<double>(
      f0, std::sin(2 * t), 0.0, 2 * std::cos(2 * t), -4 * std::sin(2 * t), 0.2, 0.4);
  const FrameState<double> f2 =
      propagateJoint<double>(f1, 1.5 * t * t, 0.0, 3 * t, 3.0, lambda, beta, delta);
  const Eigen::Vector3d ref = pose(t).topLeftCorner<3, 3>().transpose() * d2(pos, t, hh);
  EXPECT_LE(relErr(f2.accel, ref), 1e-6);
}

TEST(ArmModel, WrapAngle) {
  EXPECT_NEAR(wrapAngle(3 * kPi), kPi, 1e-12);
  EXPECT_NEAR(wrapAngle(-kPi), kPi, 1e-12);
  EXPECT_NEAR(wrapAngle(0.5 + 4 * kPi), 0.5, 1e-12);
  EXPECT_NEAR(wrapAngle(-0.5 - 2 * kPi), -0.5, 1e-12);
  // An angle already in (-pi, pi] comes back as it is, to the bit.
  for (const double a : {0.0, -0.0, 1e-300, -3.0, 3.14159, kPi, std::nextafter(-kPi, 0.0)})
    EXPECT_EQ(wrapAngle(a), a) << a;
  EXPECT_EQ(wrapAngle(-kPi), kPi);
  const double justOver = wrapAngle(std::nextafter(kPi, 4.0));  // -pi + ulp or, rounded, pi
  EXPECT_TRUE(justOver > -kPi && justOver <= kPi) << justOver;
  EXPECT_NEAR(std::abs(justOver), kPi, 1e-12);
}

}  // namespace
}  // namespace armtrack
