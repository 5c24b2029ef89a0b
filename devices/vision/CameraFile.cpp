#include "devices/vision/CameraFile.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>
#include <sstream>

namespace armtrack::devices::webcam {

using nlohmann::json;

namespace {

constexpr std::uintmax_t kMaxFileBytes = 1 << 20;

/// Reads typed values out of the JSON with messages naming the key path.
class Reader {
 public:
  explicit Reader(std::string source) : m_source(std::move(source)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& message) const {
    throw CameraFileError(m_source + ": " + (where.empty() ? "" : "'" + where + "': ") + message);
  }

  const json& member(const json& obj, const std::string& path, const char* key) const {
    if (!obj.is_object()) fail(path, "expected an object");
    const auto it = obj.find(key);
    if (it == obj.end()) fail(join(path, key), "missing");
    return *it;
  }
  const json* optional(const json& obj, const std::string& path, const char* key) const {
    if (!obj.is_object()) fail(path, "expected an object");
    const auto it = obj.find(key);
    return it == obj.end() || it->is_null() ? nullptr : &*it;
  }

  double number(const json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, "expected a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path, "expected a finite number");
    return d;
  }
  double number(const json& obj, const std::string& path, const char* key) const {
    return number(member(obj, path, key), join(path, key));
  }
  int integer(const json& v, const std::string& path, int min, int max) const {
    if (!v.is_number_integer()) fail(path, "expected a whole number");
    const auto i = v.get<std::int64_t>();
    if (i < min || i > max)
      fail(path, "must be from " + std::to_string(min) + " to " + std::to_string(max));
    return static_cast<int>(i);
  }
  std::string text(const json& obj, const std::string& path, const char* key) const {
    const json* v = optional(obj, path, key);
    if (!v) return {};
    if (!v->is_string()) fail(join(path, key), "expected a string");
    return v->get<std::string>();
  }
  template <std::size_t N>
  std::array<double, N> numbers(const json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != N)
      fail(path, "expected an array of " + std::to_string(N) + " numbers");
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = number(v[i], path + "[" + std::to_string(i) + "]");
    return out;
  }
  static std::string join(const std::string& path, const char* key) {
    return path.empty() ? std::string(key) : path + "." + key;
  }

 private:
  std::string m_source;
};

/// The JSON library's message, with the line and column of the offending token added when the
/// library gives none (out_of_range for a number such as 1e999 names the token, not where it is).
std::string jsonErrorText(const json::exception& e, std::string_view text) {
  std::string what = e.what();
  if (dynamic_cast<const json::parse_error*>(&e)) return what;  // has "at line L, column C"
  const auto open = what.find('\'');
  const auto close = open == std::string::npos ? open : what.find('\'', open + 1);
  if (close == std::string::npos || close == open + 1) return what;
  const auto at = text.find(std::string_view(what).substr(open + 1, close - open - 1));
  if (at == std::string_view::npos) return what;
  int line = 1, column = 1;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return what + " at line " + std::to_string(line) + ", column " + std::to_string(column);
}

json sizeJson(cv::Size s) {
  return json::array({s.width, s.height});
}

}  // namespace

std::string toJson(const CameraFile& f) {
  const Intrinsics& in = f.intrinsics;
  json j;
  j["format"] = "armtrack-camera";
  j["version"] = kCameraFileVersion;
  j["camera"] = {{"id", f.id}, {"name", f.name}};
  j["image_size"] = sizeJson(in.imageSize);
  j["intrinsics"] = {{"fx", in.fx}, {"fy", in.fy},        {"cx", in.cx},
                     {"cy", in.cy}, {"rms_px", in.rmsPx}, {"boards", in.boards}};
  if (f.chessboard)
    j["intrinsics"]["chessboard"] = {{"inner_corners", sizeJson(f.chessboard->innerCorners)},
                                     {"square_m", f.chessboard->squareSize}};
  j["distortion"] = json::array({in.dist[0], in.dist[1], in.dist[2], in.dist[3], in.dist[4]});
  if (f.extrinsics) {
    const Extrinsics& e = *f.extrinsics;
    json R = json::array();
    for (int r = 0; r < 3; ++r) R.push_back({e.R(r, 0), e.R(r, 1), e.R(r, 2)});
    j["extrinsics"] = {
        {"R", R}, {"t_m", {e.t[0], e.t[1], e.t[2]}}, {"rms_px", e.rmsPx}, {"markers", e.markers}};
  }
  return j.dump(2) + "\n";
}

