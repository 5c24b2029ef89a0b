// A patient's sessions as a table: date, protocol, where (clinic or home), duration, status,
// samples, what the patient said and counted at home, notes.
#pragma once

#include <QAbstractTableModel>
#include <vector>

#include "core/storage/Records.h"

namespace armtrack::gui {

class SessionTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  /// The patient's own account (pain, comment) beside where the session was, not after the
  /// technical columns.
  enum Column { Started, Protocol, Where, Patient, Duration, Status, Samples, Notes, ColumnCount };
  static constexpr int IdRole = Qt::UserRole;  ///< the session id, on any column

  using QAbstractTableModel::QAbstractTableModel;
  void setSessions(std::vector<storage::SessionInfo> sessions);
  const storage::SessionInfo* sessionAt(int row) const;

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation,
                      int role = Qt::DisplayRole) const override;
  /// A LanguageChange (passed on by the owning widget) refreshes the views' words.
  bool event(QEvent* event) override;

  /// "complete", "interrupted", "recording" in words.
  static QString statusText(const QString& status);
  /// "clinic" or "home" in words.
  static QString settingText(const QString& setting);
  /// A home session's repetitions, pain score and comment: "8 of 10 repetitions; pain 3/10;
  /// \"stiff today\"" (empty for a clinic session).
  static QString patientText(const storage::SessionInfo& s);
  /// Seconds as m:ss (or h:mm:ss).
  static QString durationText(double seconds);
  /// An ISO 8601 UTC time as the local date and time in the user's locale.
  static QString localTime(const QString& isoUtc);

 private:
  std::vector<storage::SessionInfo> m_sessions;
};

}  // namespace armtrack::gui
