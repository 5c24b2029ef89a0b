// Camera calibration for the webcam and the Kinect's colour camera (docs/devices/webcam.md):
// intrinsics from chessboard images (cv::calibrateCamera), and the camera's pose in the shoulder
// frame from one image of an ArUco board placed at a known pose. Plain C++20 and OpenCV, no Qt.
#pragma once

#include <array>
#include <cstddef>
#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace armtrack::devices::webcam {

/// A calibration that cannot be made from the given images; what() says what to change.
class CalibrationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Pinhole intrinsics with OpenCV's distortion model (docs/camera.md).
struct Intrinsics {
  cv::Size imageSize;                     ///< pixels, the size the intrinsics belong to
  double fx = 0, fy = 0, cx = 0, cy = 0;  ///< pixels
  std::array<double, 5> dist{};           ///< k1, k2, p1, p2, k3
  double rmsPx = 0.0;  ///< RMS reprojection error of the calibration, pixels (0 = not measured)
  int boards = 0;      ///< chessboard views used (0 = not from a calibration)

  cv::Matx33d cameraMatrix() const { return {fx, 0, cx, 0, fy, cy, 0, 0, 1}; }
  cv::Mat distCoeffs() const { return cv::Mat(dist, true).reshape(1, 1); }
};

/// The camera's pose: p_camera = R p_shoulder + t (OpenCV's convention, as CameraParams).
struct Extrinsics {
  cv::Matx33d R = cv::Matx33d::eye();
  cv::Vec3d t{0, 0, 0};  ///< m
  double rmsPx = 0.0;    ///< RMS reprojection error of the board corners, pixels
  int markers = 0;       ///< board markers used
};

/// A chessboard: inner corners per row and column (a board of 10 x 7 squares has 9 x 6), and the
/// side of a square in m.
struct ChessboardSpec {
  cv::Size innerCorners{9, 6};
  double squareSize = 0.025;  ///< m
};

struct NamedImage {
  std::string name;  ///< for messages (a file name)
  cv::Mat image;     ///< 8-bit gray, BGR or BGRA
};

struct IntrinsicsOptions {
  int minBoards = 4;       ///< fewer views with a board found is an error
  bool fixK3 = true;       ///< hold k3 at 0 (the usual choice for webcams; few views are unstable)
  bool fixAspect = false;  ///< fx = fy
};

struct IntrinsicsResult {
  Intrinsics intrinsics;
  std::vector<std::string> used;      ///< names of the images with a board
  std::vector<double> perViewRmsPx;   ///< one per used image
  std::vector<std::string> rejected;  ///< "name: reason" for the others
};

/// Finds the chessboard in each image (findChessboardCorners, then cornerSubPix with a window
/// sized to the board's squares) and calibrates (calibrateCamera, k1 k2 p1 p2 [k3]). Images of
/// another size than the first are rejected. Throws CalibrationError when fewer than minBoards
/// boards were found, or when the result is not finite. Any thread.
IntrinsicsResult calibrateIntrinsics(const std::vector<NamedImage>& images,
                                     const ChessboardSpec& board, const IntrinsicsOptions& = {});

/// An ArUco grid board: markersX x markersY markers of side markerLength, separated by separation
/// (m), ids from firstId row by row. Board frame: OpenCV's GridBoard (x along the rows, y along
/// the columns, z out of the printed face; origin at a corner, see docs/devices/webcam.md).
struct ArucoBoardSpec {
  std::string dictionary = "DICT_4X4_50";
  int markersX = 5, markersY = 7;
  double markerLength = 0.03;  ///< m
  double separation = 0.006;   ///< m
  int firstId = 0;
};

/// The board's corner points in its own frame (m), marker by marker (4 corners each, as OpenCV's
/// Board::objPoints), with their ids. Throws std::invalid_argument for a bad spec.
void arucoBoardLayout(const ArucoBoardSpec& board, std::vector<std::vector<cv::Point3f>>& corners,
                      std::vector<int>& ids);

/// A rigid pose, p_parent = R p_child + t.
struct Pose {
  cv::Matx33d R = cv::Matx33d::eye();
  cv::Vec3d t{0, 0, 0};  ///< m
};

/// Registers the camera to the shoulder frame from one image of the board, whose pose in the
/// shoulder frame is boardInShoulder (p_shoulder = R p_board + t). Detects the markers, solves
/// the board's pose in the camera from all detected corners (solvePnP, iterative, with the
/// intrinsics' distortion) and composes: R = R_cb R_sb^T, t = t_cb - R t_sb. Throws
/// CalibrationError when fewer than minMarkers board markers are found or the image size differs
/// from the intrinsics'. Any thread.
Extrinsics registerCamera(const cv::Mat& image, const Intrinsics& intrinsics,
                          const ArucoBoardSpec& board, const Pose& boardInShoulder,
                          int minMarkers = 4);

/// Reads a photo of a calibration board: JPEG, PNG or BMP, the formats cameras and screenshot
/// tools write. Other formats are refused before any decoder sees them (OpenCV would also try
/// DICOM, TIFF, EXR, ..., whose decoders trust sizes in the header and can allocate gigabytes
/// for a few corrupt bytes). Throws CalibrationError naming the file.
cv::Mat loadImage(const std::string& path);

/// Decodes an encoded camera image held in memory, JPEG, PNG or BMP only (see loadImage), to
/// 8-bit BGR. Returns an empty Mat and sets *why when the bytes are not one of those formats or
/// do not decode. Any thread.
cv::Mat decodeCameraImage(const unsigned char* data, std::size_t size, std::string* why = nullptr);

/// Whether R is a rotation to tol (orthonormal, determinant +1).
bool isRotation(const cv::Matx33d& R, double tol = 1e-6);

}  // namespace armtrack::devices::webcam
