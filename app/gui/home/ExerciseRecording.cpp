#include "app/gui/home/ExerciseRecording.h"

#include <QCoreApplication>

#include "app/gui/services/RecordsService.h"
#include "core/storage/DatabaseRecordingSink.h"

namespace armtrack::gui::home {

QString HomeRecordingTarget::describe() const {
  return QCoreApplication::translate("armtrack::gui::home::ExerciseRecording", "the records");
}

std::unique_ptr<RecordingSink> HomeRecordingTarget::open(const RecordingMeta&,
                                                         const RecordingColumns& columns) {
  const qint64 id = m_id;
  if (id == 0) throw RecordingError("", 0, 0, "the session was not begun in the records");
  return std::make_unique<storage::DatabaseRecordingSink>(m_url, id, columns);
}

ExerciseRecording::ExerciseRecording(const app::PluginRegistry& registry, RecordsService& records,
                                     QString patientCode, QString protocol, QObject* parent)
    : QObject(parent),
      m_records(records),
      m_patient(std::move(patientCode)),
      m_protocol(std::move(protocol)),
      m_target(std::make_shared<HomeRecordingTarget>(records.url())),
      m_gate(std::make_shared<app::gui::RecordingGate>(m_target)),
      m_controller(new app::gui::SessionController(registry, this)) {
  connect(m_controller, &app::gui::SessionController::started, this, [this](const QString& e) {
    emit started(e);
    if (e.isEmpty() && m_want) begin();
  });
  connect(m_controller, &app::gui::SessionController::stopped, this, &ExerciseRecording::onStopped);
  connect(m_controller, &app::gui::SessionController::problem, this, &ExerciseRecording::problem);
}

void ExerciseRecording::start(const app::gui::LiveSessionConfig& config) {
  m_gate->setRecording(false);
  m_controller->start(config, m_gate);
}

void ExerciseRecording::begin() {
  const auto layout = m_controller->recordingLayout();
  if (!layout || m_begun) return;
  m_begun = true;
  m_records.call(
      this,
      [patient = m_patient, protocol = m_protocol, meta = layout->first, columns = layout->second,
       settings = m_target->sessionSettings()](storage::ClinicalStore& s) {
        // The devices and filter the session controller made, as the clinic's recordings.
        return s.beginRecording(patient, protocol, meta, columns, settings);
      },
      [this](qint64 id) {
        m_target->setSessionId(id);
        if (m_stopped)
          finishInRecords();  // the exercise ended before the records answered
        else
          m_gate->setRecording(m_want);
      },
      [this](const RecordsFailure& f) {
        emit problem(tr("This exercise cannot be saved: %1").arg(f.message));
        if (m_stopped) emit finished(0, false, f.message);
        m_begun = false;
      });
}

void ExerciseRecording::setRecording(bool on) {
  m_want = on;
  if (on && !m_begun) begin();
  if (m_target->sessionId() != 0) m_gate->setRecording(on);
}

bool ExerciseRecording::drain(std::vector<session::EstimateRow>& rows,
                              std::vector<std::string>& events) {
  return m_controller->drainInto(rows, events);
}

void ExerciseRecording::stop(bool cutShort) {
  m_cutShort = cutShort;
  m_want = false;
  m_gate->setRecording(false);
  if (!m_controller->busy()) {
    emit finished(sessionId(), !cutShort, {});
    return;
  }
  m_controller->stop();
}

void ExerciseRecording::onStopped(quint64 recorded, quint64 toRecord,
                                  const QString& recorderError) {
  // Rows the gate held back (rests, pauses) were never meant for the recording.
  m_complete = !m_cutShort && recorderError.isEmpty() && recorded + m_gate->skipped() == toRecord;
  m_recorderError = recorderError;
  m_stopped = true;
  if (sessionId() != 0)
    finishInRecords();
  else if (!m_begun)
    emit finished(0, m_complete, recorderError);
  // else: begun, the id is on its way; begin()'s answer finishes it.
}

void ExerciseRecording::finishInRecords() {
  const qint64 id = sessionId();
  const bool complete = m_complete;
  const QString recorderError = m_recorderError;
  m_records.call(
      this,
      [id, complete](storage::ClinicalStore& s) {
        s.finishSession(id, complete ? storage::kStatusComplete : storage::kStatusInterrupted);
      },
      [this, id, complete, recorderError] { emit finished(id, complete, recorderError); },
      [this, id, recorderError](const RecordsFailure& f) {
        // The session stays "recording" and is marked interrupted when the records are next
        // opened; what was stored is kept.
        emit finished(id, false, recorderError.isEmpty() ? f.message : recorderError);
      });
}

session::LiveCalibrationStatus ExerciseRecording::movementCalibration() const {
  const std::shared_ptr<session::Session>& s = m_controller->session();
  return s ? s->movementCalibration() : session::LiveCalibrationStatus{};
}

}  // namespace armtrack::gui::home
