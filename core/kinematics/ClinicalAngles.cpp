#include "core/kinematics/ClinicalAngles.h"

#include <numbers>

namespace armtrack {
namespace {
constexpr double kToDeg = 180.0 / std::numbers::pi;
}

// The DH joints map one-to-one onto the named angles; only the signs differ (docs/arm-model.md):
// with x0 down, y0 forward and z0 lateral, +th0 swings the arm forward, +th1 lifts it sideways,
// +th2 turns a flexed forearm outward, +th4 bends the elbow backward and +th5 turns the thumb
// outward (supination).
std::array<double, 5> clinicalRadians(const JointVector& th) {
  return {wrapAngle(th(0)), wrapAngle(th(1)), -wrapAngle(th(2)), -wrapAngle(th(3)),
          -wrapAngle(th(4))};
}

ClinicalAngles toClinical(const JointVector& th) {
  const std::array<double, 5> r = clinicalRadians(th);
  return {r[0] * kToDeg, r[1] * kToDeg, r[2] * kToDeg, r[3] * kToDeg, r[4] * kToDeg};
}

JointVector fromClinical(const ClinicalAngles& c) {
  JointVector th;
  th << c.shoulderFlexion, c.shoulderAbduction, -c.shoulderInternalRotation, -c.elbowFlexion,
      -c.forearmPronation;
  return th / kToDeg;
}

const std::array<ClinicalAngleInfo, 5>& clinicalAngleInfo() {
  static const std::array<ClinicalAngleInfo, 5> info{{
      {"shoulder_flexion", "Shoulder flexion", "flexion (arm forward)", -60.0, 180.0},
      {"shoulder_abduction", "Shoulder abduction", "abduction (arm out to the side)", 0.0, 180.0},
      {"shoulder_internal_rotation", "Shoulder internal rotation", "internal rotation", -90.0,
       70.0},
      {"elbow_flexion", "Elbow flexion", "flexion", 0.0, 150.0},
      {"forearm_pronation", "Forearm pronation", "pronation (palm down)", -80.0, 80.0},
  }};
  return info;
}

std::array<double, 5> asArray(const ClinicalAngles& c) {
  return {c.shoulderFlexion, c.shoulderAbduction, c.shoulderInternalRotation, c.elbowFlexion,
          c.forearmPronation};
}

}  // namespace armtrack
