// Steps 0 to 2 of the batch calibration: the recording on its right-arm twin, the first
// gyroscope-bias guess and the first trajectory from the filter. See CalibrationStart.h and
// core/calibration/Calibrator.cpp.
#include "core/calibration/CalibrationStart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/kinematics/Side.h"

namespace armtrack::calib {
namespace {

constexpr double kMinDuration = 10.0;  // s

}  // namespace

// 0. The recording on the right-arm twin; throws when it cannot be used.
Prepared prepare(const Recording& recording, const CalibrationOptions& options) {
  Prepared in;
  in.left = recording.meta.side == Side::Left;
  in.nominal = recording.meta.geometry;
  in.up = in.left ? mirrorPoint(recording.meta.up) : recording.meta.up;
  in.gUp = recording.meta.g * in.up;
  in.samples.reserve(recording.samples.size());
  // Plausibility at the door: an absurd but finite reading (1e20 rad/s), a saturated burst or
  // all-zero rows would otherwise pull the whole fit (one such row gave l3 = l6 = 50 mm).
  SampleGate gate(PlausibilityLimits::forGeometry(in.nominal.l3, in.nominal.l6));
  bool hasUpper = false, hasForearm = false, hasOptical = false;
  double tFirst = std::numeric_limits<double>::infinity(), tLast = -tFirst;
  for (const ArmSample& raw : recording.samples) {
    const ArmSample s = gate.check(raw);
    in.samples.push_back(in.left ? mirrorSample(s) : s);
    hasUpper |= s.upperArm.has_value();
    hasForearm |= s.forearm.has_value();
    hasOptical |= s.elbow.has_value() || s.wrist.has_value();
    if (s.hasImu() && std::isfinite(s.t)) {
      tFirst = std::min(tFirst, s.t);
      tLast = std::max(tLast, s.t);
    }
  }
  in.implausible = gate.counters();
  const std::string refused =
      in.implausible.total() > 0 ? " (" + in.implausible.summary() + ")" : std::string();
  if (!hasUpper || !hasForearm) {
    throw std::invalid_argument("calibration needs both the upper-arm and the forearm IMU" +
                                refused);
  }
  if (!(tLast - tFirst >= kMinDuration)) {
    throw std::invalid_argument(
        "calibration needs at least 10 s of IMU data (the protocol takes about a minute)" +
        refused);
  }
  in.tFirst = tFirst;
  in.tLast = tLast;
  in.optical = hasOptical && options.useOptical;
  return in;
}

// 1. Still start: first gyroscope-bias guess per IMU (upper arm, forearm).
std::array<Vec3, 2> guessGyroBias(const Prepared& in, const CalibrationOptions& options,
                                  CalibrationResult& result, const CalibrationProgress& say) {
  const double stillEnd = in.tFirst + options.startStillSeconds;
  std::array<Vec3, 2> biasGuess;
  for (int imu = 0; imu < 2; ++imu) {
    const StillStats st = stillStats(in.samples, imu == 1, in.tFirst, stillEnd);
    const char* name = imu == 0 ? "upper-arm" : "forearm";
    // Noise alone gives the per-reading std; a moving arm gives tens of deg/s.
    const double limit = 3.0 * options.gyroStd + 2.0 * kDeg;
    if (st.count < 10 || st.maxStd > limit) {
      result.warnings.push_back(std::string("the ") + name +
                                " IMU was not still during the first " +
                                std::to_string(options.startStillSeconds) +
                                " s: no bias guess from the start, and the start-pose assumption "
                                "may not hold");
      biasGuess[imu].setZero();
    } else {
      biasGuess[imu] = st.mean;
    }
  }
  char line[200];
  std::snprintf(line, sizeof line,
                "calibrate: start-pose gyro bias guess upper [%.3f %.3f %.3f], forearm "
                "[%.3f %.3f %.3f] deg/s",
                biasGuess[0].x() / kDeg, biasGuess[0].y() / kDeg, biasGuess[0].z() / kDeg,
                biasGuess[1].x() / kDeg, biasGuess[1].y() / kDeg, biasGuess[1].z() / kDeg);
  say(line);
  return biasGuess;
}

// 2. First trajectory from the EKF with the nominal mounting and the bias guess.
std::vector<JointEstimate> firstTrajectory(const Prepared& in, const std::array<Vec3, 2>& biasGuess,
                                           const CalibrationOptions& options,
                                           const CalibrationProgress& say) {
  std::vector<ArmSample> corrected = in.samples;
  for (ArmSample& s : corrected) {
    if (s.upperArm) s.upperArm->gyr -= biasGuess[0];
    if (s.forearm) s.forearm->gyr -= biasGuess[1];
  }
  EstimatorParams ekf;
  ekf.geometry = in.nominal;
  ekf.gUp = in.gUp;
  ekf.side = Side::Right;
  ekf.useOptical = in.optical;
  ekf.jointAccelVariance = options.initialFilterJointAccelStd * options.initialFilterJointAccelStd;
  BatchResult first = estimateSamples(corrected, ekf);
  if (first.estimates.empty())
    throw std::invalid_argument("the joint-angle filter produced no estimate for the recording");
  say("calibrate: first trajectory from the EKF (" + std::to_string(first.estimates.size()) +
      " estimates)");
  return std::move(first.estimates);
}

}  // namespace armtrack::calib
