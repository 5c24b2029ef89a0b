// The home programmes page of the administrator's screen (the CLI's `programme add`, `list`,
// `remove`).
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include "app/gui/admin/AdminDialogs.h"
#include "app/gui/admin/AdminScreen.h"
#include "app/gui/common/Forms.h"
#include "app/gui/services/RecordsService.h"

namespace armtrack::gui::admin {

namespace {
struct Programme {
  std::vector<storage::ProgrammeItem> items;
  std::vector<storage::Protocol> protocols;
};
}  // namespace

ProgrammePage::ProgrammePage(RecordsService& records, QWidget* parent)
    : AdminPage(records, parent),
      m_patientLabel(new QLabel(this)),
      m_patient(new QComboBox(this)),
      m_add(addButton()),
      m_edit(addButton()),
      m_remove(addButton()) {
  auto* row = new QHBoxLayout;
  row->addWidget(m_patientLabel);
  row->addWidget(m_patient, 1);
  static_cast<QVBoxLayout*>(layout())->insertLayout(0, row);
  m_patientLabel->setBuddy(m_patient);
  setTabOrder(m_patient, m_table);
  connect(m_patient, &QComboBox::currentIndexChanged, this, [this] { loadProgramme(); });
  connect(m_add, &QPushButton::clicked, this, &ProgrammePage::addExercise);
  connect(m_edit, &QPushButton::clicked, this, &ProgrammePage::editExercise);
  connect(m_remove, &QPushButton::clicked, this, &ProgrammePage::removeExercise);
  connect(m_table, &QTableWidget::cellActivated, this, &ProgrammePage::editExercise);
  retranslateUi();
  reload();
}

void ProgrammePage::retranslateUi() {
  m_patientLabel->setText(tr("Pa&tient:"));
  m_patient->setAccessibleName(tr("Patient"));
  m_table->setAccessibleName(tr("Home programme"));
  m_add->setText(tr("&Add exercise..."));
  m_edit->setText(tr("&Edit exercise..."));
  m_remove->setText(tr("Re&move exercise..."));
}

QString ProgrammePage::patientCode() const {
  return m_patient->currentData().toString();
}

bool ProgrammePage::selectPatient(const QString& code) {
  const int i = m_patient->findData(code);
  if (i < 0) return false;
  m_patient->setCurrentIndex(i);
  return true;
}

void ProgrammePage::reload() {
  m_records.call(
      this, [](storage::ClinicalStore& s) { return s.listPatients(); },
      [this](const std::vector<storage::Patient>& patients) {
        const QString keep = patientCode();
        const QSignalBlocker quiet(m_patient);
        m_patient->clear();
        for (const storage::Patient& p : patients)
          m_patient->addItem(tr("%1 - %2").arg(p.code, p.name), p.code);
        m_patient->setCurrentIndex(std::max(0, m_patient->findData(keep)));
        loadProgramme();
      },
      [this](const RecordsFailure& f) { failed(f.message); });
}

void ProgrammePage::loadProgramme(const QString& select) {
  const QString code = patientCode();
  if (code.isEmpty()) {
    m_items.clear();
    fill({}, {}, {});
    m_message->showMessage(tr("There are no patients yet: add them on the patient list first."),
                           MessageLine::Kind::Notice);
    emit loaded();
    return;
  }
  m_records.call(
      this,
      [code](storage::ClinicalStore& s) {
        return Programme{s.programme(code), s.listProtocols()};
      },
      [this, code, select](const Programme& p) {
        if (code != patientCode()) return;  // another patient was chosen meanwhile
        m_items = p.items;
        m_protocols = p.protocols;
        const QLocale locale;
        std::vector<QStringList> rows;
        for (const storage::ProgrammeItem& item : m_items) {
          storage::Protocol protocol;
          for (const storage::Protocol& candidate : m_protocols)
            if (candidate.name == item.protocolName) protocol = candidate;
          const auto [lo, hi] = storage::effectiveTarget(item, protocol);
          const std::optional<double> trunk = storage::effectiveTrunkLimit(item, protocol);
          rows.push_back(
              {item.protocolName,
               tr("%1 x %2").arg(item.sets).arg(storage::effectiveRepetitions(item, protocol)),
               tr("%1 to %2 deg").arg(locale.toString(lo, 'f', 0), locale.toString(hi, 'f', 0)),
               tr("%1 s").arg(locale.toString(item.restS, 'f', 0)),
               trunk ? tr("%1 deg").arg(locale.toString(*trunk, 'f', 0)) : tr("off"),
               locale.toString(item.sessionsPerWeek), item.notes});
        }
        fill({tr("Exercise"), tr("Sets x repetitions"), tr("Target"), tr("Rest"), tr("Trunk limit"),
              tr("Per week"), tr("Notes")},
             rows, select);
        emit loaded();
      },
      [this](const RecordsFailure& f) { failed(f.message); });
}

void ProgrammePage::addExercise() {
  if (patientCode().isEmpty()) return failed(tr("Choose a patient first."));
  openDialog(std::nullopt);
}

void ProgrammePage::editExercise() {
  const QString name = selectedKey();
  for (const storage::ProgrammeItem& item : m_items)
    if (item.protocolName == name) return openDialog(item);
  failed(tr("Choose the exercise to edit."));
}

void ProgrammePage::openDialog(const std::optional<storage::ProgrammeItem>& item) {
  // The protocols as they are now: one may have been added since the page was read.
  m_records.call(
      this, [](storage::ClinicalStore& s) { return s.listProtocols(); },
      [this, item](const std::vector<storage::Protocol>& protocols) {
        m_protocols = protocols;
        if (m_protocols.empty())
          return failed(tr("There is no protocol yet: add one on the Protocols page first."));
        auto* dialog = new ExerciseDialog(m_protocols, item, this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        const QString code = patientCode();
        connect(dialog, &FormDialog::submitted, this, [this, dialog, code] {
          const storage::ProgrammeItem chosen = dialog->item();
          m_records.call(
              dialog,
              [code, chosen](storage::ClinicalStore& s) { s.setProgrammeExercise(code, chosen); },
              [this, dialog, code, chosen] {
                dialog->accept();
                done(tr("%1 is in the home programme of %2.").arg(chosen.protocolName, code));
                loadProgramme(chosen.protocolName);
              },
              [dialog](const RecordsFailure& f) { dialog->showError(f.message); });
        });
        dialog->open();
      },
      [this](const RecordsFailure& f) { failed(f.message); });
}

void ProgrammePage::removeExercise() {
  const QString name = selectedKey(), code = patientCode();
  if (name.isEmpty()) return failed(tr("Choose the exercise to remove."));
  confirm(tr("Remove exercise"),
          tr("Remove %1 from the home programme of %2? The sessions already done stay.")
              .arg(name, code),
          [this, name, code] {
            m_records.call(
                this, [name, code](storage::ClinicalStore& s) { s.unassignProtocol(code, name); },
                [this, name] {
                  done(tr("%1 removed from the programme.").arg(name));
                  loadProgramme();
                },
                [this](const RecordsFailure& f) { failed(f.message); });
          });
}

}  // namespace armtrack::gui::admin
