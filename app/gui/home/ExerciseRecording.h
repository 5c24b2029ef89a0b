// One exercise's live session recorded into the records as a home session: the devices started
// in a thread of their own (SessionController), the session begun in the records as soon as the
// recording's layout is known (on the records thread, never waited for), rows written only while a
// set is under way (RecordingGate) by a DatabaseRecordingSink on the session's recorder thread,
// in chunks of under a second, so a killed program loses at most the last second; then finished
// as complete, or interrupted when the exercise was cut short or rows were lost.
#pragma once

#include <QObject>
#include <atomic>
#include <memory>

#include "app/gui/services/GatedRecordingSink.h"
#include "app/gui/services/LiveSessionConfig.h"
#include "app/gui/services/SessionController.h"
#include "core/storage/DatabaseUrl.h"

namespace armtrack::gui {
class RecordsService;
}

namespace armtrack::gui::home {

/// Where the rows go: a session of the records begun by its owner; the id arrives from the
/// records thread before recording is switched on.
class HomeRecordingTarget final : public app::gui::RecordingTarget {
 public:
  explicit HomeRecordingTarget(storage::DatabaseUrl url) : m_url(std::move(url)) {}
  void setSessionId(qint64 id) { m_id = id; }
  qint64 sessionId() const { return m_id; }
  QString describe() const override;
  QString begin(const RecordingMeta&, const RecordingColumns&) override { return {}; }
  std::unique_ptr<RecordingSink> open(const RecordingMeta& meta,
                                      const RecordingColumns& columns) override;
  QString finish(std::uint64_t, bool, const QString&) override { return {}; }

 private:
  storage::DatabaseUrl m_url;
  std::atomic<qint64> m_id{0};
};

class ExerciseRecording : public QObject {
  Q_OBJECT
 public:
  /// records: signed in as the home account, outlives this. protocol: the exercise's.
  ExerciseRecording(const app::PluginRegistry& registry, RecordsService& records,
                    QString patientCode, QString protocol, QObject* parent = nullptr);

  /// Starts the devices and the session (started() follows).
  void start(const app::gui::LiveSessionConfig& config);
  /// Records while on (a set under way). The session is begun in the records the first time it
  /// is switched on (an exercise skipped before its first set leaves nothing); until the records
  /// have begun it, the wish is kept and applied then.
  void setRecording(bool on);
  bool recording() const { return m_want; }
  /// The running session's new estimates (GUI thread); false when none runs.
  bool drain(std::vector<session::EstimateRow>& rows, std::vector<std::string>& events);
  /// What the running session's calibration from movement found (State::Off when none runs).
  session::LiveCalibrationStatus movementCalibration() const;
  /// Ends the session; finished() follows once the records have it. cutShort: the exercise was
  /// stopped before its end (the session is then interrupted).
  void stop(bool cutShort);
  qint64 sessionId() const { return m_target->sessionId(); }
  bool running() const { return m_controller->busy(); }

 signals:
  /// The devices run (error empty), or why they could not start.
  void started(const QString& error);
  /// The session is finished in the records (sessionId 0: nothing was recorded). message says
  /// what went wrong, if anything.
  void finished(qint64 sessionId, bool complete, const QString& message);
  /// A problem to show (a device dropping out, the records refusing).
  void problem(const QString& message);

 private:
  void begin();
  void onStopped(quint64 recorded, quint64 toRecord, const QString& recorderError);
  void finishInRecords();

  RecordsService& m_records;
  QString m_patient, m_protocol;
  std::shared_ptr<HomeRecordingTarget> m_target;
  std::shared_ptr<app::gui::RecordingGate> m_gate;
  app::gui::SessionController* m_controller;
  bool m_want = false;
  bool m_begun = false;
  bool m_cutShort = false;
  // The outcome once the devices stopped, kept until the records have the session's id.
  bool m_stopped = false;
  bool m_complete = false;
  QString m_recorderError;
};

}  // namespace armtrack::gui::home
