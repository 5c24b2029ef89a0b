// The plain-language report of the calibration from movement
// (core/calibration/MovementCalibration.h).
#include "core/calibration/MovementCalibration.h"
#include "core/calibration/MovementReadings.h"

namespace armtrack {

using movecal::fixed1;

std::string formatMovementReport(const MovementCalibration& m) {
  std::string s = "Calibration from movement (" + sideName(m.calibration.side) + " arm; rest " +
                  fixed1(m.restStart) + "-" + fixed1(m.restEnd) + " s, " + fixed1(m.movingSeconds) +
                  " s of movement)\n\n";
  const auto find = [&](const std::string& name) -> const MovementParameter* {
    for (const MovementParameter& p : m.parameters)
      if (p.name == name) return &p;
    return nullptr;
  };
  const auto say = [&](const std::string& name, const std::string& text) {
    const MovementParameter* p = find(name);
    if (!p) return;
    if (!p->observable) {
      s += "- " + text +
           ": no movement can tell it from pronation, and no rest was in the start pose (upper "
           "arm hanging, elbow at a right angle, thumb up); the sidecar's is kept.\n";
    } else if (!p->excited) {
      s += "- " + text + ": the movement did not show it; the sidecar's " + fixed1(p->prior) + " " +
           p->unit + " is kept.\n";
    } else {
      s += "- " + text + ": " + fixed1(p->value) + " " + p->unit + " (sd " + fixed1(p->sd) + " " +
           p->unit + ").\n";
    }
  };
  s += "Upper arm:\n";
  say("upper-arm strap turn about the arm", "the strap turned about the arm by");
  say("upper-arm sensor tilt about its x axis", "the sensor tilted about its x axis by");
  say("upper-arm sensor tilt about its z axis", "the sensor tilted about its z axis by");
  say("upper-arm sensor distance from the shoulder", "the sensor sits from the shoulder at");
  say("upper-arm sensor distance from the arm's axis", "and off the arm's axis by");
  say("upper-arm length", "the upper arm (shoulder to elbow) is");
  s += "Forearm:\n";
  say("forearm sensor tilt about its x axis", "the sensor tilted about its x axis by");
  say("forearm sensor tilt about its z axis", "the sensor tilted about its z axis by");
  say("forearm sensor roll about the forearm", "its roll about the forearm");
  if (m.rollFromPose && m.poseRests > 0)
    s += "  from gravity at " + std::to_string(m.poseRests) +
         " rest(s) in the start pose (upper arm hanging, elbow at a right angle, thumb up).\n";
  say("forearm sensor distance from the elbow", "the sensor sits from the elbow at");
  if (const MovementParameter* p = find("forearm sensor distance from the elbow"); p && p->excited)
    s += "  that is " + fixed1(m.calibration.geometry.l6 * 100.0 - p->value) +
         " cm from the wrist (forearm length " + fixed1(m.calibration.geometry.l6 * 100.0) +
         " cm, the sidecar's).\n";
  say("forearm sensor distance from the forearm's axis", "and off the forearm's axis by");
  const Calibration& c = m.calibration;
  s += "Gyroscope bias at rest (deg/s): upper arm [" + fixed1(c.upperArm.gyroBias.x() / kDeg) +
       " " + fixed1(c.upperArm.gyroBias.y() / kDeg) + " " + fixed1(c.upperArm.gyroBias.z() / kDeg) +
       "], forearm [" + fixed1(c.forearm.gyroBias.x() / kDeg) + " " +
       fixed1(c.forearm.gyroBias.y() / kDeg) + " " + fixed1(c.forearm.gyroBias.z() / kDeg) + "].\n";
  s += "Fit residuals: elbow relative motion " + fixed1(m.axisResidualRms / kDeg) +
       " deg/s, joint positions " + fixed1(m.leverResidualRms) + " m/s^2 (RMS).\n";
  for (const std::string& w : m.warnings) s += "Note: " + w + ".\n";
  return s;
}

}  // namespace armtrack
