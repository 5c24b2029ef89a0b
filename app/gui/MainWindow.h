// The application's window: one screen at a time, a menu and a status bar. It knows no screen
// and no service; AppController decides what it shows.
#pragma once

#include <QMainWindow>
#include <QPointer>
#include <functional>

#include "app/gui/common/Forms.h"

class QAction;
class QLabel;
class QMenu;

namespace armtrack::ui {
class ScreenStack;
}

namespace armtrack::gui {

class HelpWindow;

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
  void setSignedIn(TextFn who);
  /// Offers the administrator's screen (an administrator is signed in) or hides it.
  void setAdministrator(bool administrator);
  /// A short message in the status bar (ms = 0: until replaced), made again in the new language
  /// when the language changes while it is shown.
  void showStatus(TextFn text, int ms = 8000);
  /// The same with a text that stays as it is.
  void showStatus(const QString& text, int ms = 8000);
  /// Asked before the window closes (its close button, File > Quit): false keeps it open (e.g.
  /// while the question whether to stop a recording is open).
  void setCloseGuard(std::function<bool()> mayClose) { m_mayClose = std::move(mayClose); }
  /// Help > User guide (F1): the guide in its own window, at the section about the screen shown
  /// and with what to do on it (HelpWindow). Also emits userGuideRequested.
  void showUserGuide();
  /// The guide's window once F1 opened it, else nullptr.
  HelpWindow* helpWindow() const;

 signals:
  void settingsRequested();
  void signOutRequested();
  void patientsRequested();
  void adminRequested();
  void userGuideRequested();

 protected:
  void closeEvent(QCloseEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  void updateTitle();

  ui::ScreenStack* m_stack;
  QLabel* m_who;
  TextFn m_whoText;
  TextFn m_statusText;
  QString m_statusShown;
  std::function<bool()> m_mayClose;
  QMenu* m_file;
  QMenu* m_help;
  QAction* m_patients;
  QAction* m_admin;
  QAction* m_settings;
  QAction* m_signOut;
  QAction* m_quit;
  QAction* m_guide;
  QAction* m_about;
  QPointer<HelpWindow> m_helpWindow;
};

}  // namespace armtrack::gui
