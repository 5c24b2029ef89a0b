// Helpers for the tests that look at the 3D arm view on the screen: where a point of the world
// appears by the textbook pinhole model (not VTK's matrices), and a frame known to be on the
// screen.
#pragma once

#include <QCoreApplication>
#include <QImage>
#include <QPointF>
#include <QtTest>
#include <cmath>
#include <numbers>

#include "tests/support/GuiTestMain.h"
#include "ui/ArmView.h"

namespace armtrack::test {

/// Where a world point appears in a widget of size w x h (logical pixels) seen by camera v, by
/// the textbook pinhole model (square pixels), not by VTK's matrices. The view angle spans the
/// shorter side: the height of a wide view, the width of a tall one (ArmScene::prepareFrame).
inline QPointF project(const ui::CameraView& v, const Eigen::Vector3d& p, double w, double h) {
  const Eigen::Vector3d d = (v.focalPoint - v.position).normalized();
  const Eigen::Vector3d up = (v.viewUp - v.viewUp.dot(d) * d).normalized();
  const Eigen::Vector3d right = d.cross(up);
  const Eigen::Vector3d rel = p - v.position;
  const double z = rel.dot(d);
  const double t = std::tan(v.viewAngleDeg * std::numbers::pi / 360.0);
  const double sx = w >= h ? w / h : 1.0, sy = w >= h ? 1.0 : h / w;
  const double xn = rel.dot(right) / (z * t * sx);
  const double yn = rel.dot(up) / (z * t * sy);
  return {(xn + 1.0) / 2.0 * w, (1.0 - yn) / 2.0 * h};
}

/// Draws two frames (the second one makes sure the first reached the screen) and returns the
/// view as the screen shows it (device pixels); a null image when no frame came in 5 s.
inline QImage freshShot(ui::ArmView* view) {
  for (int i = 0; i < 2; ++i) {
    const std::uint64_t start = view->framesRendered();
    view->scheduleFrame();
    if (!QTest::qWaitFor([&] { return view->framesRendered() > start; }, 5000)) return {};
  }
  QCoreApplication::processEvents();
  return grabFromScreen(view);
}

}  // namespace armtrack::test
