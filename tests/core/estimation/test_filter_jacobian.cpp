// The filter's measurement Jacobian (automatic differentiation) against finite differences, and
// structural properties of the measurement model that follow from the physics.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/camera/PinholeCamera.h"
#include "core/estimation/ArmFilter.h"
#include "tests/core/estimation/JacobianTesting.h"

namespace armtrack {
namespace {

using test::randomState;

using Vec15 = Eigen::Matrix<double, 15, 1>;
using Vec18 = Eigen::Matrix<double, 18, 1>;
using Jac = Eigen::Matrix<double, 18, 15>;

constexpr double kPi = std::numbers::pi;
// Rows of predictAll: [ua gyro, ua acc, fa gyro, fa acc, elbow, wrist]; columns [thdd thd th].
constexpr int kUaGyr = 0, kUaAcc = 3, kFaGyr = 6, kFaAcc = 9, kElbow = 12, kWrist = 15;
constexpr int kThdd = 0, kThd = 5, kTh = 10;

// Central differences, 4-point stencil: f' = (f(-2h) - 8 f(-h) + 8 f(h) - f(2h)) / 12h.
Jac finiteDifferenceJacobian(const EstimatorParams& p, const Vec15& x, double h) {
  Jac jac;
  for (int c = 0; c < 15; ++c) {
    auto at = [&](double k) {
      Vec15 xs = x;
      xs(c) += k * h;
      return Vec18(predictAll(p, xs));
    };
    jac.col(c) = (at(-2) - 8.0 * at(-1) + 8.0 * at(1) - at(2)) / (12.0 * h);
  }
  return jac;
}

struct ModelCase {
  MeasurementModel model;
  bool defaultGeometry;
};

std::string caseName(const testing::TestParamInfo<ModelCase>& info) {
  const std::string m = methodName(info.param.model);
  return (m == "inclinometer" ? std::string("Inclinometer") : "Method" + m) +
         (info.param.defaultGeometry ? "_DefaultGeometry" : "_OtherGeometry");
}

class JacobianVsFiniteDifferences : public testing::TestWithParam<ModelCase> {};

TEST_P(JacobianVsFiniteDifferences, AgreeAtRandomStates) {
  EstimatorParams p;
  p.model = GetParam().model;
  if (!GetParam().defaultGeometry) {
    p.geometry = test::unusualGeometry();
    p.gUp = 9.81 * Eigen::Vector3d(-0.9, 0.3, 0.2).normalized();  // a tilted trunk
  }
  std::mt19937_64 rng(42);
  double worst = 0.0;  // largest |J_ad - J_fd| / max(1, |J_fd|)
  for (int trial = 0; trial < 200; ++trial) {
    const Vec15 x = randomState(rng);
    const Jac ad = predictAllJacobian(p, x);
    const Jac fd = finiteDifferenceJacobian(p, x, 1e-6);
    ASSERT_TRUE(ad.allFinite());
    for (int r = 0; r < 18; ++r)
      for (int c = 0; c < 15; ++c) {
        const double err = std::abs(ad(r, c) - fd(r, c)) / std::max(1.0, std::abs(fd(r, c)));
        worst = std::max(worst, err);
        ASSERT_LE(err, 1e-6) << "trial " << trial << " row " << r << " col " << c << ": AD "
                             << ad(r, c) << " FD " << fd(r, c);
      }
  }
  std::ostringstream os;
  os << worst;
  RecordProperty("worstRelativeError", os.str());
}

INSTANTIATE_TEST_SUITE_P(AllModels, JacobianVsFiniteDifferences,
                         testing::Values(ModelCase{MeasurementModel::AccelGyro, true},
                                         ModelCase{MeasurementModel::AccelGyro, false},
                                         ModelCase{MeasurementModel::InclinometerGyro, true},
                                         ModelCase{MeasurementModel::InclinometerGyro, false},
                                         ModelCase{MeasurementModel::Inclinometer, true},
                                         ModelCase{MeasurementModel::Inclinometer, false},
                                         ModelCase{MeasurementModel::AugmentedBodyAccel, true},
                                         ModelCase{MeasurementModel::AugmentedBodyAccel, false}),
                         caseName);

TEST(MeasurementStructure, GyroRowsIgnoreJointAccelerations) {
  EstimatorParams p;
  p.geometry = test::unusualGeometry();
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec15 x = randomState(rng);
    const Jac jac = predictAllJacobian(p, x);
    for (int r : {kUaGyr, kFaGyr})
      EXPECT_EQ((jac.block<3, 5>(r, kThdd).cwiseAbs().maxCoeff()), 0.0) << "trial " << trial;
    Vec15 y = randomState(rng);
    y.segment<10>(kThd) = x.segment<10>(kThd);  // other joint accelerations, same rates/angles
    const Vec18 a = predictAll(p, x), b = predictAll(p, y);
    EXPECT_LE((a.segment<3>(kUaGyr) - b.segment<3>(kUaGyr)).norm(), 1e-14);
    EXPECT_LE((a.segment<3>(kFaGyr) - b.segment<3>(kFaGyr)).norm(), 1e-14);
  }
}

TEST(MeasurementStructure, GravityOnlyAccelerometerIgnoresRatesAndAccelerations) {
  for (MeasurementModel m : {MeasurementModel::InclinometerGyro, MeasurementModel::Inclinometer,
                             MeasurementModel::AugmentedBodyAccel}) {
    EstimatorParams p;
    p.model = m;
    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 50; ++trial) {
      const Jac jac = predictAllJacobian(p, randomState(rng));
      for (int r : {kUaAcc, kFaAcc})
        EXPECT_EQ((jac.block<3, 10>(r, 0).cwiseAbs().maxCoeff()), 0.0) << methodName(m);
    }
  }
  // With body acceleration modelled (Method A) the accelerometers do see rates and accelerations.
  EstimatorParams p;
  std::mt19937_64 rng(11);
  const Jac jac = predictAllJacobian(p, randomState(rng));
  EXPECT_GT((jac.block<3, 10>(kFaAcc, 0).cwiseAbs().maxCoeff()), 1e-3);
}

