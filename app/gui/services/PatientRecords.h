// A patient as the screens show them: the record, the measured segment lengths, the home
// programme, the sessions and the range of motion per session. Plain values, loaded in one go on
// the records thread.
#pragma once

#include <QJsonObject>
#include <QString>
#include <array>
#include <optional>
#include <vector>

#include "core/metrics/RangeOfMotion.h"
#include "core/storage/ClinicalStore.h"

namespace armtrack::gui {

/// The measured lengths kept in Patient::segmentLengthsJson (m). Keys this version does not
/// know are kept as they were.
struct SegmentLengths {
  std::optional<double> upperArmM;      ///< "upper_arm_m": shoulder to elbow
  std::optional<double> forearmM;       ///< "forearm_m": elbow to wrist
  std::optional<double> upperStrapM;    ///< "upper_arm_strap_m": shoulder to the upper-arm IMU
  std::optional<double> forearmStrapM;  ///< "forearm_strap_m": elbow to the forearm IMU
  QJsonObject others;                   ///< anything else in the JSON

  /// Reads the JSON; a value that is not a positive finite number is left out (counted in
  /// *ignored when given).
  static SegmentLengths fromJson(const QString& json, int* ignored = nullptr);
  QString toJson() const;
};

/// An analysed session's smallest and largest smoothed clinical angles (rad, signs of
/// ClinicalAngles), from its newest metrics: what the progress chart plots.
struct SessionExtremes {
  qint64 id = 0;
  QString startedAt;  ///< ISO 8601 UTC (storage::SessionInfo::startedAt)
  /// Per angle (clinicalAngleInfo() order); empty where not measured.
  std::array<std::optional<double>, kNumClinicalAngles> minRad{}, maxRad{};
  /// The largest trunk flexion of the session (deg, the metrics' "trunk"); empty when the
  /// session had no trunk sensor (docs/metrics.md, "Trunk compensation").
  std::optional<double> trunkFlexionDeg;
};

/// What the patient page shows.
struct PatientOverview {
  storage::Patient patient;
  std::vector<storage::ProgrammeItem> programme;
  std::vector<storage::Protocol> protocols;    ///< every protocol (for the programme's details)
  std::vector<storage::SessionInfo> sessions;  ///< newest first
  /// The angles' extremes per analysed session, oldest first.
  std::vector<SessionExtremes> progress;
};

/// Loads it (records thread). Throws StorageError (NotFound for an unknown code).
PatientOverview loadPatientOverview(storage::ClinicalStore& store, const QString& code);

/// What a patient record lacks or holds wrongly, in words (empty: fine); *field names the field
/// ("code", "name", "birthDate", "upperArm", ...). today is the date to check birth dates against.
QString patientProblem(const storage::Patient& patient, const QDate& today, QString* field);

}  // namespace armtrack::gui
