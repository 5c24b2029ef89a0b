#include "app/gui/services/RecordingTarget.h"

#include <QCoreApplication>

#include "core/storage/ClinicalStore.h"
#include "core/storage/DatabaseRecordingSink.h"
#include "core/storage/StorageError.h"

namespace armtrack::app::gui {

namespace {
// This file's texts (context "armtrack::app::gui::RecordingTarget" in
// translations/armtrack_<code>.ts).
struct Tr {
  Q_DECLARE_TR_FUNCTIONS(armtrack::app::gui::RecordingTarget)
};
}  // namespace

QString CsvRecordingTarget::describe() const {
  return QString::fromStdString(m_csv.string());
}

QString CsvRecordingTarget::begin(const RecordingMeta&, const RecordingColumns&) {
  return {};
}

std::unique_ptr<RecordingSink> CsvRecordingTarget::open(const RecordingMeta& meta,
                                                        const RecordingColumns& columns) {
  std::error_code ec;
  if (std::filesystem::exists(m_csv, ec) || std::filesystem::exists(sidecarPath(m_csv), ec))
    throw RecordingError(
        m_csv.string(), 0, 0,
        Tr::tr("a recording with this name exists; choose another name").toStdString());
  // Its folder is made here, on the recorder thread, not by the screen on the GUI thread.
  if (const std::filesystem::path folder = m_csv.parent_path(); !folder.empty()) {
    std::filesystem::create_directories(folder, ec);
    if (ec)
      throw RecordingError(
          m_csv.string(), 0, 0,
          Tr::tr("cannot create the folder %1 (%2): choose a folder you may "
                 "write to")
              .arg(QString::fromStdString(folder.string()), QString::fromStdString(ec.message()))
              .toStdString());
  }
  return std::make_unique<RecordingWriter>(m_csv, meta, columns);
}

QString CsvRecordingTarget::finish(std::uint64_t rows, bool complete, const QString&) {
  return complete ? Tr::tr("%L1 rows recorded in %2").arg(rows).arg(describe())
                  : Tr::tr("%L1 rows recorded in %2; some rows could not be written")
                        .arg(rows)
                        .arg(describe());
}

DatabaseRecordingTarget::DatabaseRecordingTarget(storage::ClinicalStore& store,
                                                 storage::DatabaseUrl url, QString patientCode,
                                                 QString protocolName)
    : m_store(store),
      m_url(std::move(url)),
      m_patient(std::move(patientCode)),
      m_protocol(std::move(protocolName)) {}

QString DatabaseRecordingTarget::describe() const {
  return Tr::tr("the records of patient %1").arg(m_patient);
}

QString DatabaseRecordingTarget::begin(const RecordingMeta& meta, const RecordingColumns& columns) {
  if (m_sessionId != 0) return {};
  try {
    m_sessionId = m_store.beginRecording(m_patient, m_protocol, meta, columns, sessionSettings());
  } catch (const storage::StorageError& e) {
    return Tr::tr("cannot record into the records: %1").arg(QString::fromStdString(e.what()));
  }
  return {};
}

std::unique_ptr<RecordingSink> DatabaseRecordingTarget::open(const RecordingMeta&,
                                                             const RecordingColumns& columns) {
  if (m_sessionId == 0) throw RecordingError("", 0, 0, "the session was not begun in the records");
  return std::make_unique<storage::DatabaseRecordingSink>(m_url, m_sessionId, columns);
}

QString DatabaseRecordingTarget::finish(std::uint64_t rows, bool complete, const QString& events) {
  if (m_sessionId == 0) return {};
  try {
    if (!events.isEmpty()) m_store.updateSessionNotes(m_sessionId, events);
    m_store.finishSession(m_sessionId,
                          complete ? storage::kStatusComplete : storage::kStatusInterrupted);
  } catch (const storage::StorageError& e) {
    return Tr::tr("session %1: %L2 rows recorded, but it could not be closed: %3")
        .arg(m_sessionId)
        .arg(rows)
        .arg(QString::fromStdString(e.what()));
  }
  return Tr::tr("session %1 saved in the records: %L2 rows").arg(m_sessionId).arg(rows);
}

}  // namespace armtrack::app::gui
