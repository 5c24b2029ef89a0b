#include "core/calibration/SensorCheck.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace armtrack {

namespace {

struct Reading {
  double t;
  ImuReading imu;
};

bool finite(const ImuReading& r) {
  return r.gyr.allFinite() && r.acc.allFinite();
}

enum class Worn { UpperArm, Forearm, Trunk };

// The readings of one sensor, an arm's mirrored onto a right arm when worn on the left (the
// sternum sensor's stay in its own axes: its mounting is given in the side's own frame 0).
std::vector<Reading> readingsOf(std::span<const ArmSample> samples, Worn worn, Side side) {
  std::vector<Reading> out;
  for (const ArmSample& s : samples) {
    const std::optional<ImuReading>& r = worn == Worn::UpperArm  ? s.upperArm
                                         : worn == Worn::Forearm ? s.forearm
                                                                 : s.trunk;
    if (worn == Worn::Trunk) {
      if (r && finite(*r) && std::isfinite(s.t)) out.push_back({s.t, *r});
      continue;
    }
    if (!r || !finite(*r) || !std::isfinite(s.t)) continue;
    out.push_back({s.t, side == Side::Left ? mirrorImu(*r) : *r});
  }
  return out;
}

struct Rest {
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();  // mean specific force while still
  Eigen::Vector3d gyr = Eigen::Vector3d::Zero();  // mean rate while still: the bias
  double seconds = 0;
};

// Mean of the still readings in [settle, restEnd]; each weighs the time to the next one.
Rest restOf(const std::vector<Reading>& r, const SensorCheckParams& p) {
  Rest rest;
  double weight = 0;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    if (r[i].t < p.settleS || r[i].t > p.restEndS) continue;
    if (r[i].imu.gyr.norm() > p.stillRateRadS) continue;
    const double w = std::clamp(r[i + 1].t - r[i].t, 0.0, 0.1);
    rest.acc += w * r[i].imu.acc;
    rest.gyr += w * r[i].imu.gyr;
    weight += w;
  }
  if (weight > 0) {
    rest.acc /= weight;
    rest.gyr /= weight;
  }
  rest.seconds = weight;
  return rest;
}

// RMS of the rotation rate (bias removed) after the still start.
double motionOf(const std::vector<Reading>& r, const Eigen::Vector3d& bias,
                const SensorCheckParams& p) {
  double sum = 0, weight = 0;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    if (r[i].t <= p.restEndS) continue;
    const double w = std::clamp(r[i + 1].t - r[i].t, 0.0, 0.1);
    sum += w * (r[i].imu.gyr - bias).squaredNorm();
    weight += w;
  }
  return weight > 0 ? std::sqrt(sum / weight) : 0.0;
}

std::string fixed(double v) {
  std::ostringstream o;
  o.precision(2);
  o << std::fixed << v;
  return o.str();
}

}  // namespace

bool SensorCheckResult::has(SensorFinding f) const {
  return std::find(findings.begin(), findings.end(), f) != findings.end();
}

