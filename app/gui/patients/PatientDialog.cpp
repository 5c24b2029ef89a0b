#include "app/gui/patients/PatientDialog.h"

#include <QComboBox>
#include <QDateEdit>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLineEdit>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "app/gui/common/Forms.h"
#include "app/gui/patients/PatientTableModel.h"
#include "app/gui/services/PatientRecords.h"
#include "core/reports/ReportText.h"

namespace armtrack::gui {

namespace {

const QDate kUnknownDate(1899, 12, 31);  // the date edit's "not given"

/// A length in cm; 0 means "not measured".
QDoubleSpinBox* lengthBox(QWidget* parent, const QString& name, std::optional<double> metres) {
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(0, 80);
  box->setDecimals(1);
  box->setSingleStep(0.5);
  box->setSuffix(PatientDialog::tr(" cm"));
  box->setSpecialValueText(PatientDialog::tr("not measured"));
  box->setValue(metres ? *metres * 100 : 0);
  box->setAccessibleName(name);
  return box;
}

std::optional<double> metresOf(const QDoubleSpinBox* box) {
  return box->value() > 0 ? std::optional(box->value() / 100) : std::nullopt;
}

void fillCombo(QComboBox* box, const QStringList& keys, const QString& current,
               const std::function<QString(const QString&)>& text) {
  for (const QString& k : keys)
    box->addItem(k.isEmpty() ? PatientDialog::tr("not given") : text(k), k);
  const int i = box->findData(current);
  box->setCurrentIndex(i >= 0 ? i : 0);
}

}  // namespace

PatientDialog::PatientDialog(const storage::Patient& patient, QWidget* parent)
    : QDialog(parent),
      m_original(patient),
      m_code(new QLineEdit(patient.code, this)),
      m_name(new QLineEdit(patient.name, this)),
      m_birth(new QDateEdit(this)),
      m_sex(new QComboBox(this)),
      m_side(new QComboBox(this)),
      m_diagnosis(new QLineEdit(patient.diagnosis, this)),
      m_notes(new QPlainTextEdit(patient.notes, this)),
      m_message(new MessageLine(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this)) {
  const bool adding = patient.code.isEmpty();
  setWindowTitle(adding ? tr("New patient") : tr("Edit patient %1").arg(patient.code));
  const SegmentLengths lengths = SegmentLengths::fromJson(patient.segmentLengthsJson);
  m_upperArm = lengthBox(this, tr("Upper arm length"), lengths.upperArmM);
  m_forearm = lengthBox(this, tr("Forearm length"), lengths.forearmM);
  m_upperStrap =
      lengthBox(this, tr("Upper-arm IMU distance from the shoulder"), lengths.upperStrapM);
  m_forearmStrap =
      lengthBox(this, tr("Forearm IMU distance from the elbow"), lengths.forearmStrapM);

  m_code->setReadOnly(!adding);
  m_code->setAccessibleName(tr("Patient code"));
  m_code->setPlaceholderText(tr("e.g. P001"));
  m_name->setAccessibleName(tr("Patient name"));
  m_birth->setAccessibleName(tr("Birth date"));
  m_birth->setDisplayFormat(reports::fullYearDateFormat(QLocale()));
  m_birth->setMinimumDate(kUnknownDate);
  m_birth->setMaximumDate(QDate::currentDate());
  m_birth->setSpecialValueText(tr("not given"));
  const QDate born = QDate::fromString(patient.birthDate, Qt::ISODate);
  m_birth->setDate(born.isValid() ? born : kUnknownDate);
  m_sex->setAccessibleName(tr("Sex"));
  fillCombo(m_sex, {QString(), QStringLiteral("f"), QStringLiteral("m"), QStringLiteral("x")},
            patient.sex, &PatientTableModel::sexText);
  m_side->setAccessibleName(tr("Affected side"));
  fillCombo(m_side,
            {QString(), QStringLiteral("left"), QStringLiteral("right"), QStringLiteral("both"),
             QStringLiteral("none")},
            patient.affectedSide, &PatientTableModel::sideText);
  m_diagnosis->setAccessibleName(tr("Diagnosis"));
  m_notes->setAccessibleName(tr("Notes"));
  m_notes->setTabChangesFocus(true);

  auto* layout = new QVBoxLayout(this);
  auto* who = new QGroupBox(tr("Patient"), this);
  auto* form = new QFormLayout(who);
  form->addRow(tr("&Code:"), m_code);
  form->addRow(tr("&Name:"), m_name);
  form->addRow(tr("&Born:"), m_birth);
  form->addRow(tr("&Sex:"), m_sex);
  form->addRow(tr("Affected &side:"), m_side);
  form->addRow(tr("&Diagnosis:"), m_diagnosis);
  layout->addWidget(who);
  auto* measured = new QGroupBox(tr("Measured segment lengths"), this);
  auto* lengthsForm = new QFormLayout(measured);
  lengthsForm->addRow(tr("&Upper arm (shoulder to elbow):"), m_upperArm);
  lengthsForm->addRow(tr("&Forearm (elbow to wrist):"), m_forearm);
  lengthsForm->addRow(tr("Upper-arm IMU from the shoulder:"), m_upperStrap);
  lengthsForm->addRow(tr("Forearm IMU from the elbow:"), m_forearmStrap);
  layout->addWidget(measured);
  auto* notesBox = new QGroupBox(tr("N&otes"), this);
  (new QVBoxLayout(notesBox))->addWidget(m_notes);
  layout->addWidget(notesBox);
  layout->addWidget(m_message);
  layout->addWidget(m_buttons);
  m_buttons->button(QDialogButtonBox::Save)->setDefault(true);
  connect(m_buttons, &QDialogButtonBox::accepted, this, &PatientDialog::submit);
  connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  (adding ? static_cast<QWidget*>(m_code) : m_name)->setFocus();
}

storage::Patient PatientDialog::patient() const {
  storage::Patient p = m_original;
  p.code = m_code->text().trimmed();
  p.name = m_name->text().trimmed();
  p.birthDate = m_birth->date() == kUnknownDate ? QString() : m_birth->date().toString(Qt::ISODate);
  p.sex = m_sex->currentData().toString();
  p.affectedSide = m_side->currentData().toString();
  p.diagnosis = m_diagnosis->text().trimmed();
  SegmentLengths lengths = SegmentLengths::fromJson(m_original.segmentLengthsJson);
  lengths.upperArmM = metresOf(m_upperArm);
  lengths.forearmM = metresOf(m_forearm);
  lengths.upperStrapM = metresOf(m_upperStrap);
  lengths.forearmStrapM = metresOf(m_forearmStrap);
  p.segmentLengthsJson = lengths.toJson();
  p.notes = m_notes->toPlainText();
  return p;
}

QWidget* PatientDialog::fieldNamed(const QString& field) const {
  if (field == QLatin1String("code")) return m_code;
  if (field == QLatin1String("name")) return m_name;
  if (field == QLatin1String("birthDate")) return m_birth;
  if (field == QLatin1String("upperArm")) return m_upperArm;
  if (field == QLatin1String("forearm")) return m_forearm;
  if (field == QLatin1String("upperStrap")) return m_upperStrap;
  if (field == QLatin1String("forearmStrap")) return m_forearmStrap;
  return nullptr;
}

void PatientDialog::submit() {
  const storage::Patient p = patient();
  QString field;
  const QString problem = patientProblem(p, QDate::currentDate(), &field);
  if (!problem.isEmpty()) {
    m_message->showMessage(problem);
    if (QWidget* w = fieldNamed(field)) w->setFocus();
    return;
  }
  m_message->showMessage(tr("Saving..."), MessageLine::Kind::Notice);
  m_buttons->setEnabled(false);
  emit saveRequested(p);
}

void PatientDialog::showError(const QString& message, const QString& field) {
  m_buttons->setEnabled(true);
  m_message->showMessage(message);
  if (QWidget* w = fieldNamed(field)) w->setFocus();
}

}  // namespace armtrack::gui
