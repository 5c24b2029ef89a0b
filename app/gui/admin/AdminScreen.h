// The administrator's screen: the accounts (add, reset a password, remove; roles, a home account
// for a patient), the protocols (add, edit) and each patient's home programme (add, edit, remove
// exercises). Every change goes through the same ClinicalStore calls as armtrack-cli's user,
// protocol and programme commands, so the same rules and the same audit apply; every call runs
// on the records' thread.
#pragma once

#include <QWidget>
#include <vector>

#include "core/storage/Records.h"

class QComboBox;
class QLabel;
class QPushButton;
class QTabWidget;
class QTableWidget;

namespace armtrack::gui {
class MessageLine;
class RecordsService;
}  // namespace armtrack::gui

namespace armtrack::gui::admin {

/// What the three pages share: a table, a row of buttons, a message line.
class AdminPage : public QWidget {
  Q_OBJECT
 public:
  AdminPage(RecordsService& records, QWidget* parent);
  /// Reads the page's records again; loaded() when shown.
  virtual void reload() = 0;
  QTableWidget* table() const { return m_table; }
  /// The name in the first column of the selected row, or "".
  QString selectedKey() const;

 signals:
  void loaded();

 protected:
  void changeEvent(QEvent* event) override;
  virtual void retranslateUi() = 0;
  QPushButton* addButton(QWidget* parent = nullptr);
  /// Fills the table (rows of cells), keeping the row whose first cell is select selected.
  void fill(const QStringList& headers, const std::vector<QStringList>& rows,
            const QString& select);
  void failed(const QString& message);
  void done(const QString& message);
  /// Asks question; yes() runs when the user agrees.
  void confirm(const QString& title, const QString& question, std::function<void()> yes);

  RecordsService& m_records;
  QTableWidget* m_table;
  MessageLine* m_message;
  QList<QPushButton*> m_buttons;
};

class AccountsPage : public AdminPage {
  Q_OBJECT
 public:
  AccountsPage(RecordsService& records, QWidget* parent);
  void reload() override;
  void addAccount();
  void resetPassword();
  /// Disables the selected account, or enables it when it is disabled.
  void toggleDisabled();
  void removeAccount();

 protected:
  void retranslateUi() override;

 private:
  /// The selected account, if any.
  const storage::User* selectedUser() const;
  /// The disable button's text for the selected account.
  void updateDisableButton();

  std::vector<storage::User> m_users;
  std::vector<storage::Patient> m_patients;
  QPushButton* m_add;
  QPushButton* m_password;
  QPushButton* m_disable;
  QPushButton* m_remove;
};

class ProtocolsPage : public AdminPage {
  Q_OBJECT
 public:
  ProtocolsPage(RecordsService& records, QWidget* parent);
  void reload() override;
  void addProtocol();
  void editProtocol();

 protected:
  void retranslateUi() override;

 private:
  void openDialog(const storage::Protocol& protocol);

  std::vector<storage::Protocol> m_protocols;
  QPushButton* m_add;
  QPushButton* m_edit;
};

class ProgrammePage : public AdminPage {
  Q_OBJECT
 public:
  ProgrammePage(RecordsService& records, QWidget* parent);
  void reload() override;
  /// Shows the programme of the patient with this code.
  bool selectPatient(const QString& code);
  QString patientCode() const;
  void addExercise();
  void editExercise();
  void removeExercise();

 protected:
  void retranslateUi() override;

 private:
  void loadProgramme(const QString& select = {});
  void openDialog(const std::optional<storage::ProgrammeItem>& item);

  QLabel* m_patientLabel;
  QComboBox* m_patient;
  std::vector<storage::Protocol> m_protocols;
  std::vector<storage::ProgrammeItem> m_items;
  QPushButton* m_add;
  QPushButton* m_edit;
  QPushButton* m_remove;
};

class AdminScreen : public QWidget {
  Q_OBJECT
 public:
  explicit AdminScreen(RecordsService& records, QWidget* parent = nullptr);
  AccountsPage* accounts() const { return m_accounts; }
  ProtocolsPage* protocols() const { return m_protocols; }
  ProgrammePage* programmes() const { return m_programmes; }
  QTabWidget* tabs() const { return m_tabs; }

 signals:
  void backRequested();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();

  QLabel* m_heading;
  QTabWidget* m_tabs;
  AccountsPage* m_accounts;
  ProtocolsPage* m_protocols;
  ProgrammePage* m_programmes;
  QPushButton* m_back;
};

}  // namespace armtrack::gui::admin
