// The live screen's recording target (app/gui/live/RecordingTarget.h) for the records reached
// through RecordsService: the session's row is begun and finished on the records thread, as
// `armtrack-cli record --db` does it, its rows committed by the session's recorder thread.
#pragma once

#include <memory>

#include "app/gui/live/RecordingTarget.h"

namespace armtrack::gui {

class RecordsService;

class RecordsRecordingTarget final : public app::gui::RecordingTarget {
 public:
  /// records must be signed in and outlive the target.
  RecordsRecordingTarget(RecordsService& records, QString patientCode, QString protocolName);
  ~RecordsRecordingTarget() override;
  QString describe() const override;
  QString begin(const RecordingMeta& meta, const RecordingColumns& columns) override;
  std::unique_ptr<RecordingSink> open(const RecordingMeta& meta,
                                      const RecordingColumns& columns) override;
  QString finish(std::uint64_t rows, bool complete, const QString& events) override;
  /// The recorded session's id (0 until recording began).
  qint64 sessionId() const;

 private:
  RecordsService& m_records;
  QString m_patient, m_protocol;
  std::unique_ptr<app::gui::DatabaseRecordingTarget> m_inner;  // used on the records thread
};

}  // namespace armtrack::gui
