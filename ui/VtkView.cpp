#include "ui/VtkView.h"

#include <vtkCommand.h>

#include <QCoreApplication>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLWidget>
#include <QOpenGLWindow>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <cmath>

#include "ui/VtkBridge.h"

namespace armtrack::ui {

namespace {
int devicePixels(int logical, qreal ratio) {
  return std::max(1, static_cast<int>(std::lround(logical * ratio)));
}
}  // namespace

// --- the hosts ------------------------------------------------------------------------------

/// What both hosts do with the bridge; Base is QOpenGLWidget or QOpenGLWindow, which share the
/// names used here (context, makeCurrent, devicePixelRatio, defaultFramebufferObject, ...).
template <class Base>
class VtkView::GlHost : public Base {
 public:
  template <class... Args>
  explicit GlHost(VtkView* view, Args&&... args)
      : Base(std::forward<Args>(args)...), m_view(view) {}
  ~GlHost() override {
    // Disconnect first: the context's aboutToBeDestroyed would call back into a half-destroyed
    // object at exit.
    QObject::disconnect(m_contextDestroyed);
    if (this->context()) {
      this->makeCurrent();
      m_view->m_bridge->cleanup();
      this->doneCurrent();
    }
  }
  /// Our context on the surface saved in initializeGL(). (Not QOpenGLWidget::makeCurrent(),
  /// which rebinds Qt's framebuffer behind VTK's state cache and leaves a black view.)
  void makeBridgeCurrent() {
    if (QOpenGLContext* c = this->context(); c && m_surface) c->makeCurrent(m_surface);
  }
  bool bridgeIsCurrent() const {
    QOpenGLContext* c = this->context();
    return c && c == QOpenGLContext::currentContext() && m_surface && c->surface() == m_surface;
  }

 protected:
  void initializeGL() override {
    m_surface = this->context()->surface();
    QObject::disconnect(m_contextDestroyed);
    m_contextDestroyed =
        QObject::connect(this->context(), &QOpenGLContext::aboutToBeDestroyed, this, [this] {
          this->makeCurrent();
          m_view->m_bridge->cleanup();
        });
    const qreal r = this->devicePixelRatio();
    m_view->m_problem = m_view->m_bridge->initialize(
        this->context(), devicePixels(this->width(), r), devicePixels(this->height(), r));
  }
  void resizeGL(int w, int h) override {
    const qreal r = this->devicePixelRatio();
    m_view->m_bridge->resize(devicePixels(w, r), devicePixels(h, r));
  }
  void paintGL() override {
    if (!m_view->m_bridge->ready()) {  // no usable context: the window colour, not garbage
      const QColor bg = m_view->palette().color(QPalette::Window);
      this->context()->functions()->glClearColor(bg.redF(), bg.greenF(), bg.blueF(), 1.0f);
      this->context()->functions()->glClear(GL_COLOR_BUFFER_BIT);
      return;
    }
    const qreal r = this->devicePixelRatio();
    m_view->m_bridge->paint(this->defaultFramebufferObject(), devicePixels(this->width(), r),
                            devicePixels(this->height(), r));
    emit m_view->frameRendered();
  }

  VtkView* m_view;
  QSurface* m_surface = nullptr;
  QMetaObject::Connection m_contextDestroyed;
};

/// A QOpenGLWidget: mouse events it ignores reach the view, its parent.
class VtkView::WidgetHost final : public GlHost<QOpenGLWidget> {
 public:
  explicit WidgetHost(VtkView* view) : GlHost(view, view) {
    setFocusPolicy(Qt::NoFocus);  // the view takes the keys
    setMinimumSize(1, 1);
  }
};

/// A QOpenGLWindow in a window container: its input is sent on to the view.
class VtkView::WindowHost final : public GlHost<QOpenGLWindow> {
 public:
  explicit WindowHost(VtkView* view) : GlHost(view, QOpenGLWindow::NoPartialUpdate) {}

