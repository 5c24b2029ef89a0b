// The review's outputs: the session report and the exports (CSV, OpenSim, BIDS, the recording),
// each asked for with a file dialog in the settings' export folder and written by a records job
// whose result (or what went wrong, with what to do) the Outputs panel shows.
#include <QDir>
#include <QFileDialog>

#include "app/gui/common/Forms.h"
#include "app/gui/common/JobProgress.h"
#include "app/gui/review/ReviewScreen.h"
#include "app/gui/services/AppSettings.h"
#include "app/gui/services/RecordsService.h"
#include "core/storage/DatabaseFiles.h"

namespace armtrack::gui {

void ReviewScreen::askReport() {
  const QString folder = m_settings.exportFolder();
  storage::makePrivateFolders(folder);  // 0700: it holds patients' data
  const QString pdf = QFileDialog::getSaveFileName(
      this, tr("Save the session report"),
      QDir(folder).filePath(
          QStringLiteral("%1_session_%2.pdf").arg(m_data.info.patientCode).arg(m_id)),
      tr("PDF files (*.pdf)"));
  if (!pdf.isEmpty()) writeReport(pdf);
}

void ReviewScreen::askExport(clinical::ExportFormat format) {
  const QString folder = m_settings.exportFolder();
  storage::makePrivateFolders(folder);  // 0700: it holds patients' data
  const QString stem =
      QDir(folder).filePath(QStringLiteral("%1_session_%2").arg(m_data.info.patientCode).arg(m_id));
  QString path;
  switch (format) {
    case clinical::ExportFormat::Bids:
      path = QFileDialog::getExistingDirectory(this, tr("Folder of the BIDS data set"), folder);
      break;
    case clinical::ExportFormat::Mot:
      path = QFileDialog::getSaveFileName(this, tr("Export as OpenSim motion"), stem + ".mot",
                                          tr("OpenSim motion (*.mot)"));
      break;
    case clinical::ExportFormat::Csv:
      path = QFileDialog::getSaveFileName(this, tr("Export the angles as CSV"), stem + ".csv",
                                          tr("CSV files (*.csv)"));
      break;
    case clinical::ExportFormat::Recording:
      path = QFileDialog::getSaveFileName(this, tr("Export the recording"), stem + "_recording.csv",
                                          tr("Recordings (*.csv)"));
      break;
  }
  if (!path.isEmpty()) exportTo(format, path);
}

void ReviewScreen::writeReport(const QString& pdf) {
  runOutput(tr("the session report"), pdf, [id = m_id, pdf](storage::ClinicalStore& s) {
    const int pages = clinical::writeSessionReport(s, id, pdf);
    return tr("Session report written: %1 (%n page(s)).", nullptr, pages)
        .arg(QDir::toNativeSeparators(pdf));
  });
}

void ReviewScreen::exportTo(clinical::ExportFormat format, const QString& path) {
  runOutput(tr("the export"), path, [id = m_id, format, path](storage::ClinicalStore& s) {
    const clinical::ExportSummary r = clinical::exportSession(s, id, format, path.toStdString());
    QString text = tr("Exported: %1.").arg(QString::fromStdString(r.what));
    for (const std::string& note : r.notes) text += u'\n' + QString::fromStdString(note);
    return text;
  });
}

void ReviewScreen::runOutput(const QString& what, const QString& path,
                             std::function<QString(storage::ClinicalStore&)> work) {
  m_outputs->setBusy(true);
  m_outputs->setResult(tr("Writing %1...").arg(what));
  RecordsJob* job = m_records.startJob(
      this,
      [work = std::move(work)](JobContext& c) {
        c.progress(5);
        return work(c.store());
      },
      [this, path](const QString& text) {
        m_outputs->setBusy(false);
        m_outputs->setResult(text);
        emit outputWritten(path, {});
      },
      [this, what, path](const RecordsFailure& f) {
        m_outputs->setBusy(false);
        const QString text = tr("%1 could not be written: %2. Choose another place and try again.")
                                 .arg(what, f.message);
        m_outputs->setResult(text);
        m_message->showMessage(text);
        emit outputWritten(path, text);
      });
  showJobProgress(this, job, tr("Writing %1...").arg(what));
}

}  // namespace armtrack::gui
