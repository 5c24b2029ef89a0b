// The calibration from ordinary movement used automatically by "armtrack-cli estimate" when no
// calibration file is given (docs/cli.md, "estimate"; docs/calibration.md, "Used
// automatically"): fitted on the recording's first seconds, applied only when it explains the
// readings clearly better than the sidecar's mounting.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/calibration/Calibration.h"
#include "core/estimation/RecordingEstimator.h"

namespace armtrack::cli {

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

struct AutoCalibrationResult {
  std::optional<Calibration> calibration;  ///< set only when the fitted one is applied
  std::string line;                        ///< "calibration from movement: ..." (no newline)
  ReadingFit sidecar, fitted;              ///< when both were measured (samples > 0)
};

/// Settings of autoCalibrate.
struct AutoCalibrationParams {
  double windowSeconds = 60.0;  ///< the fit uses the recording's first seconds, up to this
  /// The fitted mounting is applied only when its ReadingFit score is below this fraction of the
  /// sidecar's.
  double betterFraction = 0.7;
};

/// Reads the first params.windowSeconds of the recording, fits the calibration from movement
/// (core/calibration/MovementCalibration.h) and measures both mountings with ReadingFit. Never
/// throws: a recording that cannot be read or used gives "not tried" with the reason (the
/// estimate itself then reports any error of the file).
AutoCalibrationResult autoCalibrate(const std::filesystem::path& input,
                                    const EstimateOptions& options,
                                    const AutoCalibrationParams& params = {});

}  // namespace armtrack::cli
