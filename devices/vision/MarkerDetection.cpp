#include "devices/vision/MarkerDetection.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace armtrack::devices::webcam {

namespace {

bool readInt(std::string_view& text, int& value) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (r.ec != std::errc() || r.ptr == text.data()) return false;
  text.remove_prefix(static_cast<std::size_t>(r.ptr - text.data()));
  return true;
}

bool readPair(std::string_view& text, int& lo, int& hi, int max) {
  if (!readInt(text, lo) || text.empty() || text.front() != '-') return false;
  text.remove_prefix(1);
  if (!readInt(text, hi)) return false;
  return lo >= 0 && hi >= 0 && lo <= max && hi <= max;
}

struct DictionaryName {
  const char* name;
  int id;
};

constexpr std::array<DictionaryName, 21> kDictionaries{{
    {"4X4_50", cv::aruco::DICT_4X4_50},
    {"4X4_100", cv::aruco::DICT_4X4_100},
    {"4X4_250", cv::aruco::DICT_4X4_250},
    {"4X4_1000", cv::aruco::DICT_4X4_1000},
    {"5X5_50", cv::aruco::DICT_5X5_50},
    {"5X5_100", cv::aruco::DICT_5X5_100},
    {"5X5_250", cv::aruco::DICT_5X5_250},
    {"5X5_1000", cv::aruco::DICT_5X5_1000},
    {"6X6_50", cv::aruco::DICT_6X6_50},
    {"6X6_100", cv::aruco::DICT_6X6_100},
    {"6X6_250", cv::aruco::DICT_6X6_250},
    {"6X6_1000", cv::aruco::DICT_6X6_1000},
    {"7X7_50", cv::aruco::DICT_7X7_50},
    {"7X7_100", cv::aruco::DICT_7X7_100},
    {"7X7_250", cv::aruco::DICT_7X7_250},
    {"7X7_1000", cv::aruco::DICT_7X7_1000},
    {"ARUCO_ORIGINAL", cv::aruco::DICT_ARUCO_ORIGINAL},
    {"APRILTAG_16H5", cv::aruco::DICT_APRILTAG_16h5},
    {"APRILTAG_25H9", cv::aruco::DICT_APRILTAG_25h9},
    {"APRILTAG_36H10", cv::aruco::DICT_APRILTAG_36h10},
    {"APRILTAG_36H11", cv::aruco::DICT_APRILTAG_36h11},
}};

/// The 8-bit BGR view of an image: BGRA is converted, BGR passed through.
const cv::Mat& asBgr(const cv::Mat& image, cv::Mat& buffer) {
  if (image.type() == CV_8UC3) return image;
  if (image.type() == CV_8UC4) {
    cv::cvtColor(image, buffer, cv::COLOR_BGRA2BGR);
    return buffer;
  }
  throw std::invalid_argument("marker detection needs an 8-bit BGR or BGRA image, got type " +
                              cv::typeToString(image.type()));
}

}  // namespace

std::optional<HsvRange> parseHsvRange(std::string_view text) {
  HsvRange r;
  if (!readPair(text, r.hueMin, r.hueMax, 179)) return std::nullopt;
  if (text.empty() || text.front() != ':') return std::nullopt;
  text.remove_prefix(1);
  if (!readPair(text, r.satMin, r.satMax, 255) || r.satMin > r.satMax) return std::nullopt;
  if (text.empty() || text.front() != ':') return std::nullopt;
  text.remove_prefix(1);
  if (!readPair(text, r.valMin, r.valMax, 255) || r.valMin > r.valMax) return std::nullopt;
  if (!text.empty()) return std::nullopt;
  return r;
}

std::string toString(const HsvRange& r) {
  return std::to_string(r.hueMin) + "-" + std::to_string(r.hueMax) + ":" +
         std::to_string(r.satMin) + "-" + std::to_string(r.satMax) + ":" +
         std::to_string(r.valMin) + "-" + std::to_string(r.valMax);
}

// ---------------------------------------------------------------------------------------------

ColourMarkerDetector::ColourMarkerDetector(ColourMarkerParams params) : m_params(params) {}

void ColourMarkerDetector::threshold(const HsvRange& r) {
  const cv::Scalar lo(r.hueMin, r.satMin, r.valMin);
  const cv::Scalar hi(r.hueMax, r.satMax, r.valMax);
  if (r.hueMin <= r.hueMax) {
    cv::inRange(m_hsv, lo, hi, m_mask);
    return;
  }
  // The hue wraps through 0: [hueMin, 179] or [0, hueMax].
  cv::inRange(m_hsv, lo, cv::Scalar(179, r.satMax, r.valMax), m_mask);
  cv::inRange(m_hsv, cv::Scalar(0, r.satMin, r.valMin), hi, m_mask2);
  cv::bitwise_or(m_mask, m_mask2, m_mask);
}

