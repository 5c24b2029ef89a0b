// The recording's JSON sidecar (docs/recording-format.md): reading with checks, writing.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string_view>
#include <system_error>

#include "core/io/AtomicFile.h"
#include "core/io/Recording.h"
#include "core/io/RecordingFormat.h"

namespace armtrack {

namespace fs = std::filesystem;
using namespace recording_detail;

fs::path sidecarPath(const fs::path& csvPath) {
  fs::path p = csvPath;
  p.replace_extension(".json");
  return p;
}

namespace {

/// Reads a whole file into memory; errors report line 0, column 0.
std::string readWholeFile(const fs::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw RecordingError(name, 0, 0, "cannot open file: is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RecordingError(name, 0, 0, "cannot open file: " + osReason(errno));
  const auto size = fs::file_size(path, ec);
  std::string data;
  std::size_t chunk = ec ? std::size_t{1} << 20 : static_cast<std::size_t>(size) + 1;
  for (;;) {
    const std::size_t old = data.size();
    data.resize(old + chunk);
    in.read(data.data() + old, static_cast<std::streamsize>(chunk));
    const auto got = static_cast<std::size_t>(in.gcount());
    data.resize(old + got);
    if (got < chunk) break;
    chunk = std::size_t{1} << 20;
  }
  if (in.bad()) throw RecordingError(name, 0, 0, "cannot read file: " + osReason(errno));
  return data;
}

// ---------------------------------------------------------------------------------------------
// Sidecar reading

using Json = nlohmann::json;

[[noreturn]] void metaFail(const std::string& file, const std::string& message) {
  throw RecordingError(file, 0, 0, message);
}

double jsonNumber(const std::string& file, const Json& j, const std::string& key) {
  if (!j.is_number() || !std::isfinite(j.get<double>())) {
    metaFail(file, inQuotes(key) + " must be a finite number, got " + j.dump());
  }
  return j.get<double>();
}

template <std::size_t N>
std::array<double, N> jsonNumbers(const std::string& file, const Json& j, const std::string& key) {
  if (!j.is_array() || j.size() != N) {
    metaFail(file, inQuotes(key) + " must be an array of " + std::to_string(N) + " numbers, got " +
                       j.dump());
  }
  std::array<double, N> out;
  for (std::size_t i = 0; i < N; ++i) {
    out[i] = jsonNumber(file, j[i], key + "[" + std::to_string(i) + "]");
  }
  return out;
}

/// Line and column (1-based) of the byte at 1-based position byte.
std::pair<int, int> textPosition(std::string_view text, std::size_t byte) {
  const std::size_t end = std::min(byte == 0 ? 0 : byte - 1, text.size());
  int line = 1, column = 1;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

/// "\"key\" is <value> <unit>: <why>".
std::string outside(const std::string& key, double v, const std::string& unit,
                    const std::string& why) {
  return inQuotes(key) + " is " + formatDouble(v) + (unit.empty() ? "" : " " + unit) + ": " + why;
}

/// Where the JSON library's message names the offending token ("... parsing '1e999'"), the
/// line and column of its first occurrence in text; {0, 0} when it does not.
std::pair<int, int> tokenPosition(std::string_view text, const std::string& what) {
  const auto open = what.find('\'');
  const auto close = open == std::string::npos ? open : what.find('\'', open + 1);
  if (close == std::string::npos || close == open + 1) return {0, 0};
  const std::string token = what.substr(open + 1, close - open - 1);
  const auto at = text.find(token);
  if (at == std::string_view::npos) return {0, 0};
  return textPosition(text, at + 1);
}

}  // namespace

std::string metaProblem(const RecordingMeta& meta) {
  using L = MetaLimits;
  const ArmGeometry& g = meta.geometry;
  const std::pair<const char*, double> all[] = {
      {"geometry.l3", g.l3},     {"geometry.l6", g.l6},   {"geometry.lu3", g.lu3},
      {"geometry.thu4", g.thu4}, {"geometry.lu5", g.lu5}, {"geometry.lf6", g.lf6},
      {"geometry.thf7", g.thf7}, {"geometry.lf8", g.lf8}, {"g", meta.g}};
  for (const auto& [key, v] : all) {
    if (!std::isfinite(v))
      return inQuotes(key) + " is " + formatDouble(v) + ", not a finite number";
  }
  const std::string segment =
      "between " + formatDouble(L::kMinSegment) + " and " + formatDouble(L::kMaxSegment) + " m";
  if (!(g.l3 >= L::kMinSegment && g.l3 <= L::kMaxSegment))
    return outside("geometry.l3", g.l3, "m",
                   "the upper arm (shoulder to elbow) must be " + segment);
  if (!(g.l6 >= L::kMinSegment && g.l6 <= L::kMaxSegment))
    return outside("geometry.l6", g.l6, "m", "the forearm (elbow to wrist) must be " + segment);
  if (!(g.lu3 >= 0.0 && g.lu3 <= g.l3 + L::kStrapMargin))
    return outside("geometry.lu3", g.lu3, "m",
                   "the upper-arm IMU must sit on the upper arm, 0 to l3 + " +
                       formatDouble(L::kStrapMargin) + " = " +
                       formatDouble(g.l3 + L::kStrapMargin) + " m from the shoulder");
  if (!(g.lf6 >= 0.0 && g.lf6 <= g.l6 + L::kStrapMargin))
    return outside("geometry.lf6", g.lf6, "m",
                   "the forearm IMU must sit on the forearm, 0 to l6 + " +
                       formatDouble(L::kStrapMargin) + " = " +
                       formatDouble(g.l6 + L::kStrapMargin) + " m from the elbow");
  for (const auto& [key, v] :
       {std::pair{"geometry.lu5", g.lu5}, std::pair{"geometry.lf8", g.lf8}}) {
    if (!(std::abs(v) <= L::kMaxStrapRadius))
      return outside(key, v, "m",
                     "an IMU strapped to the arm sits at most " + formatDouble(L::kMaxStrapRadius) +
                         " m from the bone's axis");
  }
  for (const auto& [key, v] :
       {std::pair{"geometry.thu4", g.thu4}, std::pair{"geometry.thf7", g.thf7}}) {
    if (!(std::abs(v) <= L::kMaxStrapAngle))
      return outside(key, v, "rad",
                     "an angle about the arm's axis is between -" +
                         formatDouble(L::kMaxStrapAngle) + " and " +
                         formatDouble(L::kMaxStrapAngle) + " rad");
  }
  if (!(meta.g >= L::kMinG && meta.g <= L::kMaxG))
    return outside("g", meta.g, "m/s^2",
                   "gravity on Earth is between " + formatDouble(L::kMinG) + " and " +
                       formatDouble(L::kMaxG) + " m/s^2");
  if (!meta.up.allFinite() || !(std::abs(meta.up.norm() - 1.0) <= 0.5))
    return "\"up\" must be a unit vector (pointing up in the shoulder frame)";
  if (meta.trunk) {
    const TrunkMount& m = *meta.trunk;
    if (!m.imuPosition.allFinite())
      return "\"trunk.imu_position\" holds a value that is not a finite number";
    if (!m.imuRotation.allFinite())
      return "\"trunk.imu_rotation\" holds a value that is not a finite number";
    if (!(m.imuPosition.norm() <= L::kMaxTrunkImuDistance))
      return outside("trunk.imu_position", m.imuPosition.norm(), "m from the shoulder centre",
                     "a sternum IMU sits within " + formatDouble(L::kMaxTrunkImuDistance) +
                         " m of the shoulder (about 0.2-0.3 m); is it in metres, relative to "
                         "the shoulder centre?");
    const Eigen::Matrix3d& r = m.imuRotation;
    const double orthoError =
        (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(orthoError <= L::kRotationTolerance && r.determinant() > 0.0))
      return "\"trunk.imu_rotation\" is not a rotation matrix (orthonormal to " +
             formatDouble(L::kRotationTolerance) +
             ", determinant +1; 9 numbers row by row, its columns the IMU's axes in frame 0): "
             "|R^T R - I| reaches " +
             formatDouble(orthoError) + ", det R = " + formatDouble(r.determinant());
  }
  if (!meta.camera) return {};
  const CameraParams& c = *meta.camera;
  const std::pair<const char*, double> cam[] = {
      {"camera.fx", c.fx}, {"camera.fy", c.fy}, {"camera.cx", c.cx}, {"camera.cy", c.cy}};
  for (const auto& [key, v] : cam) {
    if (!std::isfinite(v))
      return inQuotes(key) + " is " + formatDouble(v) + ", not a finite number";
  }
  for (std::size_t i = 0; i < c.dist.size(); ++i) {
    if (!std::isfinite(c.dist[i]))
      return "\"camera.dist[" + std::to_string(i) + "]\" is not a finite number";
  }
  if (!c.R.allFinite()) return "\"camera.R\" holds a value that is not a finite number";
  if (!c.t.allFinite()) return "\"camera.t\" holds a value that is not a finite number";
  for (const auto& [key, v] : {std::pair{"camera.fx", c.fx}, std::pair{"camera.fy", c.fy}}) {
    if (!(v > 0.0 && v <= L::kMaxFocal))
      return outside(
          key, v, "pixels",
          "a focal length is positive and at most " + formatDouble(L::kMaxFocal) + " pixels");
  }
  for (const auto& [key, v] : {std::pair{"camera.cx", c.cx}, std::pair{"camera.cy", c.cy}}) {
    if (!(std::abs(v) <= L::kMaxPrincipal))
      return outside(key, v, "pixels",
                     "a principal point is at most " + formatDouble(L::kMaxPrincipal) +
                         " pixels from the image's corner");
  }
  const double orthoError =
      (c.R.transpose() * c.R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(orthoError <= L::kRotationTolerance && c.R.determinant() > 0.0))
    return "\"camera.R\" is not a rotation matrix (orthonormal to " +
           formatDouble(L::kRotationTolerance) + ", determinant +1): |R^T R - I| reaches " +
           formatDouble(orthoError) + ", det R = " + formatDouble(c.R.determinant());
  if (!(c.t.norm() <= L::kMaxCameraDistance))
    return outside(
        "camera.t", c.t.norm(), "m",
        "the camera is at most " + formatDouble(L::kMaxCameraDistance) + " m from the shoulder");
  return {};
}

namespace recording_detail {

std::string sidecarText(const RecordingMeta& meta) {
  using OJson = nlohmann::ordered_json;
  const ArmGeometry& g = meta.geometry;
  OJson j;
  j["format"] = kFormatName;
  j["version"] = kFormatVersion;
  j["geometry"] = {{"l3", g.l3},   {"l6", g.l6},   {"lu3", g.lu3},   {"thu4", g.thu4},
                   {"lu5", g.lu5}, {"lf6", g.lf6}, {"thf7", g.thf7}, {"lf8", g.lf8}};
  j["up"] = {meta.up.x(), meta.up.y(), meta.up.z()};
  j["g"] = meta.g;
  j["side"] = sideName(meta.side);
  if (meta.camera) {
    const CameraParams& c = *meta.camera;
    OJson r = OJson::array();
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) r.push_back(c.R(i, k));
    }
    j["camera"] = {{"fx", c.fx},
                   {"fy", c.fy},
                   {"cx", c.cx},
                   {"cy", c.cy},
                   {"dist", c.dist},
                   {"R", r},
                   {"t", {c.t.x(), c.t.y(), c.t.z()}}};
  }
  if (meta.trunk) {  // only then: a sidecar without a trunk keeps its bytes of before
    const TrunkMount& m = *meta.trunk;
    OJson r = OJson::array();
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) r.push_back(m.imuRotation(i, k));
    }
    j["trunk"] = {{"imu_position", {m.imuPosition.x(), m.imuPosition.y(), m.imuPosition.z()}},
                  {"imu_rotation", r}};
  }
  return j.dump(2) + "\n";
}

