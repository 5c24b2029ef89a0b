// The forearm sensor's roll from the rests in a known pose (core/calibration/MovementRestPose.h).
#include "core/calibration/MovementRestPose.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace armtrack::movecal {

namespace {

double angleBetween(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

double wrap(double a) {
  return std::remainder(a, 2.0 * std::numbers::pi);
}

/// The angle about the model forearm IMU's y axis (the forearm's long axis) of v's part across
/// it, measured as Ry turns it: Ry(a) adds a.
double aboutY(const Vec3& v) {
  return std::atan2(v.x(), v.z());
}

}  // namespace

PoseRoll rollFromRestPose(const Grid& g, const std::vector<Rest>& rests,
                          const std::vector<Eigen::Vector2d>& theta, std::size_t stride,
                          const Mat3& m1, const Mat3& m2Tilt, const ArmGeometry& geometry,
                          const Vec3& up, const JointVector& pose,
                          const MovementCalibrationParams& p) {
  PoseRoll out;
  out.rests = static_cast<int>(rests.size());
  const ArmPose atPose = forwardKinematics(geometry, pose);
  const Vec3 upUpper = atPose.upperImu.topLeftCorner<3, 3>().transpose() * up.normalized();
  const Vec3 upFore = atPose.forearmImu.topLeftCorner<3, 3>().transpose() * up.normalized();
  const double foreElevation = std::asin(std::clamp(upFore.y(), -1.0, 1.0));
  struct Found {
    double roll, weight;
  };
  std::vector<Found> found;
  double nearest = std::numeric_limits<double>::infinity();  // the worst test of the best rest
  std::string nearestWhat;
  for (const Rest& r : rests) {
    if (r.to <= r.from || theta.empty()) continue;
    const Vec3 g1 = m1 * meanOf(g.a1, r).normalized();
    const Vec3 g2 = m2Tilt * meanOf(g.a2, r).normalized();
    const std::size_t mid = (r.from + r.to) / 2;
    const std::size_t k =
        std::min(theta.size() - 1, mid > 0 ? (mid - 1 + stride / 2) / stride : std::size_t{0});
    const double upperOff = angleBetween(g1, upUpper);
    const double foreOff = std::abs(std::asin(std::clamp(g2.y(), -1.0, 1.0)) - foreElevation);
    const double elbowOff = std::abs(wrap(theta[k](0) - pose(3)));
    const double worst = std::max({upperOff, foreOff, elbowOff});
    if (worst > p.restPoseTolerance) {
      if (worst < nearest) {
        nearest = worst;
        nearestWhat = worst == upperOff  ? "the upper arm"
                      : worst == foreOff ? "the forearm's inclination"
                                         : "the elbow";
      }
      continue;
    }
    ++out.matching;
    // "Thumb up": gravity across the forearm where the pose puts it.
    const double roll = wrap(aboutY(upFore) - aboutY(g2));
    found.push_back({roll, static_cast<double>(r.to - r.from)});
  }
  if (found.empty()) {
    out.why = out.rests == 0           ? "no rest was found"
              : std::isfinite(nearest) ? "no rest was in the start pose (at best, " + nearestWhat +
                                             " " + fixed1(nearest / kDeg) + " deg from it)"
                                       : "no rest was in the start pose";
    return out;
  }
  std::vector<double> rolls;
  for (const Found& f : found) rolls.push_back(f.roll);
  std::nth_element(rolls.begin(), rolls.begin() + rolls.size() / 2, rolls.end());
  const double median = rolls[rolls.size() / 2];
  double s = 0.0, c = 0.0, w = 0.0;
  for (const Found& f : found) {
    if (std::abs(wrap(f.roll - median)) > p.poseRollSpread) continue;
    s += f.weight * std::sin(f.roll);
    c += f.weight * std::cos(f.roll);
    w += f.weight;
    ++out.agreeing;
  }
  if (2 * out.agreeing <= out.matching) {
    out.why = "the rests in the start pose disagree about it (the thumb was not always up)";
    return out;
  }
  const double roll = std::atan2(s, c);
  double spread = 0.0;
  for (const Found& f : found)
    if (std::abs(wrap(f.roll - median)) <= p.poseRollSpread)
      spread += f.weight * std::pow(wrap(f.roll - roll), 2);
  spread = std::sqrt(spread / w);
  if (std::abs(roll) > p.maxPoseRoll) {
    out.why = "the rest in the start pose gave a roll of " + fixed1(roll / kDeg) +
              " deg, more than a strap turns (was the thumb up?)";
    return out;
  }
  out.roll = roll;
  // A patient holds "thumb up" to a few degrees at each rest; the rests' own spread when larger.
  const double perRest = std::max(3.0 * kDeg, spread);
  out.sd = perRest / std::sqrt(static_cast<double>(out.agreeing));
  return out;
}

}  // namespace armtrack::movecal
