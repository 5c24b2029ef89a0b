#include "app/gui/patients/DeviceTableModel.h"

#include "app/gui/common/SessionTableModel.h"
#include "ui/Retranslate.h"

namespace armtrack::gui {

void DeviceTableModel::setDevices(std::vector<storage::DeviceInfo> devices) {
  beginResetModel();
  m_devices = std::move(devices);
  endResetModel();
}

const storage::DeviceInfo* DeviceTableModel::deviceAt(int row) const {
  if (row < 0 || row >= static_cast<int>(m_devices.size())) return nullptr;
  return &m_devices[static_cast<std::size_t>(row)];
}

int DeviceTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(m_devices.size());
}

int DeviceTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant DeviceTableModel::data(const QModelIndex& index, int role) const {
  const storage::DeviceInfo* d = deviceAt(index.row());
  if (!d) return {};
  if (role == IdRole) return d->id;
  if (role == Qt::ToolTipRole && index.column() == Label) return tr("Device %1").arg(d->id);
  if (role != Qt::DisplayRole) return {};
  switch (index.column()) {
    case Label:
      return d->label.isEmpty() ? tr("device %1").arg(d->id) : d->label;
    case Enrolled:
      return SessionTableModel::localTime(d->createdAt);
    case LastSync:
      return d->lastSeenAt.isEmpty() ? tr("never") : SessionTableModel::localTime(d->lastSeenAt);
    case Status:
      return d->revokedAt.isEmpty()
                 ? tr("enrolled")
                 : tr("revoked %1").arg(SessionTableModel::localTime(d->revokedAt));
    default:
      return {};
  }
}

QVariant DeviceTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case Label:
      return tr("Device");
    case Enrolled:
      return tr("Enrolled");
    case LastSync:
      return tr("Last sync");
    case Status:
      return tr("Status");
    default:
      return {};
  }
}

bool DeviceTableModel::event(QEvent* event) {
  ui::refreshOnLanguageChange(this, event);
  return QAbstractTableModel::event(event);
}

}  // namespace armtrack::gui
