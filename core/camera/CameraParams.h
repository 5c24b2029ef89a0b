// A calibrated camera's parameters (docs/camera.md): what a camera file, a recording's sidecar
// and a device's stream carry, and what PinholeCamera projects with.
#pragma once

#include <Eigen/Core>
#include <array>

namespace armtrack {

/// Pinhole camera with OpenCV's distortion model; R, t map shoulder-frame points to the camera.
struct CameraParams {
  double fx = 0, fy = 0, cx = 0, cy = 0;  ///< pixels
  std::array<double, 5> dist{};           ///< k1, k2, p1, p2, k3
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();  ///< m
};

}  // namespace armtrack
