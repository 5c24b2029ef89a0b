#include "core/estimation/TrunkMotionDetector.h"

#include <algorithm>
#include <cmath>

namespace armtrack {

const char* trunkCueName(TrunkCue cue) {
  switch (cue) {
    case TrunkCue::None:
      return "none";
    case TrunkCue::Shoulder:
      return "optical shoulder";
    case TrunkCue::Arm:
      return "optical elbow and wrist";
  }
  return "unknown";
}

// --- Level: a gated running mean relative to the mean of the first referenceSeconds -------------

template <int N>
void TrunkMotionDetector::Level<N>::reset() {
  m_window.clear();
  m_pending.clear();
  m_refSum.setZero();
  m_refCount = 0;
  m_refStartT.reset();
  m_refDone = false;
  m_lastT = 0;
  m_any = false;
  m_outliers = 0;
}

template <int N>
void TrunkMotionDetector::Level<N>::accept(const Entry& e) {
  m_window.push_back(e);
  while (static_cast<int>(m_window.size()) > std::max(1, m_p.windowSamples)) m_window.pop_front();
  m_lastT = e.t;
  m_any = true;
  if (m_refDone) return;
  if (!m_refStartT) m_refStartT = e.t;
  if (e.t - *m_refStartT <= m_p.referenceSeconds || m_refCount < m_p.minSamples) {
    m_refSum += e.x;
    ++m_refCount;
  } else {
    m_refDone = true;
  }
}

// The pending samples (outliers, or the first ones after a start or a gap) replace the average
// when at least `needed` of them lie within the gate of their component-wise median.
template <int N>
bool TrunkMotionDetector::Level<N>::relockFrom(int needed) {
  if (static_cast<int>(m_pending.size()) < needed) return false;
  Vec median;
  std::vector<double> c(m_pending.size());
  for (int k = 0; k < N; ++k) {
    for (std::size_t i = 0; i < m_pending.size(); ++i) c[i] = m_pending[i].x(k);
    std::nth_element(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(c.size() / 2), c.end());
    median(k) = c[c.size() / 2];
  }
  int consistent = 0;
  for (const Entry& e : m_pending) consistent += (e.x - median).norm() <= m_gate ? 1 : 0;
  if (consistent < needed) return false;
  m_window.clear();
  for (const Entry& e : m_pending) {
    if ((e.x - median).norm() <= m_gate) {
      if (e.counted) --m_outliers;
      accept(e);
    } else if (!e.counted) {
      ++m_outliers;
    }
  }
  m_pending.clear();
  return true;
}

template <int N>
bool TrunkMotionDetector::Level<N>::add(double t, const Vec& x) {
  if (m_any && t - m_lastT > m_p.maxGapSeconds) m_window.clear();
  while (!m_window.empty() && t - m_window.front().t > m_p.windowSeconds) m_window.pop_front();
  // Pending samples too old to be part of a relock are dropped for good.
  while (!m_pending.empty() && t - m_pending.front().t > m_p.maxGapSeconds) {
    if (!m_pending.front().counted) ++m_outliers;
    m_pending.pop_front();
  }
  if (m_window.empty()) {
    // Start, or after a gap: wait until three samples agree, so one wild first frame cannot
    // become the average.
    m_pending.push_back({t, x, false});
    if (m_pending.size() > 8) {
      if (!m_pending.front().counted) ++m_outliers;
      m_pending.pop_front();
    }
    relockFrom(3);
    return true;
  }
  Vec mean = Vec::Zero();
  for (const Entry& e : m_window) mean += e.x;
  mean /= static_cast<double>(m_window.size());
  if ((x - mean).norm() > m_gate) {
    ++m_outliers;
    m_pending.push_back({t, x, true});
    relockFrom(std::max(1, m_p.relockSamples));
    return false;
  }
  m_pending.clear();  // a good sample ends a run of outliers
  accept({t, x, false});
  return true;
}

template <int N>
bool TrunkMotionDetector::Level<N>::valid(double t) const {
  return m_refDone && m_refCount > 0 && static_cast<int>(m_window.size()) >= m_p.minSamples &&
         t - m_lastT <= m_p.holdSeconds;
}

template <int N>
typename TrunkMotionDetector::Level<N>::Vec TrunkMotionDetector::Level<N>::displacement() const {
  Vec mean = Vec::Zero();
  for (const Entry& e : m_window) mean += e.x;
  if (!m_window.empty()) mean /= static_cast<double>(m_window.size());
  return mean - m_refSum / std::max(1, m_refCount);
}

template class TrunkMotionDetector::Level<3>;
template class TrunkMotionDetector::Level<6>;

// --- the detector
// ---------------------------------------------------------------------------------

TrunkMotionDetector::TrunkMotionDetector(const TrunkMotionParams& params)
    : m_params(params), m_shoulder(params, params.gateM), m_arm(params, params.armGateM) {}

void TrunkMotionDetector::reset() {
  m_shoulder.reset();
  m_arm.reset();
  m_counters = {};
  m_spans.clear();
  m_last = {};
  m_lastT.reset();
  m_open = false;
}

TrunkMotionStatus TrunkMotionDetector::update(const TrunkMotionInput& in) {
  if (!std::isfinite(in.t) || (m_lastT && in.t < *m_lastT)) {
    ++m_counters.refusedTime;
    return m_last;
  }
  m_lastT = in.t;
  const auto usable = [&](const std::optional<Eigen::Vector3d>& p) {
    return p && p->allFinite() && p->norm() <= m_params.maxAbsM;
  };
  if (in.shoulder) {
    if (usable(in.shoulder)) {
      m_shoulder.add(in.t, *in.shoulder);
      m_counters.outlierShoulder = m_shoulder.outliers();
    } else {
      ++m_counters.refusedShoulder;
    }
  }
  if (in.elbow && in.wrist && in.predictedElbow && in.predictedWrist) {
    if (usable(in.elbow) && usable(in.wrist) && usable(in.predictedElbow) &&
        usable(in.predictedWrist)) {
      const Eigen::Vector3d re = *in.elbow - *in.predictedElbow;
      const Eigen::Vector3d rw = *in.wrist - *in.predictedWrist;
      Eigen::Matrix<double, 6, 1> x;
      x << 0.5 * (re + rw), rw - re;
      m_arm.add(in.t, x);
      m_counters.outlierArm = m_arm.outliers();
    } else {
      ++m_counters.refusedArm;
    }
  }
  TrunkMotionStatus s;
  decide(in.t, s);
  m_last = s;
  return s;
}

void TrunkMotionDetector::decide(double t, TrunkMotionStatus& s) {
  const bool was = m_last.moving;
  if (m_shoulder.valid(t)) {
    s.cue = TrunkCue::Shoulder;
    s.displacementM = m_shoulder.displacement().norm();
    s.moving = s.displacementM >= (was ? m_params.exitM : m_params.enterM);
  } else if (m_arm.valid(t)) {
    const Eigen::Matrix<double, 6, 1> v = m_arm.displacement();
    const double common = v.head<3>().norm();
    const double spread = v.tail<3>().norm();
    s.cue = TrunkCue::Arm;
    s.displacementM = common;
    const bool consistent = spread <= m_params.armConsistency * common + m_params.armToleranceM;
    s.moving = consistent && common >= (was ? m_params.armExitM : m_params.armEnterM);
  }
  if (s.moving) {
    if (!m_open) {
      m_spans.push_back({t, t, s.displacementM, s.cue, true});
      m_open = true;
    }
    TrunkMotionSpan& span = m_spans.back();
    span.endS = t;
    span.maxDisplacementM = std::max(span.maxDisplacementM, s.displacementM);
  } else if (m_open) {
    m_spans.back().open = false;
    m_open = false;
  }
}

std::vector<TrunkMotionSpan> TrunkMotionDetector::spans() const {
  return m_spans;
}

}  // namespace armtrack
