// The live session pipeline: device threads -> time synchroniser -> estimator worker -> recorder,
// and a results buffer the GUI drains on a timer. Qt Core only (no widgets). Devices come in as
// core SampleSources (core/devices/SampleSource.h); devices/api/DeviceThread adapts a plugin's
// Device to one. See docs/session.md and docs/architecture.md.
#pragma once

#include <QObject>
#include <QString>
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/calibration/Calibration.h"
#include "core/devices/SampleSource.h"
#include "core/estimation/ArmFilter.h"
#include "core/io/Recording.h"
#include "core/session/LiveCalibration.h"

namespace armtrack::session {

struct SessionParams {
  /// The arm, gravity, side (and camera, if no device brings one): the sidecar of the recording
  /// and the estimator's model.
  RecordingMeta meta;
  /// Estimator settings; geometry, gravity and camera are taken from meta at start().
  EstimatorParams estimator;
  bool estimate = true;                 ///< run the estimator (off: record raw data only)
  std::filesystem::path recordingPath;  ///< CSV to record into; empty = no recording
  /// Replace a recording (CSV or sidecar) that already exists at recordingPath. Off (default):
  /// start() refuses, and claims the name atomically so a file appearing meanwhile is not lost.
  bool overwrite = false;
  /// Where to record instead of recordingPath, e.g. the clinical records: called by start() (on
  /// its thread) with the recording's metadata and columns. The sink is then used from the
  /// recorder's thread only. A RecordingError it throws fails start() with its message.
  std::function<std::unique_ptr<RecordingSink>(const RecordingMeta&, const RecordingColumns&)>
      openSink;
  double latencyWindow = 0.010;            ///< s the synchroniser waits for late samples
  double mergeWindow = 0.5e-3;             ///< s within which samples share one row
  double workerPeriod = 0.002;             ///< s between synchroniser polls
  std::size_t inputCapacity = 1 << 17;     ///< samples queued between devices and the worker
  std::size_t recorderCapacity = 1 << 17;  ///< rows queued between worker and recorder
  std::size_t resultCapacity = 1 << 14;    ///< estimates kept for the GUI (oldest overwritten)
  double flushInterval = 0.5;              ///< s between recorder flushes
  double syncInterval = 5.0;               ///< s between fsyncs of the recording
  std::size_t maxEvents = 1000;            ///< session messages kept until taken
  /// s of session time without a refused reading after which the estimator's refusals are
  /// summed up in one message (the first refusal is told at once).
  double refusalQuietSeconds = 0.5;
  /// s between summaries while refusals go on.
  double refusalSummarySeconds = 5.0;
  /// s between messages that the trunk left its start pose with no trunk IMU to measure it (a
  /// patient leaning on every reach); departures in between are counted in the next message.
  double trunkMessageSeconds = 10.0;
  /// The straps fitted from the patient's movement while the session runs, for a patient with
  /// no calibration for these sensors (off by default; docs/session.md, "Calibration from
  /// movement"). Needs the estimator and both arm IMUs (off without them).
  LiveCalibrationParams movementCalibration;
  /// A sensor calibration for these sensors (the GUI's sensor calibration, a calibration file):
  /// the estimator uses its geometry and mountings, and each row's readings are turned into its
  /// sensor frames and its gyroscope biases removed before the estimator sees them, from the
  /// first row (docs/session.md, "A sensor calibration"). The recording keeps the readings as
  /// the devices gave them and meta as given. With one, the calibration from movement does not
  /// run. start() refuses one made for the other arm.
  std::optional<Calibration> calibration;
};

/// One estimate, for the GUI and `live`. Every row with IMU data gets one once the estimator has
/// started, including rows whose readings were all refused (status Predicted) and rows where it
/// re-initialised after losing the arm (status Recovered: the angles may jump there).
struct EstimateRow {
  double t = 0.0;                           ///< synchronised time (s since the session started)
  JointVector th = JointVector::Zero();     ///< rad
  std::optional<JointVector> truth;         ///< rad, simulated devices
  double latency = 0.0;                     ///< s from the oldest sample's arrival to the estimate
  JointVector thStd = JointVector::Zero();  ///< 1-sigma uncertainty of th (rad)
  /// How the estimate came about: Accepted, Initialised, Predicted or Recovered.
  UpdateResult status = UpdateResult::Accepted;
  /// No optical measurement has been fused for a while: the arm's heading about the vertical
  /// rests on the start pose alone, so the shoulder's angles drift (JointEstimator's flag).
  bool headingFromStartPoseOnly = false;
  /// The newest optical measurements that arrived since the previous estimate (rows without IMU
  /// data get no estimate of their own), for a view to draw beside the estimate: Kinect
  /// positions in the shoulder frame of the arm's side (m; in the world frame when the session
  /// has a trunk IMU or an optical shoulder, docs/trunk.md), webcam marker pixels.
  std::optional<Eigen::Vector3d> opticalElbow, opticalWrist;
  std::optional<Eigen::Vector2d> camElbow, camWrist;
  /// The trunk's flexion, lateral bending and axial rotation and their 1-sigma uncertainty
  /// (rad, patient terms, relative to the start pose; core/kinematics/Trunk.h), when a trunk IMU
  /// measures them (docs/trunk.md).
  std::optional<Eigen::Vector3d> trunk, trunkStd;
  /// The simulated trunk's true angles (rad), simulated devices.
  std::optional<Eigen::Vector3d> trueTrunk;
  /// The newest optical shoulder position (world frame, m) since the previous estimate.
  std::optional<Eigen::Vector3d> opticalShoulder;
  /// The trunk has moved from its start pose with no trunk IMU to measure it (an optical
  /// shoulder saw it, TrunkMotionDetector; `estimate`'s kStatusTrunkMoved): the shoulder angles
  /// include the lean. Never set in a session with a trunk IMU.
  bool trunkMoved = false;
};

/// Latencies in 0.1 ms bins up to 1 s.
class LatencyHistogram {
 public:
  void add(double seconds);
  /// The q-quantile (0..1) in s (upper edge of its bin); 0 when empty.
  double quantile(double q) const;
  double max() const { return m_max; }
  std::uint64_t count() const { return m_count; }

