// main() for QtTest GUI programs: the OpenGL surface format the VTK view needs is set before the
// QApplication exists (ui/OpenGlSetup.h), as the application's main() does. Screenshots a test
// takes go to screenshotDir().
#pragma once

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QScreen>
#include <QString>
#include <QWidget>
#include <QtTest>

#include "ui/OpenGlSetup.h"

namespace armtrack::test {

/// Where GUI tests write their screenshots ($ARMTRACK_SCREENSHOT_DIR, else the build's).
inline QString screenshotDir() {
  QString dir = qEnvironmentVariable("ARMTRACK_SCREENSHOT_DIR");
  if (dir.isEmpty()) dir = QStringLiteral(ARMTRACK_SCREENSHOT_DIR);
  QDir().mkpath(dir);
  return dir;
}

/// The widget's window as the X server shows it (VTK's view included, which grab() misses),
/// cut to the widget, in device pixels.
inline QImage grabFromScreen(QWidget* w) {
  QScreen* screen = w->screen();
  const QPoint topLeft = w->mapTo(w->window(), QPoint(0, 0));
  const QPixmap shot =
      screen->grabWindow(w->window()->winId(), topLeft.x(), topLeft.y(), w->width(), w->height());
  return shot.toImage().convertToFormat(QImage::Format_RGB32);
}

/// Saves the image as <screenshotDir()>/<name><$ARMTRACK_SCREENSHOT_SUFFIX>.png; returns the
/// path.
inline QString saveScreenshot(const QImage& image, const QString& name) {
  const QString path = screenshotDir() + QLatin1Char('/') + name +
                       qEnvironmentVariable("ARMTRACK_SCREENSHOT_SUFFIX") + QStringLiteral(".png");
  image.save(path);
  return path;
}

}  // namespace armtrack::test

#define ARMTRACK_GUI_TEST_MAIN(TestClass)          \
  int main(int argc, char** argv) {                \
    armtrack::ui::setDefaultSurfaceFormat();       \
    QApplication app(argc, argv);                  \
    app.setAttribute(Qt::AA_DontUseNativeDialogs); \
    TestClass test;                                \
    QTEST_SET_MAIN_SOURCE_PATH                     \
    return QTest::qExec(&test, argc, argv);        \
  }
