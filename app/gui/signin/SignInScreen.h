// Sign-in with an account of the records. A wrong password keeps what was typed; after repeated
// wrong passwords the store makes the next attempt wait, and the button counts the wait down.
#pragma once

#include <QTimer>
#include <QWidget>

#include "app/gui/common/Forms.h"

class QLabel;
class QLineEdit;
class QPushButton;

namespace armtrack::gui {

class MessageLine;

class SignInScreen : public QWidget {
  Q_OBJECT
 public:
  /// database: where the records are, as shown to the user. lastUser: pre-filled name.
  SignInScreen(const QString& database, const QString& lastUser, QWidget* parent = nullptr);

  void setBusy(bool busy);
  /// The store refused: message in words; when it names a wait ("try again in N s") the button
  /// stays disabled for that long.
  void showError(const QString& message);
  QString userName() const;

 signals:
  void signInRequested(const QString& name, const QString& password);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  void submit();
  void tick();
  void updateButtonText();
  /// The store's refusal in the current language (its English words are matched).
  QString refusalText(const QString& message) const;

  QString m_database;
  QLabel* m_heading;
  QLabel* m_where;
  QLabel* m_nameLabel;
  QLabel* m_passwordLabel;
  QLineEdit* m_name;
  QLineEdit* m_password;
  MessageLine* m_message;
  QPushButton* m_signIn;
  QTimer m_wait;
  int m_waitLeft = 0;  // s
  QString m_refusal;   // the store's last refusal, as it said it
};

}  // namespace armtrack::gui
