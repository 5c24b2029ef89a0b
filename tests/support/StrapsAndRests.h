// Two pieces of a simulated session that several calibration and estimation tests build alike:
// a strap that sits turned on its segment, and a session that starts with the arm still.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>

#include "core/simulation/Trajectory.h"

namespace armtrack::test {

/// A strap turned by up to maxRad (rad) about each of its three axes: x, then y, then z, drawn
/// in that order from rng (one statement per draw, so every compiler draws them alike).
inline Eigen::Matrix3d strapTurn(std::mt19937_64& rng, double maxRad) {
  std::uniform_real_distribution<double> u(-maxRad, maxRad);
  const double a = u(rng), b = u(rng), c = u(rng);
  return (Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(b, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(c, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

/// Still in `pose` for `rest` s, then a smooth (quintic) blend over 1.5 s into `motion`, which
/// starts at the end of the rest; no rests after. `motion` must outlive this trajectory.
class RestThenMove final : public Trajectory {
 public:
  RestThenMove(const Trajectory& motion, const JointVector& pose, double rest)
      : m_motion(motion), m_pose(pose), m_rest(rest) {}
  JointMotion at(double t) const override {
    JointMotion out;
    out.th = m_pose;
    if (t <= m_rest) return out;
    const double T = 1.5, u = std::min(1.0, (t - m_rest) / T);
    const double w = 10 * std::pow(u, 3) - 15 * std::pow(u, 4) + 6 * std::pow(u, 5);
    const double wd = u < 1.0 ? (30 * u * u - 60 * u * u * u + 30 * std::pow(u, 4)) / T : 0.0;
    const double wdd = u < 1.0 ? (60 * u - 180 * u * u + 120 * u * u * u) / (T * T) : 0.0;
    const JointMotion m = m_motion.at(t - m_rest);
    out.th = (1 - w) * m_pose + w * m.th;
    out.thd = wd * (m.th - m_pose) + w * m.thd;
    out.thdd = wdd * (m.th - m_pose) + 2 * wd * m.thd + w * m.thdd;
    return out;
  }

 private:
  const Trajectory& m_motion;
  JointVector m_pose;
  double m_rest;
};

}  // namespace armtrack::test
