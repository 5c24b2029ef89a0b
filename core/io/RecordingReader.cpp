// Reader of the open recording format's CSV (docs/recording-format.md).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string_view>
#include <system_error>

#include "core/io/FileLines.h"
#include "core/io/Recording.h"
#include "core/io/RecordingFormat.h"

namespace armtrack {

namespace fs = std::filesystem;
using namespace recording_detail;

RecordingError::RecordingError(std::string file, int line, int column, const std::string& message)
    : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) +
                         (line > 0 && column > 0 ? ":" + std::to_string(column) : std::string()) +
                         ": " + message),
      m_file(std::move(file)),
      m_line(line),
      m_column(column),
      m_message(message) {}

namespace {

// ---------------------------------------------------------------------------------------------
// CSV reading

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
    checkTime(t, lineNo);

    for (int g = 0; g < kNumGroups; ++g) present[g] = groupPresent(g, filled, lineNo);
    checkImu(kUaGyr, kUaAcc, present, lineNo);
    checkImu(kFaGyr, kFaAcc, present, lineNo);
    checkImu(kTrGyr, kTrAcc, present, lineNo);

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
    if (present[kTrGyr]) s.trunk = ImuReading{vec3(kTrGyr), vec3(kTrAcc)};
    if (present[kElbow]) s.elbow = vec3(kElbow);
    if (present[kWrist]) s.wrist = vec3(kWrist);
    if (present[kShoulder]) s.shoulder = vec3(kShoulder);
    if (present[kTrueTrunk]) s.trueTrunk = vec3(kTrueTrunk);
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
    if (m_rows == 0) m_firstT = t;
    countGap(t, lineNo);
    m_prevT = t;
    ++m_rows;
  }

  const TimeGaps& gaps() const { return m_gaps; }

 private:
  [[noreturn]] void fail(int line, int column, const std::string& message) const {
    throw RecordingError(m_file, line, column, message);
  }

  /// The row's time against the first row's and the previous one's (RecordingLimits).
  void checkTime(double t, int lineNo) const {
    using L = RecordingLimits;
    const int column = m_columnOfSlot[0] + 1;
    if (m_rows == 0) {
      if (std::fabs(t) > L::kMaxAbsTimeSeconds) {
        fail(lineNo, column,
             "first time " + formatDouble(t) + " s is no clock's reading: |t| must be at most " +
                 formatDouble(L::kMaxAbsTimeSeconds) +
                 " s (Unix time reaches that in the year 2286); is \"t\" in seconds?");
      }
      return;
    }
    if (t < m_prevT) {
      fail(lineNo, column,
           "time goes backwards: " + formatDouble(t) + " after " + formatDouble(m_prevT) +
               " (\"t\" must not decrease)");
    }
    if (t - m_firstT > L::kMaxRecordingSeconds) {
      const std::string span = ", more than " + formatDouble(L::kMaxRecordingSeconds / 3600.0) +
                               " h after the first row (" + formatDouble(m_firstT) +
                               " s): a recording spans at most " +
                               formatDouble(L::kMaxRecordingSeconds / 3600.0) + " h; ";
      if (t - m_prevT > L::kGapSeconds) {
        fail(lineNo, column,
             "t jumps from " + formatDouble(m_prevT) + " s to " + formatDouble(t) + " s" + span +
                 "is the clock right?");
      }
      fail(lineNo, column,
           "t reaches " + formatDouble(t) + " s" + span +
               "split a longer session into several recordings");
    }
  }

  /// Counts the step from the previous row as a gap when it is one (the row is accepted).
  void countGap(double t, int lineNo) {
    if (m_rows == 0) return;
    const double step = t - m_prevT;
    if (!(step > RecordingLimits::kGapSeconds)) return;
    ++m_gaps.count;
    m_gaps.totalSeconds += step;
    if (step > m_gaps.longestSeconds) {
      m_gaps.longestSeconds = step;
      m_gaps.longestFromT = m_prevT;
      m_gaps.longestLine = lineNo;
    }
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
        quotedCell(cell) + " in column " + inQuotes(slotName(m_slotOfColumn[column]));
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
  double m_firstT = 0.0;     // the first row's time
  TimeGaps m_gaps;
  std::vector<std::string_view> m_fields;
  std::array<double, kNumSlots> m_values{};
  std::vector<int> m_slotOfColumn;              // header column -> slot, -1 if ignored
  std::array<int, kNumSlots> m_columnOfSlot{};  // slot -> 0-based header column, -1 if absent
};

}  // namespace

