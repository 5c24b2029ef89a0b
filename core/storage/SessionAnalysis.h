// A stored session's analysis: its recording estimated, its estimates kept as a compressed blob
// and its clinical metrics as JSON, each run a new version beside the earlier ones
// (docs/storage.md, "Estimates" and "Metrics").
#pragma once

#include <QJsonObject>
#include <QString>
#include <atomic>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "core/calibration/Calibration.h"
#include "core/estimation/RecordingEstimator.h"
#include "core/metrics/ClinicalMetrics.h"
#include "core/metrics/TrunkCompensation.h"
#include "core/storage/ClinicalStore.h"

namespace armtrack::storage {

/// The "format" field of the metrics JSON this version writes.
inline constexpr const char* kMetricsFormat = "armtrack-metrics-v1";
/// The clinical metrics use at most one estimate per 1/kMetricsRateHz of time (Hz): the first of
/// each such cell of the settled rows. Arm movements lie below 10 Hz and the metrics smooth over
/// 0.3 s, so a faster sensor adds memory and time but no information (docs/storage.md).
inline constexpr double kMetricsRateHz = 100.0;
/// The codec of the rows the metrics were computed from, stored with them (metrics.series): an
/// EstimateCodec blob of their times and joint angles.
inline constexpr const char* kMetricRowsCodec = "metric-rows-f64-zstd-v1";

struct AnalysisOptions {
  /// Overrides the session's stored filter (else the session's, else EKF).
  std::optional<FilterKind> filter;
  /// Overrides the session's stored IMU measurement model (Method A, B or C, docs/estimator.md).
  std::optional<MeasurementModel> model;
  /// true = fuse no optical data (Kinect positions and marker pixels), whatever the session says.
  bool noOptical = false;
  /// A sensor-to-segment calibration (core/calibration, `armtrack-cli calibrate`) applied to the
  /// recording and the filter before estimating; its side must be the recording's (Usage error
  /// otherwise). Empty: the one stored with the session's filter settings ("calibration", kept
  /// by keepSessionCalibration()), if any. The parameters JSON records "calibration": true.
  std::optional<Calibration> calibration;
  /// Called on the calling thread with 0-100 (percent done, rising; 100 once stored).
  std::function<void(int percent)> progress;
  /// Checked while estimating; when it reads true the analysis stops and stores nothing
  /// (AnalysisResult::cancelled). May be set from another thread. May be null.
  const std::atomic<bool>* cancel = nullptr;
  /// Where the samples come from. Empty: the stored recording, read chunk by chunk. Otherwise a
  /// function that hands its argument the session's samples in time order, a block at a time,
  /// until the argument returns false, and returns whether it handed them all (as
  /// ClinicalStore::readRecordingChunks does): an import analyses the rows as it stores them
  /// (app/cli). It throws to abandon the analysis.
  std::function<bool(const std::function<bool(std::span<const ArmSample>)>&)> samples;
  /// The rows samples will hand over, for progress (0: the session's stored row count).
  std::size_t expectedRows = 0;
  /// A repetition whose largest trunk flexion exceeds this (deg) was made with compensation
  /// (core/metrics/TrunkCompensation.h): each repetition's "compensated" and the count
  /// "repetitions_with_compensation" in the metrics JSON. Empty (the default): for a home
  /// session the limit its exercise held the patient to (the home summary's "trunk_limit_deg",
  /// else the patient's programme exercise of the session's protocol: effectiveTrunkLimit),
  /// otherwise the session's protocol's limit (Protocol::trunkLimitDeg); without one no limit,
  /// both null. Not positive and finite: StorageError(Usage).
  std::optional<double> trunkFlexionLimitDeg;
};

struct AnalysisResult {
  bool cancelled = false;   ///< stopped by the cancel flag: nothing was stored
  int estimateVersion = 0;  ///< the version stored (0 when cancelled)
  int metricsVersion = 0;
  EstimateOptions settings;  ///< the filter settings used
  QString settingsSource;    ///< "session" (its stored filter settings) or "defaults"
  /// The calibration applied: the caller's, else the session's stored one; empty: none.
  std::optional<Calibration> calibration;
  EstimateStats stats;     ///< the estimator's run
  SessionMetrics metrics;  ///< SI units
  /// The trunk's compensation over the session and per repetition (one per repetition of
  /// metrics); its values are empty without a trunk IMU or an optical shoulder.
  TrunkCompensation trunk;
  QJsonObject metricsJson;  ///< as latestAnalysis() returns it
};

/// Filter settings as a session's filter_json holds them (docs/storage.md, "Filter settings"):
/// filter, method, optical, camera and, when set, joint_accel_std_deg.
QJsonObject filterSettingsJson(const EstimateOptions& settings);
/// The same put into a session's stored filter settings, keeping what else they hold (the
/// calibration the session was recorded with, the sensor calibration's verdict).
QJsonObject filterSettingsJson(const EstimateOptions& settings, const QString& storedJson);

/// Stores the calibration the session was recorded with (a calibration file the therapist chose,
/// or the straps the live session fitted from the movement) in its filter settings, as
/// "calibration" (docs/storage.md, "Filter settings"), so that every later analysis of it
/// (review, `session reestimate`, exports) estimates with it as the live session did. Audited as
/// a change of the session's filter settings; staff only (ClinicalStore::
/// updateSessionFilterSettings). Throws StorageError: Usage for a calibration no real arm has.
void keepSessionCalibration(ClinicalStore& store, qint64 sessionId, const Calibration& calibration);

/// Reads the session's recording, estimates it (the session's filter settings when it has any,
/// else the defaults; the geometry from its sidecar), stores the estimates (codec
/// EstimateCodec::kName) and the clinical metrics as a new version, and audits it. Repetitions
/// are counted on the protocol's primary angle, with its target range judging partial ones,
/// or, without a protocol, on the angle with the largest range of motion.
/// Throws StorageError: NotFound (no such session, or another patient's for a home account),
/// AccessDenied (home accounts do not analyse), Usage (no IMU rows to estimate from, an unknown
/// filter setting), Corrupt (as readRecording). Same thread as the store: Qt Sql connections
/// belong to the thread that opened them, so a GUI that analyses off its thread opens its own
/// Database and ClinicalStore (signed in as the same user) in that worker thread.
AnalysisResult analyseSession(ClinicalStore& store, qint64 sessionId,
                              const AnalysisOptions& options = {});

/// One stored version of a session's analysis, decoded.
struct StoredAnalysis {
  qint64 sessionId = 0;
  int version = 0;                  ///< the estimates' version
  QString createdAt;                ///< ISO 8601 UTC
  QString paramsJson;               ///< how the estimates were made (docs/storage.md)
  std::vector<double> t;            ///< s, one per output row
  std::vector<JointVector> joints;  ///< DH joint angles (rad)
  std::vector<JointVector> sd;      ///< their standard deviations (rad)
  std::vector<int> status;          ///< kStatus* (core/estimation/RecordingEstimator.h)
  /// The trunk's flexion, lateral bending and axial rotation and their standard deviations (rad,
  /// core/kinematics/Trunk.h), one per row, NaN where not measured; both empty when the
  /// estimates hold no trunk columns (a recording without a trunk IMU or optical shoulder, or
  /// estimated before schema version 9).
  std::vector<Eigen::Vector3d> trunk, trunkSd;
  AngleSeries clinical;  ///< the five clinical angles (rad) at t
  /// The metrics JSON computed from these estimates (docs/storage.md, "Metrics"); empty when the
  /// newest stored metrics belong to another version.
  std::optional<QJsonObject> metrics;
};

/// The newest analysis of the session, or nothing when it was never analysed. Throws
/// StorageError(Corrupt) naming the session and version when the blob or its parameters cannot
/// be decoded; NotFound as ClinicalStore::session.
std::optional<StoredAnalysis> latestAnalysis(ClinicalStore& store, qint64 sessionId);
/// The same for a given version (1, 2, ...; 0 = the newest): nothing when there is no such
/// version.
std::optional<StoredAnalysis> storedAnalysis(ClinicalStore& store, qint64 sessionId, int version);

/// Only the newest metrics JSON (docs/storage.md, "Metrics"), without decoding any estimates:
/// what `session show` prints. Nothing when the session was never analysed. Throws
/// StorageError(Corrupt) when the stored JSON is not an object; NotFound as
/// ClinicalStore::session.
std::optional<QJsonObject> latestMetricsJson(ClinicalStore& store, qint64 sessionId);

/// A session's newest analysis as the reports and exports use it: the clinical angles and their
/// standard deviations over the rows the metrics use (the filter's settling second after each
/// start or recovery left out), and the metrics computed from them as analyseSession did.
struct SessionAngles {
  SessionInfo info;
  Side side = Side::Right;         ///< the arm recorded (the session's sidecar)
  int version = 0;                 ///< the estimates' version
  AngleSeries series;              ///< clinical angles (rad)
  std::vector<ClinicalRow> sdRad;  ///< their standard deviations (rad), one per row of series
  /// The trunk's angles and their standard deviations (rad), one per row of series, when the
  /// estimates hold them (StoredAnalysis::trunk); empty otherwise. sessionAngles only.
  std::vector<Eigen::Vector3d> trunkRad, trunkSdRad;
  SessionMetrics metrics;
};
/// The newest analysis as stored, for a report: the rows its metrics were computed from (clinical
/// angles; no standard deviations) and the metrics read back from their JSON, without decoding
/// the estimates or computing anything again. Nothing when the newest metrics have no stored
/// rows (analyses made before schema version 6: use sessionAngles) or belong to an older version
/// of the estimates. Throws StorageError(Corrupt) when what is stored cannot be read.
std::optional<SessionAngles> storedSessionAngles(ClinicalStore& store, qint64 sessionId);
/// The metrics of a stored metrics JSON (latestMetricsJson's form) as SessionMetrics: what the
/// reports draw. Fields the JSON does not hold (sample indices, hysteresis levels) stay zero.
SessionMetrics sessionMetricsFromJson(const QJsonObject& metrics);
/// The trunk compensation of a stored metrics JSON (its "trunk", each repetition's "trunk" and
/// "repetitions_with_compensation"; docs/storage.md, "Metrics"), with one entry in repetitions
/// per repetition of the JSON. Nothing when the JSON has no "trunk" object (analysed before the
/// trunk was measured). Values that are not numbers read as empty; the row counts stay zero.
std::optional<TrunkCompensation> trunkCompensationFromJson(const QJsonObject& metrics);
/// Whether any of the four values was measured.
bool measured(const TrunkExtremes& x);

/// Which rows sessionAngles puts in its series: those the metrics use (at most kMetricsRateHz a
/// second; reports) or every settled row (exports). The metrics are the same either way.
enum class SeriesRows { Metrics, All };
/// Reads the estimates a chunk at a time. Throws StorageError: NotFound (no such session, or
/// never analysed: the message says to run `session reestimate`), Corrupt and Usage as
/// latestAnalysis and analyseSession.
SessionAngles sessionAngles(ClinicalStore& store, qint64 sessionId,
                            SeriesRows rows = SeriesRows::Metrics);

}  // namespace armtrack::storage
