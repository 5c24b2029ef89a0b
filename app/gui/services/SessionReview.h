// A stored session as the review screen shows it: its record, the patient, the protocol, the
// arm (sidecar), the newest analysis (estimates and metrics) and the patient's other sessions
// to compare with. Loaded in one go on the records thread.
#pragma once

#include <QJsonObject>
#include <optional>
#include <vector>

#include "core/metrics/SessionTime.h"
#include "core/storage/SessionAnalysis.h"

namespace armtrack::gui {

struct ReviewData {
  storage::SessionInfo info;
  storage::Patient patient;
  std::optional<storage::Protocol> protocol;
  RecordingMeta meta;                               ///< geometry, side, up, camera
  std::optional<storage::StoredAnalysis> analysis;  ///< the newest; none: never analysed
  std::optional<QJsonObject> metrics;  ///< the newest metrics with "angles" (latestMetricsJson)
  int versions = 0;                    ///< estimate versions stored
  std::vector<storage::SessionInfo> others;  ///< the patient's other sessions, newest first
  /// The first recorded row's time (s, session clock): recording time counts from it
  /// (core/metrics/SessionTime.h); empty when no row was stored.
  std::optional<double> recordingStartS;

  /// Where recording time begins: recordingStartS, else the first estimate's time, else 0.
  double timeOrigin() const;
  /// The events marked during the session (its notes), in recording time.
  std::vector<EventMark> events() const;
};

/// Throws StorageError (NotFound, Corrupt).
ReviewData loadReview(storage::ClinicalStore& store, qint64 sessionId);

/// One repetition of the metrics JSON, for the table.
struct RepetitionRow {
  double startS = 0, peakS = 0, endS = 0;
  double excursionDeg = 0;
  bool partial = false;
  std::optional<double> romDeg;            ///< of the primary angle
  std::optional<double> peakVelocityDegS;  ///< of the primary angle
  std::optional<double> sparc, ldlj;
  /// The repetition's largest trunk flexion, lateral bending and axial rotation (deg) and
  /// shoulder displacement (cm); empty when not measured (docs/storage.md, "Metrics").
  std::optional<double> trunkFlexionDeg, trunkLateralDeg, trunkRotationDeg, shoulderCm;
  /// Made with trunk compensation (flexion over the session's limit); empty without a limit.
  std::optional<bool> compensated;
};

/// The repetitions of a metrics JSON (docs/storage.md, "Metrics"), their times in recording
/// time (the session clock's times less origin, ReviewData::timeOrigin()); a malformed entry is
/// left out and counted in *skipped.
std::vector<RepetitionRow> repetitionRows(const QJsonObject& metrics, int* skipped = nullptr,
                                          double origin = 0);

/// The index of the row at or before t in times (ascending); 0 for t before the first.
std::size_t rowAt(const std::vector<double>& times, double t);

}  // namespace armtrack::gui
