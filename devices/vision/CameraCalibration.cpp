#include "devices/vision/CameraCalibration.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <opencv2/aruco.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "devices/vision/MarkerDetection.h"

namespace armtrack::devices::webcam {

namespace {

cv::Mat toGray(const cv::Mat& image) {
  cv::Mat gray;
  switch (image.type()) {
    case CV_8UC1:
      return image;
    case CV_8UC3:
      cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
      return gray;
    case CV_8UC4:
      cv::cvtColor(image, gray, cv::COLOR_BGRA2GRAY);
      return gray;
    default:
      return {};
  }
}

std::string sizeText(cv::Size s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

/// Half-size of the cornerSubPix window: under half the distance between neighbouring corners,
/// so that a window never reaches the next corner, and at most 11 (OpenCV's usual 23 x 23).
int subPixHalfWindow(const std::vector<cv::Point2f>& corners, cv::Size inner) {
  double minDist = 1e9;
  for (int r = 0; r < inner.height; ++r)
    for (int c = 0; c + 1 < inner.width; ++c) {
      const std::size_t i = static_cast<std::size_t>(r * inner.width + c);
      minDist = std::min(minDist, cv::norm(corners[i + 1] - corners[i]));
    }
  for (int r = 0; r + 1 < inner.height; ++r)
    for (int c = 0; c < inner.width; ++c) {
      const std::size_t i = static_cast<std::size_t>(r * inner.width + c);
      minDist = std::min(minDist,
                         cv::norm(corners[i + static_cast<std::size_t>(inner.width)] - corners[i]));
    }
  return std::clamp(static_cast<int>(minDist * 0.4), 2, 11);
}

bool finite(const cv::Mat& m) {
  return cv::checkRange(m);
}

}  // namespace

bool isRotation(const cv::Matx33d& R, double tol) {
  const cv::Matx33d e = R.t() * R - cv::Matx33d::eye();
  double worst = 0.0;
  for (int i = 0; i < 9; ++i) {
    if (!std::isfinite(R.val[i])) return false;
    worst = std::max(worst, std::abs(e.val[i]));
  }
  return worst <= tol && std::abs(cv::determinant(R) - 1.0) <= tol;
}

namespace {

// The leading bytes that identify the accepted formats.
const char* cameraImageFormat(const unsigned char* d, std::size_t n) {
  if (n >= 3 && d[0] == 0xFF && d[1] == 0xD8 && d[2] == 0xFF) return "JPEG";
  static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (n >= 8 && std::equal(png, png + 8, d)) return "PNG";
  if (n >= 2 && d[0] == 'B' && d[1] == 'M') return "BMP";
  return nullptr;
}

}  // namespace

cv::Mat decodeCameraImage(const unsigned char* data, std::size_t size, std::string* why) {
  auto fail = [&](std::string reason) {
    if (why) *why = std::move(reason);
    return cv::Mat();
  };
  if (size == 0) return fail("the file is empty");
  if (!cameraImageFormat(data, size))
    return fail("not a JPEG, PNG or BMP image (save the photo in one of those formats)");
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    return fail("the file is too large for an image");
  cv::Mat image;
  try {
    image =
        cv::imdecode(cv::Mat(1, static_cast<int>(size), CV_8UC1, const_cast<unsigned char*>(data)),
                     cv::IMREAD_COLOR);
  } catch (const cv::Exception& e) {
    return fail("the image does not decode (" + e.err + ")");
  }
  if (image.empty()) return fail("the image does not decode (corrupt or truncated)");
  return image;
}

cv::Mat loadImage(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CalibrationError(path + ": cannot open the image (missing or not readable)");
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  if (in.bad()) throw CalibrationError(path + ": cannot read the image (read error)");
  std::string why;
  cv::Mat image = decodeCameraImage(bytes.data(), bytes.size(), &why);
  if (image.empty()) throw CalibrationError(path + ": " + why);
  return image;
}

IntrinsicsResult calibrateIntrinsics(const std::vector<NamedImage>& images,
                                     const ChessboardSpec& board, const IntrinsicsOptions& opt) {
  const cv::Size inner = board.innerCorners;
  if (inner.width < 2 || inner.height < 2 || inner.width == inner.height)
    throw CalibrationError(
        "the chessboard needs at least 2 x 2 inner corners, and different " +
        std::string("counts across and down (so its orientation is known); got ") +
        sizeText(inner));
  if (!(board.squareSize > 0.0) || !std::isfinite(board.squareSize))
    throw CalibrationError("the chessboard square size must be a positive length in m");

  std::vector<cv::Point3f> boardPoints;
  for (int r = 0; r < inner.height; ++r)
    for (int c = 0; c < inner.width; ++c)
      boardPoints.emplace_back(static_cast<float>(c * board.squareSize),
                               static_cast<float>(r * board.squareSize), 0.0f);

  IntrinsicsResult result;
  std::vector<std::vector<cv::Point3f>> objectPoints;
  std::vector<std::vector<cv::Point2f>> imagePoints;
  cv::Size size;
  for (const NamedImage& item : images) {
    const cv::Mat gray = toGray(item.image);
    if (gray.empty()) {
      result.rejected.push_back(item.name + ": empty or not an 8-bit image");
      continue;
    }
    if (size.area() == 0) size = gray.size();
    if (gray.size() != size) {
      result.rejected.push_back(item.name + ": " + sizeText(gray.size()) + ", the others are " +
                                sizeText(size));
      continue;
    }
    std::vector<cv::Point2f> corners;
    const bool found = cv::findChessboardCorners(
        gray, inner, corners,
        cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_FAST_CHECK);
    if (!found || corners.size() != boardPoints.size()) {
      result.rejected.push_back(item.name + ": no " + sizeText(inner) + " chessboard found");
      continue;
    }
    const int half = subPixHalfWindow(corners, inner);
    cv::cornerSubPix(gray, corners, cv::Size(half, half), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 1e-3));
    objectPoints.push_back(boardPoints);
    imagePoints.push_back(std::move(corners));
    result.used.push_back(item.name);
  }

