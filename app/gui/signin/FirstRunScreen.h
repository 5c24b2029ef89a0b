// The first-run assistant: where the data lives and the administrator account. Shown when the
// records do not exist yet (or hold no account).
#pragma once

#include <QWidget>

class QGroupBox;
class QLineEdit;
class QPushButton;
class QLabel;

namespace armtrack::gui {

class MessageLine;

class FirstRunScreen : public QWidget {
  Q_OBJECT
 public:
  /// defaultFolder: offered as the data folder. fixedDatabase: when the records were named on
  /// the command line (--db), their location, shown instead of the folder choice.
  FirstRunScreen(const QString& defaultFolder, const QString& fixedDatabase,
                 QWidget* parent = nullptr);

  /// While the records are being created: the form is read-only.
  void setBusy(bool busy);
  /// Shows what went wrong; everything typed stays.
  void showError(const QString& message);

  QString folder() const;

 signals:
  /// The form is valid: create the records in folder (ignored with a fixed database) with this
  /// administrator.
  void createRequested(const QString& folder, const QString& admin, const QString& password);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  void submit();
  void chooseFolder();
  void updateDatabaseNote();

  bool m_fixed;
  QString m_fixedDatabase;
  QLabel* m_heading;
  QLabel* m_intro;
  QGroupBox* m_where;
  QGroupBox* m_account;
  QLabel* m_adminLabel;
  QLabel* m_passwordLabel;
  QLabel* m_repeatLabel;
  QLineEdit* m_folder;
  QPushButton* m_browse;
  QLabel* m_databaseNote;
  QLineEdit* m_admin;
  QLineEdit* m_password;
  QLineEdit* m_repeat;
  MessageLine* m_message;
  QPushButton* m_create;
};

}  // namespace armtrack::gui
