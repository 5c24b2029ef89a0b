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
