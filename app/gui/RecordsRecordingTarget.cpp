#include "app/gui/RecordsRecordingTarget.h"

#include <QCoreApplication>

#include "app/gui/services/RecordsService.h"

namespace armtrack::gui {

RecordsRecordingTarget::RecordsRecordingTarget(RecordsService& records, QString patientCode,
                                               QString protocolName)
    : m_records(records), m_patient(std::move(patientCode)), m_protocol(std::move(protocolName)) {}

RecordsRecordingTarget::~RecordsRecordingTarget() {
  // The inner target holds a reference to the records thread's store; it owns nothing else.
}

QString RecordsRecordingTarget::describe() const {
  return QCoreApplication::translate("armtrack::gui::RecordsRecordingTarget",
                                     "the records of patient %1")
      .arg(m_patient);
}

QString RecordsRecordingTarget::begin(const RecordingMeta& meta, const RecordingColumns& columns) {
  try {
    // One insert on the records thread; the GUI waits for it as the live screen's interface
    // asks (app/gui/live/RecordingTarget.h).
    return m_records.callBlocking([&](storage::ClinicalStore& store) {
      if (!m_inner)
        m_inner = std::make_unique<app::gui::DatabaseRecordingTarget>(store, m_records.url(),
                                                                      m_patient, m_protocol);
      return m_inner->begin(meta, columns);
    });
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
}

std::unique_ptr<RecordingSink> RecordsRecordingTarget::open(const RecordingMeta& meta,
                                                            const RecordingColumns& columns) {
  if (!m_inner) throw RecordingError("", 0, 0, "the session was not begun in the records");
  return m_inner->open(meta, columns);  // opens its own connection on the recorder thread
}

QString RecordsRecordingTarget::finish(std::uint64_t rows, bool complete, const QString& events) {
  if (!m_inner) return {};
  try {
    return m_records.callBlocking(
        [&](storage::ClinicalStore&) { return m_inner->finish(rows, complete, events); });
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
}

qint64 RecordsRecordingTarget::sessionId() const {
  return m_inner ? m_inner->sessionId() : 0;
}

}  // namespace armtrack::gui
