#include "app/gui/services/AnalyseRecording.h"

namespace armtrack::gui {

namespace {
// The analysis refuses a recording without enough settled rows with a Usage error; below this
// (s) that is what it means.
constexpr double kShortRefusalS = 5.0;
}  // namespace

QString tooShortNote(double recordedS) {
  return QStringLiteral(
             "too short to analyse: %1 s recorded, at least %2 s are needed (record again, "
             "for longer)")
      .arg(recordedS, 0, 'f', 1)
      .arg(kShortestAnalysableS, 0, 'f', 0);
}

RecordingAnalysis analyseRecording(storage::ClinicalStore& store, qint64 sessionId,
                                   const storage::AnalysisOptions& options) {
  using storage::StorageError;
  RecordingAnalysis r;
  r.recordedS = store.session(sessionId).durationS;
  const auto tooShort = [&] {
    store.markAnalysisFailed(sessionId, tooShortNote(r.recordedS));
    r.outcome = RecordingAnalysis::Outcome::TooShort;
    return r;
  };
  if (r.recordedS < kShortestAnalysableS) return tooShort();
  // The calibration the live session used (a file, or the straps fitted from the movement) is
  // kept with the session first, and this analysis reads it back as every later one does (the
  // file's form rounds the rotations by an ulp): the same estimates, bit for bit.
  storage::AnalysisOptions o = options;
  if (o.calibration) {
    storage::keepSessionCalibration(store, sessionId, *o.calibration);
    o.calibration.reset();
  }
  try {
    r.outcome = storage::analyseSession(store, sessionId, o).cancelled
                    ? RecordingAnalysis::Outcome::Cancelled
                    : RecordingAnalysis::Outcome::Analysed;
  } catch (const StorageError& e) {
    if (e.kind() == StorageError::Kind::Usage && r.recordedS < kShortRefusalS) return tooShort();
    throw;
  }
  return r;
}

}  // namespace armtrack::gui
