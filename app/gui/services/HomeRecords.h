// What the home window reads from and writes to the records: today's programme with each
// exercise's values in effect, the earlier home sessions of each exercise, and the outcome of a
// home session (its summary, the patient's pain score and comment). Plain values; the functions
// run on the records thread (RecordsService). Qt Core, no widgets.
#pragma once

#include <QJsonObject>
#include <QString>
#include <optional>
#include <vector>

#include "core/storage/ClinicalStore.h"

namespace armtrack::gui {

/// One exercise of the programme with the values in effect (its own, else its protocol's).
struct HomeExercise {
  storage::ProgrammeItem item;
  storage::Protocol protocol;
  int angle = 0;        ///< clinical angle index of the protocol's angle key
  int repetitions = 1;  ///< per set
  double targetMinDeg = 0, targetMaxDeg = 0;
  std::optional<double> trunkLimitDeg;  ///< effectiveTrunkLimit(); empty: off
};

/// What one exercise of a home session came to (the home window's count, not an analysis).
struct HomeExerciseResult {
  QString exercise;  ///< the protocol's name
  int angle = 0;
  int position = 0;
  qint64 sessionId = 0;  ///< 0 when nothing was recorded
  int setsPlanned = 0, setsDone = 0;
  int repetitionsPlanned = 0;  ///< all sets
  int repetitions = 0, partial = 0;
  double targetMinDeg = 0, targetMaxDeg = 0;
  std::optional<double> rangeMinDeg, rangeMaxDeg;  ///< empty when not measured
  int targetReached = 0, tooFast = 0, rangeNotReached = 0, compensation = 0;
  /// The trunk limit in effect (deg; empty: off) and the repetitions made leaning past it.
  std::optional<double> trunkLimitDeg;
  int trunkCompensation = 0;
  bool measured = true;       ///< false: the angle could not be trusted (no camera)
  bool stoppedEarly = false;  ///< skipped or stopped before its sets were done

  /// The summary stored with the session (docs/storage.md, "Home programmes").
  QJsonObject toJson() const;
  /// Reads a stored summary; nothing when it is not one (an empty or foreign object).
  static std::optional<HomeExerciseResult> fromJson(const QJsonObject& o);
};

/// An earlier home session of one exercise, for the summary's comparison.
struct HomeHistoryEntry {
  QString startedAt;  ///< ISO 8601 UTC
  HomeExerciseResult result;
};

struct HomePlan {
  storage::Patient patient;
  std::vector<HomeExercise> exercises;  ///< in the programme's order
  /// Per exercise (same order), its earlier home sessions that carry a summary, newest last, at
  /// most kHistory of them.
  std::vector<std::vector<HomeHistoryEntry>> history;
  static constexpr int kHistory = 3;
};

/// Loads the plan of the signed-in home account's patient (or of patientCode for staff). Throws
/// StorageError. An exercise whose protocol names an unknown angle is left out.
HomePlan loadHomePlan(storage::ClinicalStore& store, const QString& patientCode);

/// Stores each recorded exercise's summary with the patient's pain score and comment (the same
/// on every session of the visit). Throws StorageError.
void saveHomeOutcomes(storage::ClinicalStore& store, const std::vector<HomeExerciseResult>& results,
                      std::optional<int> painScore, const QString& comment);

}  // namespace armtrack::gui
