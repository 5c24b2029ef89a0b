#include "core/calibration/Calibration.h"

#include <Eigen/Geometry>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "core/io/AtomicFile.h"

namespace armtrack {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFormatName = "armtrack-calibration";
constexpr int kFormatVersion = 1;

const Eigen::Matrix3d kMirror = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();

using Json = nlohmann::json;
using OJson = nlohmann::ordered_json;

[[noreturn]] void fail(const fs::path& file, const std::string& message) {
  throw CalibrationError(file.string(), message);
}

Eigen::Vector3d rotationVector(const Eigen::Matrix3d& r) {
  const Eigen::AngleAxisd aa(r);
  return aa.angle() * aa.axis();
}

Eigen::Matrix3d fromRotationVector(const Eigen::Vector3d& v) {
  const double angle = v.norm();
  if (angle < 1e-300) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, v / angle).toRotationMatrix();
}

double number(const fs::path& file, const Json& j, const std::string& key) {
  if (!j.is_number()) fail(file, "\"" + key + "\" must be a number, got " + j.dump());
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(file, "\"" + key + "\" must be finite");
  return v;
}

Eigen::Vector3d vector3(const fs::path& file, const Json& j, const std::string& key) {
  if (!j.is_array() || j.size() != 3)
    fail(file, "\"" + key + "\" must be an array of 3 numbers, got " + j.dump());
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v(i) = number(file, j[i], key + "[" + std::to_string(i) + "]");
  return v;
}

std::vector<std::string> strings(const fs::path& file, const Json& j, const std::string& key) {
  if (!j.is_array()) fail(file, "\"" + key + "\" must be an array of strings");
  std::vector<std::string> out;
  for (const Json& e : j) {
    if (!e.is_string()) fail(file, "\"" + key + "\" must be an array of strings");
    out.push_back(e.get<std::string>());
  }
  return out;
}

OJson imuJson(const ImuCalibration& c) {
  const Eigen::Vector3d r = rotationVector(c.rotation);
  OJson j;
  j["rotationVector"] = {r.x(), r.y(), r.z()};
  j["rotationDeg"] = r.norm() * 180.0 / std::numbers::pi;
  j["gyroBias"] = {c.gyroBias.x(), c.gyroBias.y(), c.gyroBias.z()};
  return j;
}

ImuCalibration imuFromJson(const fs::path& file, const Json& j, const std::string& key) {
  if (!j.is_object()) fail(file, "\"" + key + "\" must be an object");
  ImuCalibration c;
  if (j.contains("rotationVector")) {
    const Eigen::Vector3d r = vector3(file, j["rotationVector"], key + ".rotationVector");
    if (r.norm() > std::numbers::pi + 1e-9)
      fail(file, "\"" + key + ".rotationVector\" is longer than pi rad");
    c.rotation = fromRotationVector(r);
  }
  if (j.contains("gyroBias")) c.gyroBias = vector3(file, j["gyroBias"], key + ".gyroBias");
  return c;
}

std::string osReason(int err) {
  return err != 0 ? std::strerror(err) : "unknown error";
}

}  // namespace

JointVector protocolStartPose() {
  JointVector th;
  th << 0.0, 0.0, 0.0, -90.0 * kDeg, 0.0;
  return th;
}

ImuReading applyCalibration(const ImuCalibration& c, const ImuReading& r) {
  ImuReading out;
  out.gyr = c.rotation * (r.gyr - c.gyroBias);
  out.acc = c.rotation * r.acc;
  return out;
}

void applyCalibration(const Calibration& c, ArmSample& s) {
  if (s.upperArm) s.upperArm = applyCalibration(c.upperArm, *s.upperArm);
  if (s.forearm) s.forearm = applyCalibration(c.forearm, *s.forearm);
}

void applyCalibration(const Calibration& c, RecordingMeta& meta) {
  if (meta.side != c.side) {
    throw std::invalid_argument("the calibration is for the " + sideName(c.side) +
                                " arm but the recording is of the " + sideName(meta.side) + " arm");
  }
  meta.geometry = c.geometry;
  // Only a recording with a sternum sensor has a mounting for it.
  if (c.trunk && meta.trunk) meta.trunk = c.trunk;
}

void applyCalibration(const Calibration& c, Recording& rec) {
  applyCalibration(c, rec.meta);
  for (ArmSample& s : rec.samples) applyCalibration(c, s);
}

