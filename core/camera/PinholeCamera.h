// Pinhole camera with OpenCV's distortion model (docs/camera.md). OpenCV stays inside the .cpp:
// this header exposes Eigen types only.
#pragma once

#include <Eigen/Core>

#include "core/camera/CameraParams.h"

namespace armtrack {

/// Projects shoulder-frame points to pixels and pixels back to rays, following cv::projectPoints
/// and cv::undistortPoints with the parameters of a CameraParams (p_cam = R p_shoulder + t).
class PinholeCamera {
 public:
  /// Throws std::invalid_argument when fx or fy is not a positive finite number, a coefficient is
  /// not finite, or R is not a rotation (to 1e-3).
  explicit PinholeCamera(const CameraParams& params);

  /// Pixel (u, v) of a point in the shoulder frame (m), distortion included. Returns false, and
  /// leaves pixel unchanged, when the point is not in front of the camera (z_cam <= 1e-6) or lies
  /// outside the region where the radial distortion is one-to-one (see validRadius2()).
  bool project(const Eigen::Vector3d& pShoulder, Eigen::Vector2d& pixel) const;
  /// Same, with jacobian = d(pixel)/d(pShoulder) (pixels per m). Both are left unchanged on false.
  bool project(const Eigen::Vector3d& pShoulder, Eigen::Vector2d& pixel,
               Eigen::Matrix<double, 2, 3>& jacobian) const;

  /// The ray seen at a pixel: origin = camera centre and unit direction, both in the shoulder
  /// frame.
  void ray(const Eigen::Vector2d& pixel, Eigen::Vector3d& origin, Eigen::Vector3d& direction) const;

  const CameraParams& params() const { return m_params; }
  /// Largest squared normalised radius (x/z)^2 + (y/z)^2 that project() accepts: where the radial
  /// distortion r (1 + k1 r^2 + k2 r^4 + k3 r^6) stops increasing; +infinity when it never does.
  double validRadius2() const { return m_validRadius2; }

 private:
  /// Projects a camera-frame point; optionally d(pixel)/d(pCam).
  bool projectCamera(const Eigen::Vector3d& pCam, Eigen::Vector2d& pixel,
                     Eigen::Matrix<double, 2, 3>* dPixelDpCam) const;

  CameraParams m_params;
  Eigen::Matrix3d m_Rinv;  ///< inverse of params.R (its transpose for an exact rotation)
  double m_validRadius2;
};

/// A camera `distance` m in front of the shoulder (at +distance along y0), looking back at it:
/// image down = +x0, optical axis = -y0, image right = -z0. fx = fy = 600, (cx, cy) = (320, 240),
/// k1 = -0.1, k2 = 0.02, p1 = p2 = k3 = 0.
CameraParams frontCamera(double distance = 2.0);

}  // namespace armtrack