TEST(MeasurementStructure, OpticalRowsDependOnAnglesOnly) {
  EstimatorParams p;
  p.geometry = test::unusualGeometry();
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    const Jac jac = predictAllJacobian(p, randomState(rng));
    EXPECT_EQ((jac.block<6, 10>(kElbow, 0).cwiseAbs().maxCoeff()), 0.0);
    EXPECT_GT((jac.block<6, 5>(kElbow, kTh).cwiseAbs().maxCoeff()), 1e-2);
  }
}

TEST(MeasurementStructure, ElbowPositionIgnoresElbowJoints) {
  EstimatorParams p;
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec15 x = randomState(rng);
    const Jac jac = predictAllJacobian(p, x);
    EXPECT_EQ((jac.block<3, 2>(kElbow, kTh + 3).cwiseAbs().maxCoeff()), 0.0);
    // The wrist does move with the elbow flexion (forearm length 0.2 m).
    EXPECT_GT((jac.block<3, 1>(kWrist, kTh + 3).norm()), 0.19);
  }
}

// gyro = J(th) thd exactly: linear (and homogeneous) in the joint rates, whatever thdd is.
TEST(MeasurementStructure, GyroRowsAreLinearInRates) {
  EstimatorParams p;
  p.geometry = test::unusualGeometry();
  std::mt19937_64 rng(9);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec15 x = randomState(rng);
    Vec15 x2 = x, x0 = x;
    x2.segment<5>(kThd) *= 2.0;
    x0.segment<5>(kThd).setZero();
    const Vec18 z = predictAll(p, x), z2 = predictAll(p, x2), z0 = predictAll(p, x0);
    const Jac jac = predictAllJacobian(p, x);
    for (int r : {kUaGyr, kFaGyr}) {
      EXPECT_LE((z2.segment<3>(r) - 2.0 * z.segment<3>(r)).norm(), 1e-12);
      EXPECT_LE(z0.segment<3>(r).norm(), 1e-15);
      EXPECT_LE(((jac.block<3, 5>(r, kThd) * x.segment<5>(kThd) - z.segment<3>(r)).norm()), 1e-12);
    }
  }
}

// Random angles away from the shoulder's gimbal lock (th1 = +-pi/2), zero rates and accelerations.
Vec15 randomPose(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vec15 x = Vec15::Zero();
  for (int j = 0; j < 5; ++j) x(kTh + j) = kPi * u(rng);
  x(kTh + 1) = 1.3 * u(rng);
  return x;
}