static bool inHue(int h, const HsvRange& r) {
  return r.hueMin <= r.hueMax ? (h >= r.hueMin && h <= r.hueMax) : (h >= r.hueMin || h <= r.hueMax);
}

std::optional<cv::Point2d> ColourMarkerDetector::find(const HsvRange& r) {
  threshold(r);
  const int n = cv::connectedComponentsWithStats(m_mask, m_labels, m_stats, m_centroids, 8, CV_32S);
  int best = -1;
  int bestArea = 0;
  for (int i = 1; i < n; ++i) {
    const int area = m_stats.at<int>(i, cv::CC_STAT_AREA);
    if (area > bestArea) {
      bestArea = area;
      best = i;
    }
  }
  if (best < 0 || bestArea < m_params.minAreaPx) return std::nullopt;
  const cv::Point2d plain(m_centroids.at<double>(best, 0), m_centroids.at<double>(best, 1));

  // Chroma-weighted moments over the blob grown by one pixel.
  const cv::Rect box = cv::Rect(m_stats.at<int>(best, cv::CC_STAT_LEFT) - 1,
                                m_stats.at<int>(best, cv::CC_STAT_TOP) - 1,
                                m_stats.at<int>(best, cv::CC_STAT_WIDTH) + 2,
                                m_stats.at<int>(best, cv::CC_STAT_HEIGHT) + 2) &
                       cv::Rect(0, 0, m_hsv.cols, m_hsv.rows);
  cv::Mat grown;
  cv::compare(m_labels(box), best, grown, cv::CMP_EQ);
  cv::dilate(grown, grown, cv::Mat());
  double m00 = 0.0, m10 = 0.0, m01 = 0.0;
  for (int y = 0; y < box.height; ++y) {
    const auto* g = grown.ptr<std::uint8_t>(y);
    const auto* hsv = m_hsv.ptr<cv::Vec3b>(box.y + y) + box.x;
    for (int x = 0; x < box.width; ++x) {
      if (!g[x] || !inHue(hsv[x][0], r)) continue;
      const double w = static_cast<double>(hsv[x][1]) * hsv[x][2];
      m00 += w;
      m10 += w * (box.x + x);
      m01 += w * (box.y + y);
    }
  }
  if (!(m00 > 0.0)) return plain;
  return cv::Point2d(m10 / m00, m01 / m00);
}

MarkerPair ColourMarkerDetector::detect(const cv::Mat& image) {
  if (image.empty()) return {};
  cv::Mat buffer;
  cv::cvtColor(asBgr(image, buffer), m_hsv, cv::COLOR_BGR2HSV);
  MarkerPair out;
  out.wrist = find(m_params.wrist);
  out.elbow = find(m_params.elbow);
  return out;
}

// ---------------------------------------------------------------------------------------------

std::optional<int> arucoDictionaryId(std::string_view name) {
  std::string upper;
  for (char c : name) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (upper.starts_with("DICT_")) upper.erase(0, 5);
  for (const DictionaryName& d : kDictionaries)
    if (upper == d.name) return d.id;
  return std::nullopt;
}

std::string arucoDictionaryNames() {
  std::string out;
  for (const DictionaryName& d : kDictionaries) {
    if (!out.empty()) out += ", ";
    out += std::string("DICT_") + d.name;
  }
  return out;
}

struct ArucoMarkerDetector::Impl {
  cv::Ptr<cv::aruco::Dictionary> dictionary;
  cv::Ptr<cv::aruco::DetectorParameters> parameters;
  cv::Mat gray;
  std::vector<std::vector<cv::Point2f>> corners;
  std::vector<int> ids;
};

ArucoMarkerDetector::ArucoMarkerDetector(ArucoMarkerParams params)
    : m_params(std::move(params)), m_impl(std::make_unique<Impl>()) {
  const auto id = arucoDictionaryId(m_params.dictionary);
  if (!id)
    throw std::invalid_argument("unknown ArUco dictionary '" + m_params.dictionary +
                                "' (known: " + arucoDictionaryNames() + ")");
  m_impl->dictionary = cv::aruco::getPredefinedDictionary(*id);
  const int size = m_impl->dictionary->bytesList.rows;
  for (const auto& [what, v] : {std::pair{"wrist", m_params.wristId}, {"elbow", m_params.elbowId}})
    if (v < 0 || v >= size)
      throw std::invalid_argument(std::string(what) + " marker id " + std::to_string(v) +
                                  " is not in " + m_params.dictionary + " (ids 0 to " +
                                  std::to_string(size - 1) + ")");
  if (m_params.wristId == m_params.elbowId)
    throw std::invalid_argument("the wrist and elbow markers need different ids, both are " +
                                std::to_string(m_params.wristId));
  m_impl->parameters = arucoDetectorParameters();
}

