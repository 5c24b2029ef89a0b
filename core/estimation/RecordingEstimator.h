// Offline estimation of a whole recording: the loop behind `armtrack-cli estimate`, the storage
// service's session analysis and (later) the GUI's re-estimation. It runs the joint-angle filter
// sample by sample, hands every output row to a sink, and collects error statistics against the
// recording's true angles when it has them. Qt-free.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "core/estimation/ArmFilter.h"
#include "core/estimation/TrunkMotionDetector.h"
#include "core/io/Recording.h"

namespace armtrack {

/// Choices on top of a recording's sidecar (what `estimate` takes on its command line and a
/// session stores as its filter settings).
struct EstimateOptions {
  FilterKind filter = FilterKind::Ekf;
  MeasurementModel model = MeasurementModel::AccelGyro;
  bool useOptical = true;  ///< fuse Kinect positions
  bool useCamera = true;   ///< fuse webcam marker pixels (when the sidecar has a camera)
  std::optional<double> jointAccelStdDeg;  ///< deg/s^2; empty keeps the library default
  /// The IMUs' measurement noise (white, per axis), for sensors noisier than Table 5's:
  /// gyroscopes in deg/s, accelerometers in m/s^2. Empty keeps the library default.
  std::optional<double> gyroNoiseStdDeg;
  std::optional<double> accelNoiseStd;
};

/// Filter parameters: geometry, gravity, side and camera from the sidecar, the rest from options.
EstimatorParams estimatorParamsFor(const RecordingMeta& meta, const EstimateOptions& options);

/// The columns of one output row: time, the five angles (rad), their standard deviations (rad)
/// and a status (kStatus* below). Also the header of `estimate --out`.
inline constexpr const char* kEstimateHeader =
    "t,th0,th1,th2,th4,th5,sd_th0,sd_th1,sd_th2,sd_th4,sd_th5,status";
/// The same with the trunk's angles (rad, patient terms, core/kinematics/Trunk.h) and their
/// standard deviations, for a recording with a trunk IMU or an optical shoulder. Cells the
/// recording cannot give (no trunk IMU) are empty.
inline constexpr const char* kEstimateTrunkHeader =
    "t,th0,th1,th2,th4,th5,sd_th0,sd_th1,sd_th2,sd_th4,sd_th5,status,"
    "trunk_flex,trunk_lat,trunk_rot,sd_trunk_flex,sd_trunk_lat,sd_trunk_rot";
/// Whether a recording with these columns gets the trunk columns.
inline bool hasTrunkOutput(const RecordingColumns& c) {
  return c.trunk || c.shoulder;
}
/// Status of an output row: 0 the readings were fused; 1 every reading of the row was refused as
/// implausible and the estimate is a prediction; 2 the filter (re)started here; 3 the filter had
/// lost the arm (or its start-up guess was poor) and re-initialised from the recent window. At 2
/// and 3 the angles may jump without the arm having moved. 4: fused, but the trunk had moved from
/// its start pose with no trunk IMU to measure it (an optical shoulder saw it,
/// core/estimation/TrunkMotionDetector.h): the shoulder angles then include the patient's lean.
inline constexpr int kStatusFused = 0, kStatusPredicted = 1, kStatusRestarted = 2,
                     kStatusRecovered = 3, kStatusTrunkMoved = 4;

/// After a (re)start (status 2) or a recovery (status 3) the filter settles for about this long
/// (s): the error statistics leave these rows out, and so do the clinical metrics of a session.
inline constexpr double kStartupSeconds = 1.0;

/// One output row of the estimator.
struct EstimateRow {
  double t = 0;                          ///< s, the sample's time
  JointVector th = JointVector::Zero();  ///< DH joint angles (rad)
  JointVector sd = JointVector::Zero();  ///< their standard deviations (rad)
  int status = kStatusFused;             ///< kStatus*
  /// The trunk's angles and standard deviations (rad) when a trunk IMU measures them; NaN
  /// otherwise.
  Eigen::Vector3d trunk = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d trunkSd = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

/// Per-joint RMSE of the estimates whose time lies in [from, to].
struct WindowError {
  double from = 0.0, to = 0.0;  ///< s
  std::size_t count = 0;
  JointVector rmseDeg = JointVector::Zero();
};

struct EstimateStats {
  std::size_t rows = 0;       ///< samples in the recording
  std::size_t estimates = 0;  ///< output rows: samples that carry IMU data and got an estimate
  std::size_t imuRows = 0;    ///< samples that carry IMU data (of those offered)
  std::size_t predicted = 0;  ///< output rows whose readings were all refused (predictions)
  double tFirst = 0.0;        ///< time of the first estimate (s)
  double tLast = 0.0;         ///< time of the last estimate (s)
  EstimatorCounters counters;
  bool opticalUsed = false;  ///< some optical position or marker pixel was fused
  bool cancelled = false;    ///< the cancel flag stopped the run; the rest is partial

