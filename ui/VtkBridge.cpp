#include "ui/VtkBridge.h"

#include <vtkCommand.h>
#include <vtkOpenGLState.h>

#include <QOpenGLContext>
#include <QSurfaceFormat>
#include <algorithm>
#include <cmath>

namespace armtrack::ui {

namespace {
VtkBridge::Hooks& hooksOf(void* clientData) {
  return *static_cast<VtkBridge::Hooks*>(clientData);
}
}  // namespace

VtkBridge::VtkBridge(Hooks hooks)
    : m_hooks(std::move(hooks)),
      m_window(vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New()),
      m_interactor(vtkSmartPointer<vtkGenericRenderWindowInteractor>::New()) {
  // The context is the host's: VTK neither owns it, nor renders before initialize(), nor blits
  // to the screen by itself (paint() does).
  m_window->SetOwnContext(false);
  m_window->SetReadyForRendering(false);
  m_window->SetFrameBlitModeToNoBlit();
  m_window->SetMultiSamples(0);
  m_interactor->SetRenderWindow(m_window);
  m_interactor->EnableRenderOn();

  // Make-current: the host's context on its own surface. (For a QOpenGLWidget, not
  // QOpenGLWidget::makeCurrent(), which rebinds Qt's framebuffer behind VTK's state cache and
  // leaves a black view.)
  m_makeCurrent = vtkSmartPointer<vtkCallbackCommand>::New();
  m_makeCurrent->SetClientData(&m_hooks);
  m_makeCurrent->SetCallback(
      [](vtkObject*, unsigned long, void* hooks, void*) { hooksOf(hooks).makeCurrent(); });
  m_isCurrent = vtkSmartPointer<vtkCallbackCommand>::New();
  m_isCurrent->SetClientData(&m_hooks);
  m_isCurrent->SetCallback([](vtkObject*, unsigned long, void* hooks, void* callData) {
    *static_cast<bool*>(callData) = hooksOf(hooks).isCurrent();
  });
  // A frame VTK rendered on its own (the interactor style after a mouse move): show it.
  m_frame = vtkSmartPointer<vtkCallbackCommand>::New();
  m_frame->SetClientData(this);
  m_frame->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    auto* b = static_cast<VtkBridge*>(self);
    if (!b->m_painting) b->m_hooks.requestFrame();
  });
  m_window->AddObserver(vtkCommand::WindowMakeCurrentEvent, m_makeCurrent);
  m_window->AddObserver(vtkCommand::WindowIsCurrentEvent, m_isCurrent);
  m_window->AddObserver(vtkCommand::WindowFrameEvent, m_frame);
}

VtkBridge::~VtkBridge() {
  m_window->RemoveObserver(m_makeCurrent);
  m_window->RemoveObserver(m_isCurrent);
  m_window->RemoveObserver(m_frame);
}

QString VtkBridge::initialize(QOpenGLContext* context, int widthPx, int heightPx) {
  if (!context || !context->isValid())
    return tr("OpenGL is not available, so the 3D view cannot be shown.");
  const QSurfaceFormat f = context->format();
  if (f.majorVersion() * 10 + f.minorVersion() < 32)
    return tr("The 3D view needs OpenGL 3.2; this display offers %1.%2.")
        .arg(f.majorVersion())
        .arg(f.minorVersion());
  m_window->SetReadyForRendering(true);
  m_window->SetMapped(true);
  m_window->SetIsDirect(true);
  m_window->SetSupportsOpenGL(true);
  m_window->SetForceMaximumHardwareLineWidth(1);
  m_window->SetSize(std::max(1, widthPx), std::max(1, heightPx));
  m_window->OpenGLInitContext();
  if (!m_interactor->GetInitialized()) m_interactor->Initialize();
  m_ready = true;
  return {};
}

void VtkBridge::resize(int widthPx, int heightPx) {
  if (!m_ready) return;
  const int w = std::max(1, widthPx), h = std::max(1, heightPx);
  m_interactor->UpdateSize(w, h);
  m_window->SetSize(w, h);
}

void VtkBridge::paint(unsigned int fbo, int widthPx, int heightPx) {
  if (!m_ready) return;
  const int pw = std::max(1, widthPx), ph = std::max(1, heightPx);
  m_painting = true;
  if (m_hooks.beforeRender) m_hooks.beforeRender();
  m_window->Render();  // into VTK's own framebuffer
  m_painting = false;

  vtkOpenGLState* state = m_window->GetState();
  // The host touched the GL state since VTK last looked: record it, restore it after the blit.
  state->Reset();
  state->Push();
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
  state->vtkglViewport(0, 0, pw, ph);
  state->vtkglScissor(0, 0, pw, ph);
  state->vtkglDisable(GL_SCISSOR_TEST);
  const int* size = m_window->GetSize();
  m_window->BlitDisplayFramebuffer(0, 0, 0, size[0], size[1], 0, 0, pw, ph, GL_COLOR_BUFFER_BIT,
                                   GL_NEAREST);
  // What VTK leaves in alpha must not make the view see-through when Qt composes it.
  state->vtkglColorMask(false, false, false, true);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  state->vtkglColorMask(true, true, true, true);
  state->Pop();
  ++m_frames;
}

void VtkBridge::cleanup() {
  if (!m_ready) return;
  m_window->Finalize();  // releases VTK's graphics resources in the (current) context
  m_window->SetReadyForRendering(false);
  m_ready = false;
}

void VtkBridge::mouse(unsigned long vtkEvent, QPointF posPx, bool ctrl, bool shift, bool alt,
                      bool doubleClick) {
  if (!m_ready) return;
  m_interactor->SetEventInformationFlipY(static_cast<int>(std::lround(posPx.x())),
                                         static_cast<int>(std::lround(posPx.y())), ctrl ? 1 : 0,
                                         shift ? 1 : 0, 0, doubleClick ? 1 : 0);
  m_interactor->SetAltKey(alt ? 1 : 0);
  m_interactor->InvokeEvent(vtkEvent, nullptr);
}

void VtkBridge::wheel(QPointF posPx, bool ctrl, bool shift, int deltaY) {
  if (!m_ready || deltaY == 0) return;
  m_interactor->SetEventInformationFlipY(static_cast<int>(std::lround(posPx.x())),
                                         static_cast<int>(std::lround(posPx.y())), ctrl ? 1 : 0,
                                         shift ? 1 : 0);
  m_interactor->InvokeEvent(
      deltaY > 0 ? vtkCommand::MouseWheelForwardEvent : vtkCommand::MouseWheelBackwardEvent,
      nullptr);
}

void VtkBridge::enterLeave(bool enter) {
  if (m_ready)
    m_interactor->InvokeEvent(enter ? vtkCommand::EnterEvent : vtkCommand::LeaveEvent, nullptr);
}

}  // namespace armtrack::ui
