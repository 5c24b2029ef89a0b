// Internal to core/io: the column layout of the recording format (docs/recording-format.md) and
// helpers shared by its reader, sidecar and writer. Not a public header.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <system_error>

#include "core/Strings.h"
#include "core/io/AtomicFile.h"
#include "core/io/Recording.h"

namespace armtrack::recording_detail {

inline constexpr std::string_view kFormatName = "armtrack-recording";
inline constexpr int kFormatVersion = 1;

// ---------------------------------------------------------------------------------------------
// Column groups. Every group is all-or-nothing on a row; slot 0 of a row is the time.

enum Group {
  kUaGyr,
  kUaAcc,
  kFaGyr,
  kFaAcc,
  kTrGyr,
  kTrAcc,
  kElbow,
  kWrist,
  kShoulder,
  kCamWrist,
  kCamElbow,
  kTruth,
  kTrueTrunk,
  kEstimate
};
inline constexpr int kNumGroups = 14;

struct GroupDef {
  std::string_view label;  // for messages
  int size;
  std::array<std::string_view, 5> columns;
  int firstSlot;
};

// The fixed write order; also the slot layout of a parsed row. A recording without the trunk's
// groups (tr_*, shoulder_*, true_trunk_*) has no columns for them, so its bytes are those of
// the format before they existed (tests/data/recording).
inline constexpr std::array<GroupDef, kNumGroups> kGroups{{
    {"upper-arm gyroscope", 3, {"ua_gx", "ua_gy", "ua_gz"}, 1},
    {"upper-arm accelerometer", 3, {"ua_ax", "ua_ay", "ua_az"}, 4},
    {"forearm gyroscope", 3, {"fa_gx", "fa_gy", "fa_gz"}, 7},
    {"forearm accelerometer", 3, {"fa_ax", "fa_ay", "fa_az"}, 10},
    {"trunk (sternum) gyroscope", 3, {"tr_gx", "tr_gy", "tr_gz"}, 13},
    {"trunk (sternum) accelerometer", 3, {"tr_ax", "tr_ay", "tr_az"}, 16},
    {"elbow position", 3, {"elbow_x", "elbow_y", "elbow_z"}, 19},
    {"wrist position", 3, {"wrist_x", "wrist_y", "wrist_z"}, 22},
    {"shoulder position", 3, {"shoulder_x", "shoulder_y", "shoulder_z"}, 25},
    {"wrist marker pixel", 2, {"cam_wrist_u", "cam_wrist_v"}, 28},
    {"elbow marker pixel", 2, {"cam_elbow_u", "cam_elbow_v"}, 30},
    {"true joint angles", 5, {"true_th0", "true_th1", "true_th2", "true_th4", "true_th5"}, 32},
    {"true trunk angles", 3, {"true_trunk_flex", "true_trunk_lat", "true_trunk_rot"}, 37},
    {"estimated joint angles", 5, {"est_th0", "est_th1", "est_th2", "est_th4", "est_th5"}, 40},
}};
inline constexpr int kNumSlots = 45;

constexpr bool slotsContiguous() {
  int next = 1;
  for (const GroupDef& g : kGroups) {
    if (g.firstSlot != next) return false;
    next += g.size;
  }
  return next == kNumSlots;
}
static_assert(slotsContiguous(), "kGroups' slots must follow one another");

using GroupSet = std::array<bool, kNumGroups>;

inline std::string osReason(int err) {
  return err != 0 ? std::generic_category().message(err) : std::string("unknown I/O error");
}

inline std::string inQuotes(std::string_view s) {
  return "\"" + std::string(s) + "\"";
}

inline std::string formatDouble(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Sidecar.cpp
/// The sidecar's JSON text.
std::string sidecarText(const RecordingMeta& meta);
/// Throws RecordingError on file when meta holds a value the sidecar cannot store.
void checkMetaWritable(const std::string& file, const RecordingMeta& meta);

// ---------------------------------------------------------------------------------------------
// Writing: through AtomicFile (a temporary file beside the target, renamed over it once
// complete); its failures are reported as RecordingError on the file concerned.
template <typename F>
void reportingAsRecordingError(F&& write) {
  try {
    write();
  } catch (const AtomicFileError& e) {
    throw RecordingError(e.target().string(), 0, 0, e.message());
  }
}

}  // namespace armtrack::recording_detail