struct RecordingReader::Impl {
  explicit Impl(const fs::path& csvPath) : lines(csvPath), parser(csvPath.string()) {}
  FileLines lines;
  CsvParser parser;
  int completeLines = 0;  // newline-terminated data lines read so far (header included)
  bool done = false;
};

RecordingReader::RecordingReader(const fs::path& csvPath) {
  m_impl = std::make_unique<Impl>(csvPath);  // the CSV's checks at the door come first
  const fs::path jsonPath = sidecarPath(csvPath);
  std::error_code ec;
  const fs::file_status sidecar = fs::status(jsonPath, ec);
  if (sidecar.type() == fs::file_type::not_found) {
    m_warnings.push_back("no sidecar " + inQuotes(jsonPath.string()) +
                         " found; using the default geometry, up and g");
  } else {
    // Only a small regular file is read whole; readSidecar reports one that cannot be read.
    if (fs::exists(sidecar) && !fs::is_regular_file(sidecar))
      notARegularFile(jsonPath.string(), kindOf(sidecar.type()), "a sidecar is a .json file");
    const std::uintmax_t size = fs::is_regular_file(sidecar) ? fs::file_size(jsonPath, ec) : 0;
    if (!ec && size > RecordingLimits::kMaxSidecarBytes) {
      throw RecordingError(jsonPath.string(), 0, 0,
                           "the sidecar is " + std::to_string(size) +
                               " bytes, more than a sidecar can be (" +
                               std::to_string(RecordingLimits::kMaxSidecarBytes >> 10) +
                               " KiB; a real one is under 1 KiB): is it the right file?");
    }
    m_meta = readSidecar(jsonPath);
  }
  std::string_view line;
  int number = 0;
  bool terminated = false;
  if (!m_impl->lines.next(line, number, terminated)) number = 0;
  m_impl->parser.parseHeader(line, number);
  m_impl->completeLines += terminated;
  const CsvParser& p = m_impl->parser;
  m_columns.upperArm = p.hasGroup(kUaGyr);
  m_columns.forearm = p.hasGroup(kFaGyr);
  m_columns.trunk = p.hasGroup(kTrGyr);
  m_columns.elbow = p.hasGroup(kElbow);
  m_columns.wrist = p.hasGroup(kWrist);
  m_columns.shoulder = p.hasGroup(kShoulder);
  m_columns.camWrist = p.hasGroup(kCamWrist);
  m_columns.camElbow = p.hasGroup(kCamElbow);
  m_columns.truth = p.hasGroup(kTruth);
  m_columns.trueTrunk = p.hasGroup(kTrueTrunk);
  m_columns.estimate = p.hasGroup(kEstimate);
  if (m_columns.trunk && !m_meta.trunk) {
    // A trunk IMU needs its mounting; without one the recording is still read (docs/
    // recording-format.md, "Trunk"), with the usual mounting and a warning saying what to add.
    m_meta.trunk = defaultTrunkMount(m_meta.side);
    m_warnings.push_back(
        "the recording has a trunk IMU (tr_* columns) but its sidecar " +
        inQuotes(sidecarPath(csvPath).string()) +
        " has no \"trunk\" block; assuming the sensor flat on the middle of the sternum with "
        "frame 0's axes (\"imu_position\" [0.1, 0.06, " +
        std::string(m_meta.side == Side::Left ? "0.18" : "-0.18") +
        "], \"imu_rotation\" the identity): add the block with the sensor's mounting for "
        "accurate trunk angles");
  }
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
    m_cutShort = true;
    m_warnings.push_back("line " + std::to_string(number) +
                         " was cut short (the recording was interrupted) and is ignored");
    return false;
  }
  m_impl->completeLines += terminated;
  ++m_rows;
  return true;
}

const TimeGaps& RecordingReader::gaps() const {
  return m_impl->parser.gaps();
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

}  // namespace armtrack
