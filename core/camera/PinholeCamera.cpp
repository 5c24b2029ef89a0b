#include "core/camera/PinholeCamera.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

namespace armtrack {
namespace {

constexpr double kMinDepth = 1e-6;  // m: nearer (or behind) points do not project

cv::Matx33d cameraMatrix(const CameraParams& p) {
  return {p.fx, 0.0, p.cx, 0.0, p.fy, p.cy, 0.0, 0.0, 1.0};
}

cv::Matx<double, 5, 1> distCoeffs(const CameraParams& p) {
  return {p.dist[0], p.dist[1], p.dist[2], p.dist[3], p.dist[4]};
}

/// Smallest s = r^2 > 0 where d/dr [r (1 + k1 r^2 + k2 r^4 + k3 r^6)] reaches zero, i.e. where the
/// radial distortion folds back; +infinity when it does not below s = 1e4 (about 89.4 degrees).
double foldRadius2(double k1, double k2, double k3) {
  const auto slope = [&](double s) { return 1.0 + s * (3.0 * k1 + s * (5.0 * k2 + s * 7.0 * k3)); };
  constexpr double kMaxS = 1e4;
  double lo = 0.0;
  while (lo < kMaxS) {
    const double hi = lo + std::max(1e-4, 1e-3 * lo);
    if (slope(hi) <= 0.0) {
      double a = lo, b = hi;  // slope(a) > 0 >= slope(b)
      for (int i = 0; i < 100 && b - a > 1e-15 * b; ++i) {
        const double m = 0.5 * (a + b);
        (slope(m) > 0.0 ? a : b) = m;
      }
      return a;
    }
    lo = hi;
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace

PinholeCamera::PinholeCamera(const CameraParams& params) : m_params(params) {
  const auto& p = params;
  if (!(std::isfinite(p.fx) && std::isfinite(p.fy) && p.fx > 0.0 && p.fy > 0.0)) {
    throw std::invalid_argument("PinholeCamera: fx and fy must be positive and finite");
  }
  bool finite = std::isfinite(p.cx) && std::isfinite(p.cy) && p.R.allFinite() && p.t.allFinite();
  for (double d : p.dist) finite = finite && std::isfinite(d);
  if (!finite) throw std::invalid_argument("PinholeCamera: non-finite camera parameter");
  const double orthoError =
      (p.R.transpose() * p.R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(orthoError <= 1e-3 && p.R.determinant() > 0.0)) {
    throw std::invalid_argument("PinholeCamera: R is not a rotation matrix");
  }
  m_Rinv = p.R.inverse();
  m_validRadius2 = foldRadius2(p.dist[0], p.dist[1], p.dist[4]);
}

bool PinholeCamera::projectCamera(const Eigen::Vector3d& pCam, Eigen::Vector2d& pixel,
                                  Eigen::Matrix<double, 2, 3>* dPixelDpCam) const {
  if (!pCam.allFinite() || pCam.z() <= kMinDepth) return false;
  const double xn = pCam.x() / pCam.z(), yn = pCam.y() / pCam.z();
  if (!(xn * xn + yn * yn < m_validRadius2)) return false;

  // The point is already in camera coordinates, so rvec = tvec = 0; then OpenCV's d/d(tvec) is
  // d(pixel)/d(pCam). Matrix headers over stack buffers keep OpenCV from allocating outputs.
  double object[3] = {pCam.x(), pCam.y(), pCam.z()};
  double image[2] = {0.0, 0.0};
  double jac[2 * 15];  // columns: rvec(3), tvec(3), f(2), c(2), dist(5)
  cv::Mat objectMat(1, 1, CV_64FC3, object);
  cv::Mat imageMat(1, 1, CV_64FC2, image);
  const cv::Vec3d zero(0.0, 0.0, 0.0);
  const cv::Matx33d K = cameraMatrix(m_params);
  const cv::Matx<double, 5, 1> dist = distCoeffs(m_params);
  if (dPixelDpCam) {
    cv::Mat jacMat(2, 15, CV_64F, jac);
    cv::projectPoints(objectMat, zero, zero, K, dist, imageMat, jacMat);
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 3; ++c) (*dPixelDpCam)(r, c) = jacMat.at<double>(r, 3 + c);
    }
  } else {
    cv::projectPoints(objectMat, zero, zero, K, dist, imageMat);
  }
  const cv::Vec2d uv = imageMat.at<cv::Vec2d>(0);
  pixel = {uv[0], uv[1]};
  return true;
}

bool PinholeCamera::project(const Eigen::Vector3d& pShoulder, Eigen::Vector2d& pixel) const {
  return projectCamera(m_params.R * pShoulder + m_params.t, pixel, nullptr);
}

bool PinholeCamera::project(const Eigen::Vector3d& pShoulder, Eigen::Vector2d& pixel,
                            Eigen::Matrix<double, 2, 3>& jacobian) const {
  Eigen::Vector2d px;
  Eigen::Matrix<double, 2, 3> dPixelDpCam;
  if (!projectCamera(m_params.R * pShoulder + m_params.t, px, &dPixelDpCam)) return false;
  pixel = px;
  jacobian = dPixelDpCam * m_params.R;  // p_cam = R p + t
  return true;
}

void PinholeCamera::ray(const Eigen::Vector2d& pixel, Eigen::Vector3d& origin,
                        Eigen::Vector3d& direction) const {
  // OpenCV's fixed-point undistortion gives normalised coordinates (x/z, y/z)...
  double src[2] = {pixel.x(), pixel.y()};
  double dst[2] = {0.0, 0.0};
  cv::Mat srcMat(1, 1, CV_64FC2, src);
  cv::Mat dstMat(1, 1, CV_64FC2, dst);
  cv::undistortPoints(srcMat, dstMat, cameraMatrix(m_params), distCoeffs(m_params), cv::noArray(),
                      cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 50, 1e-10));
  const cv::Vec2d n = dstMat.at<cv::Vec2d>(0);
  Eigen::Vector3d q(n[0], n[1], 1.0);

  // ...which a few Newton steps on project() polish to round-off (kept only while they help).
  Eigen::Vector2d px;
  Eigen::Matrix<double, 2, 3> J;
  if (projectCamera(q, px, &J)) {
    double err = (pixel - px).norm();
    for (int it = 0; it < 8 && err > 1e-11; ++it) {
      Eigen::Vector3d next = q;
      next.head<2>() += J.leftCols<2>().inverse() * (pixel - px);
      Eigen::Vector2d pxNext;
      Eigen::Matrix<double, 2, 3> JNext;
      if (!projectCamera(next, pxNext, &JNext)) break;
      const double errNext = (pixel - pxNext).norm();
      if (!(errNext < err)) break;
      q = next, px = pxNext, J = JNext, err = errNext;
    }
  }

  origin = -(m_Rinv * m_params.t);
  direction = (m_Rinv * q).normalized();
}

CameraParams frontCamera(double distance) {
  CameraParams c;
  c.fx = c.fy = 600.0;
  c.cx = 320.0;
  c.cy = 240.0;
  c.dist = {-0.1, 0.02, 0.0, 0.0, 0.0};
  // Rows are the camera axes in shoulder coordinates: x_cam = -z0, y_cam = +x0, z_cam = -y0.
  c.R << 0, 0, -1,  //
      1, 0, 0,      //
      0, -1, 0;
  // Camera centre C = distance * y0; t = -R C.
  c.t = -c.R * Eigen::Vector3d(0.0, distance, 0.0);
  return c;
}

}  // namespace armtrack
