#include "app/cli/Camera.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <opencv2/calib3d.hpp>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "app/cli/Args.h"
#include "app/cli/Text.h"
#include "devices/vision/CameraCalibration.h"
#include "devices/vision/CameraFile.h"
#include "devices/vision/MarkerDetection.h"

namespace armtrack::cli {

namespace fs = std::filesystem;
using namespace armtrack::devices::webcam;

namespace {

constexpr std::string_view kCalibrateHelp =
    R"(Usage: armtrack-cli camera-calibrate --images DIR --board 9x6 --square 0.025 --out CAM.json
       armtrack-cli camera-calibrate IMG1.png IMG2.png ... --board 9x6 --square 0.025 --out CAM.json

Intrinsic calibration of a camera from images of a printed chessboard (OpenCV's
calibrateCamera): focal lengths, principal point and distortion k1 k2 p1 p2 (k3 with --k3).
Take 10 to 20 images at the resolution you will track at, the whole board in view, tilted
differently in each, covering the corners of the image too. Writes the camera file without a
pose; add the pose with camera-register. docs/devices/webcam.md

Options:
  --images PATH      a folder (its .png, .jpg, .jpeg and .bmp files) or one image;
                     image files may also be given as arguments
  --board WxH        inner corners across x down, e.g. 9x6 for a board of 10 x 7 squares
                     (required)
  --square M         side of a square in m, e.g. 0.025 (required)
  --out FILE         the camera file to write (JSON, required)
  --camera-id ID     how the camera is opened (its index or /dev/video path; default "0")
  --name TEXT        a free description, e.g. "C920 on the tripod"
  --min-boards N     fewer images with the board found is an error (default 4)
  --k3               also estimate k3 (wide-angle lenses; needs many images)
)";

constexpr std::string_view kRegisterHelp =
    R"(Usage: armtrack-cli camera-register --camera CAM.json --image BOARD.png
                                    --board-pose POSE.json --out CAM.json [options]
       armtrack-cli camera-register --camera CAM.json --image BOARD.png
                                    --board-origin X,Y,Z --board-rotation RX,RY,RZ --out CAM.json

Registers a calibrated camera to the shoulder frame from one image of an ArUco grid board placed
at a known pose: p_camera = R p_shoulder + t. Adds R, t to the camera file (--out may be the
--camera file itself). The board frame is OpenCV's GridBoard's; see docs/devices/webcam.md.

Options:
  --camera FILE         camera file from camera-calibrate (required)
  --image FILE          one image of the board, at the calibrated resolution (required)
  --board-pose FILE     the board's pose in the shoulder frame (JSON: "R" or "rotation_deg",
                        "t_m", optionally its "board" layout)
  --board-origin X,Y,Z  instead: the board origin in the shoulder frame, m
  --board-rotation RX,RY,RZ
                        and its rotation as a rotation vector, degrees (default 0,0,0)
  --out FILE            the camera file to write (required)
  --markers XxY         markers across x down (default 5x7)
  --marker-length M     marker side, m (default 0.03)
  --separation M        gap between markers, m (default 0.006)
  --dictionary NAME     ArUco dictionary (default DICT_4X4_50)
  --first-id N          id of the first marker (default 0)
  --min-markers N       fewer board markers found is an error (default 4)
)";

/// "9x6" -> (9, 6).
cv::Size parseSize(const Args& a, std::string_view option, const std::string& text) {
  const auto x = text.find_first_of("xX");
  int w = 0, h = 0;
  try {
    std::size_t p1 = 0, p2 = 0;
    if (x == std::string::npos) throw std::invalid_argument("no x");
    w = std::stoi(text.substr(0, x), &p1);
    h = std::stoi(text.substr(x + 1), &p2);
    if (p1 != x || p2 != text.size() - x - 1) throw std::invalid_argument("trailing");
  } catch (const std::exception&) {
    a.fail(std::string(option) + ": expected WxH, e.g. 9x6, got " + inQuotes(text));
  }
  if (w < 1 || h < 1 || w > 1000 || h > 1000)
    a.fail(std::string(option) + ": both counts must be from 1 to 1000, got " + inQuotes(text));
  return {w, h};
}

cv::Vec3d parseTriple(const Args& a, std::string_view option, const std::string& text) {
  cv::Vec3d v;
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',', start);
    if ((i < 2) != (comma != std::string::npos))
      a.fail(std::string(option) + ": expected three numbers separated by commas, got " +
             inQuotes(text));
    const auto n = parseDouble(std::string_view(text).substr(start, comma - start));
    if (!n) a.fail(std::string(option) + ": " + inQuotes(text) + " is not three numbers");
    v[i] = *n;
    start = comma + 1;
  }
  return v;
}

bool isImageFile(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp";
}

std::string sizeText(cv::Size s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

}  // namespace

