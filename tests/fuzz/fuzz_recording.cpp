// libFuzzer target: one input = the CSV text of a recording (no sidecar), read with
// RecordingReader row by row and with readRecording; what is accepted is checked (finite, in time
// order within the limits, text only, gaps counted, a cut-short line flagged) and written back
// (every group, the trunk's included, read back the same).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/io/Recording.h"

using namespace armtrack;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const char* name) {
  static const fs::path dir = [] {
    fs::path d =
        fs::temp_directory_path() / ("armtrack-fuzz-recording-" + std::to_string(getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir / name;
}

bool finite(const Eigen::MatrixXd& m) {
  return m.allFinite();
}

void checkRow(const ArmSample& s) {
  if (!std::isfinite(s.t)) std::abort();
  if (s.upperArm && !(finite(s.upperArm->gyr) && finite(s.upperArm->acc))) std::abort();
  if (s.forearm && !(finite(s.forearm->gyr) && finite(s.forearm->acc))) std::abort();
  if (s.elbow && !finite(*s.elbow)) std::abort();
  if (s.wrist && !finite(*s.wrist)) std::abort();
  if (s.trueAngles && !finite(*s.trueAngles)) std::abort();
  if (s.trunk && !(finite(s.trunk->gyr) && finite(s.trunk->acc))) std::abort();
  if (s.shoulder && !finite(*s.shoulder)) std::abort();
  if (s.trueTrunk && !finite(*s.trueTrunk)) std::abort();
  if (s.camWrist && !finite(*s.camWrist)) std::abort();
  if (s.camElbow && !finite(*s.camElbow)) std::abort();
  if (s.estimate && !finite(*s.estimate)) std::abort();
}

/// Whether a and b hold the same sensors with the same values (a write and read back is exact).
bool sameSample(const ArmSample& a, const ArmSample& b) {
  auto imu = [](const std::optional<ImuReading>& x, const std::optional<ImuReading>& y) {
    return x.has_value() == y.has_value() && (!x || (x->gyr == y->gyr && x->acc == y->acc));
  };
  auto opt = [](const auto& x, const auto& y) {
    return x.has_value() == y.has_value() && (!x || *x == *y);
  };
  return a.t == b.t && imu(a.upperArm, b.upperArm) && imu(a.forearm, b.forearm) &&
         imu(a.trunk, b.trunk) && opt(a.elbow, b.elbow) && opt(a.wrist, b.wrist) &&
         opt(a.shoulder, b.shoulder) && opt(a.camWrist, b.camWrist) &&
         opt(a.camElbow, b.camElbow) && opt(a.trueAngles, b.trueAngles) &&
         opt(a.trueTrunk, b.trueTrunk) && opt(a.estimate, b.estimate);
}

/// Whether data holds a byte that text never holds (a C0 control other than tab, LF, CR; DEL),
/// which the reader must refuse wherever it is.
bool hasControlByte(const std::uint8_t* data, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i) {
    const std::uint8_t c = data[i];
    if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f) return true;
  }
  return false;
}

/// Whether some line of data (without its LF) is longer than the reader allows.
bool hasOverLongLine(const std::uint8_t* data, std::size_t size) {
  std::size_t start = 0;
  for (std::size_t i = 0; i <= size; ++i) {
    if (i == size || data[i] == '\n') {
      if (i - start > RecordingLimits::kMaxLineBytes) return true;
      start = i + 1;
    }
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fs::path csv = scratch("in.csv");
  {
    std::ofstream out(csv, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  std::uint64_t rows = 0;
  try {
    RecordingReader reader(csv);
    ArmSample s;
    double prev = -INFINITY;
    double first = 0.0;
    TimeGaps gaps;  // recounted from the rows
    while (reader.next(s)) {
      checkRow(s);
      if (s.t < prev) std::abort();  // the reader refuses time going backwards
      if (rows == 0) {
        first = s.t;
        if (std::fabs(first) > RecordingLimits::kMaxAbsTimeSeconds) std::abort();
      } else if (s.t - prev > RecordingLimits::kGapSeconds) {
        ++gaps.count;
        gaps.totalSeconds += s.t - prev;
        gaps.longestSeconds = std::max(gaps.longestSeconds, s.t - prev);
      }
      if (s.t - first > RecordingLimits::kMaxRecordingSeconds) std::abort();
      prev = s.t;
      ++rows;
    }
    if (reader.rows() != rows || reader.bytesRead() > size) std::abort();
    // What was accepted is text with lines of bounded length, and its gaps are counted.
    if (hasControlByte(data, size) || hasOverLongLine(data, size)) std::abort();
    const TimeGaps& g = reader.gaps();
    if (g.count != gaps.count || g.totalSeconds != gaps.totalSeconds ||
        g.longestSeconds != gaps.longestSeconds || (g.count > 0) != (g.longestLine > 0))
      std::abort();
    // A last line cut short is flagged, and said.
    bool warned = false;
    for (const std::string& w : reader.warnings()) warned |= w.find("was cut short") != w.npos;
    if (reader.cutShort() != warned) std::abort();
  } catch (const RecordingError&) {
    return 0;  // malformed input is reported by throwing
  }
  // The whole-file reader agrees, and what was accepted survives a round trip.
  const Recording rec = readRecording(csv);
  if (rec.samples.size() != rows) std::abort();
  const fs::path again = scratch("again.csv");
  writeRecording(again, rec);
  const Recording back = readRecording(again);
  if (back.samples.size() != rows) std::abort();
  for (std::size_t i = 0; i < back.samples.size(); ++i)
    if (!sameSample(back.samples[i], rec.samples[i])) std::abort();
  // A trunk IMU always comes with a mounting (the sidecar's, or the assumed one with a warning),
  // and the mounting written is read back.
  if (std::any_of(rec.samples.begin(), rec.samples.end(),
                  [](const ArmSample& x) { return x.trunk.has_value(); }) &&
      !rec.meta.trunk)
    std::abort();
  if (back.meta.trunk.has_value() != rec.meta.trunk.has_value()) std::abort();
  return 0;
}