  const int found = static_cast<int>(imagePoints.size());
  if (found < std::max(1, opt.minBoards)) {
    throw CalibrationError(
        "the " + sizeText(inner) + " chessboard (inner corners) was found in " +
        std::to_string(found) + " of " + std::to_string(images.size()) + " images; at least " +
        std::to_string(std::max(1, opt.minBoards)) +
        " are needed. Check the board size (inner corners, not squares), focus and lighting, "
        "and show the whole board, tilted differently in each image");
  }

  cv::Mat K = cv::Mat::eye(3, 3, CV_64F);
  cv::Mat dist = cv::Mat::zeros(1, 5, CV_64F);
  std::vector<cv::Mat> rvecs, tvecs;
  cv::Mat stdIn, stdEx, perView;
  int flags = 0;
  if (opt.fixK3) flags |= cv::CALIB_FIX_K3;
  if (opt.fixAspect) flags |= cv::CALIB_FIX_ASPECT_RATIO;
  double rms = 0.0;
  try {
    rms = cv::calibrateCamera(objectPoints, imagePoints, size, K, dist, rvecs, tvecs, stdIn, stdEx,
                              perView, flags);
  } catch (const cv::Exception& e) {
    throw CalibrationError("calibration failed: " + e.err +
                           "; take more images with the board at varied tilts");
  }
  if (!std::isfinite(rms) || !finite(K) || !finite(dist) || !(K.at<double>(0, 0) > 0) ||
      !(K.at<double>(1, 1) > 0))
    throw CalibrationError(
        "calibration did not converge; take more images with the board at "
        "varied tilts");

