// The administrator's forms: an account, a new password, a protocol, an exercise of a home
// programme. Each checks what it can in words before it is sent; the records check the rest with
// the same rules as the command line (core/storage), and a refusal keeps the dialog open with
// everything typed.
#pragma once

#include <QDialog>
#include <vector>

#include "core/storage/Records.h"

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QFormLayout;
class QLineEdit;
class QSpinBox;

namespace armtrack::gui {
class MessageLine;
}

namespace armtrack::gui::admin {

/// An account's role in words.
QString roleText(storage::Role role);

/// A form with a message line and Save/Cancel. Save runs check(); when it passes, submitted()
/// asks the screen to store the values, which then calls accept() or showError().
class FormDialog : public QDialog {
  Q_OBJECT
 public:
  explicit FormDialog(QWidget* parent);
  /// The store refused: says why and makes the form usable again.
  void showError(const QString& message);

 signals:
  void submitted();

 protected:
  /// What is wrong with the form in words (empty: nothing); *focus: the field to mend.
  virtual QString check(QWidget** focus) const = 0;
  QFormLayout* form() const { return m_form; }
  /// Call at the end of the subclass's constructor.
  void finish();

 private:
  void submit();

  QFormLayout* m_form;
  MessageLine* m_message;
  QDialogButtonBox* m_buttons;
};

/// A new account: name, role, the patient of a home account, the password twice.
class AccountDialog : public FormDialog {
  Q_OBJECT
 public:
  AccountDialog(const std::vector<storage::Patient>& patients, QWidget* parent);
  QString name() const;
  storage::Role role() const;
  QString patientCode() const;  ///< home accounts only
  QString password() const;

 protected:
  QString check(QWidget** focus) const override;

 private:
  QLineEdit* m_name;
  QComboBox* m_role;
  QComboBox* m_patient;
  QLineEdit* m_password;
  QLineEdit* m_repeat;
};

/// A new password for an account, typed twice.
class PasswordDialog : public FormDialog {
  Q_OBJECT
 public:
  PasswordDialog(const QString& account, QWidget* parent);
  QString password() const;

 protected:
  QString check(QWidget** focus) const override;

 private:
  QLineEdit* m_password;
  QLineEdit* m_repeat;
};

/// A protocol: a new one, or an existing one (its name stays).
class ProtocolDialog : public FormDialog {
  Q_OBJECT
 public:
  ProtocolDialog(const storage::Protocol& protocol, QWidget* parent);
  storage::Protocol protocol() const;

 protected:
  QString check(QWidget** focus) const override;

 private:
  storage::Protocol m_original;
  QLineEdit* m_name;
  QComboBox* m_angle;
  QDoubleSpinBox* m_min;
  QDoubleSpinBox* m_max;
  QSpinBox* m_reps;
  QComboBox* m_side;
  QDoubleSpinBox* m_trunk;  ///< 0: off
};

/// An exercise of a home programme: a new one (any protocol) or an existing one (its protocol
/// stays).
class ExerciseDialog : public FormDialog {
  Q_OBJECT
 public:
  ExerciseDialog(const std::vector<storage::Protocol>& protocols,
                 const std::optional<storage::ProgrammeItem>& item, QWidget* parent);
  storage::ProgrammeItem item() const;

 protected:
  QString check(QWidget** focus) const override;

 private:
  void showProtocolValues();

  std::vector<storage::Protocol> m_protocols;
  storage::ProgrammeItem m_original;
  QComboBox* m_protocol;
  QSpinBox* m_sets;
  QSpinBox* m_reps;
  QCheckBox* m_ownTarget;
  QDoubleSpinBox* m_min;
  QDoubleSpinBox* m_max;
  QDoubleSpinBox* m_rest;
  QSpinBox* m_perWeek;
  QLineEdit* m_notes;
  QDoubleSpinBox* m_trunk;  ///< 0: the protocol's
};

}  // namespace armtrack::gui::admin
