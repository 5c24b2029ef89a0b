#include "ui/ArmView.h"

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include <QAction>
#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMenu>
#include <cmath>

#include "ui/ArmScene.h"

namespace armtrack::ui {

namespace {
bool isDark(const QPalette& p) {
  return p.color(QPalette::Window).lightness() < 128;
}
}  // namespace

ArmView::ArmView(QWidget* parent, Host host) : VtkView(parent, host), m_scene(new ArmScene) {
  renderWindow()->AddRenderer(m_scene->renderer());
  auto style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
  style->SetDefaultRenderer(m_scene->renderer());
  interactor()->SetInteractorStyle(style);
  setSideLabelFor(Side::Right);

  m_resetView = new QAction(this);
  m_resetView->setShortcut(QKeySequence(Qt::Key_Home));
  m_resetView->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  connect(m_resetView, &QAction::triggered, this, &ArmView::resetView);
  addAction(m_resetView);

  applyPalette();
  retranslateUi();
  m_refresh.setTimerType(Qt::PreciseTimer);
  connect(&m_refresh, &QTimer::timeout, this, [this] {
    if (m_dirty && isVisible()) scheduleFrame();
  });
  setRefreshRate(m_refreshHz);
}

ArmView::~ArmView() = default;

void ArmView::retranslateUi() {
  // (An owner may give the view another accessible name; the description stays general.)
  if (accessibleName().isEmpty() || accessibleName() == m_defaultName) {
    m_defaultName = tr("3D view of the arm");
    setAccessibleName(m_defaultName);
  }
  setAccessibleDescription(
      tr("The estimated arm with its sensors. Arrow keys turn the view, plus and minus zoom, "
         "Home resets the view."));
  setToolTip(tr("Drag to turn the view, scroll to zoom; Home resets it"));
  m_resetView->setText(tr("Reset view"));
  setSideLabelFor(m_side);
  markDirty();
}

void ArmView::setSideLabelFor(Side side) {
  m_scene->setSideLabel(side == Side::Left ? tr("Left arm").toStdString()
                                           : tr("Right arm").toStdString());
}

void ArmView::setArm(const ArmGeometry& geometry, Side side, const Eigen::Vector3d& up,
                     const std::optional<CameraParams>& camera) {
  m_side = side;
  m_scene->setArm(geometry, side, up);
  m_scene->setCameraModel(camera);
  setSideLabelFor(side);
  markDirty();
}

void ArmView::setPose(const JointVector& th) {
  if (!th.allFinite()) {
    ++m_rejected;
    return;
  }
  m_pose = th;
  m_scene->setPose(th);
  markDirty();
}

void ArmView::setTrunk(const std::optional<TrunkAngles>& angles) {
  if (angles && !angles->allFinite()) {
    ++m_rejected;
    return;
  }
  if (angles == m_trunk) return;
  m_trunk = angles;
  m_scene->setTrunk(angles);
  markDirty();
}

void ArmView::setSternumImu(const std::optional<TrunkMount>& mount) {
  m_sternum = mount;
  m_scene->setSternumImu(mount);
  markDirty();
}

void ArmView::setTargetPose(const std::optional<JointVector>& th) {
  if (th && !th->allFinite()) {
    ++m_rejected;
    return;
  }
  m_scene->setTargetPose(th);
  markDirty();
}

void ArmView::setOptical(const OpticalMarks& marks) {
  m_scene->setOptical(marks);
  markDirty();
}

void ArmView::setRefreshRate(double hz) {
  m_refreshHz = std::isfinite(hz) && hz > 0.0 ? std::min(hz, 240.0) : 0.0;
  if (m_refreshHz > 0.0) {
    m_refresh.start(static_cast<int>(std::lround(1000.0 / m_refreshHz)));
  } else {
    m_refresh.stop();
  }
}

CameraView ArmView::camera() const {
  return m_scene->camera();
}

void ArmView::setCamera(const CameraView& view) {
  m_scene->setCamera(view);
  markDirty();
}

void ArmView::resetView() {
  m_scene->resetCamera();
  markDirty();
}

void ArmView::markDirty() {
  m_dirty = true;  // drawn at the next refresh tick (or when the owner asks for a frame)
}

void ArmView::prepareRender() {
  m_scene->setLabelScale(devicePixelRatioF());
  m_scene->prepareFrame();
  m_dirty = false;
}

void ArmView::applyPalette() {
  m_scene->setDark(isDark(palette()));
  markDirty();
}

void ArmView::keyPressEvent(QKeyEvent* event) {
  constexpr double kStepDeg = 5.0;
  switch (event->key()) {
    case Qt::Key_Left:
      m_scene->orbit(-kStepDeg, 0.0);
      break;
    case Qt::Key_Right:
      m_scene->orbit(kStepDeg, 0.0);
      break;
    case Qt::Key_Up:
      m_scene->orbit(0.0, kStepDeg);
      break;
    case Qt::Key_Down:
      m_scene->orbit(0.0, -kStepDeg);
      break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
    case Qt::Key_PageUp:
      m_scene->zoom(1.15);
      break;
    case Qt::Key_Minus:
    case Qt::Key_PageDown:
      m_scene->zoom(1.0 / 1.15);
      break;
    case Qt::Key_Home:
    case Qt::Key_R:
      m_scene->resetCamera();
      break;
    default:
      VtkView::keyPressEvent(event);
      return;
  }
  markDirty();
  scheduleFrame();
  event->accept();
}

void ArmView::changeEvent(QEvent* event) {
  if (event->type() == QEvent::PaletteChange) applyPalette();
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  VtkView::changeEvent(event);
}

void ArmView::contextMenuEvent(QContextMenuEvent* event) {
  // The right button zooms (VTK's trackball style): the menu is for the keyboard's menu key.
  if (event->reason() == QContextMenuEvent::Mouse) return;
  QMenu menu(this);
  menu.addAction(m_resetView);
  menu.exec(event->globalPos());
}

}  // namespace armtrack::ui
