#include "devices/kinect/KinectProcessing.h"

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <stdexcept>
#include <vector>

namespace armtrack::devices::kinect {

KinectProcessor::KinectProcessor(KinectProcessingParams params, webcam::MarkerDetector detector,
                                 std::optional<webcam::MarkerDetector> shoulder)
    : m_params(std::move(params)),
      m_detector(std::move(detector)),
      m_shoulder(std::move(shoulder)) {
  const webcam::Intrinsics& in = m_params.colour;
  if (!(in.fx > 0.0) || !(in.fy > 0.0) || !std::isfinite(in.cx) || !std::isfinite(in.cy))
    throw std::invalid_argument(
        "the colour camera's intrinsics need fx, fy > 0 and a finite "
        "principal point");
  if (!webcam::isRotation(m_params.pose.R, 1e-6))
    throw std::invalid_argument("the camera pose's R is not a rotation");
  if (m_params.depthWindowPx < 1 || m_params.depthWindowPx > 31 || m_params.depthWindowPx % 2 == 0)
    throw std::invalid_argument("the depth window must be an odd number of pixels from 1 to 31");
  if (!(m_params.minDepth >= 0.0) || !(m_params.maxDepth > m_params.minDepth))
    throw std::invalid_argument("the depth range must satisfy 0 <= min < max");
  m_K = in.cameraMatrix();
  m_dist = in.distCoeffs();
}

std::optional<double> KinectProcessor::depthAt(const cv::Point2d& pixel,
                                               const cv::Mat& depthMm) const {
  if (!std::isfinite(pixel.x) || !std::isfinite(pixel.y)) return std::nullopt;
  const int half = m_params.depthWindowPx / 2;
  const int u = static_cast<int>(std::lround(pixel.x));
  const int v = static_cast<int>(std::lround(pixel.y));
  std::vector<std::uint16_t> values;
  values.reserve(static_cast<std::size_t>(m_params.depthWindowPx * m_params.depthWindowPx));
  const double lo = m_params.minDepth * 1000.0, hi = m_params.maxDepth * 1000.0;
  for (int y = std::max(0, v - half); y <= std::min(depthMm.rows - 1, v + half); ++y)
    for (int x = std::max(0, u - half); x <= std::min(depthMm.cols - 1, u + half); ++x) {
      const std::uint16_t d = depthMm.at<std::uint16_t>(y, x);
      if (d != 0 && d >= lo && d <= hi) values.push_back(d);
    }
  // At least a third of the window must see the surface; fewer is an edge or a hole.
  const std::size_t needed = std::max<std::size_t>(
      1, static_cast<std::size_t>(m_params.depthWindowPx * m_params.depthWindowPx) / 3);
  if (values.size() < needed) return std::nullopt;
  auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid / 1000.0;
}

cv::Vec3d KinectProcessor::toShoulder(const cv::Point2d& pixel, double z) const {
  std::vector<cv::Point2d> in{pixel}, out;
  cv::undistortPoints(in, out, m_K, m_dist);
  const cv::Vec3d ray(out[0].x, out[0].y, 1.0);
  cv::Vec3d pCam = z * ray;
  if (m_params.jointDepth != 0.0) pCam += m_params.jointDepth * cv::normalize(ray);
  return m_params.pose.R.t() * (pCam - m_params.pose.t);
}

KinectFrame KinectProcessor::process(const cv::Mat& bgr, const cv::Mat& depthMm) {
  if (bgr.type() != CV_8UC3) throw std::invalid_argument("the colour frame must be 8-bit BGR");
  if (depthMm.type() != CV_16UC1) throw std::invalid_argument("the depth frame must be 16-bit");
  if (bgr.size() != depthMm.size())
    throw std::invalid_argument(
        "the depth frame is not registered to the colour frame (sizes "
        "differ)");
  KinectFrame f;
  f.pixels = m_detector.detect(bgr);
  if (m_shoulder) f.shoulderPixel = m_shoulder->detect(bgr).wrist;
  for (auto [pixel, out] : {std::pair{&f.pixels.wrist, &f.wrist},
                            {&f.pixels.elbow, &f.elbow},
                            {&f.shoulderPixel, &f.shoulder}}) {
    if (!*pixel) continue;
    const auto z = depthAt(**pixel, depthMm);
    if (!z) {
      ++f.depthMissing;
      continue;
    }
    *out = toShoulder(**pixel, *z);
  }
  return f;
}

}  // namespace armtrack::devices::kinect