CameraFile cameraFileFromJson(std::string_view text, const std::string& source) {
  const Reader rd(source);
  json j;
  try {
    j = json::parse(text.begin(), text.end());
  } catch (const json::exception& e) {  // parse_error, or out_of_range for a huge number
    rd.fail("", "not valid JSON (" + jsonErrorText(e, text) +
                    "); make the file again with armtrack-cli camera-calibrate");
  }
  if (!j.is_object()) rd.fail("", "expected a JSON object");
  if (const json* fmt = rd.optional(j, "", "format");
      !fmt || !fmt->is_string() || fmt->get<std::string>() != "armtrack-camera")
    rd.fail("format", "expected \"armtrack-camera\" (is this a camera file?)");
  const int version = rd.integer(rd.member(j, "", "version"), "version", 1, 1000000);
  if (version > kCameraFileVersion)
    rd.fail("version", "version " + std::to_string(version) +
                           " is newer than this program reads (" +
                           std::to_string(kCameraFileVersion) + ")");

  CameraFile f;
  if (const json* cam = rd.optional(j, "", "camera")) {
    f.id = rd.text(*cam, "camera", "id");
    f.name = rd.text(*cam, "camera", "name");
  }
  Intrinsics& in = f.intrinsics;
  const json& size = rd.member(j, "", "image_size");
  if (!size.is_array() || size.size() != 2) rd.fail("image_size", "expected [width, height]");
  in.imageSize.width = rd.integer(size[0], "image_size[0]", 1, 100000);
  in.imageSize.height = rd.integer(size[1], "image_size[1]", 1, 100000);

  const json& ij = rd.member(j, "", "intrinsics");
  in.fx = rd.number(ij, "intrinsics", "fx");
  in.fy = rd.number(ij, "intrinsics", "fy");
  in.cx = rd.number(ij, "intrinsics", "cx");
  in.cy = rd.number(ij, "intrinsics", "cy");
  if (!(in.fx > 0.0)) rd.fail("intrinsics.fx", "must be > 0");
  if (!(in.fy > 0.0)) rd.fail("intrinsics.fy", "must be > 0");
  if (const json* v = rd.optional(ij, "intrinsics", "rms_px"))
    in.rmsPx = rd.number(*v, "intrinsics.rms_px");
  if (const json* v = rd.optional(ij, "intrinsics", "boards"))
    in.boards = rd.integer(*v, "intrinsics.boards", 0, 1000000);
  if (const json* cb = rd.optional(ij, "intrinsics", "chessboard")) {
    ChessboardSpec spec;
    const json& corners = rd.member(*cb, "intrinsics.chessboard", "inner_corners");
    if (!corners.is_array() || corners.size() != 2)
      rd.fail("intrinsics.chessboard.inner_corners", "expected [across, down]");
    spec.innerCorners.width =
        rd.integer(corners[0], "intrinsics.chessboard.inner_corners[0]", 2, 1000);
    spec.innerCorners.height =
        rd.integer(corners[1], "intrinsics.chessboard.inner_corners[1]", 2, 1000);
    spec.squareSize = rd.number(*cb, "intrinsics.chessboard", "square_m");
    f.chessboard = spec;
  }
  in.dist = rd.numbers<5>(rd.member(j, "", "distortion"), "distortion");

  if (const json* ej = rd.optional(j, "", "extrinsics")) {
    Extrinsics e;
    const json& R = rd.member(*ej, "extrinsics", "R");
    if (!R.is_array() || R.size() != 3) rd.fail("extrinsics.R", "expected 3 rows of 3 numbers");
    for (int r = 0; r < 3; ++r) {
      const auto row =
          rd.numbers<3>(R[static_cast<std::size_t>(r)], "extrinsics.R[" + std::to_string(r) + "]");
      for (int c = 0; c < 3; ++c) e.R(r, c) = row[static_cast<std::size_t>(c)];
    }
    if (!isRotation(e.R, 1e-6))
      rd.fail("extrinsics.R", "not a rotation matrix (orthonormal, determinant +1, to 1e-6)");
    const auto t = rd.numbers<3>(rd.member(*ej, "extrinsics", "t_m"), "extrinsics.t_m");
    e.t = cv::Vec3d(t[0], t[1], t[2]);
    if (const json* v = rd.optional(*ej, "extrinsics", "rms_px"))
      e.rmsPx = rd.number(*v, "extrinsics.rms_px");
    if (const json* v = rd.optional(*ej, "extrinsics", "markers"))
      e.markers = rd.integer(*v, "extrinsics.markers", 0, 1000000);
    f.extrinsics = e;
  }
  return f;
}