void applyCalibration(const Calibration& c, EstimatorParams& params) {
  if (params.side != c.side) {
    throw std::invalid_argument("the calibration is for the " + sideName(c.side) +
                                " arm but the filter is set up for the " + sideName(params.side) +
                                " arm");
  }
  params.geometry = c.geometry;
}

ImuCalibration mirrorImuCalibration(const ImuCalibration& c) {
  ImuCalibration m;
  m.rotation = mirrorRotation(c.rotation);
  m.gyroBias = -(kMirror * c.gyroBias);
  return m;
}

std::string calibrationProblem(const Calibration& c) {
  const std::pair<const char*, const ImuCalibration*> imus[] = {{"upperArm", &c.upperArm},
                                                                {"forearm", &c.forearm}};
  for (const auto& [key, imu] : imus) {
    if (!imu->rotation.allFinite() || !imu->gyroBias.allFinite())
      return std::string("\"") + key + "\" holds a value that is not a finite number";
    const double e = (imu->rotation.transpose() * imu->rotation - Eigen::Matrix3d::Identity())
                         .cwiseAbs()
                         .maxCoeff();
    if (e > MetaLimits::kRotationTolerance || imu->rotation.determinant() < 0.0)
      return std::string("\"") + key + ".rotation\" is not a rotation";
  }
  if (c.trunk) {
    const Eigen::Matrix3d& r = c.trunk->imuRotation;
    if (!r.allFinite() || !c.trunk->imuPosition.allFinite())
      return "\"trunk\" holds a value that is not a finite number";
    if ((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() >
            MetaLimits::kRotationTolerance ||
        r.determinant() < 0.0)
      return "\"trunk.imu_rotation\" is not a rotation";
  }
  RecordingMeta meta;  // the limits of a sidecar's geometry; the rest are defaults
  meta.geometry = c.geometry;
  return metaProblem(meta);
}

namespace {

/// What to do about a calibration outside physical limits.
constexpr const char* kRedo =
    ": no real arm has this; redo the calibration protocol (docs/calibration.md) and calibrate "
    "again";

}  // namespace

std::string calibrationText(const Calibration& c, const fs::path& path) {
  if (const std::string problem = calibrationProblem(c); !problem.empty())
    fail(path, "refusing to write an impossible calibration: " + problem + kRedo);
  const ArmGeometry& g = c.geometry;
  for (double v : {g.l3, g.l6, g.lu3, g.thu4, g.lu5, g.lf6, g.thf7, g.lf8}) {
    if (!std::isfinite(v)) fail(path, "cannot write a non-finite geometry value");
  }
  for (const ImuCalibration* imu : {&c.upperArm, &c.forearm}) {
    if (!imu->rotation.allFinite() || !imu->gyroBias.allFinite())
      fail(path, "cannot write a non-finite rotation or bias");
  }
  OJson j;
  j["format"] = kFormatName;
  j["version"] = kFormatVersion;
  j["side"] = sideName(c.side);
  j["geometry"] = {{"l3", g.l3},   {"l6", g.l6},   {"lu3", g.lu3},   {"thu4", g.thu4},
                   {"lu5", g.lu5}, {"lf6", g.lf6}, {"thf7", g.thf7}, {"lf8", g.lf8}};
  j["upperArm"] = imuJson(c.upperArm);
  j["forearm"] = imuJson(c.forearm);
  if (c.trunk) {
    const Eigen::Vector3d& p = c.trunk->imuPosition;
    const Eigen::Matrix3d& r = c.trunk->imuRotation;
    OJson t;
    t["imu_position"] = {p.x(), p.y(), p.z()};
    t["imu_rotation"] = {r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1),
                         r(1, 2), r(2, 0), r(2, 1), r(2, 2)};
    j["trunk"] = t;
  }
  j["opticalUsed"] = c.opticalUsed;
  j["headingFromStartPoseOnly"] = c.headingFromStartPoseOnly;
  j["estimated"] = c.estimated;
  j["fromStartPose"] = c.fromStartPose;
  j["heldFixed"] = c.heldFixed;
  return j.dump(2) + "\n";
}

void writeCalibration(const fs::path& path, const Calibration& c) {
  const std::string text = calibrationText(c, path);
  try {
    AtomicFile out(path);
    out.write(text);
    out.commit();
  } catch (const AtomicFileError& e) {
    fail(path, e.message());
  }
}

