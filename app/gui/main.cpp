// armtrack: the therapist's application. Answers --help, --version and a missing display in
// plain words before Qt starts, then sets the OpenGL format the 3D view needs and hands over to
// AppController.
#include <QApplication>
#include <QIcon>
#include <cstdio>

#include "app/gui/AppController.h"
#include "app/gui/AppOptions.h"
#include "app/gui/services/AppSettings.h"
#include "ui/OpenGlSetup.h"

namespace {

void print(FILE* to, const QString& text) {
  std::fputs(text.toLocal8Bit().constData(), to);
  std::fflush(to);
}

}  // namespace

int main(int argc, char** argv) {
  QStringList arguments;
  for (int i = 0; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
  armtrack::gui::AppOptions options = armtrack::gui::parseAppOptions(arguments);
  if (!options.error.isEmpty()) {
    print(stderr, QStringLiteral("armtrack: %1\n").arg(options.error));
    return 2;
  }
  if (options.help) {
    print(stdout, armtrack::gui::appUsage());
    return 0;
  }
  if (options.version) {
    print(stdout, QStringLiteral("armtrack %1\n").arg(QStringLiteral(ARMTRACK_VERSION)));
    return 0;
  }
  QString why;
  armtrack::gui::HeldDisplay probe;  // open until Qt has connected (a fresh Xvfb resets otherwise)
  if (!armtrack::gui::displayAvailable(&why, &probe)) {
    print(stderr, why + u'\n');
    return 2;
  }
  armtrack::ui::setDefaultSurfaceFormat();  // before QApplication: the VTK view needs it
  QGuiApplication::setHighDpiScaleFactorRoundingPolicy(
      Qt::HighDpiScaleFactorRoundingPolicy::PassThrough);
  QApplication app(argc, argv);
  probe.release();
  armtrack::gui::setApplicationIdentity();
  QApplication::setApplicationDisplayName(QStringLiteral("ArmTrack"));
  QApplication::setApplicationVersion(QStringLiteral(ARMTRACK_VERSION));
  // The installed desktop entry and icon (packaging/linux, packaging/icons).
  QApplication::setDesktopFileName(QStringLiteral("org.armtrack.ArmTrack"));
  QApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral("org.armtrack.ArmTrack")));
  armtrack::gui::AppController controller(std::move(options));
  controller.start();
  return app.exec();
}
