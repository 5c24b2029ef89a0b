#include "app/gui/admin/AdminDialogs.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "app/gui/common/AngleNames.h"
#include "app/gui/common/Forms.h"
#include "core/storage/TextRules.h"

namespace armtrack::gui::admin {

namespace {

constexpr int kAngles = 5;  // clinicalAngleInfo()

QLineEdit* passwordEdit(QWidget* parent, const QString& name) {
  auto* edit = new QLineEdit(parent);
  edit->setEchoMode(QLineEdit::Password);
  edit->setAccessibleName(name);
  return edit;
}

QDoubleSpinBox* degreesBox(QWidget* parent, const QString& name, double value) {
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(-180, 180);
  box->setDecimals(0);
  box->setSuffix(FormDialog::tr(" deg"));
  box->setValue(value);
  box->setAccessibleName(name);
  return box;
}

/// A trunk limit in whole degrees, 1-90; 0 shows offText (no limit of its own).
QDoubleSpinBox* trunkLimitBox(QWidget* parent, std::optional<double> value) {
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(0, storage::kMaxTrunkLimitDeg);
  box->setDecimals(0);
  box->setSuffix(FormDialog::tr(" deg"));
  box->setValue(value.value_or(0));
  box->setAccessibleName(FormDialog::tr("Trunk limit"));
  box->setToolTip(
      FormDialog::tr("Degrees of trunk flexion: leaning further, the patient is told \"Keep your "
                     "back against the chair\" and the repetition counts as made with "
                     "compensation. Needs a trunk sensor."));
  return box;
}

std::optional<double> trunkLimitOf(const QDoubleSpinBox* box) {
  return box->value() > 0 ? std::optional(box->value()) : std::nullopt;
}

/// What is wrong with a new password typed twice (empty: nothing).
QString passwordProblem(const QLineEdit* password, const QLineEdit* repeat, QWidget** focus) {
  if (password->text().size() < storage::kMinPasswordLength) {
    *focus = const_cast<QLineEdit*>(password);
    return FormDialog::tr("Choose a password of at least %1 characters.")
        .arg(storage::kMinPasswordLength);
  }
  if (password->text() != repeat->text()) {
    *focus = const_cast<QLineEdit*>(repeat);
    return FormDialog::tr("The two passwords differ: type the same password twice.");
  }
  return {};
}

}  // namespace

QString roleText(storage::Role role) {
  switch (role) {
    case storage::Role::Admin:
      return FormDialog::tr("administrator");
    case storage::Role::Therapist:
      return FormDialog::tr("therapist");
    case storage::Role::Home:
      return FormDialog::tr("home account");
  }
  return storage::roleName(role);
}

FormDialog::FormDialog(QWidget* parent)
    : QDialog(parent),
      m_form(new QFormLayout),
      m_message(new MessageLine(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this)) {
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(m_form);
  layout->addWidget(m_message);
  layout->addWidget(m_buttons);
  m_buttons->button(QDialogButtonBox::Save)->setText(tr("&Save"));
  m_buttons->button(QDialogButtonBox::Cancel)->setText(tr("Cancel"));
  m_buttons->button(QDialogButtonBox::Save)->setDefault(true);
  connect(m_buttons, &QDialogButtonBox::accepted, this, &FormDialog::submit);
  connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

void FormDialog::finish() {
  for (int row = 0; row < m_form->rowCount(); ++row)
    if (QLayoutItem* item = m_form->itemAt(row, QFormLayout::FieldRole))
      if (QWidget* w = item->widget(); w && w->isEnabled() && (w->focusPolicy() & Qt::TabFocus)) {
        w->setFocus();
        break;
      }
}

void FormDialog::submit() {
  QWidget* focus = nullptr;
  if (const QString problem = check(&focus); !problem.isEmpty()) {
    m_message->showMessage(problem);
    if (focus) focus->setFocus();
    return;
  }
  m_message->showMessage(tr("Saving..."), MessageLine::Kind::Notice);
  m_buttons->setEnabled(false);
  emit submitted();
}

void FormDialog::showError(const QString& message) {
  m_buttons->setEnabled(true);
  m_message->showMessage(message);
}

AccountDialog::AccountDialog(const std::vector<storage::Patient>& patients, QWidget* parent)
    : FormDialog(parent),
      m_name(new QLineEdit(this)),
      m_role(new QComboBox(this)),
      m_patient(new QComboBox(this)),
      m_password(passwordEdit(this, tr("Password"))),
      m_repeat(passwordEdit(this, tr("Password again"))) {
  setWindowTitle(tr("New account"));
  m_name->setAccessibleName(tr("Account name"));
  m_role->setAccessibleName(tr("Role"));
  for (const storage::Role r :
       {storage::Role::Therapist, storage::Role::Admin, storage::Role::Home})
    m_role->addItem(roleText(r), static_cast<int>(r));
  m_patient->setAccessibleName(tr("Patient of the home account"));
  for (const storage::Patient& p : patients)
    m_patient->addItem(tr("%1 - %2").arg(p.code, p.name), p.code);
  const auto home = [this] { return role() == storage::Role::Home; };
  m_patient->setEnabled(home());
  connect(m_role, &QComboBox::currentIndexChanged, this,
          [this, home] { m_patient->setEnabled(home()); });
  form()->addRow(tr("&Name:"), m_name);
  form()->addRow(tr("&Role:"), m_role);
  form()->addRow(tr("Pa&tient (home account):"), m_patient);
  form()->addRow(tr("&Password:"), m_password);
  form()->addRow(tr("Password &again:"), m_repeat);
  finish();
}

QString AccountDialog::name() const {
  return m_name->text().trimmed();
}
storage::Role AccountDialog::role() const {
  return static_cast<storage::Role>(m_role->currentData().toInt());
}
QString AccountDialog::patientCode() const {
  return role() == storage::Role::Home ? m_patient->currentData().toString() : QString();
}
QString AccountDialog::password() const {
  return m_password->text();
}

QString AccountDialog::check(QWidget** focus) const {
  if (name().isEmpty()) {
    *focus = m_name;
    return tr("Give the account a name, e.g. the person's first name and initial.");
  }
  if (role() == storage::Role::Home && patientCode().isEmpty()) {
    *focus = m_patient;
    return tr("A home account belongs to one patient: add the patient first, then choose them.");
  }
  return passwordProblem(m_password, m_repeat, focus);
}

PasswordDialog::PasswordDialog(const QString& account, QWidget* parent)
    : FormDialog(parent),
      m_password(passwordEdit(this, tr("New password"))),
      m_repeat(passwordEdit(this, tr("New password again"))) {
  setWindowTitle(tr("New password for %1").arg(account));
  form()->addRow(tr("&New password:"), m_password);
  form()->addRow(tr("Password &again:"), m_repeat);
  finish();
}

QString PasswordDialog::password() const {
  return m_password->text();
}

QString PasswordDialog::check(QWidget** focus) const {
  return passwordProblem(m_password, m_repeat, focus);
}

ProtocolDialog::ProtocolDialog(const storage::Protocol& protocol, QWidget* parent)
    : FormDialog(parent),
      m_original(protocol),
      m_name(new QLineEdit(protocol.name, this)),
      m_angle(new QComboBox(this)),
      m_min(degreesBox(this, tr("Target from"), protocol.targetMinDeg)),
      m_max(degreesBox(this, tr("Target to"), protocol.targetMaxDeg)),
      m_reps(new QSpinBox(this)),
      m_side(new QComboBox(this)),
      m_trunk(trunkLimitBox(this, protocol.trunkLimitDeg)) {
  const bool adding = protocol.name.isEmpty();
  setWindowTitle(adding ? tr("New protocol") : tr("Edit protocol %1").arg(protocol.name));
  m_name->setReadOnly(!adding);
  m_name->setAccessibleName(tr("Protocol name"));
  m_angle->setAccessibleName(tr("Angle"));
  for (int i = 0; i < kAngles; ++i) m_angle->addItem(angleName(i), angleKey(i));
  m_angle->setCurrentIndex(std::max(0, m_angle->findData(protocol.angleKey)));
  m_reps->setRange(0, 1000);
  m_reps->setValue(protocol.repetitions);
  m_reps->setAccessibleName(tr("Repetitions"));
  m_side->setAccessibleName(tr("Side"));
  m_side->addItem(tr("either arm"), QStringLiteral("either"));
  m_side->addItem(tr("left arm"), QStringLiteral("left"));
  m_side->addItem(tr("right arm"), QStringLiteral("right"));
  m_side->setCurrentIndex(std::max(0, m_side->findData(protocol.side)));
  form()->addRow(tr("&Name:"), m_name);
  form()->addRow(tr("&Angle:"), m_angle);
  form()->addRow(tr("Target &from:"), m_min);
  form()->addRow(tr("Target &to:"), m_max);
  form()->addRow(tr("&Repetitions:"), m_reps);
  form()->addRow(tr("&Side:"), m_side);
  m_trunk->setSpecialValueText(tr("Off"));
  form()->addRow(tr("Tr&unk limit:"), m_trunk);
  finish();
}

storage::Protocol ProtocolDialog::protocol() const {
  storage::Protocol p = m_original;
  p.name = m_name->text().trimmed();
  p.angleKey = m_angle->currentData().toString();
  p.targetMinDeg = m_min->value();
  p.targetMaxDeg = m_max->value();
  p.repetitions = m_reps->value();
  p.side = m_side->currentData().toString();
  p.trunkLimitDeg = trunkLimitOf(m_trunk);
  return p;
}

QString ProtocolDialog::check(QWidget** focus) const {
  if (m_name->text().trimmed().isEmpty()) {
    *focus = m_name;
    return tr("Give the protocol a name, e.g. \"Shoulder flexion to 120\".");
  }
  if (m_min->value() > m_max->value()) {
    *focus = m_max;
    return tr("The target ends below where it starts: make \"to\" at least \"from\".");
  }
  return {};
}

ExerciseDialog::ExerciseDialog(const std::vector<storage::Protocol>& protocols,
                               const std::optional<storage::ProgrammeItem>& item, QWidget* parent)
    : FormDialog(parent),
      m_protocols(protocols),
      m_original(item.value_or(storage::ProgrammeItem{})),
      m_protocol(new QComboBox(this)),
      m_sets(new QSpinBox(this)),
      m_reps(new QSpinBox(this)),
      m_ownTarget(new QCheckBox(tr("Its own &target range"), this)),
      m_min(degreesBox(this, tr("Target from"), m_original.targetMinDeg.value_or(0))),
      m_max(degreesBox(this, tr("Target to"), m_original.targetMaxDeg.value_or(0))),
      m_rest(new QDoubleSpinBox(this)),
      m_perWeek(new QSpinBox(this)),
      m_notes(new QLineEdit(m_original.notes, this)),
      m_trunk(trunkLimitBox(this, m_original.trunkLimitDeg)) {
  setWindowTitle(item ? tr("Edit exercise %1").arg(item->protocolName) : tr("New exercise"));
  m_protocol->setAccessibleName(tr("Protocol"));
  for (const storage::Protocol& p : protocols) m_protocol->addItem(p.name, p.name);
  if (item) {
    m_protocol->setCurrentIndex(std::max(0, m_protocol->findData(item->protocolName)));
    m_protocol->setEnabled(false);
  }
  m_sets->setRange(1, 20);
  m_sets->setValue(m_original.sets);
  m_sets->setAccessibleName(tr("Sets"));
  m_reps->setRange(0, 200);
  m_reps->setValue(m_original.repetitions.value_or(0));
  m_reps->setAccessibleName(tr("Repetitions per set"));
  m_ownTarget->setChecked(m_original.targetMinDeg.has_value());
  m_rest->setRange(0, 3600);
  m_rest->setDecimals(0);
  m_rest->setSuffix(tr(" s"));
  m_rest->setValue(m_original.restS);
  m_rest->setAccessibleName(tr("Rest between sets"));
  m_perWeek->setRange(0, 21);
  m_perWeek->setValue(m_original.sessionsPerWeek);
  m_perWeek->setAccessibleName(tr("Sessions per week"));
  m_notes->setAccessibleName(tr("Notes for the patient"));
  form()->addRow(tr("&Protocol:"), m_protocol);
  form()->addRow(tr("S&ets:"), m_sets);
  form()->addRow(tr("&Repetitions per set:"), m_reps);
  form()->addRow(QString(), m_ownTarget);
  form()->addRow(tr("Target &from:"), m_min);
  form()->addRow(tr("Target &to:"), m_max);
  form()->addRow(tr("Tr&unk limit:"), m_trunk);
  form()->addRow(tr("Re&st between sets:"), m_rest);
  form()->addRow(tr("Sessions per &week:"), m_perWeek);
  form()->addRow(tr("&Notes:"), m_notes);
  connect(m_protocol, &QComboBox::currentIndexChanged, this, &ExerciseDialog::showProtocolValues);
  connect(m_ownTarget, &QCheckBox::toggled, this, &ExerciseDialog::showProtocolValues);
  showProtocolValues();
  finish();
}

void ExerciseDialog::showProtocolValues() {
  const int i = m_protocol->currentIndex();
  const storage::Protocol* p =
      i >= 0 && i < static_cast<int>(m_protocols.size()) ? &m_protocols[i] : nullptr;
  m_reps->setSpecialValueText(p ? tr("the protocol's (%1)").arg(p->repetitions)
                                : tr("the protocol's"));
  m_trunk->setSpecialValueText(
      !p ? tr("the protocol's")
      : p->trunkLimitDeg
          ? tr("the protocol's (%1 deg)").arg(QLocale().toString(*p->trunkLimitDeg, 'f', 0))
          : tr("the protocol's (off)"));
  m_min->setEnabled(m_ownTarget->isChecked());
  m_max->setEnabled(m_ownTarget->isChecked());
  if (!m_ownTarget->isChecked() && p) {
    m_min->setValue(p->targetMinDeg);
    m_max->setValue(p->targetMaxDeg);
  }
}

storage::ProgrammeItem ExerciseDialog::item() const {
  storage::ProgrammeItem item = m_original;
  item.protocolName = m_protocol->currentData().toString();
  item.sets = m_sets->value();
  item.repetitions = m_reps->value() > 0 ? std::optional(m_reps->value()) : std::nullopt;
  item.targetMinDeg = m_ownTarget->isChecked() ? std::optional(m_min->value()) : std::nullopt;
  item.targetMaxDeg = m_ownTarget->isChecked() ? std::optional(m_max->value()) : std::nullopt;
  item.restS = m_rest->value();
  item.sessionsPerWeek = m_perWeek->value();
  item.notes = m_notes->text().trimmed();
  item.trunkLimitDeg = trunkLimitOf(m_trunk);
  return item;
}

QString ExerciseDialog::check(QWidget** focus) const {
  if (m_protocol->currentIndex() < 0) {
    *focus = m_protocol;
    return tr("There is no protocol yet: add one on the Protocols page first.");
  }
  if (m_ownTarget->isChecked() && m_min->value() > m_max->value()) {
    *focus = m_max;
    return tr("The target ends below where it starts: make \"to\" at least \"from\".");
  }
  return {};
}

}  // namespace armtrack::gui::admin
