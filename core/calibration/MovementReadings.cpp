// Each IMU's readings on a uniform grid and the rest in them (core/calibration/MovementReadings.h).
#include "core/calibration/MovementReadings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace armtrack::movecal {

/// The readings at a channel's range: the largest |component| reached in at least 3 separate runs
/// or held for 8 rows in a row. Marks them.
std::vector<char> saturatedRows(const std::vector<Vec3>& v) {
  std::vector<char> out(v.size(), 0);
  for (int axis = 0; axis < 3; ++axis) {
    double top = 0.0;
    for (const Vec3& x : v) top = std::max(top, std::abs(x(axis)));
    if (!(top > 0.0)) continue;
    int runs = 0, longest = 0, run = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const bool at = std::abs(v[i](axis)) >= top * (1.0 - 1e-12);
      if (at) {
        if (run == 0) ++runs;
        ++run;
        longest = std::max(longest, run);
      } else {
        run = 0;
      }
    }
    if (runs < 3 && longest < 8) continue;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (std::abs(v[i](axis)) >= top * (1.0 - 1e-12)) out[i] = 1;
  }
  return out;
}

ImuChannels channels(const std::vector<ArmSample>& samples, bool forearm) {
  ImuChannels c;
  std::vector<double> t;
  std::vector<Vec3> g, a;
  for (const ArmSample& s : samples) {
    const std::optional<ImuReading>& r = forearm ? s.forearm : s.upperArm;
    if (!r) continue;
    ++c.rows;
    if (!r->gyr.allFinite() || !r->acc.allFinite() || !std::isfinite(s.t)) {
      ++c.nonFinite;
      continue;
    }
    t.push_back(s.t);
    g.push_back(r->gyr);
    a.push_back(r->acc);
  }
  const std::vector<char> satG = saturatedRows(g), satA = saturatedRows(a);
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (satG[i] || satA[i]) {
      ++c.saturated;
      continue;
    }
    if (c.gyr.v.empty() || g[i] != c.gyr.v.back()) {
      c.gyr.t.push_back(t[i]);
      c.gyr.v.push_back(g[i]);
    }
    if (c.acc.v.empty() || a[i] != c.acc.v.back()) {
      c.acc.t.push_back(t[i]);
      c.acc.v.push_back(a[i]);
    }
  }
  return c;
}

/// The channel at time t: a triangular-weighted mean of the readings within kHalfWidth, or the
/// linear interpolation of the nearest two when none is that close.
Vec3 smoothAt(const Channel& c, double t) {
  const auto lo = std::lower_bound(c.t.begin(), c.t.end(), t - kHalfWidth);
  Vec3 sum = Vec3::Zero();
  double wsum = 0.0;
  for (auto it = lo; it != c.t.end() && *it <= t + kHalfWidth; ++it) {
    const double w = 1.0 - std::abs(*it - t) / kHalfWidth;
    if (w <= 0.0) continue;
    sum += w * c.v[static_cast<std::size_t>(it - c.t.begin())];
    wsum += w;
  }
  if (wsum > 0.0) return sum / wsum;
  const auto hi = std::lower_bound(c.t.begin(), c.t.end(), t);
  if (hi == c.t.begin()) return c.v.front();
  if (hi == c.t.end()) return c.v.back();
  const std::size_t j = static_cast<std::size_t>(hi - c.t.begin());
  const double u = (t - c.t[j - 1]) / (c.t[j] - c.t[j - 1]);
  return (1.0 - u) * c.v[j - 1] + u * c.v[j];
}

Grid makeGrid(const ImuChannels& u, const ImuChannels& f) {
  Grid g;
  const double t0 = std::max({u.gyr.t.front(), u.acc.t.front(), f.gyr.t.front(), f.acc.t.front()});
  const double t1 = std::min({u.gyr.t.back(), u.acc.t.back(), f.gyr.t.back(), f.acc.t.back()});
  for (double t = t0; t <= t1; t += kGridDt) {
    g.t.push_back(t);
    g.w1.push_back(smoothAt(u.gyr, t));
    g.a1.push_back(smoothAt(u.acc, t));
    g.w2.push_back(smoothAt(f.gyr, t));
    g.a2.push_back(smoothAt(f.acc, t));
  }
  return g;
}

void differentiate(Grid& g) {
  const std::size_t n = g.t.size();
  g.wd1.assign(n, Vec3::Zero());
  g.wd2.assign(n, Vec3::Zero());
  for (std::size_t i = 1; i + 1 < n; ++i) {
    g.wd1[i] = (g.w1[i + 1] - g.w1[i - 1]) / (2.0 * kGridDt);
    g.wd2[i] = (g.w2[i + 1] - g.w2[i - 1]) / (2.0 * kGridDt);
  }
}

/// The longest stretch in which every 0.5 s window is still for both IMUs.
std::vector<Rest> findRests(const Grid& g, const MovementCalibrationParams& p, double gravity) {
  const std::size_t n = g.t.size();
  const std::size_t w = static_cast<std::size_t>(std::ceil(p.minRestSeconds / kGridDt));
  if (n < w + 1) return {};
  const auto still = [&](std::size_t i) {
    for (const auto* pair : {&g.w1, &g.w2}) {
      const std::vector<Vec3>& v = *pair;
      Vec3 mean = Vec3::Zero();
      for (std::size_t k = i; k < i + w; ++k) mean += v[k];
      mean /= static_cast<double>(w);
      if (mean.norm() > p.restGyroMean) return false;
      for (std::size_t k = i; k < i + w; ++k)
        if ((v[k] - mean).norm() > p.restGyroSpread) return false;
    }
    for (const auto* pair : {&g.a1, &g.a2}) {
      const std::vector<Vec3>& v = *pair;
      Vec3 mean = Vec3::Zero();
      for (std::size_t k = i; k < i + w; ++k) mean += v[k];
      mean /= static_cast<double>(w);
      if (std::abs(mean.norm() / gravity - 1.0) > p.restAccelTolerance) return false;
      for (std::size_t k = i; k < i + w; ++k)
        if ((v[k] - mean).norm() > p.restAccelSpread) return false;
    }
    return true;
  };
  std::vector<Rest> rests;
  bool inRun = false;
  for (std::size_t i = 0; i + w <= n; ++i) {
    const bool s = still(i);
    if (s && !inRun) rests.push_back({i, i + w});
    if (s) rests.back().to = i + w;
    inRun = s;
  }
  return rests;
}

std::optional<Rest> findRest(const Grid& g, const MovementCalibrationParams& p, double gravity) {
  std::optional<Rest> best;
  for (const Rest& r : findRests(g, p, gravity))
    if (!best || r.to - r.from > best->to - best->from) best = r;
  return best;
}

Vec3 meanOf(const std::vector<Vec3>& v, const Rest& r) {
  Vec3 m = Vec3::Zero();
  for (std::size_t k = r.from; k < r.to; ++k) m += v[k];
  return m / static_cast<double>(r.to - r.from);
}

std::string fixed1(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

}  // namespace armtrack::movecal