SensorCheckResult checkSensors(std::span<const ArmSample> samples, const SensorCheckParams& p) {
  SensorCheckResult result;
  const std::vector<Reading> upper = readingsOf(samples, Worn::UpperArm, p.side);
  const std::vector<Reading> fore = readingsOf(samples, Worn::Forearm, p.side);
  const std::vector<Reading> trunk =
      p.trunk ? readingsOf(samples, Worn::Trunk, p.side) : std::vector<Reading>{};
  if (upper.size() < 10) {
    result.status = SensorCheckStatus::MissingUpperArm;
    result.explanation = "no readings from the upper-arm sensor";
    return result;
  }
  if (fore.size() < 10) {
    result.status = SensorCheckStatus::MissingForearm;
    result.explanation = "no readings from the forearm sensor";
    return result;
  }
  if (p.trunk && trunk.size() < 10) {
    result.status = SensorCheckStatus::MissingTrunk;
    result.explanation = "no readings from the sternum sensor";
    return result;
  }
  const Rest restU = restOf(upper, p), restF = restOf(fore, p);
  const Rest restT = p.trunk ? restOf(trunk, p) : Rest{};
  result.restSeconds = std::min(restU.seconds, restF.seconds);
  if (p.trunk) result.restSeconds = std::min(result.restSeconds, restT.seconds);
  if (result.restSeconds < p.minRestS) {
    result.status = SensorCheckStatus::NotStill;
    result.explanation = "the arm was still for " + fixed(result.restSeconds) + " s, needs " +
                         fixed(p.minRestS) + " s";
    return result;
  }
  for (const Rest* r : {&restU, &restF, &restT}) {
    if (r == &restT && !p.trunk) continue;
    const double g = r->acc.norm();
    if (!(g > 0.6 * p.g && g < 1.4 * p.g)) {
      result.status = SensorCheckStatus::ImplausibleReadings;
      result.explanation =
          "an accelerometer read " + fixed(g) + " m/s^2 at rest, not gravity (" + fixed(p.g) + ")";
      return result;
    }
  }
  result.upperMotionRadS = motionOf(upper, restU.gyr, p);
  result.forearmMotionRadS = motionOf(fore, restF.gyr, p);
  const double mu = result.upperMotionRadS, mf = result.forearmMotionRadS;
  if (std::max(mu, mf) < p.minMotionRadS) {
    result.status = SensorCheckStatus::NoMovement;
    result.explanation = "no elbow bend seen (rotation " + fixed(std::max(mu, mf)) + " rad/s)";
    return result;
  }
  bool swapped = false;
  if (mu > p.swapRatio * mf) {
    swapped = true;
  } else if (!(mf > p.swapRatio * mu)) {
    result.status = SensorCheckStatus::BothMoved;
    result.explanation = "both sensors turned alike (" + fixed(mu) + " and " + fixed(mf) +
                         " rad/s): the upper arm moved, or both are on one segment";
    return result;
  }
  if (swapped) result.findings.push_back(SensorFinding::Swapped);

  // Gravity along each segment with the arm hanging straight, in each sensor's frame.
  const Eigen::Vector3d up = p.side == Side::Left ? mirrorPoint(p.up) : p.up;
  const JointVector zero = JointVector::Zero();
  const ArmPrediction hanging = predictSensors(p.geometry, zero, zero, zero, p.g * up);
  const Eigen::Vector3d onUpper = (swapped ? restF : restU).acc.normalized();
  const Eigen::Vector3d onFore = (swapped ? restU : restF).acc.normalized();
  result.upperCos = onUpper.dot(hanging.upper.acc.normalized());
  result.forearmCos = onFore.dot(hanging.forearm.acc.normalized());
  const auto judge = [&](double c, SensorFinding down, SensorFinding tilted) {
    if (c < -p.uprightCos)
      result.findings.push_back(down);
    else if (c < p.uprightCos)
      result.findings.push_back(tilted);
  };
  judge(result.upperCos, SensorFinding::UpperArmUpsideDown, SensorFinding::UpperArmTilted);
  judge(result.forearmCos, SensorFinding::ForearmUpsideDown, SensorFinding::ForearmTilted);
  if (p.trunk) {
    // Sitting upright and still, the sternum sensor reads +g up: R^T up in its own axes.
    const Eigen::Vector3d expected = (p.trunk->imuRotation.transpose() * p.up).normalized();
    const double c = std::clamp(restT.acc.normalized().dot(expected), -1.0, 1.0);
    result.trunkAngleDeg = std::acos(c) * 180.0 / std::numbers::pi;
    if (c < -p.uprightCos)
      result.findings.push_back(SensorFinding::TrunkUpsideDown);
    else if (result.trunkAngleDeg > p.trunkToleranceDeg)
      result.findings.push_back(SensorFinding::TrunkTurned);
  }
  std::ostringstream why;
  why << (swapped ? "swapped" : "on their segments") << "; rotation upper " << fixed(mu)
      << " rad/s, forearm " << fixed(mf) << " rad/s; gravity cos upper " << fixed(result.upperCos)
      << ", forearm " << fixed(result.forearmCos);
  if (p.trunk) why << "; sternum sensor " << fixed(result.trunkAngleDeg) << " deg from upright";
  result.explanation = why.str();
  return result;
}

}  // namespace armtrack
