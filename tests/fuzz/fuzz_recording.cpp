// libFuzzer target: one input = the CSV text of a recording (no sidecar), read with
// RecordingReader row by row and with readRecording; what is accepted is checked and written back.
#include <unistd.h>

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
    fs::path d = fs::temp_directory_path() / ("armtrack-fuzz-recording-" + std::to_string(getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir / name;
}

bool finite(const Eigen::MatrixXd& m) { return m.allFinite(); }

void checkRow(const ArmSample& s) {
  if (!std::isfinite(s.t)) std::abort();
  if (s.upperArm && !(finite(s.upperArm->gyr) && finite(s.upperArm->acc))) std::abort();
  if (s.forearm && !(finite(s.forearm->gyr) && finite(s.forearm->acc))) std::abort();
  if (s.elbow && !finite(*s.elbow)) std::abort();
  if (s.wrist && !finite(*s.wrist)) std::abort();
  if (s.trueAngles && !finite(*s.trueAngles)) std::abort();
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
    while (reader.next(s)) {
      checkRow(s);
      if (s.t < prev) std::abort();  // the reader refuses time going backwards
      prev = s.t;
      ++rows;
    }
    if (reader.rows() != rows || reader.bytesRead() > size) std::abort();
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
    if (back.samples[i].t != rec.samples[i].t) std::abort();
  return 0;
}
