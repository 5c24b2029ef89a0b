// The patient page's "Home devices": a one-time enrolment code for the patient's home account
// (shown large, in the groups the patient types, with the clinic's sync server address when the
// settings hold one), the devices enrolled with it and revoking one. Everything goes through
// ClinicalStore's createEnrolmentCode, listDevices and revokeDevice on the records' thread, so
// the store's rules (administrators and therapists only) and its audit apply (docs/sync.md).
#pragma once

#include <QGroupBox>

#include "core/storage/Records.h"

class QComboBox;
class QLabel;
class QPushButton;
class QTableView;

namespace armtrack::gui {

class DeviceTableModel;
class MessageLine;
class RecordsService;
struct AppSettings;

class HomeDevicesBox : public QGroupBox {
  Q_OBJECT
 public:
  HomeDevicesBox(RecordsService& records, const AppSettings& settings, const QString& patientCode,
                 QWidget* parent = nullptr);

  /// Reads the patient's home accounts and the chosen one's devices (again); loaded() when
  /// shown. The owner calls it first.
  void reload();
  /// Makes a code for the chosen account, valid for the chosen time; codeMade() when shown.
  void makeCode();
  /// Asks whether to revoke the selected device, then revokes it.
  void revokeSelected();

  /// The home account chosen, or "".
  QString account() const;
  /// The enrolment code shown, or "" (before one is made).
  QString shownCode() const { return m_code; }
  DeviceTableModel* devices() const { return m_devices; }
  /// The selected device's id, or 0.
  qint64 selectedDevice() const;
  /// The validity chosen, in seconds.
  qint64 validity() const;

 signals:
  void loaded();
  void codeMade(const QString& code);
  /// A call failed (message shown in the box).
  void failed(const QString& message);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  void loadDevices();
  void showCode();
  void updateButtons();
  void fail(const QString& message, bool denied);

  RecordsService& m_records;
  const AppSettings& m_settings;
  QString m_patient;
  std::vector<storage::User> m_accounts;
  QString m_code;       ///< the code shown (never stored)
  QString m_expiresAt;  ///< its expiry, ISO 8601 UTC
  bool m_busy = false;

  QLabel* m_accountLabel;
  QComboBox* m_account;
  QLabel* m_validityLabel;
  QComboBox* m_validity;
  QLabel* m_noAccount;
  QPushButton* m_make;
  QWidget* m_codeArea;
  QLabel* m_codeText;
  QLabel* m_codeInfo;
  QPushButton* m_copy;
  QLabel* m_devicesLabel;
  QTableView* m_table;
  DeviceTableModel* m_devices;
  QPushButton* m_refresh;
  QPushButton* m_revoke;
  MessageLine* m_message;
};

}  // namespace armtrack::gui
