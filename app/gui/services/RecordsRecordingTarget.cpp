#include "app/gui/services/RecordsRecordingTarget.h"

#include <QCoreApplication>

#include "app/gui/services/RecordsService.h"

namespace armtrack::gui {

RecordsRecordingTarget::RecordsRecordingTarget(RecordsService& records, QString patientCode,
                                               QString protocolName)
    : m_records(records),
      m_patient(std::move(patientCode)),
      m_protocol(std::move(protocolName)),
      m_state(std::make_shared<State>()) {}

RecordsRecordingTarget::~RecordsRecordingTarget() = default;

QString RecordsRecordingTarget::describe() const {
  return QCoreApplication::translate("armtrack::gui::RecordsRecordingTarget",
                                     "the records of patient %1")
      .arg(m_patient);
}

std::function<QString(storage::ClinicalStore&)> RecordsRecordingTarget::beginJob(
    const RecordingMeta& meta, const RecordingColumns& columns) const {
  // Holds the state, not the target: a queued call may outlive the screen that asked for it.
  return [state = m_state, url = m_records.url(), patient = m_patient, protocol = m_protocol, meta,
          columns, settings = sessionSettings()](storage::ClinicalStore& store) {
    if (!state->inner)
      state->inner =
          std::make_unique<app::gui::DatabaseRecordingTarget>(store, url, patient, protocol);
    state->inner->setSessionSettings(settings);  // the devices, as the CLI stores them
    const QString why = state->inner->begin(meta, columns);
    state->sessionId = state->inner->sessionId();
    return why;
  };
}

std::function<QString(storage::ClinicalStore&)> RecordsRecordingTarget::finishJob(
    std::uint64_t rows, bool complete, const QString& events) const {
  return [state = m_state, rows, complete, events](storage::ClinicalStore&) {
    return state->inner->finish(rows, complete, events);
  };
}

QString RecordsRecordingTarget::begin(const RecordingMeta& meta, const RecordingColumns& columns) {
  try {
    return m_records.callBlocking(beginJob(meta, columns));
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
}

void RecordsRecordingTarget::beginAsync(const RecordingMeta& meta, const RecordingColumns& columns,
                                        QObject* context, Done done) {
  m_records.call(
      context, beginJob(meta, columns), [done](const QString& why) { done(why); },
      [done](const RecordsFailure& f) { done(f.message); });
}

std::unique_ptr<RecordingSink> RecordsRecordingTarget::open(const RecordingMeta& meta,
                                                            const RecordingColumns& columns) {
  // The session thread opens the sink once the gate opened, after begin was done.
  if (!m_state->inner || m_state->sessionId == 0)
    throw RecordingError("", 0, 0, "the session was not begun in the records");
  return m_state->inner->open(meta, columns);  // opens its own connection on the recorder thread
}

QString RecordsRecordingTarget::finish(std::uint64_t rows, bool complete, const QString& events) {
  if (m_state->sessionId == 0) return {};
  try {
    return m_records.callBlocking(finishJob(rows, complete, events));
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
}

void RecordsRecordingTarget::finishAsync(std::uint64_t rows, bool complete, const QString& events,
                                         QObject* context, Done done) {
  if (m_state->sessionId == 0) return done({});
  m_records.call(
      context, finishJob(rows, complete, events), [done](const QString& line) { done(line); },
      [done](const RecordsFailure& f) { done(f.message); });
}

qint64 RecordsRecordingTarget::sessionId() const {
  return m_state->sessionId;
}

}  // namespace armtrack::gui
