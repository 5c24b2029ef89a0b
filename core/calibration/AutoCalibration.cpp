#include "core/calibration/AutoCalibration.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <utility>
#include <vector>

#include "core/estimation/RecordingEstimator.h"
#include "core/kinematics/ArmModel.h"

namespace armtrack {

namespace {

constexpr double kGyroScale = 0.05;    // rad/s
constexpr double kAccelScale = 0.5;    // m/s^2
constexpr double kDiffSeconds = 0.02;  // half the span of the central differences

struct AngleRow {
  double t = 0.0;
  JointVector th = JointVector::Zero();
  bool fused = false;
};

bool finite(const ImuReading& r) {
  return r.gyr.allFinite() && r.acc.allFinite();
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string shortest(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

double turnDeg(const Eigen::Matrix3d& r) {
  return std::acos(std::clamp((r.trace() - 1.0) / 2.0, -1.0, 1.0)) / kDeg;
}

}  // namespace

double ReadingFit::score() const {
  return std::pow(gyroRms / kGyroScale, 2) + std::pow(accelRms / kAccelScale, 2);
}

MountingSummary summarise(const MovementCalibration& m) {
  MountingSummary s;
  s.upperTurnDeg = turnDeg(m.upperMounting);
  s.forearmTurnDeg = turnDeg(m.forearmMounting);
  const ArmGeometry& g = m.calibration.geometry;
  s.upperFromShoulderCm = g.lu3 * 100.0;
  s.forearmFromWristCm = (g.l6 - g.lf6) * 100.0;
  return s;
}

/// The filter over rec, and the readings its angles predict against the measured ones.
ReadingFit measureReadingFit(const Recording& rec, const FilterParamsFor& paramsFor,
                             const std::atomic<bool>* cancel) {
  const EstimatorParams params = paramsFor(rec.meta);
  std::vector<AngleRow> rows;
  rows.reserve(rec.samples.size());
  EstimateCallbacks callbacks;
  callbacks.row = [&](const armtrack::EstimateRow& r) {
    rows.push_back({r.t, r.th, r.status == kStatusFused && r.th.allFinite()});
  };
  callbacks.cancel = cancel;
  const EstimateStats run = estimateRecording(rec, params, callbacks);
  ReadingFit fit;
  if (run.cancelled || rows.size() < 3) return fit;
  std::vector<double> dts;
  for (std::size_t i = 1; i < rows.size(); ++i) dts.push_back(rows[i].t - rows[i - 1].t);
  std::nth_element(dts.begin(), dts.begin() + dts.size() / 2, dts.end());
  const double dt = dts[dts.size() / 2];
  if (!(dt > 0.0)) return fit;
  const std::size_t k = std::max<std::size_t>(1, static_cast<std::size_t>(kDiffSeconds / dt));
  const Eigen::Vector3d gUp = rec.meta.gUp();
  const ArmGeometry& geo = rec.meta.geometry;
  const bool left = rec.meta.side == Side::Left;
  double sumG = 0.0, sumA = 0.0;
  std::size_t j = 0;  // the sample of row i
  for (std::size_t i = k; i + k < rows.size(); ++i) {
    const AngleRow &a = rows[i - k], &b = rows[i], &c = rows[i + k];
    while (j < rec.samples.size() && rec.samples[j].t < b.t) ++j;
    if (j >= rec.samples.size()) break;
    if (!a.fused || !b.fused || !c.fused || b.t < rows.front().t + kStartupSeconds) continue;
    const ArmSample& s = rec.samples[j];
    if (s.t != b.t || !s.upperArm || !s.forearm || !finite(*s.upperArm) || !finite(*s.forearm))
      continue;
    const double h1 = b.t - a.t, h2 = c.t - b.t;
    if (!(h1 > 0.0 && h2 > 0.0) || std::abs(h1 - h2) > 0.25 * (h1 + h2)) continue;
    if (((c.th - a.th).array().abs() > 1.0).any()) continue;  // a jump, not a movement
    const JointVector thd = (c.th - a.th) / (h1 + h2);
    const JointVector thdd = ((c.th - b.th) / h2 - (b.th - a.th) / h1) * (2.0 / (h1 + h2));
    const ArmKinematics<double> kin = armKinematics<double>(geo, b.th, thd, thdd, gUp);
    const ImuReading u = left ? mirrorImu(*s.upperArm) : *s.upperArm;
    const ImuReading f = left ? mirrorImu(*s.forearm) : *s.forearm;
    sumG +=
        (kin.upperImu.omega - u.gyr).squaredNorm() + (kin.forearmImu.omega - f.gyr).squaredNorm();
    sumA += (kin.upperImu.up + kin.upperImu.accel - u.acc).squaredNorm() +
            (kin.forearmImu.up + kin.forearmImu.accel - f.acc).squaredNorm();
    ++fit.samples;
  }
  if (fit.samples == 0) return fit;
  fit.gyroRms = std::sqrt(sumG / static_cast<double>(fit.samples));
  fit.accelRms = std::sqrt(sumA / static_cast<double>(fit.samples));
  return fit;
}

namespace {

/// A parameter's name said with its value: "upper-arm strap turned 23 deg about the arm",
/// "forearm sensor 4 cm from the elbow (sidecar 6 cm)".
std::string phrase(const MovementParameter& p) {
  const std::string v = fixed(p.value, 0) + " " + p.unit;
  std::string s = p.name;
  bool placed = false;
  for (const auto& [word, said] :
       {std::pair{" turn about ", " turned "}, std::pair{" tilt about ", " tilted "},
        std::pair{" roll about ", " rolled "}, std::pair{" distance from ", " "}}) {
    if (const auto at = s.find(word); at != std::string::npos) {
      // "upper-arm strap turn about the arm" -> "upper-arm strap turned V about the arm"
      const std::string w(word);
      const auto keep = w.find(' ', 1);  // " about ...", " from ..."
      s = s.substr(0, at) + said + v + s.substr(at + keep);
      placed = true;
      break;
    }
  }
  if (!placed) s += " " + v;
  if (p.unit != "deg" || p.prior != 0.0) s += " (sidecar " + fixed(p.prior, 0) + " " + p.unit + ")";
  return s;
}

/// The whole turn of each sensor from the sidecar's mounting, then the excited parameters that
/// moved clearly from the sidecar's values.
std::string changes(const MovementCalibration& m) {
  std::string s = "upper-arm sensor turned " + fixed(turnDeg(m.upperMounting), 0) +
                  " deg in all, forearm sensor " + fixed(turnDeg(m.forearmMounting), 0) + " deg";
  std::string details;
  for (const MovementParameter& p : m.parameters) {
    if (!p.excited || !p.observable || !std::isfinite(p.value)) continue;
    const double floor = p.unit == "deg" ? 3.0 : 1.0;
    if (std::abs(p.value - p.prior) < std::max(floor, 2.0 * p.sd)) continue;
    details += (details.empty() ? "" : ", ") + phrase(p);
  }
  return s + (details.empty() ? "" : " (" + details + ")");
}

/// Where the forearm sensor's roll about the forearm came from, or that it was not seen.
std::string roll(const MovementCalibration& m, bool poseExpected) {
  if (m.rollFromPose)
    return "; forearm roll from " + std::to_string(m.poseRests) + " rest(s) in the start pose";
  if (!poseExpected) return "";
  return "; forearm roll not observable (no rest with the upper arm hanging, the elbow at a right "
         "angle and the thumb up): the sidecar's kept";
}

std::string describe(const ReadingFit& f) {
  return "gyroscopes " + fixed(f.gyroRms, 3) + " rad/s, accelerometers " + fixed(f.accelRms, 2) +
         " m/s^2";
}

}  // namespace

AutoCalibrationResult autoCalibrate(const Recording& whole, const FilterParamsFor& paramsFor,
                                    const AutoCalibrationParams& params,
                                    const Calibration* current) {
  using Outcome = AutoCalibrationResult::Outcome;
  AutoCalibrationResult out;
  const std::string head = "calibration from movement: ";
  const std::string window = "the first " + shortest(params.windowSeconds) + " s";
  Recording rec;
  rec.meta = whole.meta;
  for (const ArmSample& s : whole.samples) {
    if (!rec.samples.empty() && s.t - rec.samples.front().t > params.windowSeconds) break;
    rec.samples.push_back(s);
  }
  std::string why;
  std::optional<MovementCalibration> m;
  try {
    MovementCalibrationParams mp;
    mp.expectedRestPose = params.expectedRestPose;
    m = tryCalibrateFromMovement(rec, mp, &why);
  } catch (const std::exception& e) {
    why = e.what();
  }
  if (!m) {
    out.line = head + "not tried on " + window + ": " + why;
    return out;
  }
  out.outcome = Outcome::NotApplied;
  if (const std::string problem = calibrationProblem(m->calibration); !problem.empty()) {
    out.line = head + "not applied: the fit gave values no real arm has (" + problem + ")";
    return out;
  }
  out.summary = summarise(*m);
  out.forearmRollSeen = m->rollFromPose;
  try {
    Recording reference = rec;
    if (current) applyCalibration(*current, reference);
    out.reference = measureReadingFit(reference, paramsFor, params.cancel);
    Recording calibrated = std::move(rec);
    applyCalibration(m->calibration, calibrated);
    out.fitted = measureReadingFit(calibrated, paramsFor, params.cancel);
  } catch (const std::exception& e) {
    out.line = head + "not applied: its check failed (" + e.what() + ")";
    return out;
  }
  const std::string found = changes(*m) + roll(*m, params.expectedRestPose.has_value());
  if (out.reference.samples == 0 || out.fitted.samples == 0) {
    out.line = head + found + "; not applied: too few estimates in " + window + " to check it";
    return out;
  }
  const std::string theirs = current ? " with the one in use)" : " with the sidecar's)";
  const std::string compared = " (the model misses the readings by " + describe(out.fitted) +
                               " with it, " + describe(out.reference) + theirs;
  if (!(out.fitted.score() < params.betterFraction * out.reference.score())) {
    out.line = head + found + "; not applied: the " +
               (current ? "calibration in use" : "sidecar's mounting") +
               " explains the readings as well" + compared;
    return out;
  }
  if (current && params.currentRollSeen && !m->rollFromPose) {
    out.line = head + found +
               "; not applied: the calibration in use has the forearm's roll from the start pose, "
               "this fit does not" +
               compared;
    return out;
  }
  out.outcome = Outcome::Applied;
  out.calibration = m->calibration;
  out.line = head + found + "; applied" + compared;
  return out;
}

}  // namespace armtrack