  Intrinsics& in = result.intrinsics;
  in.imageSize = size;
  in.fx = K.at<double>(0, 0);
  in.fy = K.at<double>(1, 1);
  in.cx = K.at<double>(0, 2);
  in.cy = K.at<double>(1, 2);
  for (int i = 0; i < 5; ++i) in.dist[static_cast<std::size_t>(i)] = dist.at<double>(0, i);
  in.rmsPx = rms;
  in.boards = found;
  for (int i = 0; i < perView.rows; ++i) result.perViewRmsPx.push_back(perView.at<double>(i, 0));
  return result;
}

void arucoBoardLayout(const ArucoBoardSpec& spec, std::vector<std::vector<cv::Point3f>>& corners,
                      std::vector<int>& ids) {
  const auto dict = arucoDictionaryId(spec.dictionary);
  if (!dict)
    throw std::invalid_argument("unknown ArUco dictionary '" + spec.dictionary +
                                "' (known: " + arucoDictionaryNames() + ")");
  if (spec.markersX < 1 || spec.markersY < 1 || spec.markersX * spec.markersY < 2 ||
      spec.markersX > 100 || spec.markersY > 100)
    throw std::invalid_argument("an ArUco board needs at least 2 markers (and at most 100 x 100)");
  if (!(spec.markerLength > 0.0) || !(spec.separation >= 0.0) ||
      !std::isfinite(spec.markerLength) || !std::isfinite(spec.separation))
    throw std::invalid_argument(
        "the board's marker length must be > 0 m and the separation >= 0 m");
  const auto dictionary = cv::aruco::getPredefinedDictionary(*dict);
  const int count = spec.markersX * spec.markersY;
  if (spec.firstId < 0 || spec.firstId + count > dictionary->bytesList.rows)
    throw std::invalid_argument("the board's ids " + std::to_string(spec.firstId) + " to " +
                                std::to_string(spec.firstId + count - 1) + " do not fit in " +
                                spec.dictionary + " (ids 0 to " +
                                std::to_string(dictionary->bytesList.rows - 1) + ")");
  const auto board = cv::aruco::GridBoard::create(
      spec.markersX, spec.markersY, static_cast<float>(spec.markerLength),
      static_cast<float>(spec.separation), dictionary, spec.firstId);
  corners = board->objPoints;
  ids = board->ids;
}

Extrinsics registerCamera(const cv::Mat& image, const Intrinsics& intrinsics,
                          const ArucoBoardSpec& spec, const Pose& boardInShoulder, int minMarkers) {
  std::vector<std::vector<cv::Point3f>> layout;
  std::vector<int> layoutIds;
  try {
    arucoBoardLayout(spec, layout, layoutIds);
  } catch (const std::invalid_argument& e) {
    throw CalibrationError(e.what());
  }
  if (!isRotation(boardInShoulder.R, 1e-6))
    throw CalibrationError("the board's rotation in the shoulder frame is not a rotation matrix");
  const cv::Mat gray = toGray(image);
  if (gray.empty()) throw CalibrationError("the registration image is empty or not 8-bit");
  if (intrinsics.imageSize.area() > 0 && gray.size() != intrinsics.imageSize)
    throw CalibrationError("the image is " + sizeText(gray.size()) +
                           " but the intrinsics are for " + sizeText(intrinsics.imageSize) +
                           "; take the board image at the calibrated resolution");

  const auto dictionary = cv::aruco::getPredefinedDictionary(*arucoDictionaryId(spec.dictionary));
  std::vector<std::vector<cv::Point2f>> corners;
  std::vector<int> ids;
  cv::aruco::detectMarkers(gray, dictionary, corners, ids, arucoDetectorParameters());
  for (auto& c : corners) refineMarkerCorners(gray, c, dictionary->markerSize);

  std::vector<cv::Point3f> object;
  std::vector<cv::Point2f> pixels;
  int used = 0;
  std::vector<bool> seen(layoutIds.size(), false);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const auto it = std::find(layoutIds.begin(), layoutIds.end(), ids[i]);
    if (it == layoutIds.end()) continue;
    const std::size_t k = static_cast<std::size_t>(it - layoutIds.begin());
    if (seen[k]) continue;  // a duplicate id is ambiguous; the first wins
    seen[k] = true;
    for (int c = 0; c < 4; ++c) {
      object.push_back(layout[k][static_cast<std::size_t>(c)]);
      pixels.push_back(corners[i][static_cast<std::size_t>(c)]);
    }
    ++used;
  }
  if (used < std::max(1, minMarkers))
    throw CalibrationError("found " + std::to_string(used) + " of the board's " +
                           std::to_string(layoutIds.size()) + " markers (" + spec.dictionary +
                           ", ids " + std::to_string(spec.firstId) + " up); at least " +
                           std::to_string(std::max(1, minMarkers)) +
                           " are needed. Check the board options and that the board is in view, "
                           "sharp and evenly lit");

  const cv::Matx33d K = intrinsics.cameraMatrix();
  const cv::Mat dist = intrinsics.distCoeffs();
  cv::Vec3d rvec, tvec;
  try {
    // IPPE gives the planar pose without a starting guess; the iterative solver then refines it.
    cv::solvePnP(object, pixels, K, dist, rvec, tvec, false, cv::SOLVEPNP_IPPE);
    cv::solvePnP(object, pixels, K, dist, rvec, tvec, true, cv::SOLVEPNP_ITERATIVE);
  } catch (const cv::Exception& e) {
    throw CalibrationError("the board's pose could not be solved: " + e.err);
  }
  std::vector<cv::Point2f> reprojected;
  cv::projectPoints(object, rvec, tvec, K, dist, reprojected);
  double sum = 0.0;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const cv::Point2f d = reprojected[i] - pixels[i];
    sum += d.dot(d);
  }
  cv::Matx33d Rcb;
  cv::Rodrigues(rvec, Rcb);

  Extrinsics out;
  out.R = Rcb * boardInShoulder.R.t();
  out.t = tvec - out.R * boardInShoulder.t;
  out.rmsPx = std::sqrt(sum / static_cast<double>(pixels.size()));
  out.markers = used;
  if (!isRotation(out.R, 1e-6) || !std::isfinite(out.t[0] + out.t[1] + out.t[2]) ||
      !std::isfinite(out.rmsPx))
    throw CalibrationError("the board's pose could not be solved (no finite solution)");
  return out;
}

}  // namespace armtrack::devices::webcam
