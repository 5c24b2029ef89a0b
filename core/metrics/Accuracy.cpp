#include "core/metrics/Accuracy.h"

#include <algorithm>
#include <cmath>

namespace armtrack {

void ErrorAccumulator::add(const JointVector& estimate, const JointVector& truth) {
  for (int j = 0; j < kNumJoints; ++j) {
    const double e = wrapAngle(estimate(j) - truth(j));
    m_sumSq(j) += e * e;
    m_peak(j) = std::max(m_peak(j), std::abs(e));
  }
  ++m_count;
}

JointVector ErrorAccumulator::rmse() const {
  if (m_count == 0) return JointVector::Zero();
  return (m_sumSq / static_cast<double>(m_count)).cwiseSqrt();
}

}  // namespace armtrack