void checkMetaWritable(const std::string& file, const RecordingMeta& meta) {
  const ArmGeometry& g = meta.geometry;
  bool ok = std::isfinite(g.l3) && std::isfinite(g.l6) && std::isfinite(g.lu3) &&
            std::isfinite(g.thu4) && std::isfinite(g.lu5) && std::isfinite(g.lf6) &&
            std::isfinite(g.thf7) && std::isfinite(g.lf8) && meta.up.allFinite() &&
            std::isfinite(meta.g);
  if (meta.camera) {
    const CameraParams& c = *meta.camera;
    ok = ok && std::isfinite(c.fx) && std::isfinite(c.fy) && std::isfinite(c.cx) &&
         std::isfinite(c.cy) && c.R.allFinite() && c.t.allFinite() &&
         std::all_of(c.dist.begin(), c.dist.end(), [](double d) { return std::isfinite(d); });
  }
  if (meta.trunk)
    ok = ok && meta.trunk->imuPosition.allFinite() && meta.trunk->imuRotation.allFinite();
  if (!ok) throw RecordingError(file, 0, 0, "cannot write non-finite values in the sidecar");
  if (const std::string why = metaProblem(meta); !why.empty())
    throw RecordingError(file, 0, 0, "cannot write the sidecar: " + why);
}

}  // namespace recording_detail