  /// Errors against the recording's true angles, leaving out the first second after each
  /// (re)start of the filter. truthCount is 0 when the recording has no truth.
  std::size_t truthCount = 0;
  JointVector rmseDeg = JointVector::Zero();
  JointVector peakDeg = JointVector::Zero();
  std::size_t truthRows = 0;  ///< estimates that had true angles, start-up seconds included
  /// Spans in which the trunk moved with no trunk IMU to measure it (rows of status 4).
  std::vector<TrunkMotionSpan> trunkMovedSpans;
  /// Trunk angles against the recording's true ones (flexion, lateral, axial), after start-up.
  std::size_t trunkTruthCount = 0;
  Eigen::Vector3d trunkRmseDeg = Eigen::Vector3d::Zero();
  Eigen::Vector3d trunkPeakDeg = Eigen::Vector3d::Zero();
  WindowError firstWindow;  ///< the first 10 s after start-up (shorter for a short recording)
  WindowError lastWindow;   ///< the last 10 s after the first window (may be empty)
};

/// Receives each output row, in time order, on the calling thread.
using EstimateSink = std::function<void(const EstimateRow&)>;
/// Called with 10, 20, ..., 100 (percent of the recording's rows done).
using EstimateProgress = std::function<void(int percent)>;
/// The CLI reports progress only for recordings of more rows than this.
inline constexpr std::size_t kProgressRows = 100000;

struct EstimateCallbacks {
  EstimateSink row;           ///< may be empty (statistics only)
  EstimateProgress progress;  ///< may be empty
  /// Checked every 1024 rows; when it reads true the run stops and returns with
  /// EstimateStats::cancelled set. May be set from another thread. May be null.
  const std::atomic<bool>* cancel = nullptr;
};

/// The offline estimation loop fed one sample at a time, so a recording never has to be in
/// memory whole (a file read row by row, a session's chunks decoded as they come). Each sample
/// that carries IMU data and gets an estimate yields one output row and, when it carries true
/// angles, one error sample. Memory does not grow with the recording: the statistics are summed
/// as the rows go, and only the error samples of the last 10 s are held (the last drift window
/// is known only at the end). Deterministic: the same samples and params give bit-identical rows
/// and statistics, whether pushed one by one or given as a Recording to estimateRecording.
/// Not thread-safe: one thread feeds it; separate instances may run on separate threads.
class StreamingEstimator {
 public:
  explicit StreamingEstimator(const EstimatorParams& params);
  ~StreamingEstimator();
  StreamingEstimator(const StreamingEstimator&) = delete;
  StreamingEstimator& operator=(const StreamingEstimator&) = delete;

  /// Feeds the next sample (in recording order). True when it yields an output row, which is
  /// then written to row.
  bool push(const ArmSample& sample, EstimateRow& row);
  /// The statistics of the samples pushed so far (the drift windows end at the last IMU sample
  /// pushed). May be called at any time, more than once.
  EstimateStats stats() const;
  /// Samples pushed.
  std::size_t rows() const { return m_st.rows; }

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
  EstimateStats m_st;  // the running counts; stats() completes them
};

/// Runs a whole recording through a StreamingEstimator. Any thread (one call per thread).
EstimateStats estimateRecording(const Recording& recording, const EstimatorParams& params,
                                const EstimateCallbacks& callbacks = {});

}  // namespace armtrack
