// Tests for the pinhole camera (docs/camera.md): agreement with cv::projectPoints and a hand
// formula, the Jacobian, back-projected rays, frontCamera's geometry and invalid points.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "core/camera/PinholeCamera.h"

namespace armtrack {
namespace {

/// A camera with a random pose, unequal focal lengths and the distortion of the format's example
/// plus some tangential terms (or none).
CameraParams randomCamera(std::mt19937& rng, bool distorted) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  CameraParams c;
  c.fx = 610.5;
  c.fy = 590.2;
  c.cx = 320.1;
  c.cy = 239.7;
  if (distorted) c.dist = {0.1, -0.2, 1e-3, -5e-4, 0.05};
  c.R = Eigen::AngleAxisd(angle(rng), Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized())
            .toRotationMatrix();
  c.t = Eigen::Vector3d(0.2 * n(rng), 0.2 * n(rng), 1.5 + 0.2 * n(rng));
  return c;
}

/// A shoulder-frame point in front of the camera, within about 45 degrees of its axis.
Eigen::Vector3d pointInFront(std::mt19937& rng, const CameraParams& c) {
  std::uniform_real_distribution<double> depth(0.3, 4.0), slope(-0.7, 0.7);
  const double z = depth(rng);
  const Eigen::Vector3d pCam(slope(rng) * z, slope(rng) * z, z);
  return c.R.transpose() * (pCam - c.t);
}

std::vector<CameraParams> testCameras(std::mt19937& rng) {
  return {frontCamera(2.0), randomCamera(rng, true), randomCamera(rng, true)};
}

Eigen::Vector2d openCvPixel(const CameraParams& c, const Eigen::Vector3d& p) {
  cv::Matx33d R;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) R(i, j) = c.R(i, j);
  }
  cv::Vec3d rvec;
  cv::Rodrigues(R, rvec);
  const cv::Vec3d tvec(c.t.x(), c.t.y(), c.t.z());
  const cv::Matx33d K(c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
  const std::vector<double> dist(c.dist.begin(), c.dist.end());
  std::vector<cv::Point2d> image;
  cv::projectPoints(std::vector<cv::Point3d>{{p.x(), p.y(), p.z()}}, rvec, tvec, K, dist, image);
  return {image[0].x, image[0].y};
}

TEST(PinholeCamera, MatchesOpenCvProjectPoints) {
  std::mt19937 rng(1);
  for (const CameraParams& c : testCameras(rng)) {
    const PinholeCamera cam(c);
    for (int i = 0; i < 200; ++i) {
      const Eigen::Vector3d p = pointInFront(rng, c);
      Eigen::Vector2d px;
      ASSERT_TRUE(cam.project(p, px)) << p.transpose();
      const Eigen::Vector2d expected = openCvPixel(c, p);
      EXPECT_LT((px - expected).norm(), 1e-9) << px.transpose() << " vs " << expected.transpose();
    }
  }
}

TEST(PinholeCamera, ZeroDistortionMatchesHandFormula) {
  std::mt19937 rng(2);
  const CameraParams c = randomCamera(rng, false);
  const PinholeCamera cam(c);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d p = pointInFront(rng, c);
    const Eigen::Vector3d q = c.R * p + c.t;
    const Eigen::Vector2d expected(c.fx * q.x() / q.z() + c.cx, c.fy * q.y() / q.z() + c.cy);
    Eigen::Vector2d px;
    ASSERT_TRUE(cam.project(p, px));
    EXPECT_LT((px - expected).norm(), 1e-9) << px.transpose() << " vs " << expected.transpose();
  }
}

TEST(PinholeCamera, JacobianMatchesFiniteDifferences) {
  std::mt19937 rng(3);
  for (const CameraParams& c : testCameras(rng)) {
    const PinholeCamera cam(c);
    for (int i = 0; i < 100; ++i) {
      const Eigen::Vector3d p = pointInFront(rng, c);
      Eigen::Vector2d px, pxPlain;
      Eigen::Matrix<double, 2, 3> J;
      ASSERT_TRUE(cam.project(p, px, J));
      ASSERT_TRUE(cam.project(p, pxPlain));
      EXPECT_EQ(px, pxPlain);

      constexpr double h = 1e-5;  // m
      Eigen::Matrix<double, 2, 3> fd;
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector2d plus, minus;
        ASSERT_TRUE(cam.project(p + h * Eigen::Vector3d::Unit(k), plus));
        ASSERT_TRUE(cam.project(p - h * Eigen::Vector3d::Unit(k), minus));
        fd.col(k) = (plus - minus) / (2 * h);
      }
      EXPECT_LE((J - fd).norm(), 1e-6 * J.norm()) << "J\n" << J << "\nfinite differences\n" << fd;
    }
  }
}