 private:
  static constexpr int kBins = 10000;
  static constexpr double kBin = 1e-4;
  std::array<std::uint64_t, kBins + 1> m_bins{};
  std::uint64_t m_count = 0;
  double m_max = 0.0;
};

struct StreamStats {
  std::string device;  ///< device label
  std::string stream;  ///< stream name
  StreamRole role = StreamRole::UpperArmImu;
  double rateHz = 0.0;              ///< measured by the device
  std::uint64_t published = 0;      ///< samples the device emitted
  std::uint64_t received = 0;       ///< samples the worker took from the device
  std::uint64_t rejected = 0;       ///< NaN/inf values, payloads not matching the role, bad times
  std::uint64_t late = 0;           ///< arrived after later samples were processed (time clamped)
  std::uint64_t deviceDropped = 0;  ///< samples the device reports lost on its link
  std::uint64_t deviceCorrupt = 0;  ///< packets the device rejected as malformed
  double driftPpm = 0.0;            ///< device clock drift the synchroniser estimated
  double jitterMs = 0.0;            ///< arrival jitter above the fastest delivery (ms)
  /// The stream's device's battery (0-100 %), where the device reports one (DeviceHealth).
  std::optional<double> batteryPercent;
};

struct SessionStats {
  double elapsed = 0.0;  ///< s since start()
  std::vector<StreamStats> streams;
  std::vector<DeviceState> deviceStates;
  std::vector<std::string> deviceLabels;
  std::uint64_t inputOverflow = 0;  ///< samples lost because the input queue was full
  std::uint64_t rows = 0;           ///< rows built from synchronised samples
  std::uint64_t estimates = 0;      ///< estimates made
  std::uint64_t rowsToRecord = 0;   ///< rows the recorder was given
  /// Rows that reached the file (RecordingWriter::rowsWritten(): written, whether or not yet
  /// forced to disk). Below rowsToRecord while rows are buffered, or after a write failure.
  std::uint64_t recordedRows = 0;
  std::uint64_t recorderWaits = 0;       ///< times the worker waited for a full recorder queue
  std::uint64_t resultsOverwritten = 0;  ///< GUI rows overwritten before being taken
  std::size_t maxInputQueued = 0;        ///< most samples ever waiting for the worker
  std::string recorderError;             ///< the newest recording failure, empty if none
  EstimatorCounters estimator;
  LatencyHistogram latency;       ///< sample arrival to estimate
  double workerCpuSeconds = 0.0;  ///< CPU time of the estimator worker thread
  /// Samples lost anywhere between the devices and the recorder (input overflow + rejected);
  /// device link losses are counted apart, per stream.
  std::uint64_t lost() const;
};

/// A running session. Construct, add devices, start(), later stop(). The devices, the worker and
/// the recorder each run in their own thread; the public functions are for the thread that owns
/// the Session, except stats(), takeResults() and takeEvents(), which any thread may call.
class Session : public QObject {
  Q_OBJECT
 public:
  explicit Session(SessionParams params, QObject* parent = nullptr);
  ~Session() override;  ///< stops