namespace {
RecordingMeta sidecarFromJson(const std::string& file, Json& j);
}  // namespace

RecordingMeta readSidecar(const fs::path& jsonPath) {
  const std::string file = jsonPath.string();
  const std::string text = readWholeFile(jsonPath);
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::parse_error& e) {
    const auto [line, column] = textPosition(text, e.byte);
    std::string what = e.what();
    if (const auto p = what.find("] "); p != std::string::npos) what.erase(0, p + 2);
    throw RecordingError(file, line, column,
                         "bad JSON at byte " + std::to_string(e.byte) + ": " + what);
  } catch (const Json::exception& e) {  // e.g. out_of_range for a number such as 1e999
    std::string what = e.what();
    if (const auto p = what.find("] "); p != std::string::npos) what.erase(0, p + 2);
    const auto [line, column] = tokenPosition(text, what);
    throw RecordingError(file, line, column, "bad JSON: " + what);
  }
  try {
    return sidecarFromJson(file, j);
  } catch (const Json::exception& e) {  // a check above missed a type: still name the file
    throw RecordingError(file, 0, 0, std::string("unexpected JSON content: ") + e.what());
  }
}

namespace {

/// The checked contents of a parsed sidecar.
RecordingMeta sidecarFromJson(const std::string& file, Json& j) {
  if (!j.is_object()) metaFail(file, "the sidecar must be a JSON object");

  if (!j.contains("format")) metaFail(file, "missing \"format\": expected \"armtrack-recording\"");
  if (!j["format"].is_string() || j["format"].get<std::string>() != kFormatName) {
    metaFail(file, "\"format\" is " + j["format"].dump() + ", expected \"armtrack-recording\"");
  }
  if (!j.contains("version")) metaFail(file, "missing \"version\": expected 1");
  if (!j["version"].is_number() || j["version"].get<double>() != kFormatVersion) {
    metaFail(file, "unsupported \"version\" " + j["version"].dump() + ": this reader knows 1");
  }

  RecordingMeta meta;
  if (j.contains("geometry")) {
    const Json& g = j["geometry"];
    if (!g.is_object()) metaFail(file, "\"geometry\" must be an object");
    ArmGeometry& geo = meta.geometry;
    const std::pair<const char*, double*> keys[] = {
        {"l3", &geo.l3},   {"l6", &geo.l6},   {"lu3", &geo.lu3},   {"thu4", &geo.thu4},
        {"lu5", &geo.lu5}, {"lf6", &geo.lf6}, {"thf7", &geo.thf7}, {"lf8", &geo.lf8}};
    for (const auto& [key, dst] : keys) {
      if (g.contains(key)) *dst = jsonNumber(file, g[key], std::string("geometry.") + key);
    }
  }
  if (j.contains("up")) {
    const auto u = jsonNumbers<3>(file, j["up"], "up");
    const Eigen::Vector3d up(u[0], u[1], u[2]);
    const double norm = up.norm();
    if (!(norm >= 0.5 && norm <= 1.5)) {
      metaFail(file,
               "\"up\" must be a unit vector (pointing up in the shoulder frame), its norm is " +
                   formatDouble(norm));
    }
    meta.up = up / norm;
  }
  if (j.contains("g")) {
    meta.g = jsonNumber(file, j["g"], "g");
    if (meta.g <= 0) metaFail(file, "\"g\" must be positive (m/s^2), got " + formatDouble(meta.g));
  }
  if (j.contains("camera")) {
    const Json& c = j["camera"];
    if (!c.is_object()) metaFail(file, "\"camera\" must be an object");
    CameraParams cam;
    const std::pair<const char*, double*> keys[] = {
        {"fx", &cam.fx}, {"fy", &cam.fy}, {"cx", &cam.cx}, {"cy", &cam.cy}};
    for (const auto& [key, dst] : keys) {
      if (!c.contains(key)) metaFail(file, std::string("missing \"camera.") + key + "\"");
      *dst = jsonNumber(file, c[key], std::string("camera.") + key);
    }
    if (c.contains("dist")) cam.dist = jsonNumbers<5>(file, c["dist"], "camera.dist");
    if (c.contains("R")) {
      const auto r = jsonNumbers<9>(file, c["R"], "camera.R");
      for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) cam.R(i, k) = r[3 * i + k];
      }
    }
    if (c.contains("t")) {
      const auto t = jsonNumbers<3>(file, c["t"], "camera.t");
      cam.t = Eigen::Vector3d(t[0], t[1], t[2]);
    }
    meta.camera = cam;
  }
  if (j.contains("trunk")) {
    const Json& t = j["trunk"];
    if (!t.is_object())
      metaFail(file,
               "\"trunk\" must be an object {\"imu_position\": [x, y, z], \"imu_rotation\": "
               "[9 numbers]}, got " +
                   t.dump());
    TrunkMount mount;
    for (const char* key : {"imu_position", "imu_rotation"}) {
      if (!t.contains(key))
        metaFail(file, std::string("missing \"trunk.") + key +
                           "\": the trunk block needs both the sternum IMU's position "
                           "(imu_position, m) and its axes (imu_rotation, 9 numbers row by row)");
    }
    const auto p = jsonNumbers<3>(file, t["imu_position"], "trunk.imu_position");
    mount.imuPosition = Eigen::Vector3d(p[0], p[1], p[2]);
    const auto r = jsonNumbers<9>(file, t["imu_rotation"], "trunk.imu_rotation");
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) mount.imuRotation(i, k) = r[3 * i + k];
    }
    meta.trunk = mount;
  }
  if (j.contains("side")) {
    if (!j["side"].is_string()) metaFail(file, "\"side\" must be \"left\" or \"right\"");
    try {
      meta.side = parseSide(j["side"].get<std::string>());
    } catch (const std::invalid_argument& e) {
      metaFail(file, e.what());
    }
  }
  // Unknown keys are accepted and ignored.
  if (const std::string why = metaProblem(meta); !why.empty()) metaFail(file, why);
  return meta;
}

}  // namespace

void writeSidecar(const fs::path& jsonPath, const RecordingMeta& meta) {
  checkMetaWritable(jsonPath.string(), meta);
  reportingAsRecordingError([&] {
    AtomicFile out(jsonPath);
    out.write(sidecarText(meta));
    out.commit();
  });
}
}  // namespace armtrack
