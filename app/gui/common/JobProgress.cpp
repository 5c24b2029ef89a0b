#include "app/gui/common/JobProgress.h"

#include <QCoreApplication>
#include <QProgressDialog>

#include "app/gui/services/RecordsService.h"

namespace armtrack::gui {

namespace {
struct Tr {
  Q_DECLARE_TR_FUNCTIONS(armtrack::gui::JobProgress)
};
}  // namespace

void showJobProgress(QWidget* parent, RecordsJob* job, const QString& label) {
  auto* dialog = new QProgressDialog(label, Tr::tr("Cancel"), 0, 100, parent);
  dialog->setWindowModality(Qt::WindowModal);
  dialog->setMinimumDuration(500);
  dialog->setAutoClose(false);
  dialog->setAutoReset(false);
  dialog->setAccessibleName(label);
  dialog->setValue(0);
  QObject::connect(job, &RecordsJob::progress, dialog, &QProgressDialog::setValue);
  QObject::connect(dialog, &QProgressDialog::canceled, job, [job, dialog] {
    job->cancel();
    dialog->setLabelText(Tr::tr("Stopping..."));
    dialog->setCancelButton(nullptr);
    dialog->show();
  });
  QObject::connect(job, &RecordsJob::finished, dialog, &QObject::deleteLater);
}

}  // namespace armtrack::gui
