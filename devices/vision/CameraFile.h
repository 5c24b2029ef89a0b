// The per-camera calibration file (docs/devices/webcam.md): JSON with the camera's id and name,
// image size, intrinsics, distortion and, once registered, its pose in the shoulder frame.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "devices/vision/CameraCalibration.h"

namespace armtrack::devices::webcam {

/// A calibration file that cannot be read or written. what() reads "<file>: <message>", with the
/// JSON key at fault where there is one.
class CameraFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CameraFile {
  std::string id;    ///< how the camera was opened: device index or path ("0", "/dev/video2")
  std::string name;  ///< free text, e.g. "Logitech C920 on the tripod"
  Intrinsics intrinsics;
  std::optional<ChessboardSpec> chessboard;  ///< the board the intrinsics came from
  std::optional<Extrinsics> extrinsics;      ///< absent until camera-register
};

/// Current file format version ("version" key).
inline constexpr int kCameraFileVersion = 1;

/// The file's text (pretty-printed JSON, ending in a newline). Any thread.
std::string toJson(const CameraFile& file);
/// Parses and checks a file's text: fx, fy > 0, every number finite, the image size positive, R a
/// rotation (to 1e-6). source names the text in messages. Throws CameraFileError. Any thread.
CameraFile cameraFileFromJson(std::string_view text, const std::string& source);
/// Reads and checks a file (at most 1 MiB). Throws CameraFileError.
CameraFile readCameraFile(const std::filesystem::path& path);
/// Writes all or nothing (core/io/AtomicFile). Throws CameraFileError. Not in the fuzz build,
/// which has no armtrack_core.
void writeCameraFile(const std::filesystem::path& path, const CameraFile& file);

/// Where an ArUco board was placed for camera-register: its pose in the shoulder frame and,
/// optionally, its layout.
struct BoardPoseFile {
  Pose boardInShoulder;                  ///< p_shoulder = R p_board + t (m)
  std::optional<ArucoBoardSpec> layout;  ///< when the file says
};

/// Parses a board-pose file: {"R": [[3],[3],[3]] or "rotation_deg": [rx, ry, rz] (a rotation
/// vector, degrees), "t_m": [x, y, z], optional "board": {"dictionary", "markers": [x, y],
/// "marker_m", "separation_m", "first_id"}}. Throws CameraFileError naming the key at fault.
BoardPoseFile boardPoseFromJson(std::string_view text, const std::string& source);
BoardPoseFile readBoardPoseFile(const std::filesystem::path& path);

}  // namespace armtrack::devices::webcam
