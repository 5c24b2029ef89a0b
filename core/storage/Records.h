// The rows of the clinical records as plain values (docs/storage.md, "Schema").
#pragma once

#include <QByteArray>
#include <QString>
#include <cstdint>
#include <optional>
#include <utility>

namespace armtrack::storage {

enum class Role { Admin, Therapist, Home };
QString roleName(Role role);  ///< "admin", "therapist", "home"
std::optional<Role> parseRole(const QString& name);

struct User {
  qint64 id = 0;
  QString name;
  Role role = Role::Therapist;
  std::optional<qint64> patientId;  ///< home accounts only: the one patient they may see
  int failedAttempts = 0;           ///< consecutive wrong passwords
  bool disabled = false;            ///< may not sign in (ClinicalStore::setUserDisabled)
};

/// A one-time code that enrols a home device (ClinicalStore::createEnrolmentCode).
struct EnrolmentCode {
  QString code;       ///< "7KQ2-M9XD-4TRA": shown once, never stored
  QString expiresAt;  ///< ISO 8601 UTC
};

/// What a device gets when it enrols (ClinicalStore::enrolDevice).
struct DeviceEnrolment {
  qint64 deviceId = 0;
  QString token;  ///< shown once, never stored
  QString patientCode;
};

/// A home device as the clinic sees it (ClinicalStore::listDevices).
struct DeviceInfo {
  qint64 id = 0;
  QString label;
  QString createdAt, lastSeenAt, revokedAt;  ///< empty: never / not revoked
};

struct Patient {
  qint64 id = 0;
  QString code;  ///< unique, what the clinic calls the patient in files and logs
  QString name;
  QString birthDate;     ///< YYYY-MM-DD
  QString sex;           ///< "f", "m" or "x"
  QString affectedSide;  ///< "left", "right", "both" or "none"
  QString diagnosis;
  QString segmentLengthsJson = "{}";  ///< measured lengths, e.g. {"upper_arm_m": 0.30}
  QString notes;
};

struct Protocol {
  qint64 id = 0;
  QString name;             ///< unique
  QString angleKey;         ///< the primary clinical angle, e.g. "shoulder_flexion"
  double targetMinDeg = 0;  ///< deg
  double targetMaxDeg = 0;  ///< deg
  int repetitions = 0;
  QString side = "either";  ///< "left", "right" or "either"
  /// The trunk limit (deg of trunk flexion, forward or back, 1-90): past it the live screen and
  /// the home window cue "Keep your back against the chair" and count the repetitions made with
  /// compensation (core/metrics/TrunkLimitCue.h). Empty: off (the default).
  std::optional<double> trunkLimitDeg;
};

/// One exercise of a patient's home programme: a protocol (the movement and its angle), how
/// often, in what order, and how much (docs/storage.md, "Home programmes").
struct ProgrammeItem {
  QString protocolName;
  int sessionsPerWeek = 0;
  QString notes;
  int position = 0;  ///< order in the programme, from 1; 0 when adding: after the last
  int sets = 1;      ///< 1-20
  std::optional<int> repetitions;      ///< per set, 1-200; empty: the protocol's
  std::optional<double> targetMinDeg;  ///< deg; both or neither; empty: the protocol's range
  std::optional<double> targetMaxDeg;  ///< deg
  double restS = 60;                   ///< s of rest between sets, 0-3600
  std::optional<double>
      trunkLimitDeg;  ///< deg, 1-90 (Protocol::trunkLimitDeg); empty: the protocol's
};

/// The repetitions per set an exercise asks for: its own, else its protocol's.
inline int effectiveRepetitions(const ProgrammeItem& item, const Protocol& protocol) {
  return item.repetitions.value_or(protocol.repetitions);
}
/// The target range (deg) of an exercise's angle: its own, else its protocol's.
inline std::pair<double, double> effectiveTarget(const ProgrammeItem& item,
                                                 const Protocol& protocol) {
  if (item.targetMinDeg && item.targetMaxDeg) return {*item.targetMinDeg, *item.targetMaxDeg};
  return {protocol.targetMinDeg, protocol.targetMaxDeg};
}

/// The trunk limit (deg) of an exercise: its own, else its protocol's; empty: off.
inline std::optional<double> effectiveTrunkLimit(const ProgrammeItem& item,
                                                 const Protocol& protocol) {
  return item.trunkLimitDeg ? item.trunkLimitDeg : protocol.trunkLimitDeg;
}

/// The trunk limits a protocol or an exercise may set (deg).
inline constexpr double kMinTrunkLimitDeg = 1.0;
inline constexpr double kMaxTrunkLimitDeg = 90.0;

/// Where a session was recorded: "clinic" (by a therapist) or "home" (by a home account).
inline constexpr const char* kSettingClinic = "clinic";
inline constexpr const char* kSettingHome = "home";

/// Status of a session's recording.
inline constexpr const char* kStatusRecording = "recording";
inline constexpr const char* kStatusComplete = "complete";
inline constexpr const char* kStatusInterrupted = "interrupted";

/// Where a session's rows came from: a live recording, or an imported file (an import that does
/// not finish is removed whole; a live recording that does not finish stays, interrupted).
inline constexpr const char* kOriginLive = "live";
inline constexpr const char* kOriginImport = "import";

/// Whether a session's analysis (estimates and metrics) is done: "pending" until it is (a
/// complete session's pending analysis is run by the next command or start of the app),
/// "failed" when the recording cannot be analysed (analysisNote says why), "none" for an
/// interrupted recording, which is analysed only when asked.
inline constexpr const char* kAnalysisPending = "pending";
inline constexpr const char* kAnalysisDone = "done";
inline constexpr const char* kAnalysisFailed = "failed";
inline constexpr const char* kAnalysisNone = "none";

/// How a session was made, stored beside it (docs/storage.md, "Sessions"); each a JSON object.
struct SessionSettings {
  QString devicesJson = "{}";    ///< the devices: plugin, options and streams, by device label
  QString filterJson = "{}";     ///< the filter settings its analysis uses (SessionAnalysis.h)
  QString origin = kOriginLive;  ///< kOriginImport for a file being imported
};

struct SessionInfo {
  qint64 id = 0;
  qint64 patientId = 0;
  QString patientCode;
  std::optional<qint64> therapistId;
  QString protocolName;  ///< "" without a protocol
  QString startedAt;     ///< ISO 8601 UTC
  double durationS = 0;  ///< s, from the first to the last stored sample
  QString devicesJson = "{}";
  QString calibrationJson = "{}";  ///< the recording's sidecar (arm geometry, gravity, camera)
  QString filterJson = "{}";
  QString notes;
  QString status;         ///< kStatusRecording, kStatusComplete or kStatusInterrupted
  int columnsMask = 0;    ///< the recording format's column groups (bit order of ChunkCodec)
  qint64 sampleRows = 0;  ///< rows stored
  qint64 imuSamples = 0;  ///< rows that carry an IMU reading
  qint64 chunks = 0;
  qint64 storedBytes = 0;               ///< compressed chunk bytes
  QString setting = kSettingClinic;     ///< kSettingClinic or kSettingHome
  std::optional<int> painScore;         ///< 0-10, the patient's own, home sessions
  QString patientComment;               ///< the patient's own words, home sessions
  QString homeSummaryJson = "{}";       ///< what the home window counted (docs/storage.md)
  QString origin = kOriginLive;         ///< kOriginLive or kOriginImport
  QString analysis = kAnalysisPending;  ///< kAnalysisPending, kAnalysisDone, ...
  QString analysisNote;                 ///< why an analysis failed
};

/// One stored version of a session's estimates (docs/storage.md, "Estimates").
struct EstimateRecord {
  qint64 id = 0;       ///< the row's key (its chunks refer to it)
  int version = 0;     ///< 1, 2, ... per session
  QString createdAt;   ///< ISO 8601 UTC
  QString paramsJson;  ///< how they were made (filter, method, optical, library version, rows)
  QString codec;       ///< e.g. "est-f64-zstd-v1", or its chunked form (EstimateCodec.h)
  QByteArray data;     ///< the blob; empty when the estimates are in chunks
};

struct AuditEntry {
  qint64 id = 0;
  QString at;  ///< ISO 8601 UTC
  QString userName;
  QString action;      ///< e.g. "export", "create", "update", "delete", "view", "sign-in-failed"
  QString objectType;  ///< "patient", "session", "user", "protocol", "database"
  QString objectId;    ///< the code, id or name
  QString detail;      ///< never patient data beyond identifiers
};

}  // namespace armtrack::storage