int cameraCalibrateCommand(const std::vector<std::string>& args, std::ostream& out,
                           std::ostream& err) {
  const Args a("camera-calibrate", args,
               {{"--images", true},
                {"--board", true},
                {"--square", true},
                {"--out", true},
                {"--camera-id", true},
                {"--name", true},
                {"--min-boards", true},
                {"--k3", false}});
  if (a.help()) {
    out << kCalibrateHelp;
    return 0;
  }
  ChessboardSpec board;
  board.innerCorners = parseSize(a, "--board", a.required("--board"));
  if (board.innerCorners.width < 2 || board.innerCorners.height < 2 ||
      board.innerCorners.width == board.innerCorners.height)
    a.fail(
        "--board: inner corners across and down must be at least 2 and differ (so the "
        "board's orientation is known), got " +
        sizeText(board.innerCorners));
  board.squareSize = a.positive("--square", 0.0);
  if (board.squareSize > 1.0)
    a.fail("--square: in m, e.g. 0.025; got " + shortest(board.squareSize));
  const fs::path outPath = a.required("--out");
  IntrinsicsOptions opt;
  const std::uint64_t minBoards = a.integer("--min-boards", 4);
  if (minBoards < 1 || minBoards > 1000) a.fail("--min-boards: must be from 1 to 1000");
  opt.minBoards = static_cast<int>(minBoards);
  opt.fixK3 = !a.flag("--k3");

  std::vector<fs::path> files;
  if (const auto dir = a.value("--images")) {
    if (dir->empty()) a.fail("--images: missing value");
    std::error_code ec;
    if (fs::is_directory(*dir, ec)) {
      for (const auto& entry : fs::directory_iterator(*dir, ec))
        if (entry.is_regular_file() && isImageFile(entry.path())) files.push_back(entry.path());
      if (ec) throw std::runtime_error(*dir + ": cannot list the folder (" + ec.message() + ")");
      std::sort(files.begin(), files.end());
      if (files.empty()) throw std::runtime_error(*dir + ": no .png, .jpg, .jpeg or .bmp images");
    } else {
      files.emplace_back(*dir);
    }
  }
  for (const std::string& p : a.positionals()) files.emplace_back(p);
  if (files.empty()) a.fail("no images: give --images DIR or image files");

  std::vector<NamedImage> images;
  for (const fs::path& f : files) images.push_back({f.filename().string(), loadImage(f.string())});
  err << "camera-calibrate: looking for the " << sizeText(board.innerCorners) << " chessboard in "
      << images.size() << " images\n";
  const IntrinsicsResult r = calibrateIntrinsics(images, board, opt);

  CameraFile file;
  std::error_code ec;
  if (fs::exists(outPath, ec)) {
    try {
      const CameraFile old = readCameraFile(outPath);
      if (old.extrinsics)
        err << "warning: " << outPath.string()
            << " had a pose in the shoulder frame; new intrinsics invalidate it, so it is not "
               "kept. Run camera-register again\n";
    } catch (const CameraFileError&) {
      // Replaced whatever it was.
    }
  }
  file.id = a.value("--camera-id").value_or("0");
  file.name = a.value("--name").value_or("");
  file.intrinsics = r.intrinsics;
  file.chessboard = board;
  writeCameraFile(outPath, file);

  const Intrinsics& in = r.intrinsics;
  out << "# Camera intrinsics (" << sizeText(in.imageSize) << ", " << r.used.size() << " of "
      << images.size() << " images)\n\n"
      << "| parameter | value |\n|---|---|\n"
      << "| fx (px) | " << fixed(in.fx, 2) << " |\n"
      << "| fy (px) | " << fixed(in.fy, 2) << " |\n"
      << "| cx (px) | " << fixed(in.cx, 2) << " |\n"
      << "| cy (px) | " << fixed(in.cy, 2) << " |\n"
      << "| k1, k2, p1, p2, k3 | " << fixed(in.dist[0], 5) << ", " << fixed(in.dist[1], 5) << ", "
      << fixed(in.dist[2], 5) << ", " << fixed(in.dist[3], 5) << ", " << fixed(in.dist[4], 5)
      << " |\n"
      << "| RMS reprojection error (px) | " << fixed(in.rmsPx, 3) << " |\n\n"
      << "| image | RMS (px) |\n|---|---|\n";
  for (std::size_t i = 0; i < r.used.size(); ++i)
    out << "| " << r.used[i] << " | "
        << (i < r.perViewRmsPx.size() ? fixed(r.perViewRmsPx[i], 3) : std::string("?")) << " |\n";
  for (const std::string& why : r.rejected) err << "camera-calibrate: skipped " << why << "\n";
  if (in.rmsPx > 1.0)
    err << "warning: the RMS reprojection error is " << fixed(in.rmsPx, 2)
        << " px; under 0.5 px is usual. Check --board and --square, and drop blurred images\n";
  if (r.used.size() < 10)
    err << "warning: only " << r.used.size()
        << " images with the board; 10 to 20 at varied tilts give steadier intrinsics\n";
  err << "camera-calibrate: wrote " << outPath.string() << "\n";
  return 0;
}

