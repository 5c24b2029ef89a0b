// How the home window is driven without a mouse: the keyboard alone (Space or Enter goes on,
// Escape pauses, Tab moves between the buttons), or a single switch (a device that sends one key,
// Space or Enter): either scanning, where the focus steps through the screen's choices by itself
// and the switch takes the one highlighted, or "press to go on", where the switch always takes the
// screen's main choice. Installed on the application, it acts only on key presses for its window.
#pragma once

#include <QObject>
#include <QPointer>
#include <QTimer>

namespace armtrack::gui::home {

class HomeScreen;

enum class AccessMode {
  Keyboard,  ///< keyboard or mouse (the default)
  Scanning,  ///< one switch, the choices stepped through automatically
  Step,      ///< one switch, "press to go on"
};

/// "keyboard", "scanning", "step" (anything else: Keyboard).
AccessMode parseAccessMode(const QString& name);
QString accessModeName(AccessMode mode);

class SwitchAccess : public QObject {
  Q_OBJECT
 public:
  /// window: the home window whose key presses are handled.
  explicit SwitchAccess(QWidget* window, QObject* parent = nullptr);
  ~SwitchAccess() override;

  void setMode(AccessMode mode);
  AccessMode mode() const { return m_mode; }
  /// Time each choice stays highlighted while scanning (ms; 500-10000, default 1500).
  void setScanInterval(int ms);
  int scanInterval() const { return m_timer.interval(); }
  /// The screen shown (its choices are what the keys act on).
  void setScreen(HomeScreen* screen);
  /// The choice scanning highlights now (null when not scanning).
  QWidget* highlighted() const;

 signals:
  void modeChanged(armtrack::gui::home::AccessMode mode);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void step();
  void restartScan();
  bool takeSwitch();
  bool goOn();

  QWidget* m_window;
  QPointer<HomeScreen> m_screen;
  AccessMode m_mode = AccessMode::Keyboard;
  QTimer m_timer;
  int m_index = -1;
};

}  // namespace armtrack::gui::home
