// The "estimate --method tao-hu" engine: runs the Tao-Hu tracker (webcam markers + forearm IMU,
// core/taohu) over a recording, writes one row per camera frame and reports errors against the
// recording's truth.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

#include "app/cli/CsvOutput.h"
#include "core/io/Recording.h"
#include "core/taohu/TaoHuTracker.h"

namespace armtrack::cli {

/// Header of the output CSV: time (s), wrist and elbow (m, the arm's shoulder frame), angles
/// (rad).
inline constexpr const char* kTaoHuHeader =
    "t,wrist_x,wrist_y,wrist_z,elbow_x,elbow_y,elbow_z,th0,th1,th2,th4,th5";

struct TaoHuRun {
  TaoHuResult result;
  TaoHuErrors errors;  ///< count 0 when the recording has no truth
  double seconds = 0.0;
};

/// Runs the tracker with the sidecar's geometry, side and camera and writes the frames to writer
/// when given. Throws std::runtime_error with a clear message when the recording has no camera
/// block or no forearm IMU.
TaoHuRun runTaoHuRecording(const Recording& recording, CsvOutput* writer);

/// Markdown report: per-joint RMSE/peak and the wrist/elbow position errors next to the paper's
/// +/-5 cm (empty when there is no truth).
std::string formatTaoHuReport(const TaoHuRun& run);

}  // namespace armtrack::cli
