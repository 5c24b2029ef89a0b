// Finding the wrist and elbow markers in a camera image (docs/devices/webcam.md): coloured patches
// as in Tao & Hu (one colour per marker), or ArUco markers (one id per marker). Plain C++20 and
// OpenCV, no Qt and no armtrack_core, so the fuzz build can link it.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cv::aruco {
struct DetectorParameters;
}

namespace armtrack::devices::webcam {

/// The two marker pixels of one image; std::nullopt where a marker was not found. Pixel
/// coordinates follow OpenCV: (0, 0) is the centre of the top-left pixel, u right, v down.
struct MarkerPair {
  std::optional<cv::Point2d> wrist;
  std::optional<cv::Point2d> elbow;
};

/// Which detector a device runs.
enum class MarkerKind { Colour, Aruco };

/// An HSV box in OpenCV's 8-bit scale: hue 0-179 (degrees / 2), saturation and value 0-255.
/// hueMin > hueMax wraps through 0, for reds (e.g. 170-10).
struct HsvRange {
  int hueMin = 0, hueMax = 179;
  int satMin = 0, satMax = 255;
  int valMin = 0, valMax = 255;
};

/// "h1-h2:s1-s2:v1-v2", e.g. "45-75:100-255:70-255"; std::nullopt on bad text or out-of-range
/// numbers.
std::optional<HsvRange> parseHsvRange(std::string_view text);
std::string toString(const HsvRange& range);

/// Parameters of the colour detector.
struct ColourMarkerParams {
  /// Wrist marker: green (hue 45-75, i.e. 90-150 deg; saturation >= 100; value >= 70).
  HsvRange wrist{45, 75, 100, 255, 70, 255};
  /// Elbow marker: blue (hue 100-130, i.e. 200-260 deg; saturation >= 100; value >= 70). Green
  /// and blue are far from skin tones, which sit at reds and oranges.
  HsvRange elbow{100, 130, 100, 255, 70, 255};
  /// Smallest blob accepted as a marker, pixels (default 20, a disc of about 5 px diameter).
  double minAreaPx = 20.0;
};

/// Finds each marker as the largest 8-connected blob of pixels inside its HSV box; a marker whose
/// largest blob is smaller than minAreaPx is absent. The pixel is the blob's centroid from
/// first-order moments weighted by chroma (S x V), over the blob and a one-pixel ring around it
/// restricted to the marker's hue range: edge pixels that mix marker and background count by
/// their share of marker colour, which makes the centroid sub-pixel (about 0.05 px on a clean
/// disc) instead of snapped to whole pixels. Not thread-safe (reuses buffers); one per thread.
class ColourMarkerDetector {
 public:
  explicit ColourMarkerDetector(ColourMarkerParams params = {});
  /// bgr: 8-bit, 3 channels (BGR) or 4 (BGRA). An empty image gives no markers. Throws
  /// std::invalid_argument for another pixel type.
  MarkerPair detect(const cv::Mat& bgr);
  const ColourMarkerParams& params() const { return m_params; }

 private:
  void threshold(const HsvRange& r);
  std::optional<cv::Point2d> find(const HsvRange& r);
  ColourMarkerParams m_params;
  cv::Mat m_hsv, m_mask, m_mask2, m_labels, m_stats, m_centroids;
};

/// Parameters of the ArUco detector.
struct ArucoMarkerParams {
  std::string dictionary = "DICT_4X4_50";  ///< any of OpenCV's predefined dictionaries
  int wristId = 0;
  int elbowId = 1;
};

/// OpenCV's predefined-dictionary number for a name such as "DICT_4X4_50" or "4x4_50"
/// (case-insensitive, "DICT_" optional), std::nullopt when unknown.
std::optional<int> arucoDictionaryId(std::string_view name);
/// The names arucoDictionaryId() accepts, comma-separated, for error messages.
std::string arucoDictionaryNames();

/// Finds ArUco markers (sub-pixel corner refinement) and returns, for the wrist and elbow ids,
/// the marker centre: the intersection of the diagonals of its four corners, which is the image
/// of the square's centre under any perspective. When an id appears more than once, the biggest
/// is taken. Not thread-safe; one per thread.
class ArucoMarkerDetector {
 public:
  /// Throws std::invalid_argument for an unknown dictionary or an id outside it, or the same id for
  /// both markers.
  explicit ArucoMarkerDetector(ArucoMarkerParams params = {});
  ~ArucoMarkerDetector();
  ArucoMarkerDetector(ArucoMarkerDetector&&) noexcept;
  ArucoMarkerDetector& operator=(ArucoMarkerDetector&&) noexcept;

  /// image: 8-bit gray, BGR or BGRA. Empty gives no markers; another type throws
  /// std::invalid_argument.
  MarkerPair detect(const cv::Mat& image);
  const ArucoMarkerParams& params() const { return m_params; }

 private:
  struct Impl;
  ArucoMarkerParams m_params;
  std::unique_ptr<Impl> m_impl;
};

/// Either detector behind one call, as the devices use it. Not thread-safe.
class MarkerDetector {
 public:
  explicit MarkerDetector(ColourMarkerParams colour)
      : m_kind(MarkerKind::Colour), m_colour(colour) {}
  explicit MarkerDetector(ArucoMarkerParams aruco)
      : m_kind(MarkerKind::Aruco), m_aruco(std::move(aruco)) {}
  MarkerKind kind() const { return m_kind; }
  MarkerPair detect(const cv::Mat& bgr) {
    return m_kind == MarkerKind::Colour ? m_colour.detect(bgr) : m_aruco.detect(bgr);
  }

 private:
  MarkerKind m_kind;
  ColourMarkerDetector m_colour;
  ArucoMarkerDetector m_aruco;
};

/// The detector parameters both ArUco users share (corner refinement off: see
/// refineMarkerCorners).
cv::Ptr<cv::aruco::DetectorParameters> arucoDetectorParameters();
/// Refines one marker's four corners to sub-pixel with cornerSubPix, the window sized to the
/// marker's cells (markerBits: bits per side of the dictionary, e.g. 4) so that it never reaches
/// the code inside. OpenCV's own refinement uses one window size for all markers, which biases
/// the corners of small markers.
void refineMarkerCorners(const cv::Mat& gray, std::vector<cv::Point2f>& corners, int markerBits);

/// The point where segments a0-a1 and b0-b1 (as infinite lines) cross; std::nullopt when they are
/// parallel to 1e-12.
std::optional<cv::Point2d> lineIntersection(cv::Point2d a0, cv::Point2d a1, cv::Point2d b0,
                                            cv::Point2d b1);

}  // namespace armtrack::devices::webcam