int cameraRegisterCommand(const std::vector<std::string>& args, std::ostream& out,
                          std::ostream& err) {
  const Args a("camera-register", args,
               {{"--camera", true},
                {"--image", true},
                {"--board-pose", true},
                {"--board-origin", true},
                {"--board-rotation", true},
                {"--out", true},
                {"--markers", true},
                {"--marker-length", true},
                {"--separation", true},
                {"--dictionary", true},
                {"--first-id", true},
                {"--min-markers", true}});
  if (a.help()) {
    out << kRegisterHelp;
    return 0;
  }
  if (!a.positionals().empty()) a.fail("unexpected argument " + inQuotes(a.positionals()[0]));
  const fs::path cameraPath = a.required("--camera");
  const std::string imagePath = a.required("--image");
  const fs::path outPath = a.required("--out");
  const bool poseFile = a.flag("--board-pose");
  if (poseFile == a.flag("--board-origin"))
    a.fail(
        "give the board's pose with either --board-pose FILE or --board-origin X,Y,Z (and "
        "--board-rotation)");
  if (poseFile && a.flag("--board-rotation"))
    a.fail("--board-rotation goes with --board-origin, not --board-pose");

  ArucoBoardSpec board;
  Pose pose;
  if (poseFile) {
    const BoardPoseFile f = readBoardPoseFile(a.required("--board-pose"));
    pose = f.boardInShoulder;
    if (f.layout) board = *f.layout;
  } else {
    pose.t = parseTriple(a, "--board-origin", a.required("--board-origin"));
    const cv::Vec3d deg = a.flag("--board-rotation")
                              ? parseTriple(a, "--board-rotation", a.required("--board-rotation"))
                              : cv::Vec3d(0, 0, 0);
    cv::Rodrigues(deg * (3.14159265358979323846 / 180.0), pose.R);
  }
  // Command-line layout options override the file's.
  if (const auto m = a.value("--markers")) {
    const cv::Size s = parseSize(a, "--markers", *m);
    board.markersX = s.width;
    board.markersY = s.height;
  }
  board.markerLength = a.positive("--marker-length", board.markerLength);
  board.separation = a.nonNegative("--separation", board.separation);
  if (const auto d = a.value("--dictionary")) {
    if (!arucoDictionaryId(*d))
      a.fail("--dictionary: unknown " + inQuotes(*d) + " (known: " + arucoDictionaryNames() + ")");
    board.dictionary = *d;
  }
  const std::uint64_t firstId = a.integer("--first-id", static_cast<std::uint64_t>(board.firstId));
  if (firstId > 100000) a.fail("--first-id: too large");
  board.firstId = static_cast<int>(firstId);
  const std::uint64_t minMarkers = a.integer("--min-markers", 4);
  if (minMarkers < 1 || minMarkers > 10000) a.fail("--min-markers: must be from 1 to 10000");

  CameraFile file = readCameraFile(cameraPath);
  const cv::Mat image = loadImage(imagePath);
  const Extrinsics e =
      registerCamera(image, file.intrinsics, board, pose, static_cast<int>(minMarkers));
  if (file.extrinsics)
    err << "camera-register: replacing the pose that " << cameraPath.string() << " had\n";
  file.extrinsics = e;
  writeCameraFile(outPath, file);

  const cv::Vec3d centre = -(e.R.t() * e.t);
  out << "# Camera pose in the shoulder frame (" << e.markers << " board markers)\n\n"
      << "p_camera = R p_shoulder + t\n\n"
      << "| | |\n|---|---|\n";
  for (int r = 0; r < 3; ++r)
    out << "| R row " << r + 1 << " | " << fixed(e.R(r, 0), 5) << ", " << fixed(e.R(r, 1), 5)
        << ", " << fixed(e.R(r, 2), 5) << " |\n";
  out << "| t (m) | " << fixed(e.t[0], 4) << ", " << fixed(e.t[1], 4) << ", " << fixed(e.t[2], 4)
      << " |\n"
      << "| camera centre in the shoulder frame (m) | " << fixed(centre[0], 4) << ", "
      << fixed(centre[1], 4) << ", " << fixed(centre[2], 4) << " |\n"
      << "| RMS reprojection error (px) | " << fixed(e.rmsPx, 3) << " |\n";
  if (e.rmsPx > 1.0)
    err << "warning: the board's corners reproject with " << fixed(e.rmsPx, 2)
        << " px RMS; check the board options (--markers, --marker-length, --separation) and "
           "the camera file\n";
  err << "camera-register: wrote " << outPath.string() << "\n";
  return 0;
}

}  // namespace armtrack::cli
