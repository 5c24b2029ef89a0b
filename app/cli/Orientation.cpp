#include "app/cli/Orientation.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "app/cli/Args.h"
#include "app/cli/CsvOutput.h"
#include "app/cli/Text.h"
#include "core/io/Recording.h"
#include "core/orientation/OrientationFilter.h"

namespace armtrack::cli {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kOrientationHelp =
    R"(Usage: armtrack-cli orientation IMU.csv [--out QUAT.csv] [options]

Estimates the orientation of one IMU from its gyroscope and accelerometer (no magnetometer) with
a VQF-style filter with gyroscope bias estimation (docs/orientation.md). Reads a CSV whose header
names the columns t,gyr_x,gyr_y,gyr_z,acc_x,acc_y,acc_z (s, rad/s, m/s^2) and writes
"t,qw,qx,qy,qz,flag", one row per input row: the sensor-to-world rotation, world z up. The heading
(rotation about the vertical) starts at zero and drifts. dt is taken from the timestamps.

flag: 0 = row used; 1 = row rejected (a value not finite or at or beyond the plausible range,
or the same time as the row before): the quaternion repeats the last one; 2 = first row after a
gap in time: the gyroscope was not integrated across the gap and the inclination starts again
from the accelerometer. Rejected rows and gaps are counted on standard error.

Options:
  --out FILE         write the quaternions here (default: standard output)
  --overwrite        replace the --out file if it exists (otherwise an error)
  --tau-acc S        accelerometer low-pass time constant, s (default 3)
  --no-rest-bias     no gyroscope bias estimation at rest
  --no-motion-bias   no gyroscope bias estimation during motion
  --gyr-max DEG/S    plausible gyroscope range per axis, deg/s (default 2000)
  --acc-max M/S2     plausible accelerometer range per axis, m/s^2 (default 156.9, 16 g)
  --gap S            a step in time longer than this is a gap, s (default 0.1)
)";

constexpr std::array<std::string_view, 7> kColumns = {"t",     "gyr_x", "gyr_y", "gyr_z",
                                                      "acc_x", "acc_y", "acc_z"};
constexpr std::string_view kColumnList = "t,gyr_x,gyr_y,gyr_z,acc_x,acc_y,acc_z";
constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr std::size_t kListedRows = 5;  // rejected rows and gaps listed by line and time

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::string readWholeFile(const fs::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw std::runtime_error(name + ": no such file");
  if (fs::is_directory(path, ec))
    throw RecordingError(name, 0, 0, "cannot open file: is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw RecordingError(name, 0, 0, "cannot open file: " + std::generic_category().message(errno));
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad())
    throw RecordingError(name, 0, 0, "cannot read file: " + std::generic_category().message(errno));
  return data;
}

// Splits a line at commas into trimmed fields.
void splitFields(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  for (;;) {
    const std::size_t comma = line.find(',');
    fields.push_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    line.remove_prefix(comma + 1);
  }
}

class ImuCsvParser {
 public:
  ImuCsvParser(std::string file, std::string_view text) : m_file(std::move(file)), m_text(text) {
    if (m_text.starts_with("\xEF\xBB\xBF")) m_text.remove_prefix(3);  // UTF-8 byte order mark
  }

  ImuSeries parse() {
    ImuSeries s;
    std::vector<std::string_view> fields;
    bool haveHeader = false;
    int lineNo = 0;
    std::size_t pos = 0;
    while (pos < m_text.size()) {
      std::size_t end = m_text.find('\n', pos);
      if (end == std::string_view::npos) end = m_text.size();
      const std::string_view line = trim(m_text.substr(pos, end - pos));
      pos = end + 1;
      ++lineNo;
      if (line.empty() || line.front() == '#') continue;
      splitFields(line, fields);
      if (!haveHeader) {
        readHeader(fields, lineNo);
        haveHeader = true;
        s.t.reserve(m_text.size() / 64);
        s.gyr.reserve(3 * s.t.capacity());
        s.acc.reserve(3 * s.t.capacity());
        s.line.reserve(s.t.capacity());
        continue;
      }
      const int n = static_cast<int>(fields.size());
      if (n != m_headerFields) {
        fail(lineNo, std::min(n, m_headerFields) + 1,
             "row has " + std::to_string(n) + " fields, header has " +
                 std::to_string(m_headerFields));
      }
      std::array<double, 7> v;
      for (int k = 0; k < 7; ++k) v[k] = number(fields[m_columnOf[k]], lineNo, k);
      if (!s.t.empty() && v[0] < s.t.back()) {
        fail(lineNo, m_columnOf[0] + 1,
             "time goes backwards: " + shortest(v[0]) + " after " + shortest(s.t.back()));
      }
      s.t.push_back(v[0]);
      s.line.push_back(lineNo);
      s.gyr.insert(s.gyr.end(), v.begin() + 1, v.begin() + 4);
      s.acc.insert(s.acc.end(), v.begin() + 4, v.end());
    }
    if (!haveHeader) fail(0, 0, "missing header (expected " + std::string(kColumnList) + ")");
    return s;
  }

