// Clinical CSV export (docs/exports.md, "Clinical CSV").
#include <cmath>
#include <stdexcept>

#include "core/exports/ExportFiles.h"
#include "core/exports/Exports.h"
#include "core/kinematics/ClinicalAngles.h"

namespace armtrack {

namespace fs = std::filesystem;
using exportdetail::appendFixed;

namespace {

constexpr int kAngleDecimals = 6;  // deg
constexpr int kTimeDecimals = 6;   // s

// A value in degrees, or an empty cell when it is not finite.
void appendDeg(std::string& out, double rad, std::size_t& empty) {
  const double deg = rad * kRadToDeg;
  if (std::isfinite(deg))
    appendFixed(out, deg, kAngleDecimals);
  else
    ++empty;
}

void appendMetricsRows(std::string& out, const char* scope, const std::string& repetition,
                       double startS, double endS, const std::string& partial,
                       const IntervalMetrics& m) {
  const auto& info = clinicalAngleInfo();
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    const AngleMetricsDeg d = inDegrees(m.angle[a]);
    out += scope;
    out += ',';
    out += repetition;
    out += ',';
    appendFixed(out, startS, kTimeDecimals);
    out += ',';
    appendFixed(out, endS, kTimeDecimals);
    out += ',';
    out += partial;
    out += ',';
    out += info[a].key;
    for (double v : {d.minDeg, d.maxDeg, d.romDeg, d.peakVelocityDegPerS, d.meanVelocityDegPerS,
                     d.movementTimeS}) {
      out += ',';
      appendFixed(out, v, 4);
    }
    out += '\n';
  }
}

}  // namespace

fs::path metricsCsvPath(const fs::path& anglesCsv) {
  fs::path p = anglesCsv;
  p.replace_filename(anglesCsv.stem().string() + "_metrics.csv");
  return p;
}

CsvExportResult writeClinicalCsv(const fs::path& anglesCsv, const AngleSeries& series,
                                 const SessionMetrics& metrics,
                                 const std::vector<ClinicalRow>* sdRad, const TrunkColumns* trunk) {
  if (series.angle.size() != series.t.size())
    throw std::invalid_argument("clinical CSV: " + std::to_string(series.t.size()) + " times but " +
                                std::to_string(series.angle.size()) + " angle rows");
  if (sdRad && sdRad->size() != series.t.size())
    throw std::invalid_argument("clinical CSV: " + std::to_string(series.t.size()) + " times but " +
                                std::to_string(sdRad->size()) + " sd rows");
  if (trunk && trunk->angleRad.empty()) trunk = nullptr;
  const bool trunkSd = trunk && !trunk->sdRad.empty();
  if (trunk && (trunk->angleRad.size() != series.t.size() ||
                (trunkSd && trunk->sdRad.size() != series.t.size())))
    throw std::invalid_argument("clinical CSV: " + std::to_string(series.t.size()) + " times but " +
                                std::to_string(trunk->angleRad.size()) + " trunk rows and " +
                                std::to_string(trunk->sdRad.size()) + " trunk sd rows");
  CsvExportResult result;
  result.anglesCsv = anglesCsv;
  result.metricsCsv = metricsCsvPath(anglesCsv);

  double firstT = NAN, lastT = NAN;
  for (double t : series.t) {
    if (!std::isfinite(t)) continue;
    if (std::isnan(firstT)) firstT = t;
    lastT = t;
  }
  if (std::isnan(firstT))
    throw ExportError({}, "clinical CSV: the session has no angle row with a finite time");

  exportdetail::FileSet files;
  const std::size_t angles = files.add(result.anglesCsv);
  const std::size_t table = files.add(result.metricsCsv);

  const auto& info = clinicalAngleInfo();
  std::string& out = files.buffer(angles);
  out += "time_s";
  for (const auto& a : info) out += "," + std::string(a.key) + "_deg";
  if (sdRad)
    for (const auto& a : info) out += "," + std::string(a.key) + "_sd_deg";
  static constexpr const char* kTrunkKeys[] = {"trunk_flex", "trunk_lat", "trunk_rot"};
  if (trunk)
    for (const char* k : kTrunkKeys) out += "," + std::string(k) + "_deg";
  if (trunkSd)
    for (const char* k : kTrunkKeys) out += "," + std::string(k) + "_sd_deg";
  out += '\n';
  for (std::size_t i = 0; i < series.t.size(); ++i) {
    if (!std::isfinite(series.t[i])) {
      ++result.skippedRows;
      continue;
    }
    appendFixed(out, series.t[i], kTimeDecimals);
    for (double v : series.angle[i]) {
      out += ',';
      appendDeg(out, v, result.emptyCells);
    }
    if (sdRad)
      for (double v : (*sdRad)[i]) {
        out += ',';
        appendDeg(out, v, result.emptyCells);
      }
    if (trunk)
      for (int k = 0; k < 3; ++k) {
        out += ',';
        appendDeg(out, trunk->angleRad[i](k), result.emptyCells);
      }
    if (trunkSd)
      for (int k = 0; k < 3; ++k) {
        out += ',';
        appendDeg(out, trunk->sdRad[i](k), result.emptyCells);
      }
    out += '\n';
    ++result.rows;
    files.maybeFlush(angles);
  }

  std::string& m = files.buffer(table);
  m += "scope,repetition,start_s,end_s,partial,angle,min_deg,max_deg,rom_deg,"
       "peak_velocity_deg_s,mean_velocity_deg_s,movement_time_s\n";
  appendMetricsRows(m, "session", "", firstT, lastT, "", metrics.session);
  const auto& reps = metrics.repetitions.repetitions;
  for (std::size_t r = 0; r < reps.size(); ++r)
    appendMetricsRows(m, "repetition", std::to_string(r + 1), reps[r].startS, reps[r].endS,
                      reps[r].partial ? "yes" : "no", reps[r].metrics);
  files.commit();
  return result;
}

}  // namespace armtrack