namespace {

std::string readSmallFile(const std::filesystem::path& path, const char* missingHint) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw CameraFileError(name + ": no such file" + missingHint);
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw CameraFileError(name + ": cannot read (" + ec.message() + ")");
  if (size > kMaxFileBytes) throw CameraFileError(name + ": too big for a camera file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CameraFileError(name + ": cannot open for reading");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw CameraFileError(name + ": read error");
  return text.str();
}

}  // namespace

CameraFile readCameraFile(const std::filesystem::path& path) {
  return cameraFileFromJson(readSmallFile(path, " (make it with armtrack-cli camera-calibrate)"),
                            path.string());
}

BoardPoseFile boardPoseFromJson(std::string_view text, const std::string& source) {
  const Reader rd(source);
  json j;
  try {
    j = json::parse(text.begin(), text.end());
  } catch (const json::exception& e) {  // parse_error, or out_of_range for a huge number
    rd.fail("", "not valid JSON (" + jsonErrorText(e, text) + ")");
  }
  if (!j.is_object()) rd.fail("", "expected a JSON object");
  BoardPoseFile f;
  const json* R = rd.optional(j, "", "R");
  const json* rot = rd.optional(j, "", "rotation_deg");
  if ((R != nullptr) == (rot != nullptr))
    rd.fail("",
            "give the board's rotation as either \"R\" (3 rows of 3) or \"rotation_deg\" "
            "(a rotation vector in degrees), not both or neither");
  if (R) {
    if (!R->is_array() || R->size() != 3) rd.fail("R", "expected 3 rows of 3 numbers");
    for (int r = 0; r < 3; ++r) {
      const auto row =
          rd.numbers<3>((*R)[static_cast<std::size_t>(r)], "R[" + std::to_string(r) + "]");
      for (int c = 0; c < 3; ++c) f.boardInShoulder.R(r, c) = row[static_cast<std::size_t>(c)];
    }
    if (!isRotation(f.boardInShoulder.R, 1e-6))
      rd.fail("R", "not a rotation matrix (orthonormal, determinant +1, to 1e-6)");
  } else {
    const auto v = rd.numbers<3>(*rot, "rotation_deg");
    const double k = 3.14159265358979323846 / 180.0;
    cv::Rodrigues(cv::Vec3d(v[0] * k, v[1] * k, v[2] * k), f.boardInShoulder.R);
  }
  const auto t = rd.numbers<3>(rd.member(j, "", "t_m"), "t_m");
  f.boardInShoulder.t = cv::Vec3d(t[0], t[1], t[2]);
  if (const json* b = rd.optional(j, "", "board")) {
    ArucoBoardSpec spec;
    const std::string dict = rd.text(*b, "board", "dictionary");
    if (!dict.empty()) spec.dictionary = dict;
    if (const json* m = rd.optional(*b, "board", "markers")) {
      if (!m->is_array() || m->size() != 2) rd.fail("board.markers", "expected [across, down]");
      spec.markersX = rd.integer((*m)[0], "board.markers[0]", 1, 100);
      spec.markersY = rd.integer((*m)[1], "board.markers[1]", 1, 100);
    }
    if (const json* v = rd.optional(*b, "board", "marker_m"))
      spec.markerLength = rd.number(*v, "board.marker_m");
    if (const json* v = rd.optional(*b, "board", "separation_m"))
      spec.separation = rd.number(*v, "board.separation_m");
    if (const json* v = rd.optional(*b, "board", "first_id"))
      spec.firstId = rd.integer(*v, "board.first_id", 0, 100000);
    f.layout = spec;
  }
  return f;
}

BoardPoseFile readBoardPoseFile(const std::filesystem::path& path) {
  return boardPoseFromJson(readSmallFile(path, ""), path.string());
}

}  // namespace armtrack::devices::webcam
