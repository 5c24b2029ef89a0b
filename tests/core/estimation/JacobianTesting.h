// Shared by the measurement-Jacobian tests: random filter states and an arm geometry far from
// the defaults, so a wrong length or strap angle in a derivative cannot hide behind them.
#pragma once

#include <Eigen/Core>
#include <numbers>
#include <random>

#include "core/kinematics/ArmModel.h"

namespace armtrack::test {

/// A state [th'' th' th]: accelerations up to 30 rad/s^2, rates up to 3 rad/s, angles in
/// [-pi, pi].
inline Eigen::Matrix<double, 15, 1> randomState(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Matrix<double, 15, 1> x;
  for (int j = 0; j < 5; ++j) {
    x(j) = 30.0 * u(rng);
    x(5 + j) = 3.0 * u(rng);
    x(10 + j) = std::numbers::pi * u(rng);
  }
  return x;
}

/// Segment lengths and strap placement unlike Table 7's.
inline ArmGeometry unusualGeometry() {
  ArmGeometry g;
  g.l3 = 0.31;
  g.l6 = 0.27;
  g.lu3 = 0.17;
  g.thu4 = 0.4;
  g.lu5 = 0.045;
  g.lf6 = 0.12;
  g.thf7 = -1.1;
  g.lf8 = 0.03;
  return g;
}

}  // namespace armtrack::test
