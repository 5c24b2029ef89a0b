// armtrack: the therapist's application. Answers --help, --version and a missing display in
// plain words before Qt starts, then sets the OpenGL format the 3D view needs and hands over to
// AppController.
#include <QApplication>
#include <QSurfaceFormat>
#include <cstdio>

#include "app/gui/AppController.h"
#include "app/gui/AppOptions.h"
#include "app/gui/services/AppSettings.h"

namespace {

void print(FILE* to, const QString& text) {
  std::fputs(text.toLocal8Bit().constData(), to);
  std::fflush(to);
}

/// VTK's OpenGL2 back end inside a QOpenGLWidget: OpenGL 3.2 core, RGBA8, a depth buffer, no
/// stencil, no multisampling (docs/architecture.md). Must be set before QApplication exists.
void setOpenGlFormat() {
  QSurfaceFormat f;
  f.setRenderableType(QSurfaceFormat::OpenGL);
  f.setVersion(3, 2);
  f.setProfile(QSurfaceFormat::CoreProfile);
  f.setRedBufferSize(8);
  f.setGreenBufferSize(8);
  f.setBlueBufferSize(8);
  f.setAlphaBufferSize(8);
  f.setDepthBufferSize(24);
  f.setStencilBufferSize(0);
  f.setSamples(0);
  QSurfaceFormat::setDefaultFormat(f);
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
  if (!armtrack::gui::displayAvailable(&why)) {
    print(stderr, why + u'\n');
    return 2;
  }
  setOpenGlFormat();
  QGuiApplication::setHighDpiScaleFactorRoundingPolicy(
      Qt::HighDpiScaleFactorRoundingPolicy::PassThrough);
  QApplication app(argc, argv);
  armtrack::gui::setApplicationIdentity();
  QApplication::setApplicationDisplayName(QStringLiteral("ArmTrack"));
  QApplication::setApplicationVersion(QStringLiteral(ARMTRACK_VERSION));
  QApplication::setDesktopFileName(QStringLiteral("armtrack"));
  armtrack::gui::AppController controller(std::move(options));
  controller.start();
  return app.exec();
}
