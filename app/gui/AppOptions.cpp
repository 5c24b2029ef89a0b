#include "app/gui/AppOptions.h"

#include <xcb/xcb.h>

#include <QCoreApplication>

#include "app/i18n/Language.h"

namespace armtrack::gui {

namespace {

// This file's texts are printed before Qt starts (no translator can be installed yet), so they
// are English, like armtrack-cli's; the windows speak the chosen language.
QString text(const char* english) {
  return QString::fromUtf8(english);
}

// Options of QApplication itself that take a value (they stay for it).
bool isQtOptionWithValue(const QString& a) {
  static const QStringList withValue = {
      QStringLiteral("-platform"),        QStringLiteral("-platformpluginpath"),
      QStringLiteral("-platformtheme"),   QStringLiteral("-plugin"),
      QStringLiteral("-qwindowgeometry"), QStringLiteral("-qwindowtitle"),
      QStringLiteral("-qwindowicon"),     QStringLiteral("-style"),
      QStringLiteral("-stylesheet"),      QStringLiteral("-display"),
      QStringLiteral("-geometry"),        QStringLiteral("-title")};
  return withValue.contains(a);
}

}  // namespace

QString appUsage() {
  return text(
      "Usage: armtrack [options]\n"
      "\n"
      "ArmTrack measures how a patient's arm moves during rehabilitation.\n"
      "\n"
      "Options:\n"
      "  --db URL        the clinical records to open: a file path, sqlite:PATH or\n"
      "                  postgresql://user@host:port/dbname (default: armtrack.db in the\n"
      "                  data folder chosen at the first start)\n"
      "  --demo          open a demo database (made afresh) as a demo therapist and start a\n"
      "                  live session with the virtual arm\n"
      "  --plugins DIR   also look for device plugins in DIR (repeatable)\n"
      "  --lang CODE     language of the windows and reports: en, de or es (default: the\n"
      "                  settings' choice, else the system's)\n"
      "  --quit-after S  quit after S seconds (for unattended runs)\n"
      "  --screenshot FILE\n"
      "                  with --quit-after: save the window as a PNG before quitting\n"
      "  --version       print the version and exit\n"
      "  --help          print this text and exit\n"
      "\n"
      "Without a display, run it under a virtual one:\n"
      "  xvfb-run -a -s '-screen 0 1280x800x24' armtrack --demo\n");
}

AppOptions parseAppOptions(const QStringList& arguments) {
  AppOptions o;
  if (!arguments.isEmpty()) o.qtArguments << arguments.first();
  const auto valueOf = [&](qsizetype& i, const QString& name, QString& into) {
    const QString& a = arguments[i];
    if (a.startsWith(name + u'=')) {
      into = a.mid(name.size() + 1);
    } else if (i + 1 < arguments.size()) {
      into = arguments[++i];
    } else {
      o.error = text("%1 needs a value").arg(name);
      return false;
    }
    if (into.isEmpty()) o.error = text("%1 needs a value").arg(name);
    return !into.isEmpty();
  };
  for (qsizetype i = 1; i < arguments.size() && o.error.isEmpty(); ++i) {
    const QString& a = arguments[i];
    const auto is = [&](const char* name) {
      return a == QLatin1String(name) || a.startsWith(QLatin1String(name) + u'=');
    };
    if (a == QLatin1String("--help") || a == QLatin1String("-h")) {
      o.help = true;
    } else if (a == QLatin1String("--version")) {
      o.version = true;
    } else if (a == QLatin1String("--demo")) {
      o.demo = true;
    } else if (is("--db")) {
      valueOf(i, QStringLiteral("--db"), o.database);
    } else if (is("--plugins")) {
      QString dir;
      if (valueOf(i, QStringLiteral("--plugins"), dir)) o.pluginFolders << dir;
    } else if (is("--lang")) {
      valueOf(i, QStringLiteral("--lang"), o.language);
    } else if (is("--quit-after")) {
      QString v;
      if (valueOf(i, QStringLiteral("--quit-after"), v)) {
        bool ok = false;
        o.quitAfterSeconds = v.toDouble(&ok);
        if (!ok || !(o.quitAfterSeconds > 0))
          o.error = text("--quit-after: expected a positive number of seconds, got '%1'").arg(v);
      }
    } else if (is("--screenshot")) {
      valueOf(i, QStringLiteral("--screenshot"), o.screenshot);
    } else if (isQtOptionWithValue(a) && i + 1 < arguments.size()) {
      o.qtArguments << a << arguments[++i];
    } else if (a.startsWith(u'-') && !a.startsWith(QLatin1String("--"))) {
      o.qtArguments << a;  // a Qt option without a value, e.g. -reverse
    } else {
      o.error = text("unknown option or argument '%1' (see armtrack --help)").arg(a);
    }
  }
  if (o.error.isEmpty() && !o.screenshot.isEmpty() && o.quitAfterSeconds <= 0)
    o.error = text("--screenshot needs --quit-after");
  if (o.error.isEmpty() && !o.language.isEmpty() && i18n::shippedLanguageFor(o.language).isEmpty())
    o.error = text("--lang: ArmTrack has no translation for '%1'; choose one of %2")
                  .arg(o.language, i18n::shippedLanguageList());
  return o;
}

bool displayAvailable(QString* why) {
  const QString platform = qEnvironmentVariable("QT_QPA_PLATFORM");
  // Another platform chosen on purpose (e.g. vnc) is the user's business.
  if (!platform.isEmpty() && !platform.startsWith(QLatin1String("xcb")) &&
      !platform.startsWith(QLatin1String("wayland")))
    return true;
  const QByteArray display = qgetenv("DISPLAY");
  const bool wayland = !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
  const QString howTo = text(
      "To run ArmTrack on a machine without a screen, start it under a virtual display:\n"
      "  xvfb-run -a -s '-screen 0 1280x800x24' armtrack --demo\n"
      "(xvfb-run comes with the Debian package xvfb.) The clinical records can also be "
      "reached without a display through armtrack-cli.");
  if (!display.isEmpty() && !platform.startsWith(QLatin1String("wayland"))) {
    int screen = 0;
    xcb_connection_t* c = xcb_connect(display.constData(), &screen);
    const bool ok = c && xcb_connection_has_error(c) == 0;
    if (c) xcb_disconnect(c);
    if (ok) return true;
    if (wayland) return true;  // Qt falls back to Wayland when X cannot be reached
    if (why)
      *why =
          text("ArmTrack cannot open the display \"%1\" (DISPLAY): no X server answers there.\n")
              .arg(QString::fromLocal8Bit(display)) +
          howTo;
    return false;
  }
  if (wayland) return true;
  if (why)
    *why = text(
               "ArmTrack needs a graphical display and found none (neither DISPLAY nor "
               "WAYLAND_DISPLAY is set).\n") +
           howTo;
  return false;
}

}  // namespace armtrack::gui
