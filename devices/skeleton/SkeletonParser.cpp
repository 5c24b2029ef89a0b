#include "devices/skeleton/SkeletonParser.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace armtrack::devices::skeleton {
namespace {

using nlohmann::json;

constexpr const char* kJointNames[3] = {"shoulder", "elbow", "wrist"};

// Returns an error text, or "" when `j` holds a valid joint.
std::string readJoint(const json& j, Joint& joint) {
  if (!j.is_array() || j.size() != 3) return "must be an array of 3 numbers [x, y, z] in metres";
  for (std::size_t k = 0; k < 3; ++k) {
    if (!j[k].is_number()) return "coordinate " + std::to_string(k) + " is not a number";
    const double v = j[k].get<double>();
    if (!std::isfinite(v)) return "coordinate " + std::to_string(k) + " is not finite";
    if (std::abs(v) > kMaxCoordinate)
      return "coordinate " + std::to_string(k) + " is " + std::to_string(v) + " m, beyond " +
             std::to_string(kMaxCoordinate) + " m";
    joint.position[k] = v;
  }
  return "";
}

}  // namespace

std::string encode(const Frame& f) {
  json j;
  j["v"] = kFormatVersion;
  j["t"] = f.t;
  j["frame"] = f.frame;
  j["side"] = f.side == Side::Left ? "left" : "right";
  j["joints"] = json::object();
  json conf = json::object();
  const std::optional<Joint>* joints[3] = {&f.shoulder, &f.elbow, &f.wrist};
  for (int k = 0; k < 3; ++k) {
    if (!*joints[k]) continue;
    const Joint& joint = **joints[k];
    j["joints"][kJointNames[k]] = joint.position;
    if (joint.confidence) conf[kJointNames[k]] = *joint.confidence;
  }
  if (!conf.empty()) j["confidence"] = conf;
  return j.dump();
}

std::optional<Frame> SkeletonParser::parseDatagram(std::span<const std::uint8_t> d) {
  return parseDatagram(std::string_view(reinterpret_cast<const char*>(d.data()), d.size()));
}

std::optional<Frame> SkeletonParser::parseDatagram(std::string_view d) {
  const std::uint64_t index = m_datagrams++;
  const std::string where = "datagram " + std::to_string(index) + ": ";
  auto fail = [&](std::uint64_t offset, const std::string& what) {
    m_errors.report(offset, where + what);
    return std::nullopt;
  };
  if (d.size() > kMaxDatagramBytes)
    return fail(0, std::to_string(d.size()) + " bytes, more than the " +
                       std::to_string(kMaxDatagramBytes) + " allowed");

  json j;
  try {
    j = json::parse(d);
  } catch (const json::parse_error& e) {
    return fail(e.byte, std::string("not valid JSON: ") + e.what());
  } catch (const std::exception& e) {
    return fail(0, std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_object()) return fail(0, "top level must be a JSON object");

  const auto v = j.find("v");
  if (v == j.end() || !v->is_number_integer() || v->get<std::int64_t>() != kFormatVersion)
    return fail(0, "\"v\" must be the integer 1 (format version)");
  const auto t = j.find("t");
  if (t == j.end() || !t->is_number() || !std::isfinite(t->get<double>()))
    return fail(0, "\"t\" must be a finite number of seconds");
  const auto frameNo = j.find("frame");
  if (frameNo == j.end() || !frameNo->is_number_unsigned())
    return fail(0, "\"frame\" must be a non-negative integer");
  const auto side = j.find("side");
  if (side == j.end() || !side->is_string() ||
      (side->get<std::string>() != "left" && side->get<std::string>() != "right"))
    return fail(0, "\"side\" must be \"left\" or \"right\"");
  const auto joints = j.find("joints");
  if (joints == j.end() || !joints->is_object())
    return fail(0, "\"joints\" must be an object of [x, y, z] arrays");
  const auto conf = j.find("confidence");
  if (conf != j.end() && !conf->is_object())
    return fail(0, "\"confidence\" must be an object of numbers in 0..1");

  Frame f;
  f.t = t->get<double>();
  f.frame = frameNo->get<std::uint64_t>();
  f.side = side->get<std::string>() == "left" ? Side::Left : Side::Right;
  std::optional<Joint>* slots[3] = {&f.shoulder, &f.elbow, &f.wrist};
  for (int k = 0; k < 3; ++k) {
    const auto it = joints->find(kJointNames[k]);
    if (it == joints->end() || it->is_null()) continue;  // not tracked
    Joint joint;
    const std::string err = readJoint(*it, joint);
    if (!err.empty()) return fail(0, std::string("joint \"") + kJointNames[k] + "\" " + err);
    if (conf != j.end()) {
      const auto c = conf->find(kJointNames[k]);
      if (c != conf->end()) {
        if (!c->is_number() || !(c->get<double>() >= 0.0 && c->get<double>() <= 1.0))
          return fail(
              0, std::string("confidence of \"") + kJointNames[k] + "\" must be a number in 0..1");
        joint.confidence = c->get<double>();
      }
    }
    *slots[k] = joint;
  }
  if (!f.shoulder && !f.elbow && !f.wrist)
    return fail(0, "no tracked joint (shoulder, elbow or wrist)");

  // The frame counter tells lost frames (gaps), frames overtaken by newer ones on the way (UDP
  // reorders: not returned, so that time never goes back, but counted reordered, not lost) and
  // duplicates (not returned). A jump by 2^20 or more either
  // way, or back beyond the reorder window, is a restarted tracker: followed anew.
  if (m_seq.started()) {
    const std::uint64_t last = m_lastFrame;
    const bool farAhead = f.frame > last && f.frame - last >= (1u << 20);
    const bool farBack = f.frame < last && last - f.frame >= SequenceTracker::kWindow;
    if (farAhead || farBack) m_seq.restart();
  }
  switch (m_seq.add(f.frame)) {
    case SequenceStatus::InOrder:
      m_lastFrame = f.frame;
      break;
    case SequenceStatus::Reordered:  // counted in reorderedFrames(), not an error
    case SequenceStatus::Duplicate:  // counted in duplicateFrames(), not an error
    case SequenceStatus::TooLate:
      return std::nullopt;
  }
  ++m_frames;
  return f;
}

}  // namespace armtrack::devices::skeleton
