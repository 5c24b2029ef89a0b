#include "core/sync/TimeSync.h"

#include <cmath>

namespace armtrack {

double TimestampUnwrapper::unwrap(double raw) {
  if (!(period > 0.0)) return raw;
  if (!started) {
    started = true;
    last = raw;
    return raw + offset;
  }
  const double step = raw - last;
  if (step < -0.5 * period) {
    offset += period;
    ++wraps;
    last = raw;
  } else if (step > 0.5 * period) {
    return raw + offset - period;  // straggler from before the last wrap
  } else {
    last = raw;
  }
  return raw + offset;
}

DeviceClock::DeviceClock(const ClockParams& params) : m_p(params) {
  if (!(params.binSeconds > 0.0) || !(params.windowSeconds >= params.binSeconds) ||
      !(params.envelopeGate > 0.0) || !(params.jumpThreshold > 0.0) || !(params.maxDelay > 0.0) ||
      !(params.backwardTolerance >= 0.0) || params.jumpConfirmSamples < 1 ||
      !(params.stallConfirmSeconds >= 0.0) || !(params.delaySteadiness > 0.0) ||
      !(params.maxDrift >= 0.0) || !(params.wrapPeriod >= 0.0) ||
      !(params.statsAlpha > 0.0 && params.statsAlpha <= 1.0))
    throw std::invalid_argument("DeviceClock: invalid parameters");
  m_maxBins = static_cast<std::size_t>(std::ceil(params.windowSeconds / params.binSeconds));
  m_hull.reserve(m_maxBins + 1);
  reset();
}

void DeviceClock::reset() {
  m_s = ClockState{};
  m_s.bins.reserve(m_maxBins + 1);
  m_s.b = m_p.initialDrift;
  m_s.unwrapper.period = m_p.wrapPeriod;
}

double DeviceClock::jitter() const {
  return std::sqrt(std::max(0.0, m_s.delaySq - m_s.delayMean * m_s.delayMean));
}

void DeviceClock::lock(double t, double y, double drift) {
  m_s.locked = true;
  m_s.bins.clear();
  m_s.b = drift;
  m_s.tc = t;
  m_s.a = y;
  m_s.origin = t;
  m_s.open = ClockBin{0, t, y};
  m_s.lastT = t;
  m_s.candidate = false;
  m_s.delayedRun = false;
}

ClockUpdate DeviceClock::update(double deviceTime, double arrivalTime) {
  ClockUpdate u;
  if (!std::isfinite(deviceTime) || !std::isfinite(arrivalTime)) {
    ++m_s.counters.rejectedNonFinite;
    return u;
  }
  const double t = m_s.unwrapper.unwrap(deviceTime);
  const double y = arrivalTime - t;
  u.deviceTime = t;

  if (!m_s.locked) {
    lock(t, y, m_p.initialDrift);
    accept(t, y);
    u.hostTime = toHost(t);
    u.status = ClockStatus::Locked;
    return u;
  }

  const double r = y - line(t);
  if (t >= m_s.lastT - m_p.backwardTolerance && r >= -m_p.jumpThreshold) {
    if (m_s.candidate) {
      ++m_s.counters.glitches;
      m_s.candidate = false;
    }
    u.status = ClockStatus::Locked;
    if (r > m_p.maxDelay) {
      ++m_s.counters.delayed;
      if (m_s.delayedRun) {
        m_s.delayedMin = std::min(m_s.delayedMin, r);
        m_s.delayedMax = std::max(m_s.delayedMax, r);
        if (m_s.delayedMax - m_s.delayedMin > m_p.delaySteadiness) {
          // The delay grows or drains: a backlog, not a clock that fell back. Start again here.
          ++m_s.counters.unsteady;
          m_s.delayedRun = false;
        }
      }
      if (!m_s.delayedRun) {
        m_s.delayedRun = true;
        m_s.delayedSince = arrivalTime;
        m_s.delayedMin = m_s.delayedMax = r;
      } else if (arrivalTime - m_s.delayedSince >= m_p.stallConfirmSeconds) {
        // Not a burst after a stall: the clock fell back. Re-lock, keeping the drift.
        ++m_s.counters.jumps;
        lock(t, y, m_s.b);
        u.relocked = true;
      }
    } else {
      m_s.delayedRun = false;
    }
    accept(t, y);
    u.hostTime = toHost(t);
    return u;
  }

  // A clock-jump candidate: does it agree with the previous candidates?
  const double b = m_s.b;
  bool agrees = false;
  if (m_s.candidate && t >= m_s.candLastT - m_p.backwardTolerance) {
    const double rc = y - (m_s.candA + b * (t - m_s.candT0));
    agrees = rc >= -m_p.jumpThreshold && rc <= m_p.maxDelay;
  }
  if (agrees) {
    ++m_s.candCount;
    m_s.candA = std::min(m_s.candA, y - b * (t - m_s.candT0));
    m_s.candLastT = std::max(m_s.candLastT, t);
  } else {
    m_s.candidate = true;
    m_s.candT0 = t;
    m_s.candA = y;
    m_s.candLastT = t;
    m_s.candCount = 1;
  }
  u.hostTime = t + m_s.candA + b * (t - m_s.candT0);
  if (m_s.candCount >= m_p.jumpConfirmSamples) {
    ++m_s.counters.jumps;
    const double a0 = m_s.candA, t0 = m_s.candT0;
    lock(t0, a0, b);  // the drift belongs to the crystal: keep it
    m_s.lastT = t;
    m_s.open = ClockBin{0, t0, a0};
    accept(t, y);
    u.hostTime = toHost(t);
    u.status = ClockStatus::Locked;
    u.relocked = true;
  } else {
    ++m_s.counters.provisional;
    u.status = ClockStatus::Provisional;
  }
  return u;
}

void DeviceClock::accept(double t, double y) {
  ClockState& s = m_s;
  ++s.counters.accepted;
  const double dt = t - s.lastT;
  if (dt < 0.0) {
    ++s.counters.backwards;
  } else if (dt > m_p.gapSeconds) {
    ++s.counters.gaps;
  } else if (dt > 0.0) {
    s.dtMean = s.dtMean > 0.0 ? s.dtMean + m_p.statsAlpha * (dt - s.dtMean) : dt;
  }
  s.lastT = std::max(s.lastT, t);

  const auto index = static_cast<std::int64_t>(std::floor((t - s.origin) / m_p.binSeconds));
  if (index > s.open.index) {
    s.bins.push_back(s.open);
    const std::int64_t oldest = index - static_cast<std::int64_t>(m_maxBins);
    std::size_t drop = 0;
    while (drop < s.bins.size() && s.bins[drop].index < oldest) ++drop;
    if (drop > 0) s.bins.erase(s.bins.begin(), s.bins.begin() + static_cast<std::ptrdiff_t>(drop));
    refit();
    s.open = ClockBin{index, t, y};
  } else if (y < s.open.y) {
    s.open.t = t;
    s.open.y = y;
  }

  // The envelope never lies above a sample.
  double r = y - line(t);
  if (r < 0.0) {
    s.a += r;
    r = 0.0;
  }
  const double w = s.counters.accepted == 1 ? 1.0 : m_p.statsAlpha;
  s.delayMean += w * (r - s.delayMean);
  s.delaySq += w * (r * r - s.delaySq);
}

void DeviceClock::refit() {
  ClockState& s = m_s;
  ++s.counters.refits;
  const auto& p = s.bins;
  const std::size_t n = p.size();
  if (n == 0) return;
  double b = s.b;
  double tc = p.back().t;
  const double span = p.back().t - p.front().t;
  if (n >= 2 && span >= m_p.minDriftSpan) {
    // Lower convex hull of the bin minima (t increasing; relative to the first point).
    const double t0 = p.front().t, y0 = p.front().y;
    auto cross = [&](std::size_t o, std::size_t a, std::size_t c) {
      return (p[a].t - p[o].t) * (p[c].y - p[o].y) - (p[a].y - p[o].y) * (p[c].t - p[o].t);
    };
    m_hull.clear();
    double tMean = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      tMean += p[i].t - t0;
      while (m_hull.size() >= 2 && cross(m_hull[m_hull.size() - 2], m_hull.back(), i) <= 0.0)
        m_hull.pop_back();
      m_hull.push_back(i);
    }
    tMean = t0 + tMean / static_cast<double>(n);
    // The hull edge above the mean time is the line under all points with the least total delay.
    std::size_t k = 0;
    while (k + 2 < m_hull.size() && p[m_hull[k + 1]].t < tMean) ++k;
    const ClockBin& e0 = p[m_hull[k]];
    const ClockBin& e1 = p[m_hull[std::min(k + 1, m_hull.size() - 1)]];
    const double hullB = e1.t > e0.t ? (e1.y - e0.y) / (e1.t - e0.t) : s.b;
    // Least squares over the minima near the hull: same line, less sensitive to single points.
    double sw = 0, st = 0, sy = 0, stt = 0, sty = 0, tMin = 0, tMax = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double ti = p[i].t - t0, yi = p[i].y - y0;
      if (p[i].y - (e0.y + hullB * (p[i].t - e0.t)) > m_p.envelopeGate) continue;
      if (sw == 0.0) tMin = ti;
      tMax = ti;
      sw += 1.0;
      st += ti;
      sy += yi;
      stt += ti * ti;
      sty += ti * yi;
    }
    const double den = sw * stt - st * st;
    b = hullB;
    if (sw >= 3.0 && tMax - tMin >= 0.5 * m_p.minDriftSpan && den > 0.0)
      b = (sw * sty - st * sy) / den;
    b = std::clamp(b, -m_p.maxDrift, m_p.maxDrift);
    tc = tMean;
    s.driftFitted = true;
  }
  // Lower the line onto the lowest point.
  double a = std::numeric_limits<double>::infinity();
  for (const ClockBin& q : p) a = std::min(a, q.y - b * (q.t - tc));
  s.a = a;
  s.b = b;
  s.tc = tc;
}

}  // namespace armtrack