// The joint-rate direction that turns the arm about `up`, found without the DH axes: the shoulder
// rates whose elbow and wrist velocities are up x elbow and up x wrist (least squares over the six
// optical rows). Returns false when the positions do not pin the three shoulder rates down.
bool verticalRotationFromPositions(const Jac& jac, const Vec18& z, const Eigen::Vector3d& up,
                                   JointVector& d) {
  Eigen::Matrix<double, 6, 3> a = jac.block<6, 3>(kElbow, kTh);
  Eigen::Matrix<double, 6, 1> b;
  b << up.cross(Eigen::Vector3d(z.segment<3>(kElbow))),
      up.cross(Eigen::Vector3d(z.segment<3>(kWrist)));
  const Eigen::JacobiSVD<Eigen::Matrix<double, 6, 3>> svd(
      a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  if (svd.singularValues()(2) < 0.02) return false;
  d.setZero();
  d.head<3>() = svd.solve(b);
  EXPECT_LT((a * d.head<3>() - b).norm(), 1e-12);  // a rigid rotation is reachable exactly
  d.normalize();
  return true;
}

// Physics of the model: rotating the whole arm about the vertical through the shoulder changes no
// IMU reading (the heading is unobservable without optical data).
TEST(HeadingDirection, VerticalRotationLeavesImuReadingsUnchanged) {
  for (bool tilted : {false, true}) {
    EstimatorParams p;
    if (tilted) p.gUp = 9.81 * Eigen::Vector3d(-0.9, 0.3, 0.2).normalized();
    const Eigen::Vector3d up = p.gUp.normalized();
    std::mt19937_64 rng(13);
    int tested = 0;
    for (int trial = 0; trial < 300; ++trial) {
      const Vec15 x = randomPose(rng);
      const Jac jac = predictAllJacobian(p, x);
      JointVector d;
      if (!verticalRotationFromPositions(jac, predictAll(p, x), up, d)) continue;
      ++tested;
      EXPECT_LT(((jac.topRows<12>().rightCols<5>() * d).cwiseAbs().maxCoeff()), 1e-9);
    }
    EXPECT_GT(tested, 200);
  }
}

// headingDirection() is that rotation: along it the IMU rows do not change, while the elbow and
// wrist do (unless the elbow lies almost on the vertical through the shoulder).
TEST(HeadingDirection, LeavesImuReadingsUnchangedAndMovesTheArm) {
  for (bool tilted : {false, true}) {
    EstimatorParams p;
    if (tilted) p.gUp = 9.81 * Eigen::Vector3d(-0.9, 0.3, 0.2).normalized();
    const Eigen::Vector3d up = p.gUp.normalized();
    std::mt19937_64 rng(13);
    double worstImu = 0.0;
    int moved = 0;
    for (int trial = 0; trial < 300; ++trial) {
      const Vec15 x = randomPose(rng);
      const JointVector h = headingDirection(x.segment<5>(kTh), up);
      ASSERT_NEAR(h.norm(), 1.0, 1e-12);
      EXPECT_EQ(h(3), 0.0);
      EXPECT_EQ(h(4), 0.0);
      const Jac jac = predictAllJacobian(p, x);
      const double imu = (jac.topRows<12>().rightCols<5>() * h).cwiseAbs().maxCoeff();
      worstImu = std::max(worstImu, imu);
      const Eigen::Vector3d elbow = predictAll(p, x).segment<3>(kElbow);
      if ((elbow - elbow.dot(up) * up).norm() < 0.05) continue;
      ++moved;
      EXPECT_GT(((jac.bottomRows<6>().rightCols<5>() * h).norm()), 1e-3) << "trial " << trial;
    }
    EXPECT_GT(moved, 150);
    EXPECT_LT(worstImu, 1e-9) << (tilted ? "tilted trunk" : "upright trunk")
                              << ": headingDirection is off the vertical rotation";
  }
}

// Second-order check along a finite step: th + eps h changes the IMU readings by O(eps^2).
TEST(HeadingDirection, FiniteRotationChangesImuOnlyToSecondOrder) {
  EstimatorParams p;
  const Eigen::Vector3d up = p.gUp.normalized();
  std::mt19937_64 rng(17);
  double worst = 0.0;  // largest |dz| / eps^2
  for (int trial = 0; trial < 50; ++trial) {
    const Vec15 x = randomPose(rng);
    const JointVector h = headingDirection(x.segment<5>(kTh), up);
    const Vec18 z = predictAll(p, x);
    for (double eps : {1e-2, 1e-3, 1e-4, 1e-5}) {
      Vec15 y = x;
      y.segment<5>(kTh) += eps * h;
      const double dz = (predictAll(p, y) - z).head<12>().cwiseAbs().maxCoeff();
      worst = std::max(worst, dz / (eps * eps));
    }
  }
  // A first-order term would make dz / eps^2 grow like 1 / eps.
  EXPECT_LT(worst, 50.0);
}

// At a moving state the turn about the vertical also carries the joint rates and accelerations;
// the full-state direction must leave every IMU reading unchanged while moving the optical ones.
TEST(HeadingSymmetry, ImuReadingsInvariantAtMovingStates) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> ang(-1.2, 1.2), rate(-3.0, 3.0), acc(-30.0, 30.0);
  EstimatorParams p;
  double worstImu = 0.0;
  for (int i = 0; i < 200; ++i) {
    Eigen::Matrix<double, 15, 1> x;
    for (int k = 0; k < 5; ++k) {
      x(k) = acc(rng);
      x(5 + k) = rate(rng);
      x(10 + k) = ang(rng);
    }
    const Eigen::Matrix<double, 15, 1> v = headingSymmetry(x, p.gUp.normalized());
    ASSERT_NEAR(v.segment<5>(10).norm(), 1.0, 1e-12);
    const Eigen::Matrix<double, 18, 15> jac = predictAllJacobian(p, x);
    const Eigen::Matrix<double, 18, 1> d = jac * v;
    // Relative to how strongly the readings depend on the state at all.
    const double scale = jac.topRows<12>().norm();
    worstImu = std::max(worstImu, d.head<12>().norm() / scale);
    EXPECT_LT(d.head<12>().norm(), 1e-6 * scale) << "state " << x.transpose();
    EXPECT_GT(d.tail<6>().norm(), 1e-3);
    // The angle-only direction is not enough once the arm moves.
    Eigen::Matrix<double, 15, 1> thetaOnly = Eigen::Matrix<double, 15, 1>::Zero();
    thetaOnly.segment<5>(10) = v.segment<5>(10);
    EXPECT_GT((jac * thetaOnly).head<12>().norm(), 1e3 * d.head<12>().norm() + 1e-9);
  }
  RecordProperty("worst_relative_imu_change", std::to_string(worstImu));
}

