// A VTK render window in a Qt 6 window. Debian's VTK Qt module is built for Qt 5 and must not be
// linked, so this is our own bridge (ui/VtkBridge.h): VTK renders through a
// vtkGenericOpenGLRenderWindow into its own framebuffer in Qt's OpenGL context, and the host's
// paintGL() blits it into the host. Two hosts (docs/gui.md, "The 3D view"):
// - Host::Widget, a QOpenGLWidget: composed with the other widgets like any widget, but then
//   Qt composes the whole top-level window in OpenGL on every repaint of any widget, which on
//   software OpenGL (Mesa's llvmpipe, Xvfb) costs tens of milliseconds a frame;
// - Host::Window, a QOpenGLWindow in a window container: a native child window that renders
//   only itself, so the rest of the window stays plain raster painting. The default.
#pragma once

#include <QWidget>
#include <cstdint>
#include <memory>

class vtkGenericOpenGLRenderWindow;
class vtkRenderWindowInteractor;

namespace armtrack::ui {

class VtkBridge;

/// The view owns the render window and its interactor. Mouse and wheel events go to the
/// interactor (and so to its interactor style); keys do not (VTK's default keys quit or change
/// the rendering mode): subclasses handle them in keyPressEvent(). The default QSurfaceFormat
/// must be vtkSurfaceFormat() (ui/OpenGlSetup.h) before QApplication is constructed. GUI
/// thread only.
class VtkView : public QWidget {
  Q_OBJECT
 public:
  enum class Host { Widget, Window };
  /// $ARMTRACK_VTK_HOST ("widget" or "window"), else Host::Window.
  static Host defaultHost();

  explicit VtkView(QWidget* parent = nullptr, Host host = defaultHost());
  ~VtkView() override;

  Host host() const { return m_host; }
  vtkGenericOpenGLRenderWindow* renderWindow() const;
  vtkRenderWindowInteractor* interactor() const;

  /// Schedules a frame (QWidget::update() repaints only this widget, not the OpenGL host).
  void scheduleFrame();
  /// Frames drawn since the view was created (for the GUI benchmark and tests).
  std::uint64_t framesRendered() const;
  /// The OpenGL context could not be created or is too old; the view then shows nothing and
  /// problem() says why.
  bool failed() const { return !m_problem.isEmpty(); }
  QString problem() const { return m_problem; }

 signals:
  /// After each frame drawn.
  void frameRendered();

 protected:
  /// Called just before VTK renders a frame, with the context current.
  virtual void prepareRender() {}
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void enterEvent(QEnterEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  template <class Base>
  class GlHost;
  class WidgetHost;
  class WindowHost;
  void forwardMouse(QMouseEvent* event, unsigned long vtkEvent);
  qreal hostPixelRatio() const;

  Host m_host;
  std::unique_ptr<VtkBridge> m_bridge;
  WidgetHost* m_widgetHost = nullptr;
  WindowHost* m_windowHost = nullptr;
  QWidget* m_container = nullptr;
  QString m_problem;
};

}  // namespace armtrack::ui