Calibration readCalibration(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) fail(path, "no such file");
  if (fs::is_directory(path, ec)) fail(path, "is a directory, expected a calibration JSON file");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open: " + osReason(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  return parseCalibration(ss.str(), path);
}

Calibration parseCalibration(const std::string& text, const fs::path& path) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::parse_error& e) {
    std::string what = e.what();
    if (const auto p = what.find("] "); p != std::string::npos) what.erase(0, p + 2);
    fail(path, "bad JSON at byte " + std::to_string(e.byte) + ": " + what);
  }
  if (!j.is_object()) fail(path, "a calibration file must be a JSON object");
  if (!j.contains("format") || !j["format"].is_string() ||
      j["format"].get<std::string>() != kFormatName) {
    fail(path, "\"format\" must be \"armtrack-calibration\"" +
                   (j.contains("format") ? ", got " + j["format"].dump() : std::string()) +
                   " (is this a calibration file?)");
  }
  if (!j.contains("version") || !j["version"].is_number() ||
      j["version"].get<double>() != kFormatVersion) {
    fail(path, "unsupported \"version\"" +
                   (j.contains("version") ? " " + j["version"].dump() : std::string()) +
                   ": this reader knows 1");
  }
  Calibration c;
  if (j.contains("side")) {
    if (!j["side"].is_string()) fail(path, "\"side\" must be \"left\" or \"right\"");
    try {
      c.side = parseSide(j["side"].get<std::string>());
    } catch (const std::invalid_argument& e) {
      fail(path, e.what());
    }
  }
  if (!j.contains("geometry")) fail(path, "missing \"geometry\"");
  const Json& g = j["geometry"];
  if (!g.is_object()) fail(path, "\"geometry\" must be an object");
  ArmGeometry& geo = c.geometry;
  const std::pair<const char*, double*> keys[] = {
      {"l3", &geo.l3},   {"l6", &geo.l6},   {"lu3", &geo.lu3},   {"thu4", &geo.thu4},
      {"lu5", &geo.lu5}, {"lf6", &geo.lf6}, {"thf7", &geo.thf7}, {"lf8", &geo.lf8}};
  for (const auto& [key, dst] : keys) {
    if (!g.contains(key)) fail(path, std::string("missing \"geometry.") + key + "\"");
    *dst = number(path, g[key], std::string("geometry.") + key);
  }
  for (double len : {geo.l3, geo.l6}) {
    if (!(len > 0.0)) fail(path, "segment lengths l3 and l6 must be positive (m)");
  }
  if (j.contains("upperArm")) c.upperArm = imuFromJson(path, j["upperArm"], "upperArm");
  if (j.contains("forearm")) c.forearm = imuFromJson(path, j["forearm"], "forearm");
  if (j.contains("trunk")) {
    const Json& t = j["trunk"];
    if (!t.is_object() || !t.contains("imu_position") || !t.contains("imu_rotation"))
      fail(path, "\"trunk\" must be an object with \"imu_position\" and \"imu_rotation\"");
    TrunkMount m;
    m.imuPosition = vector3(path, t["imu_position"], "trunk.imu_position");
    const Json& r = t["imu_rotation"];
    if (!r.is_array() || r.size() != 9)
      fail(path,
           "\"trunk.imu_rotation\" must be an array of 9 numbers (row-major), got " + r.dump());
    for (int i = 0; i < 9; ++i)
      m.imuRotation(i / 3, i % 3) = number(path, r[static_cast<std::size_t>(i)],
                                           "trunk.imu_rotation[" + std::to_string(i) + "]");
    c.trunk = m;
  }
  if (j.contains("opticalUsed") && j["opticalUsed"].is_boolean())
    c.opticalUsed = j["opticalUsed"].get<bool>();
  if (j.contains("headingFromStartPoseOnly") && j["headingFromStartPoseOnly"].is_boolean())
    c.headingFromStartPoseOnly = j["headingFromStartPoseOnly"].get<bool>();
  if (j.contains("estimated")) c.estimated = strings(path, j["estimated"], "estimated");
  if (j.contains("fromStartPose"))
    c.fromStartPose = strings(path, j["fromStartPose"], "fromStartPose");
  if (j.contains("heldFixed")) c.heldFixed = strings(path, j["heldFixed"], "heldFixed");
  if (const std::string problem = calibrationProblem(c); !problem.empty())
    fail(path, "an impossible calibration: " + problem + kRedo);
  return c;
}

}  // namespace armtrack
