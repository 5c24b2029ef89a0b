// The "estimate" command's engine: runs a joint-angle filter over a recording, streams the
// angles to a CSV and collects error statistics against the recording's true angles.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "app/cli/CsvOutput.h"
#include "core/estimation/ArmFilter.h"
#include "core/io/Recording.h"

namespace armtrack::cli {

/// Command-line choices on top of the recording's sidecar.
struct EstimateOptions {
  FilterKind filter = FilterKind::Ekf;
  MeasurementModel model = MeasurementModel::AccelGyro;
  bool useOptical = true;  ///< fuse Kinect positions
  bool useCamera = true;   ///< fuse webcam marker pixels (when the sidecar has a camera)
  std::optional<double> jointAccelStdDeg;  ///< deg/s^2; empty keeps the library default
};

/// Filter parameters: geometry and gravity from the sidecar, the rest from options.
EstimatorParams makeParams(const RecordingMeta& meta, const EstimateOptions& options);

/// Per-joint RMSE of the estimates whose time lies in [from, to].
struct WindowError {
  double from = 0.0, to = 0.0;  ///< s
  std::size_t count = 0;
  JointVector rmseDeg = JointVector::Zero();
};

struct EstimateStats {
  std::size_t rows = 0;       ///< samples offered to the filter
  std::size_t estimates = 0;  ///< output rows: samples that carry IMU data and got an estimate
  std::size_t imuRows = 0;    ///< samples that carry IMU data
  std::size_t predicted = 0;  ///< output rows whose readings were all refused (predictions)
  double tFirst = 0.0;        ///< time of the first estimate (s)
  double tLast = 0.0;         ///< time of the last estimate (s)
  EstimatorCounters counters;
  bool opticalUsed = false;  ///< some optical position was fused

  /// Errors against the recording's true angles, leaving out the first second after each
  /// (re)start of the filter. truthCount is 0 when the recording has no truth.
  std::size_t truthCount = 0;
  JointVector rmseDeg = JointVector::Zero();
  JointVector peakDeg = JointVector::Zero();
  std::size_t truthRows = 0;  ///< estimates that had true angles, start-up seconds included
  WindowError firstWindow;  ///< the first 10 s after start-up (shorter for a short recording)
  WindowError lastWindow;   ///< the last 10 s after the first window (may be empty)
};

/// Called with 10, 20, ..., 100 (percent of rows done) for recordings of more than
/// kProgressRows rows.
using EstimateProgress = std::function<void(int percent)>;
inline constexpr std::size_t kProgressRows = 100000;

/// The header of `estimate --out`: time, the five angles (rad), their standard deviations (rad)
/// and a status per row (kStatus* below).
inline constexpr const char* kEstimateHeader =
    "t,th0,th1,th2,th4,th5,sd_th0,sd_th1,sd_th2,sd_th4,sd_th5,status";
/// Status of an output row: 0 the readings were fused; 1 every reading of the row was refused as
/// implausible and the estimate is a prediction; 2 the filter (re)started here; 3 the filter had
/// lost the arm (or its start-up guess was poor) and re-initialised from the recent window. At 2
/// and 3 the angles may jump without the arm having moved.
inline constexpr double kStatusFused = 0, kStatusPredicted = 1, kStatusRestarted = 2,
                        kStatusRecovered = 3;

/// Runs the filter sample by sample. Each sample that carries IMU data and gets an estimate yields
/// one output row (kEstimateHeader, written to writer when given) and, when it carries true
/// angles, one error sample.
EstimateStats estimateRecording(const Recording& recording, const EstimatorParams& params,
                                CsvOutput* writer, const EstimateProgress& progress = {});

/// Markdown report of the errors (empty when there is no truth) and, when no optical data was
/// fused, the heading note and the first-vs-last 10 s comparison.
std::string formatReport(const EstimateStats& stats);

}  // namespace armtrack::cli
