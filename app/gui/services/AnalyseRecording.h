// A session's analysis as the GUI starts it after a recording and at the next start: a recording
// too short to analyse (Stop pressed a moment after Record) is not an error with the filter's
// figures but a plain outcome, stored as the analysis's note. Runs on the records' job thread.
#pragma once

#include <QString>

#include "core/storage/ClinicalStore.h"
#include "core/storage/SessionAnalysis.h"

namespace armtrack::gui {

/// Recordings shorter than this (s) are not analysed: the filter needs its start-up second and
/// the metrics at least a second more.
inline constexpr double kShortestAnalysableS = 2.0;

struct RecordingAnalysis {
  enum class Outcome { Analysed, Cancelled, TooShort };
  Outcome outcome = Outcome::Analysed;
  double recordedS = 0;  ///< the session's recorded duration (s)
};

/// The note stored with a session too short to analyse (English, as the records' notes are).
QString tooShortNote(double recordedS);

/// Analyses sessionId. A calibration in options (the one the live session used) is first stored
/// with the session (storage::keepSessionCalibration), so that later analyses use it too. One
/// too short to analyse (under kShortestAnalysableS, or refused by the
/// analysis for want of rows and under a few seconds) has its analysis marked failed with
/// tooShortNote() and answers TooShort. Other errors are thrown (StorageError).
RecordingAnalysis analyseRecording(storage::ClinicalStore& store, qint64 sessionId,
                                   const storage::AnalysisOptions& options);

}  // namespace armtrack::gui
