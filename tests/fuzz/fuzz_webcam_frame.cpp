// libFuzzer target: one input = one camera frame as an encoded image (through decodeCameraImage,
// so JPEG, PNG or BMP, as the calibration commands read them) into both marker detectors, or, when
// the first byte is '{', a camera file and a board-pose file for their JSON parsers.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <opencv2/core/utils/logger.hpp>
#include <string_view>

#include "devices/vision/CameraCalibration.h"
#include "devices/vision/CameraFile.h"
#include "devices/vision/MarkerDetection.h"

using namespace armtrack::devices::webcam;

namespace {

void checkInside(const std::optional<cv::Point2d>& p, const cv::Mat& image) {
  if (!p) return;
  // A centroid or a diagonal crossing lies within the image, give or take half a pixel.
  if (!std::isfinite(p->x) || !std::isfinite(p->y) || p->x < -1.0 || p->y < -1.0 ||
      p->x > image.cols || p->y > image.rows)
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // A few bytes of PNG can claim a huge image; keep decoding within the fuzzer's memory limit.
  setenv("OPENCV_IO_MAX_IMAGE_PIXELS", "4000000", 1);
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  cv::setNumThreads(1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 0 && data[0] == '{') {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
      const CameraFile f = cameraFileFromJson(text, "fuzz");
      // What the parser accepts is valid and survives a round trip.
      if (!(f.intrinsics.fx > 0) || !(f.intrinsics.fy > 0)) std::abort();
      if (f.extrinsics && !isRotation(f.extrinsics->R, 1e-6)) std::abort();
      const CameraFile g = cameraFileFromJson(toJson(f), "again");
      if (toJson(g) != toJson(f)) std::abort();
    } catch (const CameraFileError&) {
    }
    try {
      boardPoseFromJson(text, "fuzz");
    } catch (const CameraFileError&) {
    }
    return 0;
  }
  const cv::Mat image = decodeCameraImage(data, size);
  if (image.empty()) return 0;
  static ColourMarkerDetector colour;
  static ArucoMarkerDetector aruco;
  const MarkerPair c = colour.detect(image);
  checkInside(c.wrist, image);
  checkInside(c.elbow, image);
  const MarkerPair a = aruco.detect(image);
  checkInside(a.wrist, image);
  checkInside(a.elbow, image);
  return 0;
}
