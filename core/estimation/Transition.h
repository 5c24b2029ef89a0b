// The filter's state transition (eqs. 3-4) applied through its block structure: the state is
// [th'' th' th] for the five joints (plus Method B's body accelerations), and F is
//   [phi I 0 0; dt I I 0; dt^2/2 I dt I I] (and phiB I for the augmented states),
// so F x and F P F^T are a few scaled additions of 5-row (5-column) blocks, done in place.
// Qt-free; no allocation.
#pragma once

#include <Eigen/Core>

namespace armtrack {

/// Rows of m (N x C, the state's order) <- F m. The angle rows first, then the rates, then the
/// accelerations, so each reads the rows before F touched them.
template <typename Rows>
void transitionRows(Rows&& m, double dt, double phi, double phiB) {
  m.template middleRows<5>(10) +=
      dt * m.template middleRows<5>(5) + 0.5 * dt * dt * m.template middleRows<5>(0);
  m.template middleRows<5>(5) += dt * m.template middleRows<5>(0);
  m.template middleRows<5>(0) *= phi;
  if (m.rows() > 15) m.bottomRows(m.rows() - 15) *= phiB;
}

/// P <- F P F^T in place: F on P's rows, then on the columns of the result (F P F^T =
/// (F (F P)^T)^T, and F on columns is F on the rows of the transpose), without transposing.
template <int N>
void transitionCovariance(Eigen::Matrix<double, N, N>& p, double dt, double phi, double phiB) {
  transitionRows(p, dt, phi, phiB);
  p.template middleCols<5>(10) +=
      dt * p.template middleCols<5>(5) + 0.5 * dt * dt * p.template middleCols<5>(0);
  p.template middleCols<5>(5) += dt * p.template middleCols<5>(0);
  p.template middleCols<5>(0) *= phi;
  if constexpr (N > 15) p.template rightCols<N - 15>() *= phiB;
}

}  // namespace armtrack
