// The calibration from ordinary movement used automatically by "armtrack-cli estimate" when no
// calibration file is given (docs/cli.md, "estimate"; docs/calibration.md, "Used
// automatically"): the recording's first seconds read from the file and handed to the shared
// implementation, core/calibration/AutoCalibration.h.
#pragma once

#include <filesystem>

#include "core/calibration/AutoCalibration.h"
#include "core/estimation/RecordingEstimator.h"

namespace armtrack::cli {

using armtrack::AutoCalibrationParams;
using armtrack::AutoCalibrationResult;
using armtrack::ReadingFit;

/// Reads the first params.windowSeconds of the recording and runs armtrack::autoCalibrate on
/// them with the filter of options. Never throws: a recording that cannot be read or used gives
/// "not tried" with the reason (the estimate itself then reports any error of the file).
AutoCalibrationResult autoCalibrate(const std::filesystem::path& input,
                                    const EstimateOptions& options,
                                    const AutoCalibrationParams& params = {});

}  // namespace armtrack::cli
