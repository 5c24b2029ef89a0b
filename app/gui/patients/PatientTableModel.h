// The patients as a table for the list screen (QSortFilterProxyModel searches it).
#pragma once

#include <QAbstractTableModel>
#include <vector>

#include "core/storage/Records.h"

namespace armtrack::gui {

class PatientTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Code, Name, BirthDate, Sex, Side, Diagnosis, ColumnCount };
  /// Qt::UserRole on any column gives the patient's code.
  static constexpr int CodeRole = Qt::UserRole;

  using QAbstractTableModel::QAbstractTableModel;
  void setPatients(std::vector<storage::Patient> patients);
  const storage::Patient* patientAt(int row) const;
  /// The row of the patient with that code, or -1.
  int rowOf(const QString& code) const;

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation,
                      int role = Qt::DisplayRole) const override;
  /// A LanguageChange (passed on by the owning widget) refreshes the views' words.
  bool event(QEvent* event) override;

  /// "f", "m", "x" and sides as words for the user.
  static QString sexText(const QString& sex);
  static QString sideText(const QString& side);

 private:
  std::vector<storage::Patient> m_patients;
};

}  // namespace armtrack::gui
