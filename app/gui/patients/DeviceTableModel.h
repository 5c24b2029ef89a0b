// A home account's enrolled devices as a table: the label the device gave, when it enrolled,
// when it last synced and whether it is revoked (ClinicalStore::listDevices).
#pragma once

#include <QAbstractTableModel>
#include <vector>

#include "core/storage/Records.h"

namespace armtrack::gui {

class DeviceTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Label, Enrolled, LastSync, Status, ColumnCount };
  static constexpr int IdRole = Qt::UserRole;  ///< the device's id, on any column

  using QAbstractTableModel::QAbstractTableModel;
  void setDevices(std::vector<storage::DeviceInfo> devices);
  /// The device of a row, or nullptr.
  const storage::DeviceInfo* deviceAt(int row) const;

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation,
                      int role = Qt::DisplayRole) const override;
  /// A LanguageChange (passed on by the owning widget) refreshes the views' words.
  bool event(QEvent* event) override;

 private:
  std::vector<storage::DeviceInfo> m_devices;
};

}  // namespace armtrack::gui
