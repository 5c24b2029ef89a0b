// The 3D view's framing for an exercise: the default view (ui/ArmView) frames the space an arm
// usually reaches round the shoulder; a shoulder raised high takes the light target arm out of
// it. fitView() widens the view, from the same direction, until it holds given points too.
// Plain C++ and Eigen (with ui/ArmFigure), tested without a display.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/kinematics/ArmModel.h"
#include "core/kinematics/Side.h"
#include "ui/ArmView.h"

namespace armtrack::gui::home {

/// base unchanged when the sphere it frames (round its focal point, as wide as its view angle
/// shows at its distance) already holds every point with margin (m) to spare; otherwise the
/// camera looks from the same direction at the centre of a sphere holding both, from a distance
/// at which that sphere fills its view angle. Non-finite points are ignored.
ui::CameraView fitView(const ui::CameraView& base, const std::vector<Eigen::Vector3d>& points,
                       double margin = 0.05);

/// The points the arm passes through in the poses (shoulder, elbow, wrist and the hand's end,
/// about handLength past the wrist), in the 3D view's frame for that side.
std::vector<Eigen::Vector3d> reachOf(const ArmGeometry& geometry, Side side,
                                     const std::vector<JointVector>& poses,
                                     double handLength = 0.1);

}  // namespace armtrack::gui::home
