#include "app/gui/patients/PatientTableModel.h"

#include <QDate>
#include <QLocale>

#include "ui/Retranslate.h"

namespace armtrack::gui {

void PatientTableModel::setPatients(std::vector<storage::Patient> patients) {
  beginResetModel();
  m_patients = std::move(patients);
  endResetModel();
}

const storage::Patient* PatientTableModel::patientAt(int row) const {
  return row >= 0 && row < static_cast<int>(m_patients.size()) ? &m_patients[row] : nullptr;
}

int PatientTableModel::rowOf(const QString& code) const {
  for (std::size_t i = 0; i < m_patients.size(); ++i)
    if (m_patients[i].code == code) return static_cast<int>(i);
  return -1;
}

int PatientTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(m_patients.size());
}

int PatientTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QString PatientTableModel::sexText(const QString& sex) {
  if (sex == QLatin1String("f")) return tr("female");
  if (sex == QLatin1String("m")) return tr("male");
  if (sex == QLatin1String("x")) return tr("diverse");
  return {};
}

QString PatientTableModel::sideText(const QString& side) {
  if (side == QLatin1String("left")) return tr("left");
  if (side == QLatin1String("right")) return tr("right");
  if (side == QLatin1String("both")) return tr("both");
  if (side == QLatin1String("none")) return tr("none");
  return side;
}

QVariant PatientTableModel::data(const QModelIndex& index, int role) const {
  const storage::Patient* p = patientAt(index.row());
  if (!p) return {};
  if (role == CodeRole) return p->code;
  if (role == Qt::DisplayRole || role == Qt::AccessibleTextRole) {
    switch (index.column()) {
      case Code:
        return p->code;
      case Name:
        return p->name;
      case BirthDate: {
        const QDate d = QDate::fromString(p->birthDate, Qt::ISODate);
        return d.isValid() ? QLocale().toString(d, QLocale::ShortFormat) : p->birthDate;
      }
      case Sex:
        return sexText(p->sex);
      case Side:
        return sideText(p->affectedSide);
      case Diagnosis:
        return p->diagnosis;
      default:
        return {};
    }
  }
  // Sorting by birth date sorts the ISO text, not the locale's.
  if (role == Qt::EditRole && index.column() == BirthDate) return p->birthDate;
  return {};
}

QVariant PatientTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case Code:
      return tr("Code");
    case Name:
      return tr("Name");
    case BirthDate:
      return tr("Born");
    case Sex:
      return tr("Sex");
    case Side:
      return tr("Affected side");
    case Diagnosis:
      return tr("Diagnosis");
    default:
      return {};
  }
}

bool PatientTableModel::event(QEvent* event) {
  ui::refreshOnLanguageChange(this, event);
  return QAbstractTableModel::event(event);
}

}  // namespace armtrack::gui
