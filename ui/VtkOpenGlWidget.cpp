#include "ui/VtkOpenGlWidget.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkOpenGLState.h>
#include <vtkSmartPointer.h>

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QWheelEvent>
#include <cmath>

namespace armtrack::ui {

struct VtkOpenGlWidget::Vtk {
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor;
  vtkSmartPointer<vtkCallbackCommand> makeCurrent, isCurrent, frame;
};

namespace {
VtkOpenGlWidget* widgetOf(void* clientData) {
  return static_cast<VtkOpenGlWidget*>(clientData);
}
}  // namespace

VtkOpenGlWidget::VtkOpenGlWidget(QWidget* parent) : QOpenGLWidget(parent), m_vtk(new Vtk) {
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(false);
  setMinimumSize(1, 1);
  Vtk& v = *m_vtk;
  v.window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  // The context is Qt's: VTK neither owns it, nor renders before initializeGL(), nor blits to
  // the screen by itself (paintGL() does).
  v.window->SetOwnContext(false);
  v.window->SetReadyForRendering(false);
  v.window->SetFrameBlitModeToNoBlit();
  v.window->SetMultiSamples(0);
  v.interactor = vtkSmartPointer<vtkGenericRenderWindowInteractor>::New();
  v.interactor->SetRenderWindow(v.window);
  v.interactor->EnableRenderOn();

  // Make-current: our context on the surface saved in initializeGL(). QOpenGLWidget::makeCurrent()
  // would rebind Qt's framebuffer behind VTK's state cache (a black view).
  v.makeCurrent = vtkSmartPointer<vtkCallbackCommand>::New();
  v.makeCurrent->SetClientData(this);
  v.makeCurrent->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    VtkOpenGlWidget* w = widgetOf(self);
    if (QOpenGLContext* c = w->context(); c && w->m_surface) c->makeCurrent(w->m_surface);
  });
  v.isCurrent = vtkSmartPointer<vtkCallbackCommand>::New();
  v.isCurrent->SetClientData(this);
  v.isCurrent->SetCallback([](vtkObject*, unsigned long, void* self, void* callData) {
    VtkOpenGlWidget* w = widgetOf(self);
    QOpenGLContext* c = w->context();
    *static_cast<bool*>(callData) =
        c && c == QOpenGLContext::currentContext() && w->m_surface && c->surface() == w->m_surface;
  });
  // A frame VTK rendered on its own (the interactor style after a mouse move): show it.
  v.frame = vtkSmartPointer<vtkCallbackCommand>::New();
  v.frame->SetClientData(this);
  v.frame->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    VtkOpenGlWidget* w = widgetOf(self);
    if (!w->m_inPaint) w->update();
  });
  v.window->AddObserver(vtkCommand::WindowMakeCurrentEvent, v.makeCurrent);
  v.window->AddObserver(vtkCommand::WindowIsCurrentEvent, v.isCurrent);
  v.window->AddObserver(vtkCommand::WindowFrameEvent, v.frame);
}

VtkOpenGlWidget::~VtkOpenGlWidget() {
  // Disconnect first: the context's aboutToBeDestroyed would otherwise call back into a
  // half-destroyed object at exit.
  QObject::disconnect(m_contextDestroyed);
  if (context()) {
    QOpenGLWidget::makeCurrent();
    cleanupGl();
    doneCurrent();
  }
  m_vtk->window->RemoveObserver(m_vtk->makeCurrent);
  m_vtk->window->RemoveObserver(m_vtk->isCurrent);
  m_vtk->window->RemoveObserver(m_vtk->frame);
}

vtkGenericOpenGLRenderWindow* VtkOpenGlWidget::renderWindow() const {
  return m_vtk->window;
}

vtkRenderWindowInteractor* VtkOpenGlWidget::interactor() const {
  return m_vtk->interactor;
}

void VtkOpenGlWidget::cleanupGl() {
  if (!m_surface) return;
  m_vtk->window->Finalize();  // releases VTK's graphics resources in our (current) context
  m_vtk->window->SetReadyForRendering(false);
  m_surface = nullptr;
}

void VtkOpenGlWidget::initializeGL() {
  QOpenGLContext* c = context();
  if (!c || !c->isValid()) {
    m_problem = tr("OpenGL is not available, so the 3D view cannot be shown.");
    return;
  }
  const QSurfaceFormat f = c->format();
  if (f.majorVersion() * 10 + f.minorVersion() < 32) {
    m_problem = tr("The 3D view needs OpenGL 3.2; this display offers %1.%2.")
                    .arg(f.majorVersion())
                    .arg(f.minorVersion());
    return;
  }
  m_surface = c->surface();
  QObject::disconnect(m_contextDestroyed);
  m_contextDestroyed = connect(c, &QOpenGLContext::aboutToBeDestroyed, this, [this] {
    QOpenGLWidget::makeCurrent();
    cleanupGl();
  });
  vtkGenericOpenGLRenderWindow* w = m_vtk->window;
  w->SetReadyForRendering(true);
  w->SetMapped(true);
  w->SetIsDirect(true);
  w->SetSupportsOpenGL(true);
  w->SetForceMaximumHardwareLineWidth(1);
  const qreal dpr = devicePixelRatioF();
  w->SetSize(std::max(1, static_cast<int>(std::lround(width() * dpr))),
             std::max(1, static_cast<int>(std::lround(height() * dpr))));
  w->OpenGLInitContext();
  if (!m_vtk->interactor->GetInitialized()) m_vtk->interactor->Initialize();
}

void VtkOpenGlWidget::resizeGL(int w, int h) {
  if (!m_surface) return;
  const qreal dpr = devicePixelRatioF();
  const int pw = std::max(1, static_cast<int>(std::lround(w * dpr)));
  const int ph = std::max(1, static_cast<int>(std::lround(h * dpr)));
  m_vtk->interactor->UpdateSize(pw, ph);  // also resizes the render window
  m_vtk->window->SetSize(pw, ph);
}

