// The bridge between a VTK render window and a Qt OpenGL surface (internal to ui/): VTK renders
// through a vtkGenericOpenGLRenderWindow into its own framebuffer in the host's context, and
// paint() blits that into the host's framebuffer. The host is a QOpenGLWidget or a QOpenGLWindow
// (VtkView chooses); it tells the bridge how to make its context current.
#pragma once

#include <vtkCallbackCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkSmartPointer.h>
#include <QCoreApplication>

#include <QPointF>
#include <QString>
#include <cstdint>
#include <functional>

class QOpenGLContext;

namespace armtrack::ui {

class VtkBridge {
  Q_DECLARE_TR_FUNCTIONS(armtrack::ui::VtkBridge)

 public:
  struct Hooks {
    std::function<void()> makeCurrent;   ///< the host's context current on its surface
    std::function<bool()> isCurrent;     ///< is it?
    std::function<void()> requestFrame;  ///< schedule a repaint (VTK rendered on its own)
    std::function<void()> beforeRender;  ///< in paint(), before VTK renders
  };

  explicit VtkBridge(Hooks hooks);
  ~VtkBridge();
  VtkBridge(const VtkBridge&) = delete;
  VtkBridge& operator=(const VtkBridge&) = delete;

  vtkGenericOpenGLRenderWindow* window() const { return m_window; }
  vtkGenericRenderWindowInteractor* interactor() const { return m_interactor; }

  /// From the host's initializeGL (context current). Returns an empty string, or why the view
  /// cannot be shown (no context, OpenGL older than 3.2).
  QString initialize(QOpenGLContext* context, int widthPx, int heightPx);
  /// From resizeGL, in device pixels.
  void resize(int widthPx, int heightPx);
  /// From paintGL: renders and blits into fbo (the host's default framebuffer object).
  void paint(unsigned int fbo, int widthPx, int heightPx);
  /// Releases VTK's OpenGL resources (context current); the bridge can be initialised again.
  void cleanup();
  bool ready() const { return m_ready; }
  bool painting() const { return m_painting; }
  std::uint64_t frames() const { return m_frames; }

  /// Mouse input in device pixels (y down) of a host heightPx tall.
  void mouse(unsigned long vtkEvent, QPointF posPx, bool ctrl, bool shift, bool alt,
             bool doubleClick);
  void wheel(QPointF posPx, bool ctrl, bool shift, int deltaY);
  void enterLeave(bool enter);

 private:
  Hooks m_hooks;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> m_window;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> m_interactor;
  vtkSmartPointer<vtkCallbackCommand> m_makeCurrent, m_isCurrent, m_frame;
  bool m_ready = false;
  bool m_painting = false;
  std::uint64_t m_frames = 0;
};

}  // namespace armtrack::ui
