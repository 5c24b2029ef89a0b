// The command line of `armtrack`, parsed before any QApplication exists (so that --help and a
// missing display can be answered on a machine without a screen).
#pragma once

#include <QString>
#include <QStringList>

namespace armtrack::gui {

struct AppOptions {
  QString database;             ///< --db URL (empty: the settings' or the default)
  bool demo = false;            ///< --demo
  bool home = false;            ///< --home (with --demo): the demo home account's window
  QStringList pluginFolders;    ///< --plugins DIR, repeatable
  QString language;             ///< --lang CODE (empty: settings, else the system's)
  double quitAfterSeconds = 0;  ///< --quit-after S: quit after S seconds (0: never)
  QString screenshot;           ///< --screenshot FILE: the window as PNG when quitting
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

/// Whether a display can be reached for the default platform (X11 through DISPLAY, or Wayland).
/// When not, why says what is missing and how to run under xvfb-run.
bool displayAvailable(QString* why);

}  // namespace armtrack::gui
