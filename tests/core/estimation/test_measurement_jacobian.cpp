// The hand-differentiated measurement model (core/estimation/MeasurementJacobian.h) against the
// automatic-differentiation one the filter was built on (predictAll, predictAllJacobian) and
// against finite differences of the predicted readings, at random states, at the shoulder's
// gimbal lock, for the default and another geometry with a tilted trunk, with and without body
// acceleration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/estimation/ArmFilter.h"
#include "core/estimation/MeasurementJacobian.h"
#include "tests/core/estimation/JacobianTesting.h"

namespace armtrack {
namespace {

using test::randomState;

using Vec15 = Eigen::Matrix<double, 15, 1>;

constexpr double kPi = std::numbers::pi;

struct Case {
  MeasurementModel model;
  bool otherGeometry;
};

EstimatorParams paramsFor(const Case& c) {
  EstimatorParams p;
  p.model = c.model;
  if (c.otherGeometry) {
    p.geometry = test::unusualGeometry();
    p.gUp = 9.81 * Eigen::Vector3d(-0.9, 0.3, 0.2).normalized();
  }
  return p;
}

class MeasurementJacobianTest : public testing::TestWithParam<Case> {
 protected:
  // Random states, and states at and near the gimbal lock (abduction 90 deg) and at rest.
  static std::vector<Vec15> states() {
    std::mt19937_64 rng(11);
    std::vector<Vec15> xs;
    for (int i = 0; i < 300; ++i) xs.push_back(randomState(rng));
    for (const double th1 : {kPi / 2, -kPi / 2, kPi / 2 + 1e-9}) {
      Vec15 x = randomState(rng);
      x(11) = th1;
      xs.push_back(x);
    }
    xs.push_back(Vec15::Zero());
    return xs;
  }
  static bool bodyAccel(const EstimatorParams& p) { return p.model == MeasurementModel::AccelGyro; }
};

// The readings are those of the automatic-differentiation model to round-off, and so is the
// Jacobian, entry by entry.
TEST_P(MeasurementJacobianTest, EqualsAutomaticDifferentiation) {
  const EstimatorParams p = paramsFor(GetParam());
  double worstValue = 0.0, worstJac = 0.0;
  for (const Vec15& x : states()) {
    ModelReadings h;
    ModelJacobian jac;
    predictReadings(p.geometry, p.gUp, bodyAccel(p), x, h, &jac);
    const ModelReadings hRef = predictAll(p, x);
    const ModelJacobian jacRef = predictAllJacobian(p, x);
    ASSERT_TRUE(h.allFinite() && jac.allFinite());
    for (int r = 0; r < kMeasurementModelRows; ++r) {
      worstValue =
          std::max(worstValue, std::abs(h(r) - hRef(r)) / std::max(1.0, std::abs(hRef(r))));
      for (int c = 0; c < kMeasurementStates; ++c)
        worstJac = std::max(
            worstJac, std::abs(jac(r, c) - jacRef(r, c)) / std::max(1.0, std::abs(jacRef(r, c))));
    }
    // Without the Jacobian the readings are the same.
    ModelReadings h2;
    predictReadings(p.geometry, p.gUp, bodyAccel(p), x, h2, nullptr);
    ASSERT_EQ(h2, h);
    // Without the positions the IMU rows are the same, and the position rows are not written.
    ModelReadings h3 = ModelReadings::Constant(-7.0);
    ModelJacobian jac3 = ModelJacobian::Constant(-7.0);
    predictReadings(p.geometry, p.gUp, bodyAccel(p), x, h3, &jac3, false);
    ASSERT_EQ(h3.head<12>(), h.head<12>());
    ASSERT_EQ(jac3.topRows<12>(), jac.topRows<12>());
    ASSERT_TRUE((h3.tail<6>().array() == -7.0).all() &&
                (jac3.bottomRows<6>().array() == -7.0).all());
  }
  EXPECT_LE(worstValue, 1e-13);
  EXPECT_LE(worstJac, 1e-12);
}

// Independent of both models' differentiation: 4-point central differences of the readings.
TEST_P(MeasurementJacobianTest, AgreesWithFiniteDifferences) {
  const EstimatorParams p = paramsFor(GetParam());
  const double step = 1e-6;
  double worst = 0.0;
  for (const Vec15& x : states()) {
    ModelReadings h;
    ModelJacobian jac;
    predictReadings(p.geometry, p.gUp, bodyAccel(p), x, h, &jac);
    for (int c = 0; c < kMeasurementStates; ++c) {
      const auto at = [&](double k) {
        Vec15 xs = x;
        xs(c) += k * step;
        ModelReadings out;
        predictReadings(p.geometry, p.gUp, bodyAccel(p), xs, out, nullptr);
        return out;
      };
      const ModelReadings fd = (at(-2) - 8.0 * at(-1) + 8.0 * at(1) - at(2)) / (12.0 * step);
      for (int r = 0; r < kMeasurementModelRows; ++r)
        worst = std::max(worst, std::abs(jac(r, c) - fd(r)) / std::max(1.0, std::abs(fd(r))));
    }
  }
  EXPECT_LE(worst, 1e-6);
}

// Frame 0 moving with the trunk (docs/estimator.md, "Trunk"): the base's rate, angular
// acceleration and acceleration reach every reading through the arm's pose, and the Jacobian
// must carry their turning with the angles too.
TEST_P(MeasurementJacobianTest, MovingBaseAgreesWithFiniteDifferences) {
  const EstimatorParams p = paramsFor(GetParam());
  std::mt19937_64 rng(29);
  std::normal_distribution<double> n(0.0, 1.0);
  const auto vec = [&](double scale) { return Eigen::Vector3d(n(rng), n(rng), n(rng)) * scale; };
  const double step = 1e-6;
  double worst = 0.0;
  for (const Vec15& x : states()) {
    FrameState<double> base;
    base.omega = vec(1.0);     // rad/s: a trunk turning fast
    base.omegaDot = vec(5.0);  // rad/s^2
    base.accel = vec(2.0);     // m/s^2
    base.up = p.gUp.norm() * vec(1.0).normalized();
    ModelReadings h;
    ModelJacobian jac;
    predictReadings(p.geometry, base, bodyAccel(p), x, h, &jac);
    for (int c = 0; c < kMeasurementStates; ++c) {
      const auto at = [&](double k) {
        Vec15 xs = x;
        xs(c) += k * step;
        ModelReadings out;
        predictReadings(p.geometry, base, bodyAccel(p), xs, out, nullptr);
        return out;
      };
      const ModelReadings fd = (at(-2) - 8.0 * at(-1) + 8.0 * at(1) - at(2)) / (12.0 * step);
      for (int r = 0; r < kMeasurementModelRows; ++r)
        worst = std::max(worst, std::abs(jac(r, c) - fd(r)) / std::max(1.0, std::abs(fd(r))));
    }
  }
  EXPECT_LE(worst, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Models, MeasurementJacobianTest,
                         testing::Values(Case{MeasurementModel::AccelGyro, false},
                                         Case{MeasurementModel::AccelGyro, true},
                                         Case{MeasurementModel::InclinometerGyro, false},
                                         Case{MeasurementModel::InclinometerGyro, true}),
                         [](const testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.model == MeasurementModel::AccelGyro
                                                  ? "BodyAccel"
                                                  : "GravityOnly") +
                                  (info.param.otherGeometry ? "_OtherGeometry"
                                                            : "_DefaultGeometry");
                         });

}  // namespace
}  // namespace armtrack