 private:
  void readHeader(const std::vector<std::string_view>& fields, int lineNo) {
    m_headerFields = static_cast<int>(fields.size());
    m_columnOf.fill(-1);
    for (int c = 0; c < m_headerFields; ++c) {
      for (int k = 0; k < 7; ++k) {
        if (fields[c] != kColumns[k]) continue;
        if (m_columnOf[k] >= 0) fail(lineNo, c + 1, "duplicate column " + inQuotes(kColumns[k]));
        m_columnOf[k] = c;
      }
    }
    for (int k = 0; k < 7; ++k) {
      if (m_columnOf[k] < 0) {
        fail(lineNo, 0,
             "missing column " + inQuotes(kColumns[k]) + " in header (expected " +
                 std::string(kColumnList) + ")");
      }
    }
  }

  double number(std::string_view cell, int lineNo, int k) const {
    const int column = m_columnOf[k] + 1;
    const std::string where = " in column " + inQuotes(kColumns[k]);
    if (cell.empty()) fail(lineNo, column, "empty cell" + where);
    const char* b = cell.data();
    const char* e = b + cell.size();
    if (*b == '+' && e - b > 1 && b[1] != '-' && b[1] != '+') ++b;  // from_chars rejects '+'
    double x = 0.0;
    const auto r = std::from_chars(b, e, x);
    if (r.ptr == e && r.ec == std::errc() && std::isfinite(x)) return x;
    // A sensor value that is a number but not a finite double (nan, inf, 1e999): the row is
    // kept and the filter rejects it, so one bad reading does not cost the whole file.
    if (k > 0 && r.ptr == e && (r.ec == std::errc() || r.ec == std::errc::result_out_of_range))
      return std::numeric_limits<double>::quiet_NaN();
    if (r.ptr != e || r.ec == std::errc::invalid_argument) {
      fail(lineNo, column,
           "bad number " + quotedCell(cell) + where +
               " (expected a decimal number such as -1.25e-3)");
    }
    if (r.ec == std::errc::result_out_of_range)
      fail(lineNo, column, "number out of range " + quotedCell(cell) + where);
    fail(lineNo, column,
         "not a finite number " + quotedCell(cell) + where + " (NaN and infinity are not allowed)");
  }

  [[noreturn]] void fail(int line, int column, const std::string& message) const {
    throw RecordingError(m_file, line, column, message);
  }

  std::string m_file;
  std::string_view m_text;
  int m_headerFields = 0;
  std::array<int, 7> m_columnOf{};  // field index of each of kColumns
};

}  // namespace

ImuSeries readImuCsv(const fs::path& path) {
  const std::string text = readWholeFile(path);
  return ImuCsvParser(path.string(), text).parse();
}

int orientationCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const Args a("orientation", args,
               {{"--out", true},
                {"--tau-acc", true},
                {"--no-rest-bias", false},
                {"--no-motion-bias", false},
                {"--gyr-max", true},
                {"--acc-max", true},
                {"--gap", true},
                {"--overwrite", false}});
  if (a.help()) {
    out << kOrientationHelp;
    return 0;
  }
  const fs::path input = a.single("the IMU file to read (orientation IMU.csv)");

  OrientationParams params;
  params.tauAcc = a.positive("--tau-acc", params.tauAcc);
  params.restBiasEstEnabled = !a.flag("--no-rest-bias");
  params.motionBiasEstEnabled = !a.flag("--no-motion-bias");
  params.gyrMax = a.positive("--gyr-max", params.gyrMax);
  params.accMax = a.positive("--acc-max", params.accMax);
  params.gapSeconds = a.positive("--gap", params.gapSeconds);
  std::optional<fs::path> outPath;
  if (const auto v = a.value("--out")) {
    if (v->empty()) a.fail("--out: missing value");
    outPath = *v;
    if (samePath(*outPath, input))
      a.fail("--out: " + inQuotes(outPath->string()) + " would overwrite the input");
    checkOutputPath(*outPath, a.flag("--overwrite"));
  }

  const ImuSeries s = readImuCsv(input);
  const std::size_t n = s.t.size();
  if (n == 0) throw std::runtime_error(input.string() + ": no samples");
  // dt of each row from the timestamps; the first row takes the first positive step.
  std::vector<double> dt(n);
  double firstStep = 0.0;
  for (std::size_t i = 1; i < n && firstStep <= 0.0; ++i) firstStep = s.t[i] - s.t[i - 1];
  if (!(firstStep > 0.0)) {
    throw std::runtime_error(input.string() +
                             ": need at least two samples with increasing time to derive dt");
  }
  dt[0] = firstStep;
  for (std::size_t i = 1; i < n; ++i) dt[i] = s.t[i] - s.t[i - 1];

  OrientationFilter filter(params);
  std::vector<double> quat(4 * n);
  std::vector<OrientationStatus> status(n);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t accepted = filter.updateBatch(s.gyr, s.acc, dt, quat, status);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (accepted == 0) {
    throw std::runtime_error(input.string() + ": no plausible sample in " + std::to_string(n) +
                             " rows (every row has a value that is not finite or at or beyond "
                             "--gyr-max or --acc-max, or repeats the time before it)");
  }

  CsvOutput writer("t,qw,qx,qy,qz,flag", outPath, &out);
  for (std::size_t i = 0; i < n; ++i) {
    std::array<double, 5> v;
    std::copy_n(&quat[4 * i], 4, v.begin());
    v[4] = static_cast<double>(status[i]);
    writer.row(s.t[i], v.data(), 5);
  }
  writer.commit();

  const OrientationState& st = filter.state();
  const Eigen::Vector3d b = filter.bias() * kRadToDeg;
  err << "orientation: " << n << " samples (" << shortest(s.t.front()) << " to "
      << shortest(s.t.back()) << " s";
  if (n > 1) err << ", " << fixed((n - 1) / (s.t.back() - s.t.front()), 1) << " Hz";
  err << "), " << fixed(1e9 * seconds / n, 0) << " ns per sample; gyroscope bias at the end "
      << fixed(b.x(), 3) << " " << fixed(b.y(), 3) << " " << fixed(b.z(), 3) << " deg/s (sigma "
      << fixed(filter.biasSigma() * kRadToDeg, 3) << ")";
  if (outPath) err << "; wrote " << outPath->string();
  err << "\n";

  // Where: "line L (t = T s)" for the first few rows of a kind.
  const auto listRows = [&](OrientationStatus kind) {
    std::string where;
    std::size_t listed = 0, total = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (status[i] != kind) continue;
      if (++total > kListedRows) continue;
      where += (listed++ ? ", line " : "line ") + std::to_string(s.line[i]) +
               " (t = " + shortest(s.t[i]) + " s)";
    }
    if (total > listed) where += ", ...";
    return where;
  };
  if (st.rejected > 0) {
    std::uint64_t nonFinite = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double* g = &s.gyr[3 * i];
      const double* c = &s.acc[3 * i];
      if (status[i] == OrientationStatus::Rejected &&
          !std::isfinite(g[0] + g[1] + g[2] + c[0] + c[1] + c[2]))
        ++nonFinite;
    }
    err << "orientation: " << st.rejected << " row(s) rejected (flag 1; their output repeats the "
        << "previous orientation): " << st.outOfRange << " at or beyond " << shortest(params.gyrMax)
        << " deg/s or " << shortest(params.accMax) << " m/s^2 on an axis, " << nonFinite
        << " not finite, " << st.rejected - st.outOfRange - nonFinite
        << " with the same time as the previous row; " << listRows(OrientationStatus::Rejected)
        << "\n";
  }
  if (st.gaps > 0) {
    err << "orientation: " << st.gaps << " gap(s) in time longer than "
        << shortest(params.gapSeconds) << " s (" << fixed(st.gapTime, 3)
        << " s in all): the gyroscope is not integrated across a gap, the inclination starts "
        << "again from the accelerometer at the row after it (flag 2); "
        << listRows(OrientationStatus::AfterGap) << "\n";
  }
  if (st.noAcc > 0) {
    err << "orientation: " << st.noAcc
        << " row(s) with zero acceleration, taken as missing: gyroscope only\n";
  }
  return 0;
}

}  // namespace armtrack::cli
