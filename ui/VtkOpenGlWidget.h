// A VTK render window hosted in a Qt 6 QOpenGLWidget. Debian's VTK Qt module is built for Qt 5
// and must not be linked, so this is our own bridge: VTK renders through a
// vtkGenericOpenGLRenderWindow into its own framebuffer inside the widget's OpenGL context, and
// paintGL() blits that into the widget (docs/gui.md, "The 3D view").
#pragma once

#include <QOpenGLWidget>
#include <cstdint>
#include <memory>

class vtkGenericOpenGLRenderWindow;
class vtkRenderWindowInteractor;
class QSurface;

namespace armtrack::ui {

/// The widget owns the render window and its interactor. Mouse and wheel events go to the
/// interactor (and so to its interactor style); keys do not (VTK's default keys quit or change
/// the rendering mode), subclasses handle them. The default QSurfaceFormat must be
/// vtkSurfaceFormat() (ui/OpenGlSetup.h) before QApplication is constructed. GUI thread only.
class VtkOpenGlWidget : public QOpenGLWidget {
  Q_OBJECT
 public:
  explicit VtkOpenGlWidget(QWidget* parent = nullptr);
  ~VtkOpenGlWidget() override;

  vtkGenericOpenGLRenderWindow* renderWindow() const;
  vtkRenderWindowInteractor* interactor() const;

  /// Frames drawn into the widget since it was created (for the GUI benchmark and tests).
  std::uint64_t framesRendered() const { return m_frames; }
  /// The OpenGL context could not be created or VTK could not initialise it; the widget then
  /// shows nothing and problem() says why.
  bool failed() const { return !m_problem.isEmpty(); }
  QString problem() const { return m_problem; }

 signals:
  /// After each frame drawn by paintGL().
  void frameRendered();

 protected:
  void initializeGL() override;
  void resizeGL(int w, int h) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void enterEvent(QEnterEvent* event) override;
  void leaveEvent(QEvent* event) override;
  /// Called in paintGL() just before VTK renders, with the context current.
  virtual void prepareRender() {}

 private:
  struct Vtk;
  void cleanupGl();
  void forwardMouse(QMouseEvent* event, unsigned long vtkEvent);

  std::unique_ptr<Vtk> m_vtk;
  QSurface* m_surface = nullptr;
  QMetaObject::Connection m_contextDestroyed;
  bool m_inPaint = false;
  std::uint64_t m_frames = 0;
  QString m_problem;
};

}  // namespace armtrack::ui
