// Connecting the home install to the clinic: the server's address and the enrolment code the
// therapist gave, typed in once (docs/sync.md, "The home install"). Large and clear as the other
// home screens, usable with the keyboard alone.
#pragma once

#include <QDateTime>

#include "app/gui/home/HomeScreen.h"
#include "app/sync/HomeSyncClient.h"

class QLabel;
class QLineEdit;
class QPushButton;

namespace armtrack::gui::home {

class HomeConnectScreen : public HomeScreen {
  Q_OBJECT
 public:
  /// server: the address known already (shown to change), or empty.
  explicit HomeConnectScreen(const QString& server, QWidget* parent = nullptr);

  QList<QAbstractButton*> choices() const override;
  QAbstractButton* defaultChoice() const override;
  QLineEdit* serverField() const { return m_server; }
  QLineEdit* codeField() const { return m_code; }
  QString resultText() const;
  /// The answer: connected, or why not (the fields can be used again).
  void showResult(bool ok, const QString& text);

  /// The home window's sync line: "3 sessions waiting to be sent · Sent today 10:42", or why
  /// nothing is sent ("Not connected: sessions are kept and sent later"). now: local time.
  static QString stateText(const sync::SyncStatus& status, const QDateTime& now);
  /// What an enrolment came to, in the patient's words.
  static QString enrolText(bool ok, sync::SyncProblem problem, const QString& detail);

 signals:
  void connectRequested(const QString& server, const QString& code);
  void backRequested();

 protected:
  void retranslate() override;

 private:
  void submit();

  QLabel* m_title;
  QLabel* m_intro;
  QLabel* m_serverLabel;
  QLineEdit* m_server;
  QLabel* m_codeLabel;
  QLineEdit* m_code;
  QLabel* m_result;
  QPushButton* m_connect;
  QPushButton* m_back;
};

}  // namespace armtrack::gui::home
