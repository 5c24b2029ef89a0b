// The home window: a window of its own for a patient's home account, one screen at a time, with
// nothing else of the application in it (no menu, no other patients, no settings). Large text,
// high contrast, usable with the keyboard alone or a single switch (SwitchAccess).
#pragma once

#include <QWidget>
#include <functional>

class QLabel;

namespace armtrack::ui {
class ScreenStack;
}

namespace armtrack::gui::home {

class HomeScreen;
class SwitchAccess;

class HomeWindow : public QWidget {
  Q_OBJECT
 public:
  explicit HomeWindow(QWidget* parent = nullptr);

  /// Shows screen in place of the current one (deleted), focus on its main choice.
  void showScreen(HomeScreen* screen);
  HomeScreen* currentScreen() const;
  /// The line above every screen: whose exercises, and the step ("Exercise 1 of 2", said again
  /// when the language changes).
  void setHeading(const QString& who, std::function<QString()> step);
  QString stepText() const;
  /// The line under every screen saying where the sessions stand ("3 sessions waiting to be
  /// sent"); hidden when empty (no sync on this install).
  void setSyncText(const QString& text);
  QString syncText() const;
  SwitchAccess* access() const { return m_access; }
  /// Closing is first asked of the owner (closeRequested); it closes once allowed.
  void allowClose() { m_closeAllowed = true; }

 signals:
  /// The window was asked to close (its close button, Alt+F4) while not allowed yet.
  void closeRequested();

 protected:
  void closeEvent(QCloseEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();

  QLabel* m_who;
  QLabel* m_step;
  QLabel* m_sync;
  std::function<QString()> m_stepText;
  ui::ScreenStack* m_stack;
  SwitchAccess* m_access;
  bool m_closeAllowed = false;
};

}  // namespace armtrack::gui::home
