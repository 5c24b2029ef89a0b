// Reader and writer for the open recording format; the format itself is specified in
// docs/recording-format.md.
#include "core/io/Recording.h"

#include <fcntl.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>

#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string_view>
#include <system_error>

#include "core/io/AtomicFile.h"

namespace armtrack {

namespace fs = std::filesystem;

RecordingError::RecordingError(std::string file, int line, int column, const std::string& message)
    : std::runtime_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                         message),
      m_file(std::move(file)),
      m_line(line),
      m_column(column),
      m_message(message) {}

fs::path sidecarPath(const fs::path& csvPath) {
  fs::path p = csvPath;
  p.replace_extension(".json");
  return p;
}

namespace {

constexpr std::string_view kFormatName = "armtrack-recording";
constexpr int kFormatVersion = 1;

// ---------------------------------------------------------------------------------------------
// Column groups. Every group is all-or-nothing on a row; slot 0 of a row is the time.

enum Group {
  kUaGyr,
  kUaAcc,
  kFaGyr,
  kFaAcc,
  kElbow,
  kWrist,
  kCamWrist,
  kCamElbow,
  kTruth,
  kEstimate
};
constexpr int kNumGroups = 10;

struct GroupDef {
  std::string_view label;  // for messages
  int size;
  std::array<std::string_view, 5> columns;
  int firstSlot;
};

// The fixed write order; also the slot layout of a parsed row.
constexpr std::array<GroupDef, kNumGroups> kGroups{{
    {"upper-arm gyroscope", 3, {"ua_gx", "ua_gy", "ua_gz"}, 1},
    {"upper-arm accelerometer", 3, {"ua_ax", "ua_ay", "ua_az"}, 4},
    {"forearm gyroscope", 3, {"fa_gx", "fa_gy", "fa_gz"}, 7},
    {"forearm accelerometer", 3, {"fa_ax", "fa_ay", "fa_az"}, 10},
    {"elbow position", 3, {"elbow_x", "elbow_y", "elbow_z"}, 13},
    {"wrist position", 3, {"wrist_x", "wrist_y", "wrist_z"}, 16},
    {"wrist marker pixel", 2, {"cam_wrist_u", "cam_wrist_v"}, 19},
    {"elbow marker pixel", 2, {"cam_elbow_u", "cam_elbow_v"}, 21},
    {"true joint angles", 5, {"true_th0", "true_th1", "true_th2", "true_th4", "true_th5"}, 23},
    {"estimated joint angles", 5, {"est_th0", "est_th1", "est_th2", "est_th4", "est_th5"}, 28},
}};
constexpr int kNumSlots = 33;

std::string osReason(int err) {
  return err != 0 ? std::generic_category().message(err) : std::string("unknown I/O error");
}

std::string inQuotes(std::string_view s) {
  return "\"" + std::string(s) + "\"";
}

std::string formatDouble(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

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
// CSV reading

/// Reads a file in chunks and yields the lines that carry data (not blank, not comments) with
/// their physical line numbers, and whether each ended with a newline (the last line of a file
/// cut short by a kill does not). Memory: one chunk plus the longest line.
class FileLines {
 public:
  explicit FileLines(const fs::path& path) : m_name(path.string()) {
    std::error_code ec;
    if (fs::is_directory(path, ec))
      throw RecordingError(m_name, 0, 0, "cannot open file: is a directory");
    errno = 0;
    m_in.open(path, std::ios::binary);
    if (!m_in) throw RecordingError(m_name, 0, 0, "cannot open file: " + osReason(errno));
    m_size = fs::file_size(path, ec);
    if (ec) m_size = 0;
  }

  /// The next data line (valid until the next call), or false at the end of the file.
  bool next(std::string_view& line, int& number, bool& terminated) {
    for (;;) {
      if (m_p == m_buf.size() && !refill()) return false;
      const char* base = m_buf.data();
      const char* nl = static_cast<const char*>(std::memchr(base + m_p, '\n', m_buf.size() - m_p));
      if (!nl && !m_eof) {  // the line may go on in the next chunk
        refill();
        continue;
      }
      const std::size_t end = nl ? static_cast<std::size_t>(nl - base) : m_buf.size();
      std::string_view s(base + m_p, end - m_p);
      m_p = nl ? end + 1 : end;
      ++m_line;
      if (m_line == 1 && s.starts_with("\xEF\xBB\xBF")) s.remove_prefix(3);  // UTF-8 BOM
      if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
      if (!s.empty() && s.front() == '#') continue;
      if (s.find_first_not_of(" \t") == std::string_view::npos) continue;
      line = s;
      number = m_line;
      terminated = nl != nullptr;
      return true;
    }
  }

  std::uint64_t bytesRead() const { return m_consumed + m_p; }
  std::uint64_t size() const { return m_size; }

 private:
  // Keeps the unread tail, appends the next chunk. False when nothing more could be read.
  bool refill() {
    if (m_eof) return false;
    m_consumed += m_p;
    m_buf.erase(0, m_p);
    m_p = 0;
    const std::size_t old = m_buf.size();
    constexpr std::size_t kChunk = std::size_t{1} << 20;
    m_buf.resize(old + kChunk);
    m_in.read(m_buf.data() + old, static_cast<std::streamsize>(kChunk));
    const auto got = static_cast<std::size_t>(m_in.gcount());
    m_buf.resize(old + got);
    if (m_in.bad()) throw RecordingError(m_name, 0, 0, "cannot read file: " + osReason(errno));
    if (got < kChunk) m_eof = true;
    return got > 0;
  }

  std::string m_name;
  std::ifstream m_in;
  std::string m_buf;
  std::size_t m_p = 0;           // next unread byte in m_buf
  std::uint64_t m_consumed = 0;  // bytes dropped from the front of m_buf
  std::uint64_t m_size = 0;
  bool m_eof = false;
  int m_line = 0;
};

/// Splits a line at commas into out (cleared first).
void splitFields(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  const char* p = line.data();
  const char* e = p + line.size();
  for (;;) {
    const char* c = static_cast<const char*>(std::memchr(p, ',', e - p));
    out.emplace_back(p, (c ? c : e) - p);
    if (!c) break;
    p = c + 1;
  }
}

/// Parses the CSV's header, then its rows one at a time (each checked against the previous one's
/// time). Errors throw RecordingError with the line and column.
class CsvParser {
 public:
  explicit CsvParser(std::string file) : m_file(std::move(file)) {}

  /// The header line, or lineNo 0 when the file has no data line at all.
  void parseHeader(std::string_view line, int lineNo) {
    m_headerLine = lineNo;
    if (lineNo == 0)
      fail(0, 0, "missing header (the file has no lines other than comments and blank lines)");
    std::vector<std::string_view> names;
    splitFields(line, names);
    m_columnOfSlot.fill(-1);
    m_slotOfColumn.assign(names.size(), -1);
    for (int c = 0; c < static_cast<int>(names.size()); ++c) {
      const std::string_view name = trim(names[c]);
      const int slot = slotOf(name);
      if (slot < 0) continue;  // unknown columns are ignored
      if (m_columnOfSlot[slot] >= 0)
        fail(m_headerLine, c + 1, "duplicate column " + inQuotes(name));
      m_columnOfSlot[slot] = c;
      m_slotOfColumn[c] = slot;
    }
    if (m_columnOfSlot[0] < 0) fail(m_headerLine, 0, "no \"t\" column in header");
    for (int g = 0; g < kNumGroups; ++g) {
      const GroupDef& def = kGroups[g];
      int have = -1, missing = -1;
      for (int k = def.size - 1; k >= 0; --k) {
        (m_columnOfSlot[def.firstSlot + k] >= 0 ? have : missing) = k;  // the first of each
      }
      if (have >= 0 && missing >= 0) {
        fail(m_headerLine, m_columnOfSlot[def.firstSlot + have] + 1,
             "column " + inQuotes(def.columns[have]) + " without " +
                 inQuotes(def.columns[missing]) + ": the " + std::string(def.label) +
                 " needs all of " + listColumns(def));
      }
    }
  }

  /// Whether the header has the columns of group g.
  bool hasGroup(int g) const { return m_columnOfSlot[kGroups[g].firstSlot] >= 0; }

  /// One data row into s (overwritten whole).
  void parseRow(std::string_view line, int lineNo, ArmSample& s) {
    std::vector<std::string_view>& fields = m_fields;
    std::array<double, kNumSlots>& v = m_values;
    std::array<bool, kNumSlots> filled{};
    std::array<bool, kNumGroups> present{};
    splitFields(line, fields);
    const int n = static_cast<int>(fields.size());
    const int expected = static_cast<int>(m_slotOfColumn.size());
    if (n != expected) {
      fail(lineNo, std::min(n, expected) + 1,
           "row has " + std::to_string(n) + " fields, header has " + std::to_string(expected));
    }
    for (int c = 0; c < n; ++c) {
      const int slot = m_slotOfColumn[c];
      if (slot < 0) continue;
      const std::string_view cell = trim(fields[c]);
      if (cell.empty()) continue;
      v[slot] = parseNumber(cell, lineNo, c);
      filled[slot] = true;
    }

    if (!filled[0]) fail(lineNo, m_columnOfSlot[0] + 1, "empty cell in required column \"t\"");
    const double t = v[0];
    if (m_rows > 0 && t < m_prevT) {
      fail(lineNo, m_columnOfSlot[0] + 1,
           "time goes backwards: " + formatDouble(t) + " after " + formatDouble(m_prevT) +
               " (\"t\" must not decrease)");
    }

    for (int g = 0; g < kNumGroups; ++g) present[g] = groupPresent(g, filled, lineNo);
    checkImu(kUaGyr, kUaAcc, present, lineNo);
    checkImu(kFaGyr, kFaAcc, present, lineNo);

    s = ArmSample{};
    s.t = t;
    auto vec3 = [&](Group g) {
      const int k = kGroups[g].firstSlot;
      return Eigen::Vector3d(v[k], v[k + 1], v[k + 2]);
    };
    auto vec2 = [&](Group g) {
      const int k = kGroups[g].firstSlot;
      return Eigen::Vector2d(v[k], v[k + 1]);
    };
    if (present[kUaGyr]) s.upperArm = ImuReading{vec3(kUaGyr), vec3(kUaAcc)};
    if (present[kFaGyr]) s.forearm = ImuReading{vec3(kFaGyr), vec3(kFaAcc)};
    if (present[kElbow]) s.elbow = vec3(kElbow);
    if (present[kWrist]) s.wrist = vec3(kWrist);
    if (present[kCamWrist]) s.camWrist = vec2(kCamWrist);
    if (present[kCamElbow]) s.camElbow = vec2(kCamElbow);
    auto joints = [&](Group g) {
      const int k = kGroups[g].firstSlot;
      JointVector th;
      th << v[k], v[k + 1], v[k + 2], v[k + 3], v[k + 4];
      return th;
    };
    if (present[kTruth]) s.trueAngles = joints(kTruth);
    if (present[kEstimate]) s.estimate = joints(kEstimate);
    m_prevT = t;
    ++m_rows;
  }

 private:
  [[noreturn]] void fail(int line, int column, const std::string& message) const {
    throw RecordingError(m_file, line, column, message);
  }

  static int slotOf(std::string_view name) {
    if (name == "t") return 0;
    for (const GroupDef& def : kGroups) {
      for (int k = 0; k < def.size; ++k) {
        if (def.columns[k] == name) return def.firstSlot + k;
      }
    }
    return -1;
  }

  static std::string listColumns(const GroupDef& def) {
    std::string s;
    for (int k = 0; k < def.size; ++k) s += (k ? ", " : "") + std::string(def.columns[k]);
    return s;
  }

  std::string_view slotName(int slot) const {
    if (slot == 0) return "t";
    for (const GroupDef& def : kGroups) {
      if (slot < def.firstSlot + def.size) return def.columns[slot - def.firstSlot];
    }
    return "?";
  }

  double parseNumber(std::string_view cell, int line, int column) const {
    const char* b = cell.data();
    const char* e = b + cell.size();
    if (*b == '+' && e - b > 1 && b[1] != '-' && b[1] != '+') ++b;  // from_chars rejects '+'
    double x;
    const auto r = std::from_chars(b, e, x);
    if (r.ptr == e && r.ec == std::errc() && std::isfinite(x)) return x;
    const std::string where =
        inQuotes(cell) + " in column " + inQuotes(slotName(m_slotOfColumn[column]));
    if (r.ptr != e || r.ec == std::errc::invalid_argument) {
      fail(line, column + 1,
           "bad number " + where + " (expected a decimal number such as -1.25e-3)");
    }
    if (r.ec == std::errc::result_out_of_range) {
      fail(line, column + 1, "number out of range " + where);
    }
    fail(line, column + 1, "not a finite number " + where + " (NaN and infinity are not allowed)");
  }

  bool groupPresent(int g, const std::array<bool, kNumSlots>& filled, int line) const {
    const GroupDef& def = kGroups[g];
    if (m_columnOfSlot[def.firstSlot] < 0) return false;  // not in the header
    int count = 0;
    for (int k = 0; k < def.size; ++k) count += filled[def.firstSlot + k];
    if (count == 0) return false;
    if (count == def.size) return true;
    int empty = 0, set = 0;
    for (int k = def.size - 1; k >= 0; --k) (filled[def.firstSlot + k] ? set : empty) = k;
    fail(line, m_columnOfSlot[def.firstSlot + empty] + 1,
         "empty cell in column " + inQuotes(def.columns[empty]) + " while " +
             inQuotes(def.columns[set]) + " is set: the " + std::string(def.label) +
             " needs all of " + listColumns(def) + " or none");
  }

  void checkImu(Group gyr, Group acc, const std::array<bool, kNumGroups>& present, int line) const {
    if (present[gyr] == present[acc]) return;
    const Group have = present[gyr] ? gyr : acc;
    const Group missing = present[gyr] ? acc : gyr;
    const int col = m_columnOfSlot[kGroups[missing].firstSlot] >= 0
                        ? m_columnOfSlot[kGroups[missing].firstSlot]
                        : m_columnOfSlot[kGroups[have].firstSlot];
    fail(line, col + 1,
         std::string(kGroups[have].label) + " values but no " +
             std::string(kGroups[missing].label) + " values (" + listColumns(kGroups[missing]) +
             "); an IMU reading needs both");
  }

  std::string m_file;
  int m_headerLine = 0;
  std::uint64_t m_rows = 0;  // rows parsed
  double m_prevT = 0.0;      // the last row's time
  std::vector<std::string_view> m_fields;
  std::array<double, kNumSlots> m_values{};
  std::vector<int> m_slotOfColumn;              // header column -> slot, -1 if ignored
  std::array<int, kNumSlots> m_columnOfSlot{};  // slot -> 0-based header column, -1 if absent
};

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

/// Appends ",<shortest round-trip form>".
inline void appendNumber(std::string& out, double v) {
  char buf[32];
  buf[0] = ',';
  const auto r = std::to_chars(buf + 1, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

std::string csvHeader(const std::array<bool, kNumGroups>& present) {
  std::string h = "t";
  for (int g = 0; g < kNumGroups; ++g) {
    if (!present[g]) continue;
    for (int k = 0; k < kGroups[g].size; ++k) h += "," + std::string(kGroups[g].columns[k]);
  }
  return h;
}

using GroupSet = std::array<bool, kNumGroups>;

GroupSet groupsOf(const ArmSample& s) {
  GroupSet g{};
  g[kUaGyr] = g[kUaAcc] = s.upperArm.has_value();
  g[kFaGyr] = g[kFaAcc] = s.forearm.has_value();
  g[kElbow] = s.elbow.has_value();
  g[kWrist] = s.wrist.has_value();
  g[kCamWrist] = s.camWrist.has_value();
  g[kCamElbow] = s.camElbow.has_value();
  g[kTruth] = s.trueAngles.has_value();
  g[kEstimate] = s.estimate.has_value();
  return g;
}

std::string fileHeader(const GroupSet& present) {
  return "# ArmTrack recording, format version 1\n" + csvHeader(present) + "\n";
}

/// Appends one CSV row for the columns in `present`. `prevT` is the previous row's time (NaN for
/// the first row). Throws RecordingError for non-finite values, decreasing time, or a sensor the
/// columns do not hold.
void appendRow(std::string& buf, const GroupSet& present, const ArmSample& s, double prevT,
               const std::string& file, int line) {
  if (!std::isfinite(s.t)) {
    throw RecordingError(file, line, 1, "cannot write non-finite time " + formatDouble(s.t));
  }
  if (s.t < prevT) {
    throw RecordingError(
        file, line, 1,
        "cannot write decreasing time: " + formatDouble(s.t) + " after " + formatDouble(prevT));
  }
  std::array<double, kNumSlots> v{};
  const GroupSet has = groupsOf(s);
  auto put = [&](Group g, const auto& x) {
    for (int k = 0; k < kGroups[g].size; ++k) v[kGroups[g].firstSlot + k] = x[k];
  };
  if (s.upperArm) {
    put(kUaGyr, s.upperArm->gyr);
    put(kUaAcc, s.upperArm->acc);
  }
  if (s.forearm) {
    put(kFaGyr, s.forearm->gyr);
    put(kFaAcc, s.forearm->acc);
  }
  if (s.elbow) put(kElbow, *s.elbow);
  if (s.wrist) put(kWrist, *s.wrist);
  if (s.camWrist) put(kCamWrist, *s.camWrist);
  if (s.camElbow) put(kCamElbow, *s.camElbow);
  if (s.trueAngles) put(kTruth, *s.trueAngles);
  if (s.estimate) put(kEstimate, *s.estimate);

  const std::size_t rowStart = buf.size();
  char tbuf[32];
  const auto tr = std::to_chars(tbuf, tbuf + sizeof tbuf, s.t);
  buf.append(tbuf, tr.ptr);
  int column = 1;
  for (int g = 0; g < kNumGroups; ++g) {
    const GroupDef& def = kGroups[g];
    if (!present[g]) {
      if (has[g]) {
        buf.resize(rowStart);
        throw RecordingError(
            file, line, 1,
            "cannot write the " + std::string(def.label) + ": the recording has no columns for it");
      }
      continue;
    }
    if (!has[g]) {
      buf.append(static_cast<std::size_t>(def.size), ',');
      column += def.size;
      continue;
    }
    for (int k = 0; k < def.size; ++k) {
      const double x = v[def.firstSlot + k];
      ++column;
      if (!std::isfinite(x)) {
        buf.resize(rowStart);
        throw RecordingError(file, line, column,
                             "cannot write non-finite value " + formatDouble(x) + " in column " +
                                 inQuotes(def.columns[k]));
      }
      appendNumber(buf, x);
    }
  }
  buf += '\n';
}

/// Writes the CSV into an open temporary file.
void writeCsv(AtomicFile& out, const std::string& file, const Recording& rec) {
  GroupSet present{};
  for (const ArmSample& s : rec.samples) {
    const GroupSet g = groupsOf(s);
    for (int k = 0; k < kNumGroups; ++k) present[k] = present[k] || g[k];
  }
  constexpr std::size_t kFlushAt = std::size_t{1} << 20;
  std::string buf;
  buf.reserve(kFlushAt + 4096);
  buf += fileHeader(present);
  constexpr int kFirstRowLine = 3;  // comment, header
  double prevT = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < rec.samples.size(); ++i) {
    appendRow(buf, present, rec.samples[i], prevT, file, kFirstRowLine + static_cast<int>(i));
    prevT = rec.samples[i].t;
    if (buf.size() >= kFlushAt) {
      out.write(buf);
      buf.clear();
    }
  }
  out.write(buf);
}

}  // namespace

struct RecordingReader::Impl {
  explicit Impl(const fs::path& csvPath) : lines(csvPath), parser(csvPath.string()) {}
  FileLines lines;
  CsvParser parser;
  int completeLines = 0;  // newline-terminated data lines read so far (header included)
  bool done = false;
};

RecordingReader::RecordingReader(const fs::path& csvPath) {
  const fs::path jsonPath = sidecarPath(csvPath);
  std::error_code ec;
  if (fs::status(jsonPath, ec).type() != fs::file_type::not_found) {
    m_meta = readSidecar(jsonPath);  // also reports a sidecar that exists but cannot be read
  } else {
    m_warnings.push_back("no sidecar " + inQuotes(jsonPath.string()) +
                         " found; using the default geometry, up and g");
  }
  m_impl = std::make_unique<Impl>(csvPath);
  std::string_view line;
  int number = 0;
  bool terminated = false;
  if (!m_impl->lines.next(line, number, terminated)) number = 0;
  m_impl->parser.parseHeader(line, number);
  m_impl->completeLines += terminated;
  const CsvParser& p = m_impl->parser;
  m_columns.upperArm = p.hasGroup(kUaGyr);
  m_columns.forearm = p.hasGroup(kFaGyr);
  m_columns.elbow = p.hasGroup(kElbow);
  m_columns.wrist = p.hasGroup(kWrist);
  m_columns.camWrist = p.hasGroup(kCamWrist);
  m_columns.camElbow = p.hasGroup(kCamElbow);
  m_columns.truth = p.hasGroup(kTruth);
  m_columns.estimate = p.hasGroup(kEstimate);
}

RecordingReader::~RecordingReader() = default;

bool RecordingReader::next(ArmSample& sample) {
  if (m_impl->done) return false;
  std::string_view line;
  int number = 0;
  bool terminated = false;
  if (!m_impl->lines.next(line, number, terminated)) {
    m_impl->done = true;
    return false;
  }
  try {
    m_impl->parser.parseRow(line, number, sample);
  } catch (const RecordingError&) {
    // A session killed while writing leaves its last line cut short: drop that line alone, when
    // the header and at least one row came before it whole.
    if (terminated || m_impl->completeLines < 2) throw;
    m_impl->done = true;
    m_warnings.push_back("line " + std::to_string(number) +
                         " was cut short (the recording was interrupted) and is ignored");
    return false;
  }
  m_impl->completeLines += terminated;
  ++m_rows;
  return true;
}

std::uint64_t RecordingReader::bytesRead() const {
  return m_impl->lines.bytesRead();
}
std::uint64_t RecordingReader::fileSize() const {
  return m_impl->lines.size();
}

Recording readRecording(const fs::path& csvPath) {
  RecordingReader reader(csvPath);
  Recording rec;
  rec.meta = reader.meta();
  // After the first rows, reserve for the whole file at their bytes per row (plus a margin), so
  // the vector is not regrown and copied while the peak memory is at its highest.
  ArmSample s;
  while (reader.next(s)) {
    rec.samples.push_back(std::move(s));
    if (rec.samples.size() == 1000 && reader.fileSize() > 0) {
      const double perRow = static_cast<double>(reader.bytesRead()) / 1000.0;
      rec.samples.reserve(static_cast<std::size_t>(1.02 * reader.fileSize() / perRow) + 16);
    }
  }
  rec.warnings = reader.warnings();
  return rec;
}

RecordingWriter::RecordingWriter(const fs::path& csvPath, const RecordingMeta& meta,
                                 const RecordingColumns& c)
    : m_path(csvPath), m_prevT(std::numeric_limits<double>::quiet_NaN()) {
  static_assert(std::tuple_size_v<decltype(m_present)> == kNumGroups);
  m_present[kUaGyr] = m_present[kUaAcc] = c.upperArm;
  m_present[kFaGyr] = m_present[kFaAcc] = c.forearm;
  m_present[kElbow] = c.elbow;
  m_present[kWrist] = c.wrist;
  m_present[kCamWrist] = c.camWrist;
  m_present[kCamElbow] = c.camElbow;
  m_present[kTruth] = c.truth;
  m_present[kEstimate] = c.estimate;
  writeSidecar(sidecarPath(csvPath), meta);
  m_fd = ::open(csvPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (m_fd < 0)
    throw RecordingError(csvPath.string(), 0, 0, "cannot create the file: " + osReason(errno));
  m_buf = fileHeader(m_present);
  flush();
}

RecordingWriter::~RecordingWriter() {
  if (m_fd < 0) return;
  try {
    sync();
  } catch (const RecordingError&) {
    // Nothing more can be done here; the caller that wanted to know calls close().
  }
  ::close(m_fd);
}

void RecordingWriter::append(const ArmSample& sample) {
  if (m_fd < 0) throw RecordingError(m_path.string(), 0, 0, "the recording is closed");
  appendRow(m_buf, m_present, sample, m_prevT, m_path.string(), static_cast<int>(m_rows) + 3);
  m_prevT = sample.t;
  ++m_rows;
}

void RecordingWriter::writeAll(std::string_view data, std::size_t& written) {
  while (!data.empty()) {
    const ssize_t n = ::write(m_fd, data.data(), data.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      throw RecordingError(m_path.string(), 0, 0,
                           "cannot write (" + osReason(n < 0 ? errno : ENOSPC) +
                               "); free some disk space or choose another folder");
    }
    data.remove_prefix(static_cast<std::size_t>(n));
    written += static_cast<std::size_t>(n);
  }
}

void RecordingWriter::flush() {
  if (m_fd < 0) throw RecordingError(m_path.string(), 0, 0, "the recording is closed");
  // What could not be written stays buffered for the next attempt, so a retry after freeing space
  // completes the file; a row cut by the failure is completed by that retry (or dropped by the
  // reader if none comes).
  std::size_t written = 0;
  try {
    writeAll(m_buf, written);
  } catch (...) {
    m_buf.erase(0, written);
    throw;
  }
  m_buf.clear();
}

void RecordingWriter::sync() {
  flush();
  if (::fsync(m_fd) != 0)
    throw RecordingError(m_path.string(), 0, 0, "cannot force to disk: " + osReason(errno));
}

void RecordingWriter::close() {
  sync();
  ::close(m_fd);
  m_fd = -1;
}

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

void writeRecording(const fs::path& csvPath, const Recording& recording) {
  const fs::path jsonPath = sidecarPath(csvPath);
  checkMetaWritable(jsonPath.string(), recording.meta);
  reportingAsRecordingError([&] {
    AtomicFile csv(csvPath);
    writeCsv(csv, csvPath.string(), recording);
    csv.finish();
    AtomicFile json(jsonPath);
    json.write(sidecarText(recording.meta));
    json.commit();
    csv.publish();
  });
}

}  // namespace armtrack