void VtkOpenGlWidget::paintGL() {
  if (!m_surface) {
    // No usable context: clear to the window colour so the widget is not garbage.
    if (QOpenGLContext* c = QOpenGLContext::currentContext()) {
      const QColor bg = palette().color(QPalette::Window);
      c->functions()->glClearColor(bg.redF(), bg.greenF(), bg.blueF(), 1.0f);
      c->functions()->glClear(GL_COLOR_BUFFER_BIT);
    }
    return;
  }
  vtkGenericOpenGLRenderWindow* w = m_vtk->window;
  m_inPaint = true;
  prepareRender();
  w->Render();  // into VTK's own framebuffer
  m_inPaint = false;

  const qreal dpr = devicePixelRatioF();
  const int pw = std::max(1, static_cast<int>(std::lround(width() * dpr)));
  const int ph = std::max(1, static_cast<int>(std::lround(height() * dpr)));
  vtkOpenGLState* state = w->GetState();
  // Qt touched the GL state since VTK last looked: record it, then restore it after the blit.
  state->Reset();
  state->Push();
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  state->vtkglViewport(0, 0, pw, ph);
  state->vtkglScissor(0, 0, pw, ph);
  state->vtkglDisable(GL_SCISSOR_TEST);
  const int* size = w->GetSize();
  w->BlitDisplayFramebuffer(0, 0, 0, size[0], size[1], 0, 0, pw, ph, GL_COLOR_BUFFER_BIT,
                            GL_NEAREST);
  // What VTK leaves in alpha must not make the widget see-through when Qt composes it.
  state->vtkglColorMask(false, false, false, true);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  state->vtkglColorMask(true, true, true, true);
  state->Pop();
  ++m_frames;
  emit frameRendered();
}

void VtkOpenGlWidget::forwardMouse(QMouseEvent* event, unsigned long vtkEvent) {
  if (!m_surface) return;
  const qreal dpr = devicePixelRatioF();
  const QPointF p = event->position() * dpr;
  vtkRenderWindowInteractor* i = m_vtk->interactor;
  i->SetEventInformationFlipY(
      static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())),
      (event->modifiers() & Qt::ControlModifier) ? 1 : 0,
      (event->modifiers() & Qt::ShiftModifier) ? 1 : 0, 0,
      vtkEvent == vtkCommand::LeftButtonPressEvent && event->type() == QEvent::MouseButtonDblClick
          ? 1
          : 0);
  i->SetAltKey((event->modifiers() & Qt::AltModifier) ? 1 : 0);
  i->InvokeEvent(vtkEvent, event);
}

namespace {
unsigned long pressEventFor(Qt::MouseButton b) {
  switch (b) {
    case Qt::LeftButton:
      return vtkCommand::LeftButtonPressEvent;
    case Qt::MiddleButton:
      return vtkCommand::MiddleButtonPressEvent;
    case Qt::RightButton:
      return vtkCommand::RightButtonPressEvent;
    default:
      return vtkCommand::NoEvent;
  }
}
unsigned long releaseEventFor(Qt::MouseButton b) {
  switch (b) {
    case Qt::LeftButton:
      return vtkCommand::LeftButtonReleaseEvent;
    case Qt::MiddleButton:
      return vtkCommand::MiddleButtonReleaseEvent;
    case Qt::RightButton:
      return vtkCommand::RightButtonReleaseEvent;
    default:
      return vtkCommand::NoEvent;
  }
}
}  // namespace

void VtkOpenGlWidget::mousePressEvent(QMouseEvent* event) {
  if (const unsigned long e = pressEventFor(event->button()); e != vtkCommand::NoEvent)
    forwardMouse(event, e);
  event->accept();
}

void VtkOpenGlWidget::mouseDoubleClickEvent(QMouseEvent* event) {
  mousePressEvent(event);
}

void VtkOpenGlWidget::mouseMoveEvent(QMouseEvent* event) {
  forwardMouse(event, vtkCommand::MouseMoveEvent);
  event->accept();
}

void VtkOpenGlWidget::mouseReleaseEvent(QMouseEvent* event) {
  if (const unsigned long e = releaseEventFor(event->button()); e != vtkCommand::NoEvent)
    forwardMouse(event, e);
  event->accept();
}

void VtkOpenGlWidget::wheelEvent(QWheelEvent* event) {
  if (!m_surface) return;
  const qreal dpr = devicePixelRatioF();
  const QPointF p = event->position() * dpr;
  vtkRenderWindowInteractor* i = m_vtk->interactor;
  i->SetEventInformationFlipY(static_cast<int>(std::lround(p.x())),
                              static_cast<int>(std::lround(p.y())),
                              (event->modifiers() & Qt::ControlModifier) ? 1 : 0,
                              (event->modifiers() & Qt::ShiftModifier) ? 1 : 0);
  const int delta = event->angleDelta().y();
  if (delta > 0)
    i->InvokeEvent(vtkCommand::MouseWheelForwardEvent, event);
  else if (delta < 0)
    i->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, event);
  event->accept();
}

void VtkOpenGlWidget::enterEvent(QEnterEvent* event) {
  if (m_surface) m_vtk->interactor->InvokeEvent(vtkCommand::EnterEvent, event);
  QOpenGLWidget::enterEvent(event);
}

void VtkOpenGlWidget::leaveEvent(QEvent* event) {
  if (m_surface) m_vtk->interactor->InvokeEvent(vtkCommand::LeaveEvent, event);
  QOpenGLWidget::leaveEvent(event);
}

}  // namespace armtrack::ui
