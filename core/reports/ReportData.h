// The plain values a PDF report is drawn from (docs/reports.md). The caller fills them from the
// clinical records (core/storage) and the metrics (core/metrics); the report code never opens
// the database. Angles are SI (rad) as core/metrics gives them; the report converts to degrees.
#pragma once

#include <QDateTime>
#include <QString>
#include <array>
#include <optional>
#include <vector>

#include "core/metrics/ClinicalMetrics.h"
#include "core/metrics/PatientNorms.h"
#include "core/metrics/RangeOfMotion.h"
#include "core/metrics/SessionTime.h"
#include "core/metrics/TrunkCompensation.h"
#include "core/storage/Records.h"

namespace armtrack::reports {

/// Range of motion of the five clinical angles at one point in time (one session), in the order
/// of clinicalAngleInfo(). An empty value is drawn as "-" (angle not measured).
struct RomSnapshot {
  QString date;                     ///< YYYY-MM-DD or ISO 8601; shown as its date part
  std::optional<qint64> sessionId;  ///< the session it comes from, when known
  std::array<std::optional<double>, kNumClinicalAngles> romRad{};  ///< rad, max - min
};

/// Everything a session report shows. Only `patient`, `session`, `angles` and `metrics` are
/// needed; the rest may stay empty and its section says so.
struct SessionReportData {
  storage::Patient patient;
  storage::SessionInfo session;  ///< startedAt, durationS, devicesJson, calibrationJson, notes
  std::optional<storage::Protocol> protocol;  ///< set when the session followed a protocol
  QString therapistName;                      ///< "" = not recorded
  /// The arm measured ("left"/"right"); "" = the calibration JSON's "side", else the patient's
  /// affected side.
  QString side;
  AngleSeries angles;  ///< the session's clinical angles (rad) over time (s, session clock)
  /// The time of the recording's first row (s, session clock): the report's times are recording
  /// time from it (core/metrics/SessionTime.h), as the review shows them. Empty = the first
  /// angle's time.
  std::optional<double> recordingStartS;
  /// The events marked during the session (recording time), read from its notes.
  std::vector<EventMark> events;
  SessionMetrics metrics;  ///< computeSessionMetrics(angles, ...)
  /// The trunk's compensation (docs/metrics.md, "Trunk compensation"), one entry per repetition
  /// of metrics; empty for an analysis made before the trunk was measured (no section then).
  std::optional<TrunkCompensation> trunk;
  /// The trunk flexion limit (deg) the repetitions were judged against; empty = none.
  std::optional<double> trunkFlexionLimitDeg;
  /// Earlier sessions of the same patient, oldest first (the current one is added by the report).
  std::vector<RomSnapshot> earlierSessions;
  /// The other side's latest range of motion, when it was measured.
  std::optional<RomSnapshot> otherSide;
  /// Time printed in the footer; invalid = now (UTC).
  QDateTime generatedAt;
  /// The age- and sex-specific reference values the normative comparison picks from with the
  /// patient's birth date and sex on the session's (UTC) date (patientNorms()); the limits they
  /// do not give are AAOS.
  std::span<const SoucieValue> soucieValues = soucieReferenceValues();
};

/// Where the session report's times begin on the session clock (s): the recording's first row
/// (recordingStartS), else the first angle's time; the report prints recording time,
/// recordingTime(t, timeOrigin(d)), as the review does.
double timeOrigin(const SessionReportData& d);

/// One session of a progress report.
struct ProgressSession {
  qint64 id = 0;
  QString startedAt;               ///< ISO 8601 UTC (storage::SessionInfo::startedAt)
  QString protocolName;            ///< "" without a protocol
  double durationS = 0;            ///< s
  std::optional<int> repetitions;  ///< full + partial repetitions, when computed
  std::array<std::optional<double>, kNumClinicalAngles> romRad{};  ///< rad, max - min
  /// rad, the largest angle reached: the peak in the direction the angle is named after
  /// (flexion, abduction, internal rotation, elbow flexion, pronation), which the normal range of
  /// the named motion (namedMotionNormalRad) measures.
  std::array<std::optional<double>, kNumClinicalAngles> maxRad{};
  /// rad, the smallest angle reached: minus the peak in the opposite direction (shoulder
  /// extension, external rotation, supination).
  std::array<std::optional<double>, kNumClinicalAngles> minRad{};
  /// deg, the session's largest trunk flexion (its metrics' "trunk"); empty when not measured.
  std::optional<double> trunkFlexionDeg;
};

/// A patient's range of motion over a date range.
struct ProgressReportData {
  storage::Patient patient;
  QString fromDate, toDate;               ///< YYYY-MM-DD, as asked for (inclusive)
  QString therapistName;                  ///< "" = not named
  std::vector<ProgressSession> sessions;  ///< any order; the report sorts them by startedAt
  QDateTime generatedAt;                  ///< invalid = now (UTC)
};

/// The period a progress report covers, as its header prints it: the dates asked for, or where
/// one is empty or not a date the first or last session's date ("12.11.2026 to 26.11.2026",
/// "no sessions" when nothing is known).
QString progressPeriod(const ProgressReportData& d);

/// The five ranges of motion of computed metrics, for earlierSessions or otherSide.
RomSnapshot romSnapshot(const QString& date, std::optional<qint64> sessionId,
                        const SessionMetrics& metrics);

/// A progress-report row from a stored session and its metrics (repetitions: full + partial).
ProgressSession progressSession(const storage::SessionInfo& session, const SessionMetrics& metrics);

}  // namespace armtrack::reports
