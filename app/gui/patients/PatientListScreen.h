// The patients: a searchable table (code, name, birth date, sex, side, diagnosis), add and edit.
#pragma once

#include <QWidget>

#include "core/storage/Records.h"

class QLabel;
class QLineEdit;
class QPushButton;
class QSortFilterProxyModel;
class QTableView;

namespace armtrack::gui {

class MessageLine;
class PatientTableModel;
class RecordsService;

class PatientListScreen : public QWidget {
  Q_OBJECT
 public:
  /// select: the patient to select once the list is read.
  explicit PatientListScreen(RecordsService& records, const QString& select = {},
                             QWidget* parent = nullptr);

  /// Reads the list again, then selects the patient with that code (if any).
  void reload(const QString& select = {});
  /// The code of the selected patient, or "".
  QString selectedCode() const;
  /// Opens the dialog for a new patient.
  void addPatient();
  /// Opens the dialog for the selected patient.
  void editPatient();

 signals:
  void openRequested(const QString& code);
  /// A list was shown (after every reload), with how many patients.
  void loaded(int patients);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  void openSelected();
  void updateButtons();
  void saveFromDialog(class PatientDialog* dialog, const storage::Patient& p, bool adding);

  RecordsService& m_records;
  QLabel* m_heading;
  QLabel* m_searchLabel;
  PatientTableModel* m_model;
  QSortFilterProxyModel* m_proxy;
  QLineEdit* m_search;
  QTableView* m_table;
  QPushButton* m_open;
  QPushButton* m_add;
  QPushButton* m_edit;
  MessageLine* m_message;
  bool m_canWrite = true;
};

}  // namespace armtrack::gui
