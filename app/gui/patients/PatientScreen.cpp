#include "app/gui/patients/PatientScreen.h"

#include <QDate>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QStandardItemModel>
#include <QTableView>
#include <QVBoxLayout>

#include "app/clinical/Outputs.h"
#include "app/gui/common/AngleNames.h"
#include "app/gui/common/Forms.h"
#include "app/gui/common/JobProgress.h"
#include "app/gui/common/SessionTableModel.h"
#include "app/gui/patients/HomeDevicesBox.h"
#include "app/gui/patients/PatientDialog.h"
#include "app/gui/patients/PatientTableModel.h"
#include "app/gui/patients/ProgressChart.h"
#include "app/gui/services/AppSettings.h"
#include "app/gui/services/RecordsService.h"
#include "core/storage/DatabaseFiles.h"
#include "ui/Retranslate.h"

namespace armtrack::gui {

namespace {

QLabel* value(const QString& text, QWidget* parent) {
  auto* l = new QLabel(text.isEmpty() ? QStringLiteral("-") : text, parent);
  l->setWordWrap(true);
  l->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  return l;
}

QString cm(const std::optional<double>& metres) {
  return metres ? PatientScreen::tr("%L1 cm").arg(*metres * 100, 0, 'f', 1) : QString();
}

QTableView* plainTable(QAbstractItemModel* model, const QString& name, QWidget* parent) {
  auto* t = new QTableView(parent);
  t->setModel(model);
  t->setAccessibleName(name);
  t->setEditTriggers(QAbstractItemView::NoEditTriggers);
  t->setSelectionBehavior(QAbstractItemView::SelectRows);
  t->setSelectionMode(QAbstractItemView::SingleSelection);
  t->setTabKeyNavigation(false);
  t->verticalHeader()->hide();
  t->horizontalHeader()->setStretchLastSection(true);
  return t;
}

/// The sessions sorted, with the order in the sorted column's header in words or an arrow (the
/// style's own indicator draws descending as an upward arrow, which reads as "oldest first").
class SortedSessions : public QSortFilterProxyModel {
 public:
  using QSortFilterProxyModel::QSortFilterProxyModel;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override {
    QVariant v = QSortFilterProxyModel::headerData(section, orientation, role);
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole || section != sortColumn())
      return v;
    const bool up = sortOrder() == Qt::AscendingOrder;
    if (section == SessionTableModel::Started)
      return up ? PatientScreen::tr("%1 (oldest first)").arg(v.toString())
                : PatientScreen::tr("%1 (newest first)").arg(v.toString());
    return v.toString() + (up ? QStringLiteral(" \u25b2") : QStringLiteral(" \u25bc"));
  }
  void sort(int column, Qt::SortOrder order) override {
    QSortFilterProxyModel::sort(column, order);
    if (columnCount() > 0) emit headerDataChanged(Qt::Horizontal, 0, columnCount() - 1);
  }
};

}  // namespace