ArucoMarkerDetector::~ArucoMarkerDetector() = default;
ArucoMarkerDetector::ArucoMarkerDetector(ArucoMarkerDetector&&) noexcept = default;
ArucoMarkerDetector& ArucoMarkerDetector::operator=(ArucoMarkerDetector&&) noexcept = default;

cv::Ptr<cv::aruco::DetectorParameters> arucoDetectorParameters() {
  auto p = cv::aruco::DetectorParameters::create();
  // Corners are refined afterwards by refineMarkerCorners, with a window fitted to each marker.
  p->cornerRefinementMethod = cv::aruco::CORNER_REFINE_NONE;
  return p;
}

void refineMarkerCorners(const cv::Mat& gray, std::vector<cv::Point2f>& corners, int markerBits) {
  if (corners.size() != 4 || gray.empty()) return;
  double side = 1e9;
  for (std::size_t k = 0; k < 4; ++k)
    side = std::min(side, cv::norm(corners[(k + 1) % 4] - corners[k]));
  // One cell of the marker's grid (bits plus the one-cell black border), in pixels. A window
  // reaching into the next cell would pull the corner toward the code's own edges.
  const double cell = side / (markerBits + 2);
  const int half = std::clamp(static_cast<int>(cell * 0.7), 1, 10);
  if (half < 2) return;  // too small to refine; the polygon's corners are the best there is
  cv::cornerSubPix(gray, corners, cv::Size(half, half), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 0.01));
}

std::optional<cv::Point2d> lineIntersection(cv::Point2d a0, cv::Point2d a1, cv::Point2d b0,
                                            cv::Point2d b1) {
  const cv::Point2d da = a1 - a0;
  const cv::Point2d db = b1 - b0;
  const double den = da.cross(db);
  const double scale = std::max(1.0, cv::norm(da) * cv::norm(db));
  if (!(std::abs(den) > 1e-12 * scale)) return std::nullopt;
  const double s = (b0 - a0).cross(db) / den;
  return a0 + s * da;
}

MarkerPair ArucoMarkerDetector::detect(const cv::Mat& image) {
  if (image.empty()) return {};
  Impl& d = *m_impl;
  if (image.type() == CV_8UC1) {
    d.gray = image;
  } else if (image.type() == CV_8UC3) {
    cv::cvtColor(image, d.gray, cv::COLOR_BGR2GRAY);
  } else if (image.type() == CV_8UC4) {
    cv::cvtColor(image, d.gray, cv::COLOR_BGRA2GRAY);
  } else {
    throw std::invalid_argument(
        "ArUco detection needs an 8-bit gray, BGR or BGRA image, got type " +
        cv::typeToString(image.type()));
  }
  d.corners.clear();
  d.ids.clear();
  cv::aruco::detectMarkers(d.gray, d.dictionary, d.corners, d.ids, d.parameters);
  for (std::size_t i = 0; i < d.ids.size() && i < d.corners.size(); ++i)
    if (d.ids[i] == m_params.wristId || d.ids[i] == m_params.elbowId)
      refineMarkerCorners(d.gray, d.corners[i], d.dictionary->markerSize);
  MarkerPair out;
  double wristPerimeter = 0.0, elbowPerimeter = 0.0;
  for (std::size_t i = 0; i < d.ids.size() && i < d.corners.size(); ++i) {
    const std::vector<cv::Point2f>& c = d.corners[i];
    if (c.size() != 4) continue;
    const double perimeter = cv::arcLength(c, true);
    const auto centre = lineIntersection(c[0], c[2], c[1], c[3]);
    if (!centre || !std::isfinite(centre->x) || !std::isfinite(centre->y)) continue;
    if (d.ids[i] == m_params.wristId && perimeter > wristPerimeter) {
      out.wrist = centre;
      wristPerimeter = perimeter;
    } else if (d.ids[i] == m_params.elbowId && perimeter > elbowPerimeter) {
      out.elbow = centre;
      elbowPerimeter = perimeter;
    }
  }
  return out;
}

}  // namespace armtrack::devices::webcam
