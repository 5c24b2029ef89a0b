#include "app/gui/JobProgress.h"

#include <QProgressDialog>

#include "app/gui/services/RecordsService.h"

namespace armtrack::gui {

void showJobProgress(QWidget* parent, RecordsJob* job, const QString& label) {
  auto* dialog = new QProgressDialog(label, QObject::tr("Cancel"), 0, 100, parent);
  dialog->setWindowModality(Qt::WindowModal);
  dialog->setMinimumDuration(500);
  dialog->setAutoClose(false);
  dialog->setAutoReset(false);
  dialog->setAccessibleName(label);
  dialog->setValue(0);
  QObject::connect(job, &RecordsJob::progress, dialog, &QProgressDialog::setValue);
  QObject::connect(dialog, &QProgressDialog::canceled, job, [job, dialog] {
    job->cancel();
    dialog->setLabelText(QObject::tr("Stopping..."));
    dialog->setCancelButton(nullptr);
    dialog->show();
  });
  QObject::connect(job, &RecordsJob::finished, dialog, &QObject::deleteLater);
}

}  // namespace armtrack::gui
