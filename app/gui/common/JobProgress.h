// A window-modal progress dialog for a long records job: its percentage, a Cancel button that
// asks the job to stop, and nothing else to click while it runs.
#pragma once

#include <QString>

class QWidget;

namespace armtrack::gui {

class RecordsJob;

/// Shows progress of job over parent until the job finishes (the dialog then closes itself).
/// Appears only when the job takes longer than half a second.
void showJobProgress(QWidget* parent, RecordsJob* job, const QString& label);

}  // namespace armtrack::gui
