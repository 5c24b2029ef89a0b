// Joint-angle error statistics against a known truth.
#pragma once

#include <cstddef>

#include "core/kinematics/ArmModel.h"

namespace armtrack {

/// Accumulates per-joint errors (wrapped to (-pi, pi]); RMSE and peak in rad.
class ErrorAccumulator {
 public:
  void add(const JointVector& estimate, const JointVector& truth);
  std::size_t count() const { return m_count; }
  JointVector rmse() const;                    ///< rad; zero when empty
  JointVector peak() const { return m_peak; }  ///< largest absolute error (rad)

 private:
  JointVector m_sumSq = JointVector::Zero();
  JointVector m_peak = JointVector::Zero();
  std::size_t m_count = 0;
};

}  // namespace armtrack
