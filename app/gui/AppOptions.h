// The command line of `armtrack`, parsed before any QApplication exists (so that --help and a
// missing display can be answered on a machine without a screen).
#pragma once

#include <QString>
#include <QStringList>

struct xcb_connection_t;  // <xcb/xcb.h>, kept out of this header

namespace armtrack::gui {

struct AppOptions {
  QString database;             ///< --db URL (empty: the settings' or the default)
  bool demo = false;            ///< --demo
  bool home = false;            ///< --home (with --demo): the demo home account's window
  QStringList pluginFolders;    ///< --plugins DIR, repeatable
  QString language;             ///< --lang CODE (empty: settings, else the system's)
  double quitAfterSeconds = 0;  ///< --quit-after S: quit after S seconds (0: never)
  QString screenshot;           ///< --screenshot FILE: the window as PNG when quitting
  bool quitWhenLive = false;    ///< --quit-when-live: quit once a live session shows estimates
  bool help = false;
  bool version = false;
  QString error;            ///< a usage error, in words; empty when the line was fine
  QStringList qtArguments;  ///< what is left for QApplication (argv[0] and Qt's own options)
};

/// Parses argv (including the program name). Qt's own options (-platform, -style, ...) are
/// left for QApplication.
AppOptions parseAppOptions(const QStringList& arguments);

/// The --help text.
QString appUsage();

/// The X connection displayAvailable() opened to probe the display, kept open until release() or
/// destruction. An X server whose last client leaves resets itself (Xvfb and xvfb-run do unless
/// given -noreset), and a client connecting during that reset is refused: probing a fresh Xvfb
/// and closing the probe made QApplication fail to connect in 2 of 20 starts. Hold the probe
/// until QApplication has its own connection.
class HeldDisplay {
 public:
  HeldDisplay() = default;
  ~HeldDisplay() { release(); }
  HeldDisplay(const HeldDisplay&) = delete;
  HeldDisplay& operator=(const HeldDisplay&) = delete;
  void release();
  bool isHeld() const { return m_connection != nullptr; }

 private:
  friend bool displayAvailable(QString* why, HeldDisplay* hold);
  xcb_connection_t* m_connection = nullptr;
};

/// Whether a display can be reached for the default platform (X11 through DISPLAY, or Wayland).
/// When not, why says what is missing and how to run under xvfb-run. With hold, a working X
/// connection stays open in it (see HeldDisplay); without, it is closed at once.
bool displayAvailable(QString* why, HeldDisplay* hold = nullptr);

}  // namespace armtrack::gui
