// OpenSim motion file export (docs/exports.md, "OpenSim .mot").
#include <cmath>
#include <stdexcept>

#include "core/exports/ExportFiles.h"
#include "core/exports/Exports.h"

namespace armtrack {

namespace fs = std::filesystem;
using exportdetail::appendFixed;

std::vector<std::string> openSimCoordinateNames(Side side) {
  const std::string s = side == Side::Left ? "_l" : "_r";
  return {"arm_flex" + s, "arm_add" + s, "arm_rot" + s, "elbow_flex" + s, "pro_sup" + s};
}

ClinicalRow openSimCoordinatesDeg(const ClinicalRow& c) {
  // Signs: docs/exports.md. The Rajagopal model's left-arm axes are the mirror images of the
  // right arm's, so the same signs hold on both sides.
  return {c[0] * kRadToDeg, -c[1] * kRadToDeg, c[2] * kRadToDeg, c[3] * kRadToDeg,
          c[4] * kRadToDeg};
}

std::vector<std::string> openSimLumbarNames() {
  return {"lumbar_extension", "lumbar_bending", "lumbar_rotation"};
}

Eigen::Vector3d openSimLumbarDeg(const Eigen::Vector3d& t) {
  // The back joint turns the torso about +z (right: its up axis tips backward, extension), then
  // the moved +x (forward: up tips to the right) and +y (up: the right side comes forward), the
  // ISB thorax sequence of the trunk's angles (docs/exports.md).
  return Eigen::Vector3d(-t(0), t(1), t(2)) * kRadToDeg;
}

MotExportResult writeOpenSimMot(const fs::path& motPath, const AngleSeries& series, Side side,
                                const MotOptions& options, const TrunkColumns* trunk) {
  if (series.angle.size() != series.t.size())
    throw std::invalid_argument("OpenSim export: " + std::to_string(series.t.size()) +
                                " times but " + std::to_string(series.angle.size()) +
                                " angle rows");
  if (trunk && !trunk->angleRad.empty() && trunk->angleRad.size() != series.t.size())
    throw std::invalid_argument("OpenSim export: " + std::to_string(trunk->angleRad.size()) +
                                " trunk rows for " + std::to_string(series.t.size()) + " rows");
  // The lumbar coordinates only when some row has the trunk's angles: a session whose trunk was
  // never measured keeps the file the arm's alone.
  const auto finiteTrunk = [&](std::size_t i) { return trunk->angleRad[i].allFinite(); };
  bool withTrunk = false;
  if (trunk)
    for (std::size_t i = 0; i < trunk->angleRad.size() && !withTrunk; ++i)
      withTrunk = finiteTrunk(i);
  if (options.name.empty() || options.name.find_first_of("\r\n") != std::string::npos)
    throw std::invalid_argument("OpenSim export: the name must be one non-empty line");
  if (!std::isfinite(options.proSupOffsetDeg))
    throw std::invalid_argument("OpenSim export: the pro_sup offset must be finite");

  MotExportResult result;
  std::vector<std::size_t> keep;
  keep.reserve(series.t.size());
  double prevT = -INFINITY;
  for (std::size_t i = 0; i < series.t.size(); ++i) {
    bool finite = std::isfinite(series.t[i]);
    for (double v : series.angle[i]) finite = finite && std::isfinite(v);
    if (finite && withTrunk && !finiteTrunk(i)) {
      ++result.skippedTrunkRows;
      finite = false;
    }
    if (!finite) {
      ++result.skippedRows;
      continue;
    }
    if (!(series.t[i] > prevT))
      throw ExportError(motPath, "time does not increase at row " + std::to_string(i + 1) +
                                     " (t = " + std::to_string(series.t[i]) + " s)");
    prevT = series.t[i];
    keep.push_back(i);
  }
  if (keep.empty())
    throw ExportError(motPath, withTrunk ? "no row with a finite time, five finite angles and "
                                           "finite trunk angles to export"
                                         : "no row with a finite time and five finite angles to "
                                           "export");
  result.rows = keep.size();
  result.trunk = withTrunk;

  exportdetail::FileSet files;
  const std::size_t f = files.add(motPath);
  std::string& out = files.buffer(f);
  auto names = openSimCoordinateNames(side);
  if (withTrunk)
    for (std::string& n : openSimLumbarNames()) names.push_back(std::move(n));
  out += options.name + "\n";
  out += "version=1\n";
  out += "nRows=" + std::to_string(keep.size()) + "\n";
  out += "nColumns=" + std::to_string(names.size() + 1) + "\n";
  out += "inDegrees=yes\n";
  out += "endheader\n";
  out += "time";
  for (const auto& n : names) out += "\t" + n;
  out += '\n';
  for (std::size_t i : keep) {
    appendFixed(out, series.t[i], 6);
    ClinicalRow q = openSimCoordinatesDeg(series.angle[i]);
    q[4] += options.proSupOffsetDeg;
    for (double v : q) {
      out += '\t';
      appendFixed(out, v, 6);
    }
    if (withTrunk)
      for (double v : openSimLumbarDeg(trunk->angleRad[i])) {
        out += '\t';
        appendFixed(out, v, 6);
      }
    out += '\n';
    files.maybeFlush(f);
  }
  files.commit();
  return result;
}

}  // namespace armtrack