 protected:
  void mousePressEvent(QMouseEvent* e) override {
    m_view->setFocus(Qt::MouseFocusReason);
    QCoreApplication::sendEvent(m_view, e);
  }
  void mouseReleaseEvent(QMouseEvent* e) override { QCoreApplication::sendEvent(m_view, e); }
  void mouseMoveEvent(QMouseEvent* e) override { QCoreApplication::sendEvent(m_view, e); }
  void mouseDoubleClickEvent(QMouseEvent* e) override { QCoreApplication::sendEvent(m_view, e); }
  void wheelEvent(QWheelEvent* e) override { QCoreApplication::sendEvent(m_view, e); }
  void keyPressEvent(QKeyEvent* e) override { QCoreApplication::sendEvent(m_view, e); }
  void keyReleaseEvent(QKeyEvent* e) override { QCoreApplication::sendEvent(m_view, e); }
};

// --- the view --------------------------------------------------------------------------------

VtkView::Host VtkView::defaultHost() {
  const QString h = qEnvironmentVariable("ARMTRACK_VTK_HOST").toLower();
  return h == QLatin1String("widget") ? Host::Widget : Host::Window;
}

VtkView::VtkView(QWidget* parent, Host host) : QWidget(parent), m_host(host) {
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(1, 1);
  VtkBridge::Hooks hooks;
  hooks.makeCurrent = [this] {
    if (m_widgetHost) m_widgetHost->makeBridgeCurrent();
    if (m_windowHost) m_windowHost->makeBridgeCurrent();
  };
  hooks.isCurrent = [this] {
    return m_widgetHost ? m_widgetHost->bridgeIsCurrent()
                        : m_windowHost && m_windowHost->bridgeIsCurrent();
  };
  hooks.requestFrame = [this] { scheduleFrame(); };
  hooks.beforeRender = [this] { prepareRender(); };
  m_bridge = std::make_unique<VtkBridge>(std::move(hooks));

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  if (host == Host::Widget) {
    m_widgetHost = new WidgetHost(this);
    layout->addWidget(m_widgetHost);
  } else {
    m_windowHost = new WindowHost(this);
    m_container = QWidget::createWindowContainer(m_windowHost, this);
    m_container->setFocusPolicy(Qt::NoFocus);
    m_container->setMinimumSize(1, 1);
    layout->addWidget(m_container);
  }
}

VtkView::~VtkView() {
  // The hosts clean up VTK's OpenGL resources while the bridge still exists.
  delete m_widgetHost;
  m_widgetHost = nullptr;
  delete m_container;  // owns the window host
  m_container = nullptr;
  m_windowHost = nullptr;
}

vtkGenericOpenGLRenderWindow* VtkView::renderWindow() const {
  return m_bridge->window();
}

vtkRenderWindowInteractor* VtkView::interactor() const {
  return m_bridge->interactor();
}

std::uint64_t VtkView::framesRendered() const {
  return m_bridge->frames();
}

void VtkView::scheduleFrame() {
  if (m_widgetHost) m_widgetHost->update();
  if (m_windowHost) m_windowHost->update();
}

qreal VtkView::hostPixelRatio() const {
  return m_windowHost ? m_windowHost->devicePixelRatio() : devicePixelRatio();
}

void VtkView::forwardMouse(QMouseEvent* event, unsigned long vtkEvent) {
  const QPointF p = event->position() * hostPixelRatio();
  const Qt::KeyboardModifiers m = event->modifiers();
  m_bridge->mouse(vtkEvent, p, m & Qt::ControlModifier, m & Qt::ShiftModifier, m & Qt::AltModifier,
                  event->type() == QEvent::MouseButtonDblClick);
  event->accept();
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

void VtkView::mousePressEvent(QMouseEvent* event) {
  if (const unsigned long e = pressEventFor(event->button()); e != vtkCommand::NoEvent)
    forwardMouse(event, e);
}

void VtkView::mouseDoubleClickEvent(QMouseEvent* event) {
  mousePressEvent(event);
}

void VtkView::mouseMoveEvent(QMouseEvent* event) {
  forwardMouse(event, vtkCommand::MouseMoveEvent);
}

void VtkView::mouseReleaseEvent(QMouseEvent* event) {
  if (const unsigned long e = releaseEventFor(event->button()); e != vtkCommand::NoEvent)
    forwardMouse(event, e);
}

void VtkView::wheelEvent(QWheelEvent* event) {
  const QPointF p = event->position() * hostPixelRatio();
  m_bridge->wheel(p, event->modifiers() & Qt::ControlModifier,
                  event->modifiers() & Qt::ShiftModifier, event->angleDelta().y());
  event->accept();
}

void VtkView::enterEvent(QEnterEvent* event) {
  m_bridge->enterLeave(true);
  QWidget::enterEvent(event);
}

void VtkView::leaveEvent(QEvent* event) {
  m_bridge->enterLeave(false);
  QWidget::leaveEvent(event);
}

}  // namespace armtrack::ui
