#include "core/calibration/TrunkMounting.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace armtrack {

TrunkMount levelTrunkMount(const TrunkMount& initial, const Eigen::Vector3d& accAtRest,
                           const Eigen::Vector3d& up) {
  if (!accAtRest.allFinite() || accAtRest.norm() < 1e-9 || !up.allFinite() || up.norm() < 1e-9)
    return initial;
  // At rest the accelerometer reads +g up: R a = up for the mounting R (columns: the sensor's
  // axes in frame 0). The smallest turn taking R0 a onto up has its axis normal to up.
  const Eigen::Vector3d predicted = initial.imuRotation * accAtRest.normalized();
  const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(predicted, up.normalized());
  TrunkMount out = initial;
  out.imuRotation = turn.toRotationMatrix() * initial.imuRotation;
  return out;
}

TrunkMounting calibrateTrunkMount(std::span<const ArmSample> samples, const TrunkMount& initial,
                                  const TrunkMountingParams& p) {
  TrunkMounting result;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double weight = 0;
  const ArmSample* previous = nullptr;
  for (const ArmSample& s : samples) {
    if (!s.trunk || !std::isfinite(s.t) || !s.trunk->acc.allFinite() || !s.trunk->gyr.allFinite())
      continue;
    if (previous && s.t >= p.fromS && s.t <= p.toS &&
        previous->trunk->gyr.norm() <= p.stillRateRadS) {
      const double w = std::clamp(s.t - previous->t, 0.0, 0.1);
      sum += w * previous->trunk->acc;
      weight += w;
    }
    previous = &s;
  }
  result.stillSeconds = weight;
  if (weight < p.minStillS) {
    result.problem = "the sternum sensor was still for " + std::to_string(weight) +
                     " s of the start pose, needs " + std::to_string(p.minStillS) + " s";
    return result;
  }
  const Eigen::Vector3d acc = sum / weight;
  if (!(std::abs(acc.norm() - p.g) < 0.2 * p.g)) {
    result.problem =
        "the sternum sensor read " + std::to_string(acc.norm()) + " m/s^2 at rest, not gravity";
    return result;
  }
  result.mount = levelTrunkMount(initial, acc, p.up);
  const Eigen::Vector3d before = initial.imuRotation * acc.normalized();
  result.tiltDeg =
      std::acos(std::clamp(before.dot(p.up.normalized()), -1.0, 1.0)) * 180.0 / std::numbers::pi;
  return result;
}

}  // namespace armtrack
