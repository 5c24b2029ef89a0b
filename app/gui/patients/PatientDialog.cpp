#include "app/gui/patients/PatientDialog.h"

#include <QComboBox>
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
#include "app/gui/patients/BirthDateField.h"
#include "app/gui/patients/PatientTableModel.h"
#include "app/gui/services/PatientRecords.h"
#include "core/reports/ReportText.h"

namespace armtrack::gui {

namespace {

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
      m_birth(new BirthDateField(this)),
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
  m_birth->setDate(QDate::fromString(patient.birthDate, Qt::ISODate));
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
  // Tab goes down the screen: the patient, the lengths, the notes, the buttons.
  QWidget* order[] = {m_code,
                      m_name,
                      m_birth->lineEdit(),
                      m_sex,
                      m_side,
                      m_diagnosis,
                      m_upperArm,
                      m_forearm,
                      m_upperStrap,
                      m_forearmStrap,
                      m_notes,
                      m_buttons->button(QDialogButtonBox::Save),
                      m_buttons->button(QDialogButtonBox::Cancel)};
  for (std::size_t i = 1; i < std::size(order); ++i) setTabOrder(order[i - 1], order[i]);
  for (auto* edit : {m_code, m_name, m_diagnosis, m_birth->lineEdit()})
    connect(edit, &QLineEdit::textChanged, this, &PatientDialog::recheck);
  for (auto* box : {m_upperArm, m_forearm, m_upperStrap, m_forearmStrap})
    connect(box, &QDoubleSpinBox::valueChanged, this, &PatientDialog::recheck);
  (adding ? static_cast<QWidget*>(m_code) : m_name)->setFocus();
}

storage::Patient PatientDialog::patient() const {
  storage::Patient p = m_original;
  p.code = m_code->text().trimmed();
  p.name = m_name->text().trimmed();
  // A text that is not a date is passed on as typed, so that no check takes it for "not given".
  p.birthDate = m_birth->isEmpty()          ? QString()
                : m_birth->date().isValid() ? m_birth->date().toString(Qt::ISODate)
                                            : m_birth->text().trimmed();
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
  if (field == QLatin1String("birthDate")) return m_birth->lineEdit();
  if (field == QLatin1String("upperArm")) return m_upperArm;
  if (field == QLatin1String("forearm")) return m_forearm;
  if (field == QLatin1String("upperStrap")) return m_upperStrap;
  if (field == QLatin1String("forearmStrap")) return m_forearmStrap;
  return nullptr;
}

QString PatientDialog::problem(QString* field) const {
  const QDate today = QDate::currentDate();
  const storage::Patient p = patient();
  // The code and name first, as the form shows them; then the birth date in the words of the
  // field that was typed into.
  QString found = patientProblem(p, today, field);
  if (!found.isEmpty() && (*field == QLatin1String("code") || *field == QLatin1String("name")))
    return found;
  if (const QString born = m_birth->problem(today); !born.isEmpty()) {
    *field = QStringLiteral("birthDate");
    return born;
  }
  return found;
}

void PatientDialog::recheck() {
  if (m_problemField.isEmpty()) return;
  // The records' answer (a code taken) goes when its field is edited; the form's own checks when
  // they pass.
  if (!m_problemLocal && sender() != fieldNamed(m_problemField) &&
      !(m_problemField == QLatin1String("birthDate") && sender() == m_birth->lineEdit()))
    return;
  QString field;
  const QString now = problem(&field);
  if (now.isEmpty() || field != m_problemField) {
    m_problemField.clear();
    m_message->clear();
  }
}

void PatientDialog::submit() {
  QString field;
  const QString found = problem(&field);
  if (!found.isEmpty()) {
    m_problemField = field;
    m_problemLocal = true;
    m_message->showMessage(found);
    if (QWidget* w = fieldNamed(field)) w->setFocus();
    return;
  }
  m_problemField.clear();
  m_message->showMessage(tr("Saving..."), MessageLine::Kind::Notice);
  m_buttons->setEnabled(false);
  emit saveRequested(patient());
}

void PatientDialog::showError(const QString& message, const QString& field) {
  m_buttons->setEnabled(true);
  m_problemField = field;  // goes once that field is edited
  m_problemLocal = false;
  m_message->showMessage(message);
  if (QWidget* w = fieldNamed(field)) w->setFocus();
}

}  // namespace armtrack::gui
