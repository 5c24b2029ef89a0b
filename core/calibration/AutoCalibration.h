// The calibration from ordinary movement used automatically when no calibration file exists
// (docs/calibration.md, "Used automatically"): fitted on a window of the readings
// (core/calibration/MovementCalibration.h) and applied only when it explains the readings
// clearly better than the mounting in use. One implementation for "armtrack-cli estimate"
// (app/cli/AutoCalibration.h), the live session (core/session) and the GUI. Qt-free; any thread.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>

#include "core/calibration/Calibration.h"
#include "core/calibration/MovementCalibration.h"
#include "core/estimation/ArmFilter.h"
#include "core/io/Recording.h"

namespace armtrack {

/// How well the model explains one recording's IMU readings with a mounting: the filter is run
/// over the readings, and the readings its angles predict (rates and accelerations by central
/// differences of the angles) are compared with the measured ones, RMS over the samples.
struct ReadingFit {
  double gyroRms = 0.0;   ///< rad/s, per IMU sample (both IMUs' three axes)
  double accelRms = 0.0;  ///< m/s^2
  std::size_t samples = 0;
  /// The one number compared: gyroRms / 0.05 rad/s and accelRms / 0.5 m/s^2, summed in squares.
  double score() const;
};

/// What was found, in numbers a screen says in its own words (no text).
struct MountingSummary {
  double upperTurnDeg = 0.0;    ///< the upper-arm sensor's whole turn from the sidecar's mounting
  double forearmTurnDeg = 0.0;  ///< the forearm sensor's
  double upperFromShoulderCm = 0.0;  ///< the upper-arm sensor's distance from the shoulder
  double forearmFromWristCm = 0.0;   ///< the forearm sensor's distance from the wrist
};

/// The summary of a fitted calibration (geometry from m.calibration).
MountingSummary summarise(const MovementCalibration& m);

struct AutoCalibrationResult {
  enum class Outcome {
    NotTried,    ///< the window could not be read or used (too short, no rest, ...)
    NotApplied,  ///< fitted, but not better by the rule, or not checkable
    Applied,     ///< calibration is set
  };
  Outcome outcome = Outcome::NotTried;
  std::optional<Calibration> calibration;  ///< set only when the fitted one is applied
  std::optional<MountingSummary> summary;  ///< set whenever a fit was made
  std::string line;                        ///< "calibration from movement: ..." (no newline)
  ReadingFit reference, fitted;            ///< when both were measured (samples > 0)
  /// The fit took the forearm sensor's roll from rests in the start pose (false: the sidecar's).
  bool forearmRollSeen = false;
};

/// Settings of autoCalibrate.
struct AutoCalibrationParams {
  double windowSeconds = 60.0;  ///< the fit uses the window's first seconds, up to this
  /// The fitted mounting is applied only when its ReadingFit score is below this fraction of the
  /// reference's (the sidecar's, or the calibration in use).
  double betterFraction = 0.7;
  /// The pose the patient is told to rest in at the start (protocolStartPose(): upper arm
  /// hanging, elbow at a right angle, thumb up; docs/calibration.md, "The rest pose"). The rests
  /// that look like it give the forearm sensor's roll about the forearm, which no movement shows
  /// (MovementCalibrationParams::expectedRestPose). Unset: the roll stays the sidecar's.
  std::optional<JointVector> expectedRestPose = protocolStartPose();
  /// The calibration in use (`current`) has the forearm's roll from a rest in the start pose: a
  /// fit that did not see the roll is not applied over it (it would put the sidecar's back).
  bool currentRollSeen = false;
  /// Checked while the filter runs; when it reads true the check stops early and nothing is
  /// applied. May be set from another thread. May be null.
  const std::atomic<bool>* cancel = nullptr;
};

/// The filter parameters for a recording's metadata (geometry, gravity, side, camera from it).
using FilterParamsFor = std::function<EstimatorParams(const RecordingMeta&)>;

/// Fits the calibration from movement on window (its readings as recorded, its sidecar the
/// prior; samples beyond params.windowSeconds are left out) and measures it with ReadingFit
/// against the reference: the sidecar's mounting, or `current` when given (a calibration applied
/// earlier, to be replaced only by a clearly better one). Never throws: a window that cannot be
/// used gives NotTried with the reason in line.
AutoCalibrationResult autoCalibrate(const Recording& window, const FilterParamsFor& paramsFor,
                                    const AutoCalibrationParams& params = {},
                                    const Calibration* current = nullptr);

/// The ReadingFit of a recording (readings as they are, filter parameters from its meta).
ReadingFit measureReadingFit(const Recording& rec, const FilterParamsFor& paramsFor,
                             const std::atomic<bool>* cancel = nullptr);

}  // namespace armtrack