TEST(PinholeCamera, RayThroughProjectionContainsThePoint) {
  std::mt19937 rng(4);
  for (const CameraParams& c : testCameras(rng)) {
    const PinholeCamera cam(c);
    const Eigen::Vector3d centre = -c.R.transpose() * c.t;
    for (int i = 0; i < 200; ++i) {
      const Eigen::Vector3d p = pointInFront(rng, c);
      Eigen::Vector2d px;
      ASSERT_TRUE(cam.project(p, px));
      Eigen::Vector3d origin, direction;
      cam.ray(px, origin, direction);
      EXPECT_LT((origin - centre).norm(), 1e-12);
      EXPECT_NEAR(direction.norm(), 1.0, 1e-12);
      const Eigen::Vector3d d = p - origin;
      EXPECT_GT(d.dot(direction), 0.0);  // the point is ahead along the ray
      EXPECT_LT((d - d.dot(direction) * direction).norm(), 1e-6) << "pixel " << px.transpose();
    }
  }
}

TEST(PinholeCamera, FrontCameraGeometry) {
  const CameraParams c = frontCamera(2.0);
  EXPECT_LT((c.R.transpose() * c.R - Eigen::Matrix3d::Identity()).norm(), 1e-15);
  EXPECT_NEAR(c.R.determinant(), 1.0, 1e-15);
  const PinholeCamera cam(c);

  Eigen::Vector3d origin, direction;
  cam.ray({c.cx, c.cy}, origin, direction);
  EXPECT_LT((origin - Eigen::Vector3d(0, 2, 0)).norm(), 1e-12);      // 2 m in front (+y0)
  EXPECT_LT((direction - Eigen::Vector3d(0, -1, 0)).norm(), 1e-12);  // looking back (-y0)

  Eigen::Vector2d shoulder, below, lateral;
  ASSERT_TRUE(cam.project(Eigen::Vector3d::Zero(), shoulder));
  EXPECT_LT((shoulder - Eigen::Vector2d(320, 240)).norm(), 1e-9);

  // Below the shoulder (+x0) is lower in the image: larger v, same u.
  ASSERT_TRUE(cam.project(Eigen::Vector3d(0.3, 0, 0), below));
  EXPECT_GT(below.y(), shoulder.y() + 50);
  EXPECT_NEAR(below.x(), shoulder.x(), 1e-9);

  // +z0 (the patient's right, lateral for a right arm): x_cam = -z0, so u decreases. The camera
  // faces the patient, whose right side appears on the left of the image, as in a photograph.
  ASSERT_TRUE(cam.project(Eigen::Vector3d(0, 0, 0.3), lateral));
  EXPECT_LT(lateral.x(), shoulder.x() - 50);
  EXPECT_NEAR(lateral.y(), shoulder.y(), 1e-9);

  // frontCamera's mild distortion never folds back.
  EXPECT_EQ(cam.validRadius2(), std::numeric_limits<double>::infinity());
}

TEST(PinholeCamera, PointsBehindTheCameraDoNotProject) {
  const PinholeCamera cam(frontCamera(2.0));
  const Eigen::Vector2d sentinel(-7, -7);
  Eigen::Vector2d px = sentinel;
  Eigen::Matrix<double, 2, 3> J = Eigen::Matrix<double, 2, 3>::Constant(-7);
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 3, 0), Eigen::Vector3d(0.5, 2.5, -0.2),
                                   Eigen::Vector3d(0, 2, 0), Eigen::Vector3d(0.1, 2 - 1e-7, 0)}) {
    EXPECT_FALSE(cam.project(p, px)) << p.transpose();
    EXPECT_FALSE(cam.project(p, px, J)) << p.transpose();
  }
  EXPECT_EQ(px, sentinel);
  EXPECT_EQ(J, (Eigen::Matrix<double, 2, 3>::Constant(-7)));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(cam.project(Eigen::Vector3d(nan, 0, 0), px));
}

TEST(PinholeCamera, RejectsPointsBeyondTheDistortionFold) {
  // k1 = -0.3 alone: r (1 - 0.3 r^2) peaks at r^2 = 1 / 0.9; beyond it pixels fold back inwards.
  CameraParams c = frontCamera(2.0);
  c.dist = {-0.3, 0, 0, 0, 0};
  const PinholeCamera cam(c);
  EXPECT_NEAR(cam.validRadius2(), 1 / 0.9, 1e-12);
  Eigen::Vector2d px;
  // Normalised radius r = |z0| / 2 (the shoulder is 2 m away on the optical axis).
  EXPECT_TRUE(cam.project(Eigen::Vector3d(0, 0, 2 * 0.9), px));
  EXPECT_FALSE(cam.project(Eigen::Vector3d(0, 0, 2 * 1.2), px));
}

TEST(PinholeCamera, RejectsInvalidParameters) {
  CameraParams c = frontCamera(2.0);
  c.fx = 0;
  EXPECT_THROW(PinholeCamera{c}, std::invalid_argument);
  c = frontCamera(2.0);
  c.R(0, 0) = 0.5;  // not orthonormal
  EXPECT_THROW(PinholeCamera{c}, std::invalid_argument);
  c = frontCamera(2.0);
  c.R = -c.R;  // a reflection
  EXPECT_THROW(PinholeCamera{c}, std::invalid_argument);
  c = frontCamera(2.0);
  c.dist[1] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(PinholeCamera{c}, std::invalid_argument);
}

}  // namespace
}  // namespace armtrack
