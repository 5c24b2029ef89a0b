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
  return angleSample(row.t, row.th, row.thStd);
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
  }
  if (std::isfinite(m_keep) && !m_rows.empty()) {
    const double oldest = m_rows.back().t - m_keep;
    while (m_rows.size() > 1 && m_rows[1].t < oldest) m_rows.pop_front();
  }
  return kept;
}

void AngleTrace::clear() {
  m_rows.clear();
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

}  // namespace armtrack::ui
