// The 3D arm view: the arm model drawn from the newest estimate, with the IMUs on their straps,
// the optical measurements beside it, an optional translucent target arm (demonstrations,
// review overlays), the trunk on the patient's side and a floor grid. Hosted in a Qt 6
// QOpenGLWindow or QOpenGLWidget (ui/VtkView.h). docs/gui.md describes it.
#pragma once

#include <Eigen/Core>
#include <QTimer>
#include <memory>
#include <optional>

#include "core/io/Recording.h"
#include "core/kinematics/ArmModel.h"
#include "core/kinematics/Side.h"
#include "core/kinematics/Trunk.h"
#include "ui/VtkView.h"

class QAction;

namespace armtrack::ui {

class ArmScene;

/// A camera, in metres in the shoulder frame of the arm's side.
struct CameraView {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d focalPoint = Eigen::Vector3d::Zero();
  Eigen::Vector3d viewUp = -Eigen::Vector3d::UnitX();
  double viewAngleDeg = 30.0;  ///< vertical field of view
};

/// Optical measurements to draw beside the estimate (each empty when not measured).
struct OpticalMarks {
  std::optional<Eigen::Vector3d> elbow, wrist;        ///< Kinect positions, shoulder frame (m)
  std::optional<Eigen::Vector2d> camElbow, camWrist;  ///< webcam marker pixels (u, v)
};

/// Draws the newest pose it was given, at most refreshRate() times a second: setPose() and the
/// other setters only store what to draw, so a caller may feed every sample without costing a
/// frame each. The camera orbits with the left mouse button, pans with the middle one (or
/// Shift + left), zooms with the wheel or the right button; keys: arrows orbit, + and - zoom,
/// Home or R resets the view. GUI thread only.
class ArmView : public VtkView {
  Q_OBJECT
 public:
  explicit ArmView(QWidget* parent = nullptr, Host host = defaultHost());
  ~ArmView() override;

  /// The arm's segment lengths and sensor mounting, its side, the up direction (unit, shoulder
  /// frame) and the webcam's model (to draw marker pixels as rays; none: pixels are not drawn).
  void setArm(const ArmGeometry& geometry, Side side,
              const Eigen::Vector3d& up = -Eigen::Vector3d::UnitX(),
              const std::optional<CameraParams>& camera = std::nullopt);
  /// The estimated joint angles (rad). A vector with a non-finite value is ignored (the last
  /// good pose stays) and counted in rejectedPoses().
  void setPose(const JointVector& th);
  /// The trunk's flexion, lateral bending and axial rotation (rad, patient terms,
  /// core/kinematics/Trunk.h), e.g. the estimate's when a sternum sensor measures them; empty:
  /// upright. The torso leans and turns about the hip and the arm hangs from the moving shoulder.
  /// Non-finite angles are ignored (the last good trunk stays) and counted in rejectedPoses().
  void setTrunk(const std::optional<TrunkAngles>& angles);
  const std::optional<TrunkAngles>& trunk() const { return m_trunk; }
  /// The sternum IMU on the chest, when the session has one (its mounting from the sidecar or
  /// the calibration; defaultTrunkMount(side) when only its presence is known); empty: none.
  void setSternumImu(const std::optional<TrunkMount>& mount);
  const std::optional<TrunkMount>& sternumImu() const { return m_sternum; }
  /// A second, translucent arm (a demonstration or another session); empty hides it.
  void setTargetPose(const std::optional<JointVector>& th);
  void setOptical(const OpticalMarks& marks);
  const JointVector& pose() const { return m_pose; }
  std::uint64_t rejectedPoses() const { return m_rejected; }

  /// Frames per second at most (default 60); 0 draws only when scheduleFrame() or
  /// updateIfChanged()
  /// is called.
  void setRefreshRate(double hz);
  /// Schedules a frame if something changed since the last one (for an owner that drives the
  /// frames from its own timer, so that every view repaints in one pass).
  void updateIfChanged() {
    if (m_dirty) scheduleFrame();
  }
  double refreshRate() const { return m_refreshHz; }

  CameraView camera() const;
  void setCamera(const CameraView& view);
  /// The action that resets the view (Home), for menus and tool bars.
  QAction* resetViewAction() const { return m_resetView; }

 public slots:
  void resetView();

 protected:
  void keyPressEvent(QKeyEvent* event) override;
  void changeEvent(QEvent* event) override;
  void contextMenuEvent(QContextMenuEvent* event) override;
  void prepareRender() override;

 private:
  void markDirty();
  void setSideLabelFor(Side side);
  void applyPalette();
  void retranslateUi();

  std::unique_ptr<ArmScene> m_scene;
  QTimer m_refresh;
  double m_refreshHz = 60.0;
  bool m_dirty = true;
  JointVector m_pose = JointVector::Zero();
  std::optional<TrunkAngles> m_trunk;
  std::optional<TrunkMount> m_sternum;
  Side m_side = Side::Right;
  std::uint64_t m_rejected = 0;
  QAction* m_resetView = nullptr;
  QString m_defaultName;  // the accessible name given here, in the language it was made in
};

}  // namespace armtrack::ui