PatientScreen::PatientScreen(RecordsService& records, const AppSettings& settings,
                             const QString& code, QWidget* parent)
    : QWidget(parent),
      m_records(records),
      m_settings(settings),
      m_code(code),
      m_canWrite(records.signedIn() && records.user().role != storage::Role::Home),
      m_canDelete(records.signedIn() && records.user().role == storage::Role::Admin),
      m_title(heading(code, this)),
      m_programme(new QStandardItemModel(this)),
      m_chart(new ProgressChart(this)),
      m_sessions(new SessionTableModel(this)),
      m_sessionsSorted(new SortedSessions(this)),
      m_message(new MessageLine(this)),
      m_newSession(new QPushButton(this)),
      m_review(new QPushButton(this)),
      m_delete(new QPushButton(this)),
      m_report(new QPushButton(this)),
      m_edit(new QPushButton(this)),
      m_back(new QPushButton(this)) {
  m_chart->setRadians(settings.units == AppSettings::AngleUnit::Radians);
  auto* layout = new QVBoxLayout(this);
  auto* top = new QHBoxLayout;
  // The heading follows the width (updateTitle() elides the name), so it never holds the window
  // wider than the screen.
  m_title->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  top->addWidget(m_title, 1);
  m_back->setShortcut(QKeySequence::Back);
  top->addWidget(m_back);
  layout->addLayout(top);
  layout->addWidget(m_message);

  // Left: who the patient is. Right: how they progress, and their sessions.
  auto* split = new QSplitter(Qt::Horizontal, this);
  auto* side = new QWidget;
  auto* sideLayout = new QVBoxLayout(side);
  m_detailsBox = new QGroupBox(side);
  auto* detailsForm = new QFormLayout(m_detailsBox);
  for (int i = 0; i < 6; ++i) {
    m_detailNames.push_back(new QLabel(m_detailsBox));
    m_detailValues.push_back(value({}, m_detailsBox));
    detailsForm->addRow(m_detailNames.back(), m_detailValues.back());
  }
  sideLayout->addWidget(m_detailsBox);
  m_lengthsBox = new QGroupBox(side);
  auto* lengthsForm = new QFormLayout(m_lengthsBox);
  for (int i = 0; i < 4; ++i) {
    m_lengthNames.push_back(new QLabel(m_lengthsBox));
    m_lengthValues.push_back(value({}, m_lengthsBox));
    lengthsForm->addRow(m_lengthNames.back(), m_lengthValues.back());
  }
  m_lengthsNote = value({}, m_lengthsBox);
  m_lengthsNote->hide();
  lengthsForm->addRow(m_lengthsNote);
  sideLayout->addWidget(m_lengthsBox);
  m_programmeBox = new QGroupBox(side);
  auto* programmeLayout = new QVBoxLayout(m_programmeBox);
  m_programmeTable = plainTable(m_programme, QString(), m_programmeBox);
  programmeLayout->addWidget(m_programmeTable);
  sideLayout->addWidget(m_programmeBox);
  sideLayout->addWidget(m_edit);
  if (m_canWrite) {  // the store lets administrators and therapists enrol devices
    m_homeDevices = new HomeDevicesBox(records, settings, code, side);
    sideLayout->addWidget(m_homeDevices);
  }
  sideLayout->addStretch();
  auto* scroll = new QScrollArea;
  scroll->setWidget(side);
  scroll->setWidgetResizable(true);
  scroll->setMinimumWidth(300);
  split->addWidget(scroll);

  auto* main = new QWidget;
  auto* mainLayout = new QVBoxLayout(main);
  m_progressBox = new QGroupBox(main);
  (new QVBoxLayout(m_progressBox))->addWidget(m_chart);
  mainLayout->addWidget(m_progressBox, 3);
  m_sessionsBox = new QGroupBox(main);
  auto* sessionsLayout = new QVBoxLayout(m_sessionsBox);
  m_sessionsSorted->setSourceModel(m_sessions);
  m_sessionsSorted->setSortRole(Qt::EditRole);
  m_sessionTable = plainTable(m_sessionsSorted, QString(), m_sessionsBox);
  m_sessionTable->setSortingEnabled(true);
  m_sessionTable->horizontalHeader()->setSortIndicatorShown(false);  // SortedSessions says it
  m_sessionTable->sortByColumn(SessionTableModel::Started, Qt::DescendingOrder);
  sessionsLayout->addWidget(m_sessionTable);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_newSession);
  buttons->addWidget(m_report);
  buttons->addStretch();
  buttons->addWidget(m_delete);
  buttons->addWidget(m_review);
  sessionsLayout->addLayout(buttons);
  mainLayout->addWidget(m_sessionsBox, 2);
  // A low screen (1024x600) scrolls the chart and the sessions rather than squeeze the chart
  // until its labels read "...".
  m_sessionsBox->setMinimumHeight(220);
  auto* mainScroll = new QScrollArea;
  mainScroll->setWidget(main);
  mainScroll->setWidgetResizable(true);
  mainScroll->setFrameShape(QFrame::NoFrame);
  split->addWidget(mainScroll);
  split->setStretchFactor(0, 1);
  split->setStretchFactor(1, 3);
  layout->addWidget(split, 1);

  m_review->setDefault(true);
  m_newSession->setVisible(m_canWrite);
  m_edit->setVisible(m_canWrite);
  m_delete->setVisible(m_canDelete);
  connect(m_delete, &QPushButton::clicked, this, &PatientScreen::deleteSession);
  connect(m_back, &QPushButton::clicked, this, &PatientScreen::backRequested);
  connect(m_newSession, &QPushButton::clicked, this, [this] { emit newSessionRequested(m_code); });
  connect(m_review, &QPushButton::clicked, this, [this] {
    if (const qint64 id = selectedSession()) emit reviewRequested(id);
  });
  connect(m_sessionTable, &QTableView::activated, m_review, &QPushButton::click);
  connect(m_report, &QPushButton::clicked, this, &PatientScreen::askProgressReport);
  connect(m_edit, &QPushButton::clicked, this, &PatientScreen::editPatient);
  connect(m_sessionTable->selectionModel(), &QItemSelectionModel::selectionChanged, this,
          &PatientScreen::updateButtons);
  setTabOrder(m_back, m_chart);
  setTabOrder(m_chart, m_sessionTable);
  setTabOrder(m_sessionTable, m_review);
  setTabOrder(m_review, m_delete);
  setTabOrder(m_delete, m_newSession);
  setTabOrder(m_newSession, m_report);
  setTabOrder(m_report, m_edit);
  setFocusProxy(m_sessionTable);
  retranslateUi();
  updateButtons();
  reload();
}

