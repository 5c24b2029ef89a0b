// The application's window: one screen at a time, a menu and a status bar. It knows no screen
// and no service; AppController decides what it shows.
#pragma once

#include <QMainWindow>
#include <QPointer>

class QAction;
class QLabel;
class QStackedWidget;

namespace armtrack::gui {

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);

  /// Shows screen in place of the current one, which is deleted. The window's title follows the
  /// screen's windowTitle. Keyboard focus goes to the screen's focus proxy (or its first
  /// focusable child).
  void showScreen(QWidget* screen);
  QWidget* currentScreen() const;
  /// Shows who is signed in (empty: nobody) and enables the actions that need an account.
  void setSignedIn(const QString& who);
  /// A short message in the status bar (ms = 0: until replaced).
  void showStatus(const QString& text, int ms = 8000);

 signals:
  void settingsRequested();
  void signOutRequested();
  void patientsRequested();
  void userGuideRequested();

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void updateTitle();

  QStackedWidget* m_stack;
  QPointer<QWidget> m_current;
  QLabel* m_who;
  QAction* m_patients;
  QAction* m_settings;
  QAction* m_signOut;
};

}  // namespace armtrack::gui
