#include "app/gui/home/ExerciseFraming.h"

#include <cmath>
#include <numbers>

#include "ui/ArmFigure.h"

namespace armtrack::gui::home {

ui::CameraView fitView(const ui::CameraView& base, const std::vector<Eigen::Vector3d>& points,
                       double margin) {
  const Eigen::Vector3d back = base.position - base.focalPoint;
  const double distance = back.norm();
  const double half = base.viewAngleDeg * std::numbers::pi / 360.0;
  if (!(distance > 0) || !(half > 0) || !std::isfinite(distance)) return base;
  // What the base view holds: the sphere its view cone touches.
  Eigen::Vector3d centre = base.focalPoint;
  double radius = distance * std::sin(half);
  bool grown = false;
  for (const Eigen::Vector3d& p : points) {
    if (!p.allFinite()) continue;
    const double d = (p - centre).norm();
    if (d + margin <= radius) continue;
    // Grow the sphere just enough to take the point (with its margin) in.
    const double r = (radius + d + margin) / 2;
    if (d > 0) centre += (r - radius) / d * (p - centre);
    radius = r;
    grown = true;
  }
  if (!grown) return base;
  ui::CameraView v = base;
  v.focalPoint = centre;
  v.position = centre + back / distance * (radius / std::sin(half));
  return v;
}

std::vector<Eigen::Vector3d> reachOf(const ArmGeometry& geometry, Side side,
                                     const std::vector<JointVector>& poses, double handLength) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(poses.size() * 3 + 1);
  points.push_back(Eigen::Vector3d::Zero());  // the shoulder
  for (const JointVector& th : poses) {
    const ui::ArmFigure f = ui::armFigure(geometry, th, side);
    points.push_back(f.elbow);
    points.push_back(f.wrist);
    const Eigen::Vector3d fore = f.wrist - f.elbow;
    if (fore.norm() > 0) points.push_back(f.wrist + fore.normalized() * handLength);
  }
  return points;
}

}  // namespace armtrack::gui::home