void PatientScreen::retranslateUi() {
  setWindowTitle(m_loaded ? m_overview.patient.name : tr("Patient %1").arg(m_code));
  m_newSession->setText(tr("&New session..."));
  m_newSession->setShortcut(QKeySequence(tr("Ctrl+R")));
  m_newSession->setToolTip(tr("Record a new session with this patient (%1)")
                               .arg(m_newSession->shortcut().toString(QKeySequence::NativeText)));
  m_review->setText(tr("&Review session"));
  m_delete->setText(tr("&Delete session..."));
  m_report->setText(tr("&Progress report (PDF)..."));
  m_edit->setText(tr("&Edit patient..."));
  ui::setButtonText(m_back, tr("&Back to patients"));
  m_detailsBox->setTitle(tr("Details"));
  const QStringList details = {tr("Code:"),          tr("Born:"),      tr("Sex:"),
                               tr("Affected side:"), tr("Diagnosis:"), tr("Notes:")};
  for (std::size_t i = 0; i < m_detailNames.size(); ++i)
    m_detailNames[i]->setText(details[static_cast<qsizetype>(i)]);
  m_lengthsBox->setTitle(tr("Measured segment lengths"));
  const QStringList lengths = {tr("Upper arm:"), tr("Forearm:"), tr("Upper-arm IMU:"),
                               tr("Forearm IMU:")};
  for (std::size_t i = 0; i < m_lengthNames.size(); ++i)
    m_lengthNames[i]->setText(lengths[static_cast<qsizetype>(i)]);
  m_programmeBox->setTitle(tr("Home programme"));
  m_programmeTable->setAccessibleName(tr("Home programme"));
  m_progressBox->setTitle(tr("Progress"));
  m_sessionsBox->setTitle(tr("Sessions"));
  m_sessionTable->setAccessibleName(tr("Sessions"));
  // What was read, in words of the new language (sex, side, the programme's headers).
  if (m_loaded) show(m_overview, true);
}

void PatientScreen::updateTitle() {
  if (!m_loaded) return;
  const storage::Patient& p = m_overview.patient;
  const QString code = tr("(%1)").arg(p.code);
  const QFontMetrics fm(m_title->font());
  const int room = std::max(0, m_title->width() - fm.horizontalAdvance(u' ' + code) - 8);
  const QString name = fm.elidedText(p.name, Qt::ElideRight, room);
  m_title->setText(tr("%1 (%2)").arg(name, p.code));
  m_title->setToolTip(name == p.name ? QString() : p.name);
  m_title->setAccessibleName(tr("%1 (%2)").arg(p.name, p.code));
}

void PatientScreen::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  updateTitle();
}

void PatientScreen::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWidget::changeEvent(event);
}

void PatientScreen::reload() {
  if (m_homeDevices) m_homeDevices->reload();
  m_message->showMessage([] { return tr("Loading..."); }, MessageLine::Kind::Notice);
  m_records.call(
      this, [code = m_code](storage::ClinicalStore& s) { return loadPatientOverview(s, code); },
      [this](const PatientOverview& o) {
        m_message->clear();
        show(o);
        emit loaded();
      },
      [this](const RecordsFailure& f) {
        m_message->showMessage(
            [why = f.message] { return tr("This patient could not be read: %1").arg(why); });
      });
}

