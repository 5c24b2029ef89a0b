// Writers of the open recording format (docs/recording-format.md): a whole recording at once,
// and row by row for live sessions.
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>

#include "core/io/AtomicFile.h"
#include "core/io/Recording.h"
#include "core/io/RecordingFormat.h"

namespace armtrack {

namespace fs = std::filesystem;
using namespace recording_detail;

namespace {

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

GroupSet groupsOf(const ArmSample& s) {
  GroupSet g{};
  g[kUaGyr] = g[kUaAcc] = s.upperArm.has_value();
  g[kFaGyr] = g[kFaAcc] = s.forearm.has_value();
  g[kTrGyr] = g[kTrAcc] = s.trunk.has_value();
  g[kElbow] = s.elbow.has_value();
  g[kWrist] = s.wrist.has_value();
  g[kShoulder] = s.shoulder.has_value();
  g[kCamWrist] = s.camWrist.has_value();
  g[kCamElbow] = s.camElbow.has_value();
  g[kTruth] = s.trueAngles.has_value();
  g[kTrueTrunk] = s.trueTrunk.has_value();
  g[kEstimate] = s.estimate.has_value();
  return g;
}

std::string fileHeader(const GroupSet& present) {
  return "# ArmTrack recording, format version 1\n" + csvHeader(present) + "\n";
}

GroupSet groupsOf(const RecordingColumns& c) {
  GroupSet g{};
  g[kUaGyr] = g[kUaAcc] = c.upperArm;
  g[kFaGyr] = g[kFaAcc] = c.forearm;
  g[kTrGyr] = g[kTrAcc] = c.trunk;
  g[kElbow] = c.elbow;
  g[kWrist] = c.wrist;
  g[kShoulder] = c.shoulder;
  g[kCamWrist] = c.camWrist;
  g[kCamElbow] = c.camElbow;
  g[kTruth] = c.truth;
  g[kTrueTrunk] = c.trueTrunk;
  g[kEstimate] = c.estimate;
  return g;
}

RecordingColumns columnsOf(const GroupSet& g) {
  RecordingColumns c;
  c.upperArm = g[kUaGyr];
  c.forearm = g[kFaGyr];
  c.trunk = g[kTrGyr];
  c.elbow = g[kElbow];
  c.wrist = g[kWrist];
  c.shoulder = g[kShoulder];
  c.camWrist = g[kCamWrist];
  c.camElbow = g[kCamElbow];
  c.truth = g[kTruth];
  c.trueTrunk = g[kTrueTrunk];
  c.estimate = g[kEstimate];
  return c;
}

/// The row's values in slot order (slot 0, the time, left 0).
std::array<double, kNumSlots> slotsOf(const ArmSample& s) {
  std::array<double, kNumSlots> v{};
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
  if (s.trunk) {
    put(kTrGyr, s.trunk->gyr);
    put(kTrAcc, s.trunk->acc);
  }
  if (s.elbow) put(kElbow, *s.elbow);
  if (s.wrist) put(kWrist, *s.wrist);
  if (s.shoulder) put(kShoulder, *s.shoulder);
  if (s.camWrist) put(kCamWrist, *s.camWrist);
  if (s.camElbow) put(kCamElbow, *s.camElbow);
  if (s.trueAngles) put(kTruth, *s.trueAngles);
  if (s.trueTrunk) put(kTrueTrunk, *s.trueTrunk);
  if (s.estimate) put(kEstimate, *s.estimate);
  return v;
}

/// Appends one CSV row (checked with checkRow) for the columns in `present`. `prevT` is the
/// previous row's time and `firstT` the first's (NaN for the first row). Throws RecordingError
/// naming file, line and
/// column for what checkRow refuses.
void appendRow(std::string& buf, const GroupSet& present, const ArmSample& s, double prevT,
               double firstT, const std::string& file, int line) {
  if (const std::optional<RowProblem> p = checkRow(s, columnsOf(present), prevT, firstT))
    throw RecordingError(file, line, p->column, p->message);
  const std::array<double, kNumSlots> v = slotsOf(s);
  const GroupSet has = groupsOf(s);
  char tbuf[32];
  const auto tr = std::to_chars(tbuf, tbuf + sizeof tbuf, s.t);
  buf.append(tbuf, tr.ptr);
  for (int g = 0; g < kNumGroups; ++g) {
    const GroupDef& def = kGroups[g];
    if (!present[g]) continue;
    if (!has[g]) {
      buf.append(static_cast<std::size_t>(def.size), ',');
      continue;
    }
    for (int k = 0; k < def.size; ++k) appendNumber(buf, v[def.firstSlot + k]);
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
    appendRow(buf, present, rec.samples[i], prevT,
              i == 0 ? std::numeric_limits<double>::quiet_NaN() : rec.samples[0].t, file,
              kFirstRowLine + static_cast<int>(i));
    prevT = rec.samples[i].t;
    if (buf.size() >= kFlushAt) {
      out.write(buf);
      buf.clear();
    }
  }
  out.write(buf);
}

}  // namespace

std::optional<RowProblem> checkRow(const ArmSample& s, const RecordingColumns& columns,
                                   double prevT, double firstT) {
  if (!std::isfinite(s.t))
    return RowProblem{1, "cannot write non-finite time " + formatDouble(s.t)};
  if (std::fabs(s.t) > RecordingLimits::kMaxAbsTimeSeconds)
    return RowProblem{1, "cannot write time " + formatDouble(s.t) +
                             " s: beyond any clock (a recording's times stay within +-1e10 s)"};
  if (std::isfinite(firstT) && s.t - firstT > RecordingLimits::kMaxRecordingSeconds)
    return RowProblem{1, "cannot write time " + formatDouble(s.t) +
                             " s, more than 12 h after "
                             "the first row (" +
                             formatDouble(firstT) +
                             " s): a recording spans at most 12 h; start a new one"};
  if (s.t < prevT)
    return RowProblem{
        1, "cannot write decreasing time: " + formatDouble(s.t) + " after " + formatDouble(prevT)};
  const GroupSet present = groupsOf(columns);
  const GroupSet has = groupsOf(s);
  const std::array<double, kNumSlots> v = slotsOf(s);
  int column = 1;
  for (int g = 0; g < kNumGroups; ++g) {
    const GroupDef& def = kGroups[g];
    if (!present[g]) {
      if (has[g])
        return RowProblem{1, "cannot write the " + std::string(def.label) +
                                 ": the recording has no columns for it"};
      continue;
    }
    if (!has[g]) {
      column += def.size;
      continue;
    }
    for (int k = 0; k < def.size; ++k) {
      const double x = v[def.firstSlot + k];
      ++column;
      if (!std::isfinite(x))
        return RowProblem{column, "cannot write non-finite value " + formatDouble(x) +
                                      " in column " + inQuotes(def.columns[k])};
    }
  }
  return std::nullopt;
}

RecordingWriter::RecordingWriter(const fs::path& csvPath, const RecordingMeta& meta,
                                 const RecordingColumns& c)
    : m_path(csvPath), m_prevT(std::numeric_limits<double>::quiet_NaN()) {
  static_assert(std::tuple_size_v<decltype(m_present)> == kNumGroups);
  m_present = groupsOf(c);
  // Check everything that can be checked before creating anything, so a refused recording
  // leaves no file behind (not even a sidecar).
  const std::string name = csvPath.string();
  const fs::path jsonPath = sidecarPath(csvPath);
  checkMetaWritable(jsonPath.string(), meta);
  if (jsonPath == csvPath)
    throw RecordingError(name, 0, 0,
                         "a recording's name must not end in .json, the extension of its sidecar");
  std::error_code ec;
  if (fs::is_directory(csvPath, ec))
    throw RecordingError(name, 0, 0, "cannot record into a directory; give a file name");
  if (fs::is_directory(jsonPath, ec))
    throw RecordingError(jsonPath.string(), 0, 0,
                         "cannot write the sidecar: is a directory; give another file name");
  bool created = true;
  m_fd = ::open(csvPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, S_IRUSR | S_IWUSR);
  if (m_fd < 0 && errno == EEXIST) {
    created = false;
    m_fd = ::open(csvPath.c_str(), O_WRONLY | O_CLOEXEC);  // not truncated until locked
  }
  if (m_fd < 0) throw RecordingError(name, 0, 0, "cannot create the file: " + osReason(errno));
  // One writer per file: the lock is held until the file is closed (or the process ends).
  if (::flock(m_fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(m_fd);
    m_fd = -1;
    if (err == EWOULDBLOCK)
      throw RecordingError(name, 0, 0,
                           "another recording is being written to this file (another process "
                           "holds its lock); choose another file or end that recording first");
    throw RecordingError(name, 0, 0, "cannot lock the file: " + osReason(err));
  }
  try {
    // A recording is a patient's data: 0600 whatever the umask, also for a file it replaces
    // (docs/storage.md, "Files and permissions"). A file of another owner keeps its mode.
    if (::fchmod(m_fd, S_IRUSR | S_IWUSR) != 0 && created)
      throw RecordingError(name, 0, 0, "cannot make the file private: " + osReason(errno));
    writeSidecar(jsonPath, meta);
    if (!created && ::ftruncate(m_fd, 0) != 0)
      throw RecordingError(name, 0, 0, "cannot empty the file: " + osReason(errno));
    m_buf = fileHeader(m_present);
    flush();
  } catch (...) {
    if (created) ::unlink(csvPath.c_str());
    ::close(m_fd);
    m_fd = -1;
    throw;
  }
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
  appendRow(m_buf, m_present, sample, m_prevT, m_firstT, m_path.string(),
            static_cast<int>(m_rows) + 3);
  if (m_rows == 0) m_firstT = sample.t;
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
  auto countLines = [&] {
    const char* p = m_buf.data();
    const char* e = p + written;
    while ((p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(e - p))))) {
      ++p;
      ++m_linesWritten;
    }
  };
  try {
    writeAll(m_buf, written);
  } catch (...) {
    countLines();
    m_buf.erase(0, written);
    throw;
  }
  countLines();
  m_buf.clear();
}

std::uint64_t RecordingWriter::rowsWritten() const {
  constexpr std::uint64_t kHeaderLines = 2;  // the comment and the column names
  return m_linesWritten > kHeaderLines ? m_linesWritten - kHeaderLines : 0;
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