// ---------------------------------------------------------------------------------------------
// Marker pixels: the predicted pixel is the camera's projection of the arm's marker, and its
// Jacobian (OpenCV's projection derivative chained with the kinematics) matches finite
// differences.

class MarkerPixel : public testing::TestWithParam<Side> {};

TEST_P(MarkerPixel, IsTheProjectionOfTheMarkerAndItsJacobianMatchesFiniteDifferences) {
  EstimatorParams p;
  p.side = GetParam();
  p.geometry = test::unusualGeometry();
  p.camera = frontCamera(1.5);
  const PinholeCamera camera(*p.camera);
  std::mt19937_64 rng(11);
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    Vec15 x = randomState(rng);
    x.segment<3>(kTh) *= 0.5;  // keep the arm roughly in front of the camera
    for (const bool wrist : {true, false}) {
      Eigen::Vector2d px;
      Eigen::Matrix<double, 2, 15> jac;
      const ArmPose pose = forwardKinematics(p.geometry, x.segment<5>(kTh));
      Eigen::Vector3d marker = wrist ? pose.wrist : pose.elbow;
      // The filter works on a right arm; the camera sees the left arm's points mirrored back.
      if (p.side == Side::Left) marker = mirrorPoint(marker);
      Eigen::Vector2d expected;
      const bool visible = camera.project(marker, expected);
      ASSERT_EQ(predictMarkerPixel(p, x, wrist, px, &jac), visible);
      if (!visible) continue;
      EXPECT_LT((px - expected).norm(), 1e-9);
      const double h = 1e-6;
      Eigen::Matrix<double, 2, 15> fd;
      for (int c = 0; c < 15; ++c) {
        Vec15 xp = x, xm = x;
        xp(c) += h;
        xm(c) -= h;
        Eigen::Vector2d a, b;
        ASSERT_TRUE(predictMarkerPixel(p, xp, wrist, a));
        ASSERT_TRUE(predictMarkerPixel(p, xm, wrist, b));
        fd.col(c) = (a - b) / (2 * h);
      }
      // Pixels per rad are in the hundreds: compare relative to the largest entry.
      EXPECT_LT((jac - fd).cwiseAbs().maxCoeff(), 1e-5 * std::max(1.0, fd.cwiseAbs().maxCoeff()));
      // Only the angles move a marker; the elbow marker ignores the elbow joints.
      EXPECT_EQ(jac.leftCols<10>().cwiseAbs().maxCoeff(), 0.0);
      if (!wrist) {
        EXPECT_EQ(jac.rightCols<2>().cwiseAbs().maxCoeff(), 0.0);
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 60);  // most poses are in view
}

TEST(MarkerPixelWithoutCamera, IsNotPredicted) {
  EstimatorParams p;
  Eigen::Vector2d px(1, 2);
  EXPECT_FALSE(predictMarkerPixel(p, Vec15::Zero(), true, px));
  EXPECT_EQ(px, Eigen::Vector2d(1, 2));
}

INSTANTIATE_TEST_SUITE_P(BothArms, MarkerPixel, testing::Values(Side::Right, Side::Left),
                         [](const auto& info) { return sideName(info.param); });

}  // namespace
}  // namespace armtrack