void PatientScreen::show(const PatientOverview& o, bool again) {
  m_overview = o;
  m_loaded = true;
  const storage::Patient& p = o.patient;
  updateTitle();
  setWindowTitle(p.name);
  const QDate born = QDate::fromString(p.birthDate, Qt::ISODate);
  const QStringList details = {
      p.code,
      born.isValid() ? QLocale().toString(born, QLocale::LongFormat) : QString(),
      PatientTableModel::sexText(p.sex),
      PatientTableModel::sideText(p.affectedSide),
      p.diagnosis,
      p.notes};
  for (int i = 0; i < details.size(); ++i)
    m_detailValues[static_cast<std::size_t>(i)]->setText(details[i].isEmpty() ? QStringLiteral("-")
                                                                              : details[i]);
  int ignored = 0;
  const SegmentLengths l = SegmentLengths::fromJson(p.segmentLengthsJson, &ignored);
  const std::optional<double> lengths[] = {l.upperArmM, l.forearmM, l.upperStrapM, l.forearmStrapM};
  for (std::size_t i = 0; i < 4; ++i) {
    const QString text = cm(lengths[i]);
    m_lengthValues[i]->setText(text.isEmpty() ? tr("not measured") : text);
  }
  m_lengthsNote->setText(
      ignored > 0 ? tr("%n stored length(s) could not be read.", nullptr, ignored) : QString());
  m_lengthsNote->setVisible(ignored > 0);

  m_programme->clear();
  m_programme->setHorizontalHeaderLabels(
      {tr("Protocol"), tr("Angle"), tr("Sets"), tr("Target (\u00b0)"), tr("Rest"), tr("Per week")});
  for (const storage::ProgrammeItem& item : o.programme) {
    QString angle, target, sets;
    for (const storage::Protocol& pr : o.protocols) {
      if (pr.name != item.protocolName) continue;
      angle = angleName(angleIndex(pr.angleKey));
      const auto [lo, hi] = storage::effectiveTarget(item, pr);
      target = QStringLiteral("%L1\u2013%L2").arg(lo, 0, 'f', 0).arg(hi, 0, 'f', 0);
      sets = tr("%L1 \u00d7 %L2").arg(item.sets).arg(storage::effectiveRepetitions(item, pr));
    }
    m_programme->appendRow({new QStandardItem(item.protocolName), new QStandardItem(angle),
                            new QStandardItem(sets), new QStandardItem(target),
                            new QStandardItem(tr("%L1 s").arg(item.restS, 0, 'f', 0)),
                            new QStandardItem(QLocale().toString(item.sessionsPerWeek))});
  }
  m_programmeTable->resizeColumnsToContents();  // a narrow pane scrolls; no name is cut
  if (again) return;  // the chart, the sessions' table and the choices in them stay
  m_chart->setPatient(o.patient.birthDate, o.patient.sex);
  m_chart->setSessions(o.progress);
  m_sessions->setSessions(o.sessions);
  // Open on the angle the latest protocol trains, if any.
  for (const storage::SessionInfo& s : o.sessions) {
    const auto pr = std::find_if(o.protocols.begin(), o.protocols.end(),
                                 [&](const auto& x) { return x.name == s.protocolName; });
    if (pr != o.protocols.end() && angleIndex(pr->angleKey) >= 0) {
      m_chart->setAngle(angleIndex(pr->angleKey));
      break;
    }
  }
  m_sessionTable->resizeColumnsToContents();
  if (m_sessionsSorted->rowCount() > 0) m_sessionTable->selectRow(0);
  updateButtons();
}

qint64 PatientScreen::selectedSession() const {
  const QModelIndexList rows = m_sessionTable->selectionModel()->selectedRows();
  return rows.isEmpty() ? 0 : rows.first().data(SessionTableModel::IdRole).toLongLong();
}

void PatientScreen::updateButtons() {
  m_review->setEnabled(selectedSession() != 0);
  m_delete->setEnabled(selectedSession() != 0);
  m_report->setEnabled(!m_overview.sessions.empty());
}

