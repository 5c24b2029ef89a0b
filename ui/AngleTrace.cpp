#include "ui/AngleTrace.h"

#include <algorithm>
#include <cmath>

#include "core/kinematics/ClinicalAngles.h"
#include "core/session/Session.h"

namespace armtrack::ui {

namespace {
constexpr double kRadToDegree = 180.0 / 3.14159265358979323846;

double clampDeg(double v, double limit) {
  return std::clamp(v, -limit, limit);
}

/// Column of time t in [t0, t1) split into `columns`.
int columnOf(double t, double t0, double t1, int columns) {
  const int c = static_cast<int>((t - t0) / (t1 - t0) * columns);
  return std::clamp(c, 0, columns - 1);
}
}  // namespace

AngleSample angleSample(double t, const JointVector& thRad, const JointVector& thStdRad) {
  AngleSample s;
  s.t = t;
  if (thRad.allFinite()) {
    s.deg = asArray(toClinical(thRad));
  } else {
    // One unknown joint must not hide the others.
    const std::array<double, kAngleCount> sign{1, 1, -1, -1, -1};
    for (int i = 0; i < kAngleCount; ++i)
      s.deg[i] = std::isfinite(thRad(i)) ? sign[i] * wrapAngle(thRad(i)) * kRadToDegree
                                         : std::numeric_limits<double>::quiet_NaN();
  }
  for (int i = 0; i < kAngleCount; ++i) {
    const double sd = std::abs(thStdRad(i)) * kRadToDegree;
    s.sigmaDeg[i] = std::isfinite(sd) ? sd : 0.0;
  }
  return s;
}

AngleSample angleSample(const session::EstimateRow& row) {
  AngleSample s = angleSample(row.t, row.th, row.thStd);
  s.headingFromStartPose = row.headingFromStartPoseOnly;
  s.predicted = row.status == UpdateResult::Predicted;
  if (row.trunk)
    setTrunk(s, *row.trunk, row.trunkStd ? *row.trunkStd : Eigen::Vector3d::Zero().eval());
  return s;
}

void setTrunk(AngleSample& s, const Eigen::Vector3d& trunkRad, const Eigen::Vector3d& sdRad) {
  for (int i = 0; i < kTrunkAngleCount; ++i) {
    const double v = trunkRad(i) * kRadToDegree;
    s.trunkDeg[i] = std::isfinite(v) ? v : kNoAngle;
    const double sd = std::abs(sdRad(i)) * kRadToDegree;
    s.trunkSigmaDeg[i] = std::isfinite(sd) ? sd : 0.0;
  }
}

bool AngleSample::hasTrunk() const {
  return std::any_of(trunkDeg.begin(), trunkDeg.end(), [](double v) { return std::isfinite(v); });
}

std::size_t AngleTrace::append(const std::vector<AngleSample>& rows) {
  std::size_t kept = 0;
  for (const AngleSample& r : rows) {
    if (!std::isfinite(r.t) || (!m_rows.empty() && r.t < m_rows.back().t)) {
      ++m_refused;
      continue;
    }
    m_rows.push_back(r);
    ++kept;
    ++m_appended;
  }
  if (std::isfinite(m_keep) && !m_rows.empty()) {
    const double oldest = m_rows.back().t - m_keep;
    while (m_rows.size() > 1 && m_rows[1].t < oldest) m_rows.pop_front();
  }
  return kept;
}

void AngleTrace::clear() {
  m_rows.clear();
  ++m_clears;
  m_refused = 0;
}

std::size_t AngleTrace::lowerBound(double t) const {
  return static_cast<std::size_t>(
      std::lower_bound(m_rows.begin(), m_rows.end(), t,
                       [](const AngleSample& s, double v) { return s.t < v; }) -
      m_rows.begin());
}

const AngleSample* AngleTrace::at(double t) const {
  if (m_rows.empty() || t < m_rows.front().t) return nullptr;
  std::size_t i = lowerBound(t);
  if (i == m_rows.size() || m_rows[i].t > t) --i;
  return &m_rows[i];
}

void decimateAngle(const AngleTrace& trace, int angle, double t0, double t1, int columns,
                   std::vector<QPointF>& out, double limitDeg) {
  out.clear();
  const auto& rows = trace.samples();
  if (rows.empty() || columns <= 0 || !(t1 > t0)) return;
  std::size_t i = trace.lowerBound(t0);
  // The sample before the window, so the line starts at the left edge.
  for (std::size_t k = i; k-- > 0;) {
    if (std::isfinite(rows[k].deg[angle])) {
      out.emplace_back(rows[k].t, clampDeg(rows[k].deg[angle], limitDeg));
      break;
    }
  }
  int column = -1;
  QPointF lo, hi;
  int count = 0;
  auto flush = [&] {
    if (count == 0) return;
    if (count == 1 || lo == hi) {
      out.push_back(lo);
    } else if (lo.x() <= hi.x()) {
      out.push_back(lo);
      out.push_back(hi);
    } else {
      out.push_back(hi);
      out.push_back(lo);
    }
    count = 0;
  };
  for (; i < rows.size() && rows[i].t <= t1; ++i) {
    const double v = rows[i].deg[angle];
    if (!std::isfinite(v)) continue;
    const int c = columnOf(rows[i].t, t0, t1, columns);
    if (c != column) {
      flush();
      column = c;
    }
    const QPointF p(rows[i].t, clampDeg(v, limitDeg));
    if (count == 0) {
      lo = hi = p;
    } else {
      if (p.y() < lo.y()) lo = p;
      if (p.y() > hi.y()) hi = p;
    }
    ++count;
  }
  flush();
  for (; i < rows.size(); ++i) {
    if (std::isfinite(rows[i].deg[angle])) {
      out.emplace_back(rows[i].t, clampDeg(rows[i].deg[angle], limitDeg));
      break;
    }
  }
}

void decimateBand(const AngleTrace& trace, int angle, double t0, double t1, int columns, double k,
                  std::vector<QPointF>& upper, std::vector<QPointF>& lower, double limitDeg) {
  upper.clear();
  lower.clear();
  const auto& rows = trace.samples();
  if (rows.empty() || columns <= 0 || !(t1 > t0)) return;
  int column = -1;
  double hi = 0, lo = 0, tSum = 0;
  int count = 0;
  auto flush = [&] {
    if (count == 0) return;
    const double t = tSum / count;
    upper.emplace_back(t, clampDeg(hi, limitDeg));
    lower.emplace_back(t, clampDeg(lo, limitDeg));
    count = 0;
    tSum = 0;
  };
  for (std::size_t i = trace.lowerBound(t0); i < rows.size() && rows[i].t <= t1; ++i) {
    const double v = rows[i].deg[angle];
    const double s = rows[i].sigmaDeg[angle];
    if (!std::isfinite(v) || !std::isfinite(s)) continue;
    const int c = columnOf(rows[i].t, t0, t1, columns);
    if (c != column) {
      flush();
      column = c;
    }
    const double up = v + k * s, down = v - k * s;
    if (count == 0) {
      hi = up;
      lo = down;
    } else {
      hi = std::max(hi, up);
      lo = std::min(lo, down);
    }
    tSum += rows[i].t;
    ++count;
  }
  flush();
}

void ColumnDecimator::clear() {
  m_columns.clear();
  m_width = 0;
}

void ColumnDecimator::update(const AngleTrace& trace, int angle, double columnSeconds, double k,
                             double limitDeg) {
  if (!(columnSeconds > 0) || !std::isfinite(columnSeconds)) return clear();
  const auto& rows = trace.samples();
  std::uint64_t fresh = trace.appended() - m_seen;
  if (columnSeconds != m_width || k != m_k || limitDeg != m_limit || angle != m_angle ||
      trace.clears() != m_clears || fresh > rows.size() || trace.appended() < m_seen) {
    m_columns.clear();
    m_width = columnSeconds;
    m_k = k;
    m_limit = limitDeg;
    m_angle = angle;
    m_clears = trace.clears();
    fresh = rows.size();
  }
  for (std::size_t i = rows.size() - static_cast<std::size_t>(fresh); i < rows.size(); ++i)
    fold(rows[i]);
  m_seen = trace.appended();
  if (!rows.empty()) {
    const auto first = static_cast<std::int64_t>(std::floor(rows.front().t / m_width));
    while (!m_columns.empty() && m_columns.front().index < first - 1) m_columns.pop_front();
  }
}

void ColumnDecimator::fold(const AngleSample& s) {
  if (m_angle < 0 || m_angle >= kAngleCount) return;
  const double v = s.deg[static_cast<std::size_t>(m_angle)];
  const double sd = s.sigmaDeg[static_cast<std::size_t>(m_angle)];
  if (!std::isfinite(v)) return;
  const auto index = static_cast<std::int64_t>(std::floor(s.t / m_width));
  if (m_columns.empty() || m_columns.back().index != index) {
    m_columns.push_back({});
    m_columns.back().index = index;
  }
  Column& c = m_columns.back();
  const QPointF p(s.t, clampDeg(v, m_limit));
  if (c.count == 0) {
    c.lo = c.hi = p;
  } else {
    if (p.y() < c.lo.y()) c.lo = p;
    if (p.y() > c.hi.y()) c.hi = p;
  }
  ++c.count;
  if (!std::isfinite(sd)) return;
  const double up = v + m_k * sd, down = v - m_k * sd;
  c.bandHi = c.bandCount == 0 ? up : std::max(c.bandHi, up);
  c.bandLo = c.bandCount == 0 ? down : std::min(c.bandLo, down);
  c.tSum += s.t;
  ++c.bandCount;
}

void ColumnDecimator::points(double t0, double t1, std::vector<QPointF>& line,
                             std::vector<QPointF>& upper, std::vector<QPointF>& lower) const {
  line.clear();
  upper.clear();
  lower.clear();
  if (m_columns.empty() || !(m_width > 0)) return;
  const auto first = static_cast<std::int64_t>(std::floor(t0 / m_width)) - 1;
  const auto last = static_cast<std::int64_t>(std::floor(t1 / m_width));
  for (const Column& c : m_columns) {
    if (c.index < first) continue;
    if (c.index > last) break;
    if (c.count == 1 || c.lo == c.hi) {
      line.push_back(c.lo);
    } else if (c.lo.x() <= c.hi.x()) {
      line.push_back(c.lo);
      line.push_back(c.hi);
    } else {
      line.push_back(c.hi);
      line.push_back(c.lo);
    }
    if (c.bandCount > 0) {
      const double t = c.tSum / c.bandCount;
      upper.emplace_back(t, clampDeg(c.bandHi, m_limit));
      lower.emplace_back(t, clampDeg(c.bandLo, m_limit));
    }
  }
}

}  // namespace armtrack::ui