  /// Adds a device before start(); returns its index. The session owns it. A plugin's Device
  /// comes wrapped in a devices::DeviceThread, which runs it in a thread of its own.
  int addDevice(std::unique_ptr<SampleSource> device, const QString& label);

  /// Checks the set-up (one stream per role, a camera model for pixels), opens the recording and
  /// starts every thread. Returns an empty string, or what is wrong and what to do (nothing is
  /// started then).
  QString start();
  /// Stops the devices, processes every sample already received, closes the recording and joins
  /// the threads (no terminate()). Idempotent.
  void stop();
  bool running() const { return m_running; }

  /// The recording's metadata as written (after start()).
  const RecordingMeta& meta() const { return m_params.meta; }

  SessionStats stats() const;
  /// What the calibration from movement did so far (State::Off when not asked for). Any thread.
  LiveCalibrationStatus movementCalibration() const;
  /// Where the calibration from movement the session used was written at stop() (a recording
  /// file beside the CSV, movementCalibrationPath()); empty when none was used or written.
  std::filesystem::path movementCalibrationFile() const { return m_movementCalibrationFile; }

  /// Moves the estimates made since the last call into out (appended); returns how many.
  std::size_t takeResults(std::vector<EstimateRow>& out);
  /// Moves the session messages (device states, problems, recorder failures, readings the
  /// estimator refused, its recoveries and restarts) into out.
  std::size_t takeEvents(std::vector<std::string>& out);

 signals:
  /// Emitted from the device's thread.
  void deviceStateChanged(int device, armtrack::DeviceState state, const QString& reason);
  /// A problem worth showing the user. Emitted from any of the session's threads.
  void problem(const QString& message);

 private:
  class DeviceInput;  // the input port of one device (Session.cpp)
  class Worker;       // the worker thread's state and steps (SessionWorker.cpp)
  struct Stream {
    int device = 0;
    int index = 0;  ///< within the device
    StreamInfo info;
  };
  struct DeviceEntry {
    std::unique_ptr<SampleInput> input;  // declared first: outlives the device using it
    std::unique_ptr<SampleSource> device;
    QString label;
    bool started = false;
    int firstStream = 0;
  };

  /// The recording's columns from the streams (a camera needs its model); "" or why not.
  QString columnsOfStreams(RecordingColumns& columns, bool& imu);
  /// The recording's sink (openSink, or a file at recordingPath claimed unless overwrite); "" or
  /// why not.
  QString openRecording(const RecordingColumns& columns);
  void onSamples(int device, const SampleBatch& batch);
  void logEvent(const std::string& text);
  void workerLoop();
  void recorderLoop();
  void stopDevices();
  /// After stop(): writes the calibration from movement in use beside the recording file.
  void keepMovementCalibration();

  SessionParams m_params;
  std::vector<DeviceEntry> m_devices;
  std::vector<Stream> m_streams;
  RecordingColumns m_columns;  // the recording's, set by start()
  bool m_running = false;
  double m_startTime = 0.0;
  double m_scale = 1.0;  // device seconds per host second (replays faster than real time)

  // devices -> worker
  std::mutex m_inputMutex;
  std::condition_variable m_inputCv;
  std::vector<DeviceSample> m_input;  // stream index is global here
  bool m_inputClosed = false;

  // worker -> recorder
  std::mutex m_recMutex;
  std::condition_variable m_recCv, m_recSpaceCv;
  std::deque<ArmSample> m_recQueue;
  bool m_recClosed = false;
  std::unique_ptr<RecordingSink> m_writer;

  // worker -> GUI
  mutable std::mutex m_resultMutex;
  std::deque<EstimateRow> m_results;

  mutable std::mutex m_statsMutex;
  SessionStats m_stats;
  std::vector<std::string> m_events;

  // The calibration from movement (when asked for): fed and polled by the worker.
  std::unique_ptr<LiveCalibration> m_liveCalibration;
  std::filesystem::path m_movementCalibrationFile;

  std::thread m_worker, m_recorder;
};

/// The session's filter parameters for a sidecar: base with the geometry, gravity, camera, side
/// and sternum mounting of meta (what start() does with SessionParams::estimator).
EstimatorParams sessionFilterParams(const EstimatorParams& base, const RecordingMeta& meta);

}  // namespace armtrack::session