void PatientScreen::editPatient() {
  if (m_overview.patient.code.isEmpty()) return;
  auto* dialog = new PatientDialog(m_overview.patient, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &PatientDialog::saveRequested, this, [this, dialog](const storage::Patient& p) {
    m_records.call(
        dialog, [p](storage::ClinicalStore& s) { s.updatePatient(p); },
        [this, dialog] {
          dialog->accept();
          reload();
        },
        [dialog](const RecordsFailure& f) { dialog->showError(f.message); });
  });
  dialog->open();
}

void PatientScreen::deleteSession() {
  const qint64 id = selectedSession();
  if (!id || !m_canDelete) return;
  QString what = tr("session %1").arg(id);
  for (const storage::SessionInfo& s : m_overview.sessions)
    if (s.id == id)
      what = tr("the session of %1 (%2, %3, session %4)")
                 .arg(SessionTableModel::localTime(s.startedAt),
                      s.protocolName.isEmpty() ? tr("free movement") : s.protocolName,
                      SessionTableModel::durationText(s.durationS))
                 .arg(id);
  auto* box = new QMessageBox(
      QMessageBox::Warning, tr("Delete session"),
      tr("Delete %1 of %2? Its recording, angles and metrics are removed for good; the audit log "
         "keeps that you did it.")
          .arg(what, m_overview.patient.name),
      QMessageBox::Cancel, this);
  box->addButton(tr("&Delete"), QMessageBox::DestructiveRole);
  box->setDefaultButton(QMessageBox::Cancel);  // Enter alone deletes nothing
  box->setAttribute(Qt::WA_DeleteOnClose);
  connect(box, &QMessageBox::buttonClicked, this, [this, box, id](QAbstractButton* button) {
    if (box->buttonRole(button) != QMessageBox::DestructiveRole) return;
    m_records.call(
        this, [id](storage::ClinicalStore& s) { s.removeSession(id); },
        [this, id] {
          // Said once the page shows the sessions without it (reload() clears the message).
          auto once = std::make_shared<QMetaObject::Connection>();
          *once = connect(this, &PatientScreen::loaded, this, [this, id, once] {
            disconnect(*once);
            m_message->showMessage([id] { return tr("Session %1 deleted.").arg(id); },
                                   MessageLine::Kind::Notice);
          });
          reload();
        },
        [this](const RecordsFailure& f) {
          m_message->showMessage(
              [why = f.message] { return tr("The session could not be deleted: %1").arg(why); });
        });
  });
  box->open();
}

void PatientScreen::askProgressReport() {
  const QString folder = m_settings.exportFolder();
  storage::makePrivateFolders(folder);  // 0700: it holds patients' data
  const QString suggested = QDir(folder).filePath(
      QStringLiteral("%1_progress_%2.pdf").arg(m_code, QDate::currentDate().toString(Qt::ISODate)));
  const QString pdf = QFileDialog::getSaveFileName(this, tr("Save the progress report"), suggested,
                                                   tr("PDF files (*.pdf)"));
  if (!pdf.isEmpty()) writeProgressReport(pdf);
}

void PatientScreen::writeProgressReport(const QString& pdf) {
  m_message->showMessage([] { return tr("Writing the progress report..."); },
                         MessageLine::Kind::Notice);
  RecordsJob* job = m_records.startJob(
      this,
      [code = m_code, pdf](JobContext& c) {
        c.progress(10);
        const reports::ProgressReportData d = clinical::progressReportData(c.store(), code);
        c.progress(60);
        return clinical::writeProgressReport(c.store(), d, pdf);
      },
      [this, pdf](int pages) {
        m_message->showMessage(
            [pages, pdf] {
              return tr("Progress report written: %1 (%n page(s)).", nullptr, pages)
                  .arg(QDir::toNativeSeparators(pdf));
            },
            MessageLine::Kind::Notice);
        emit reportWritten(pdf, {});
      },
      [this, pdf](const RecordsFailure& f) {
        const auto text = [why = f.message] {
          return tr("The progress report could not be written: %1. Choose another folder or "
                    "file name and try again.")
              .arg(why);
        };
        m_message->showMessage(text);
        emit reportWritten(pdf, text());
      });
  showJobProgress(this, job, tr("Writing the progress report..."));
}

}  // namespace armtrack::gui
