// The live screen's recording target (app/gui/services/RecordingTarget.h) for the records reached
// through RecordsService: the session's row is begun and finished on the records thread, as
// `armtrack-cli record --db` does it, its rows committed by the session's recorder thread.
#pragma once

#include <atomic>
#include <functional>
#include <memory>

#include "app/gui/services/RecordingTarget.h"

namespace armtrack::gui {

class RecordsService;

class RecordsRecordingTarget final : public app::gui::RecordingTarget {
 public:
  /// records must be signed in and outlive the target.
  RecordsRecordingTarget(RecordsService& records, QString patientCode, QString protocolName);
  ~RecordsRecordingTarget() override;
  QString describe() const override;
  /// Blocking (the records thread does the work, the caller waits): for callers off the GUI
  /// thread. The live screen uses beginAsync() and finishAsync(), which do not wait.
  QString begin(const RecordingMeta& meta, const RecordingColumns& columns) override;
  std::unique_ptr<RecordingSink> open(const RecordingMeta& meta,
                                      const RecordingColumns& columns) override;
  QString finish(std::uint64_t rows, bool complete, const QString& events) override;
  void beginAsync(const RecordingMeta& meta, const RecordingColumns& columns, QObject* context,
                  Done done) override;
  void finishAsync(std::uint64_t rows, bool complete, const QString& events, QObject* context,
                   Done done) override;
  /// The recorded session's id (0 until recording began).
  qint64 sessionId() const;

 private:
  /// What the records thread works on; shared with its queued calls, so that a call still
  /// queued when the screen (and this target) has gone finds it alive.
  struct State {
    std::unique_ptr<app::gui::DatabaseRecordingTarget> inner;  // used on the records thread
    std::atomic<qint64> sessionId{0};
  };
  /// The work begin and finish do on the records thread.
  std::function<QString(storage::ClinicalStore&)> beginJob(const RecordingMeta& meta,
                                                           const RecordingColumns& columns) const;
  std::function<QString(storage::ClinicalStore&)> finishJob(std::uint64_t rows, bool complete,
                                                            const QString& events) const;
  RecordsService& m_records;
  QString m_patient, m_protocol;
  std::shared_ptr<State> m_state;
};

}  // namespace armtrack::gui
