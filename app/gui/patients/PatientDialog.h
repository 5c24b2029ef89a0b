// Add or edit a patient: code, name, birth date, sex, affected side, diagnosis, the measured
// segment lengths and notes. Checks the form in words before saving; a failed save keeps the
// dialog open with everything typed.
#pragma once

#include <QDialog>

#include "core/storage/Records.h"

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLineEdit;
class QPlainTextEdit;

namespace armtrack::gui {

class BirthDateField;
class MessageLine;

class PatientDialog : public QDialog {
  Q_OBJECT
 public:
  /// An empty patient (no code) adds one; otherwise edits it (the code stays as it is).
  explicit PatientDialog(const storage::Patient& patient, QWidget* parent = nullptr);

  /// The patient as the form holds it.
  storage::Patient patient() const;
  /// The save failed: says why, re-enables the form, puts the focus on field (as
  /// patientProblem() names them) when given.
  void showError(const QString& message, const QString& field = {});

 signals:
  /// The form is valid; save it, then call accept() (or showError()).
  void saveRequested(const storage::Patient& patient);

 private:
  void submit();
  /// The form's first problem in words (empty: none), *field naming its field.
  QString problem(QString* field) const;
  /// After an edit: a shown problem that is mended goes away.
  void recheck();
  QWidget* fieldNamed(const QString& field) const;

  storage::Patient m_original;
  QLineEdit* m_code;
  QLineEdit* m_name;
  BirthDateField* m_birth;
  QComboBox* m_sex;
  QComboBox* m_side;
  QLineEdit* m_diagnosis;
  QDoubleSpinBox* m_upperArm;
  QDoubleSpinBox* m_forearm;
  QDoubleSpinBox* m_upperStrap;
  QDoubleSpinBox* m_forearmStrap;
  QPlainTextEdit* m_notes;
  MessageLine* m_message;
  QDialogButtonBox* m_buttons;
  QString m_problemField;       ///< the field the shown problem is about
  bool m_problemLocal = false;  ///< found by the form (not the records)
};

}  // namespace armtrack::gui
