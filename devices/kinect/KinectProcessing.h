// The Kinect v1's image side, without Qt or libfreenect (docs/devices/kinect.md): the wrist and
// elbow markers, and optionally a shoulder marker, found in the colour image (the webcam's
// detectors), their depth read from the depth image registered to it, and the 3D points moved
// into the registered frame (the shoulder frame at registration: the world frame).
#pragma once

#include <opencv2/core.hpp>
#include <optional>

#include "devices/vision/CameraCalibration.h"
#include "devices/vision/MarkerDetection.h"

namespace armtrack::devices::kinect {

struct KinectProcessingParams {
  /// The colour camera's intrinsics; a registered depth image shares them.
  webcam::Intrinsics colour;
  /// The colour camera's pose: p_camera = R p_shoulder + t (m).
  webcam::Extrinsics pose;
  /// Side of the square of depth pixels around a marker whose median is its depth (odd, px;
  /// default 5).
  int depthWindowPx = 5;
  /// Depths outside [minDepth, maxDepth] m are treated as missing (default 0.4-4.5 m, the
  /// Kinect v1's working range).
  double minDepth = 0.4, maxDepth = 4.5;
  /// m from the marker's surface to the joint centre, along the viewing ray (default 0: the
  /// marker's own surface point).
  double jointDepth = 0.0;
};

/// One processed frame. A position is absent when its marker was not found, or when no valid
/// depth lies under it (then depthMissing counts it).
struct KinectFrame {
  webcam::MarkerPair pixels;                 ///< in the colour image, pixels
  std::optional<cv::Point2d> shoulderPixel;  ///< the shoulder marker, with a shoulder detector
  std::optional<cv::Vec3d> wrist;            ///< registered frame, m
  std::optional<cv::Vec3d> elbow;            ///< registered frame, m
  std::optional<cv::Vec3d> shoulder;         ///< registered frame, m (the marker's point)
  int depthMissing = 0;                      ///< markers seen without a usable depth (0-3)
};

/// Turns colour + registered depth frames into marker positions in the registered frame. Not
/// thread-safe; one per thread.
class KinectProcessor {
 public:
  /// Throws std::invalid_argument when the intrinsics are not positive, R is not a rotation, the
  /// window is not odd and within 1-31, or the depth range is empty. `shoulder`, when given, finds
  /// the shoulder marker as its *wrist* marker (a detector of its own, so the webcam's pair of
  /// markers stays as it is; its elbow result is ignored).
  KinectProcessor(KinectProcessingParams params, webcam::MarkerDetector detector,
                  std::optional<webcam::MarkerDetector> shoulder = std::nullopt);

  /// bgr: 8-bit BGR colour image; depthMm: 16-bit depth in mm (0 = no reading), registered to the
  /// colour image (same size, pixel for pixel). Throws std::invalid_argument when the types or
  /// sizes do not fit.
  KinectFrame process(const cv::Mat& bgr, const cv::Mat& depthMm);

  /// The median valid depth (m) around a pixel, if any.
  std::optional<double> depthAt(const cv::Point2d& pixel, const cv::Mat& depthMm) const;
  /// The registered-frame point (m) seen at pixel at depth z (m, along the optical axis), plus
  /// jointDepth along the ray.
  cv::Vec3d toShoulder(const cv::Point2d& pixel, double z) const;

  const KinectProcessingParams& params() const { return m_params; }

 private:
  KinectProcessingParams m_params;
  webcam::MarkerDetector m_detector;
  std::optional<webcam::MarkerDetector> m_shoulder;
  cv::Matx33d m_K;
  cv::Mat m_dist;
};

}  // namespace armtrack::devices::kinect
