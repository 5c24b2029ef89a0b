// A calibration file as core's CameraParams, the camera model the estimator and the recordings
// use. Not in the fuzz build: it needs armtrack_core's types.
#pragma once

#include <optional>

#include "core/camera/CameraParams.h"
#include "devices/vision/CameraFile.h"

namespace armtrack::devices::webcam {

/// The CameraParams of a calibration file (intrinsics, distortion and pose), when it has a pose.
std::optional<CameraParams> toCameraParams(const CameraFile& file);

}  // namespace armtrack::devices::webcam
