// Synthetic camera images for the webcam tests: coloured discs and ArUco markers at sub-pixel
// positions, chessboards and ArUco boards seen through a known pinhole camera.
#pragma once

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <opencv2/aruco.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <vector>

namespace armtrack::test::webcam {

constexpr double kPi = 3.14159265358979323846;

/// A fresh directory under the system temp dir, removed on destruction.
class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    static int counter = 0;
    m_path =
        std::filesystem::temp_directory_path() /
        ("armtrack-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(++counter));
    std::filesystem::remove_all(m_path);
    std::filesystem::create_directories(m_path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(m_path, ec);
  }
  const std::filesystem::path& path() const { return m_path; }
  std::string file(const std::string& name) const { return (m_path / name).string(); }

 private:
  std::filesystem::path m_path;
};

/// A filled, anti-aliased disc centred at a sub-pixel position (1/256 px).
inline void drawDisc(cv::Mat& img, cv::Point2d centre, double radius, const cv::Scalar& bgr) {
  constexpr int kShift = 8;
  constexpr double kScale = 1 << kShift;
  cv::circle(img, cv::Point(cvRound(centre.x * kScale), cvRound(centre.y * kScale)),
             cvRound(radius * kScale), bgr, cv::FILLED, cv::LINE_AA, kShift);
}

/// An ArUco marker of side `side` px (border included) with a white quiet zone, rotated by
/// angleDeg and pasted so that its centre lands on `centre` (bilinear resampling).
inline void drawAruco(cv::Mat& img, int id, cv::Point2d centre, int side, double angleDeg,
                      const std::string& dictionary = "DICT_4X4_50") {
  cv::Mat marker;
  const int dict = dictionary == "DICT_4X4_50" ? cv::aruco::DICT_4X4_50 : cv::aruco::DICT_5X5_100;
  cv::aruco::drawMarker(cv::aruco::getPredefinedDictionary(dict), id, side, marker, 1);
  const int margin = side / 3;
  cv::copyMakeBorder(marker, marker, margin, margin, margin, margin, cv::BORDER_CONSTANT, 255);
  cv::cvtColor(marker, marker, cv::COLOR_GRAY2BGR);
  const double c = (marker.cols - 1) / 2.0;
  cv::Mat A = cv::getRotationMatrix2D(cv::Point2f(static_cast<float>(c), static_cast<float>(c)),
                                      angleDeg, 1.0);
  A.at<double>(0, 2) += centre.x - c;
  A.at<double>(1, 2) += centre.y - c;
  cv::warpAffine(marker, img, A, img.size(), cv::INTER_LINEAR, cv::BORDER_TRANSPARENT);
}

/// The analytic marker paths of the test videos (pixels), frame k at fps, in a w x h image. With
/// apart, the wrist stays in the left half and the elbow in the right (ArUco markers with their
/// quiet zones must not overlap); otherwise the paths cross.
struct Path {
  double w = 320, h = 240, fps = 30;
  bool apart = false;
  cv::Point2d wrist(int k) const {
    const double t = k / fps, c = std::cos(2 * kPi * 0.4 * t), s = std::sin(2 * kPi * 0.4 * t);
    if (apart) return {0.3 * w + 0.12 * w * c, h / 2 + 0.25 * h * s};
    return {w / 2 + 0.3 * w * c, h / 2 + 0.25 * h * s};
  }
  cv::Point2d elbow(int k) const {
    const double t = k / fps, c = std::cos(2 * kPi * 0.3 * t), s = std::sin(2 * kPi * 0.3 * t);
    if (apart) return {0.72 * w + 0.1 * w * s + 0.37, h / 2 - 0.2 * h * c};
    return {w / 2 - 0.2 * w * s + 0.37, h / 2 - 0.2 * h * c};
  }
};

/// A pinhole camera without distortion.
struct TrueCamera {
  cv::Size size{640, 480};
  double fx = 800, fy = 790, cx = 322.5, cy = 237.5;
  cv::Matx33d K() const { return {fx, 0, cx, 0, fy, cy, 0, 0, 1}; }
};

inline std::vector<cv::Point2d> project(const std::vector<cv::Point3d>& pts, const cv::Vec3d& rvec,
                                        const cv::Vec3d& tvec, const TrueCamera& cam) {
  std::vector<cv::Point2d> px;
  cv::projectPoints(pts, rvec, tvec, cam.K(), cv::noArray(), px);
  return px;
}

inline void fillQuad(cv::Mat& img, const std::vector<cv::Point2d>& q, const cv::Scalar& colour) {
  constexpr int kShift = 8;
  std::vector<cv::Point> pts;
  for (const auto& p : q) pts.emplace_back(cvRound(p.x * 256), cvRound(p.y * 256));
  cv::fillConvexPoly(img, pts, colour, cv::LINE_AA, kShift);
}

/// A chessboard with `inner` inner corners and squares of `square` m, board frame x along the
/// rows, seen from pose (rvec, tvec) (board to camera).
inline cv::Mat renderChessboard(const TrueCamera& cam, cv::Size inner, double square,
                                const cv::Vec3d& rvec, const cv::Vec3d& tvec) {
  cv::Mat img(cam.size, CV_8UC3, cv::Scalar(150, 150, 150));
  const auto quad = [&](double x0, double y0, double x1, double y1) {
    return project({{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}}, rvec, tvec, cam);
  };
  fillQuad(img,
           quad(-2 * square, -2 * square, (inner.width + 1) * square, (inner.height + 1) * square),
           cv::Scalar(245, 245, 245));
  for (int j = -1; j < inner.height; ++j)
    for (int i = -1; i < inner.width; ++i)
      if (((i + j) & 1) == 0)
        fillQuad(img, quad(i * square, j * square, (i + 1) * square, (j + 1) * square),
                 cv::Scalar(15, 15, 15));
  return img;
}

/// An ArUco grid board (corner points `layout` in the board frame, `ids`) seen from pose
/// (rvec, tvec): each marker image is warped onto its projected corners.
/// The scene is drawn at 4x the resolution and averaged down (cv::INTER_AREA), so that edges are
/// anti-aliased like a real camera's rather than snapped to whole pixels.
inline cv::Mat renderArucoBoard(const TrueCamera& camera,
                                const std::vector<std::vector<cv::Point3f>>& layout,
                                const std::vector<int>& ids, int dictionary, const cv::Vec3d& rvec,
                                const cv::Vec3d& tvec, double margin) {
  constexpr int kSuper = 4;
  TrueCamera cam = camera;
  cam.size = camera.size * kSuper;
  cam.fx *= kSuper;
  cam.fy *= kSuper;
  // Pixel j of the final image averages fine pixels kSuper j .. kSuper j + kSuper - 1, whose
  // centre is at kSuper j + (kSuper - 1) / 2.
  cam.cx = kSuper * camera.cx + (kSuper - 1) / 2.0;
  cam.cy = kSuper * camera.cy + (kSuper - 1) / 2.0;
  cv::Mat img(cam.size, CV_8UC3, cv::Scalar(120, 120, 120));
  // White card under the markers.
  float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
  for (const auto& m : layout)
    for (const auto& p : m) {
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x),
      y1 = std::max(y1, p.y);
    }
  fillQuad(img,
           project({{x0 - margin, y0 - margin, 0},
                    {x1 + margin, y0 - margin, 0},
                    {x1 + margin, y1 + margin, 0},
                    {x0 - margin, y1 + margin, 0}},
                   rvec, tvec, cam),
           cv::Scalar(250, 250, 250));
  const auto dict = cv::aruco::getPredefinedDictionary(dictionary);
  for (std::size_t k = 0; k < layout.size(); ++k) {
    constexpr int kSide = 120;
    cv::Mat marker;
    cv::aruco::drawMarker(dict, ids[k], kSide, marker, 1);
    cv::cvtColor(marker, marker, cv::COLOR_GRAY2BGR);
    std::vector<cv::Point3d> c3;
    for (const auto& p : layout[k]) c3.emplace_back(p.x, p.y, p.z);
    const auto c2 = project(c3, rvec, tvec, cam);
    // Marker image corners (pixel edges) in OpenCV's corner order: top-left, top-right,
    // bottom-right, bottom-left.
    const std::vector<cv::Point2f> src{
        {-0.5f, -0.5f}, {kSide - 0.5f, -0.5f}, {kSide - 0.5f, kSide - 0.5f}, {-0.5f, kSide - 0.5f}};
    std::vector<cv::Point2f> dst;
    for (const auto& p : c2) dst.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
    // Warp into the marker's bounding box only (the full fine image is large).
    const cv::Rect box = cv::boundingRect(dst) & cv::Rect(0, 0, img.cols, img.rows);
    if (box.empty()) continue;
    for (auto& p : dst) p -= cv::Point2f(static_cast<float>(box.x), static_cast<float>(box.y));
    const cv::Mat H = cv::getPerspectiveTransform(src, dst);
    cv::Mat roi = img(box);
    cv::warpPerspective(marker, roi, H, roi.size(), cv::INTER_LINEAR, cv::BORDER_TRANSPARENT);
  }
  cv::Mat out;
  cv::resize(img, out, camera.size, 0, 0, cv::INTER_AREA);
  return out;
}

}  // namespace armtrack::test::webcam
