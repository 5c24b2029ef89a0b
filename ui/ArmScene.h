// The VTK scene of the 3D arm view (internal to ui/): the estimated arm, an optional translucent
// target arm, the IMUs on their straps, the optical measurements, the trunk, a floor grid and the
// side's label. Plain VTK; ArmView hosts it in a Qt widget.
#pragma once

#include <vtkSmartPointer.h>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

#include "core/io/Recording.h"
#include "core/kinematics/Trunk.h"
#include "ui/ArmFigure.h"

class vtkRenderer;

namespace armtrack::ui {

struct CameraView;
struct OpticalMarks;

class ArmScene {
 public:
  ArmScene();
  ~ArmScene();

  vtkRenderer* renderer() const;

  /// The arm's dimensions, its side and the direction up (unit, shoulder frame). Resets the
  /// camera when the side or up changes.
  void setArm(const ArmGeometry& geometry, Side side, const Eigen::Vector3d& up);
  /// The webcam's model, to draw marker pixels as rays (none or invalid: pixels not drawn).
  void setCameraModel(const std::optional<CameraParams>& camera);
  void setPose(const JointVector& th);
  /// The trunk's flexion, lateral bending and axial rotation (rad, patient terms,
  /// core/kinematics/Trunk.h); empty: upright. The torso, the head and the arms (which hang from
  /// the moving shoulder) turn with it about the hip pivot; the floor, the camera and the optical
  /// marks (world frame) stay.
  void setTrunk(const std::optional<TrunkAngles>& angles);
  /// The sternum IMU (when the session has one): drawn on the chest at the mounting's height
  /// and side, in its orientation, turning with the trunk. Empty, or a mounting that is not a
  /// finite rotation: none drawn.
  void setSternumImu(const std::optional<TrunkMount>& mount);
  /// The drawn sternum IMU's axes and centre (world), for the tests; empty when none is drawn.
  std::optional<Eigen::Isometry3d> sternumImuPose() const;
  /// The pivot the drawn trunk turns about (shoulder frame, m): 0.45 m below and 0.15 m medial to
  /// the shoulder, the simulator's default hip (core/simulation/TrunkMotion.h).
  Eigen::Vector3d hipPivot() const;
  /// The trunk's pose in the world as drawn: p_world = pose * p_trunk, i.e. s + R p with
  /// R = trunkRotation(angles) and s = h - R h (docs/trunk.md).
  Eigen::Isometry3d trunkPose() const;
  /// What is drawn, for the tests: the estimated arm in the world and the actors' matrices.
  const ArmFigure& figure() const;
  Eigen::Vector3d shoulderActorCentre() const;
  /// The torso box's axes (unit columns: medial, up, forward as drawn) and its centre.
  Eigen::Matrix3d torsoAxes() const;
  Eigen::Vector3d torsoCentre() const;
  Eigen::Vector3d headCentre() const;
  void setTargetPose(const std::optional<JointVector>& th);
  void setOptical(const OpticalMarks& marks);
  void setSideLabel(const std::string& text);
  /// Scales the label's font (the device pixel ratio).
  void setLabelScale(double scale);
  /// Dark or light background and colours to match.
  void setDark(bool dark);

  void resetCamera();
  CameraView camera() const;
  void setCamera(const CameraView& view);
  /// Turns the camera about the focal point (deg): azimuth about the up direction, elevation
  /// about the horizontal axis.
  void orbit(double azimuthDeg, double elevationDeg);
  /// Moves the camera towards the focal point (factor > 1) or away (< 1).
  void zoom(double factor);
  /// Before each render: fits the clipping range to what is shown.
  void prepareFrame();

 private:
  struct Impl;
  std::unique_ptr<Impl> m;
};

}  // namespace armtrack::ui
