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

}  // namespace

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
  if (!ok) throw RecordingError(file, 0, 0, "cannot write non-finite values in the sidecar");
}

}  // namespace recording_detail

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
  }
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
  if (j.contains("side")) {
    if (!j["side"].is_string()) metaFail(file, "\"side\" must be \"left\" or \"right\"");
    try {
      meta.side = parseSide(j["side"].get<std::string>());
    } catch (const std::invalid_argument& e) {
      metaFail(file, e.what());
    }
  }
  // Unknown keys are accepted and ignored.
  return meta;
}

void writeSidecar(const fs::path& jsonPath, const RecordingMeta& meta) {
  checkMetaWritable(jsonPath.string(), meta);
  reportingAsRecordingError([&] {
    AtomicFile out(jsonPath);
    out.write(sidecarText(meta));
    out.commit();
  });
}
}  // namespace armtrack
