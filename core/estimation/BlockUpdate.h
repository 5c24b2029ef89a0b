// One block of a sequential Kalman update, on fixed-size matrices: the arithmetic of ArmFilter's
// EKF update, where R is block-diagonal and the blocks are fused one after another (exactly the
// batch update, at a third of the cost). Qt-free; no allocation.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace armtrack {

/// A direction the update must not move the state along (a Schmidt, or "consider", update along
/// one direction): the gain K becomes Kb = (I - v u^T) K, with u . v = 1.
template <int N>
struct BlindDirection {
  const Eigen::Matrix<double, N, 1>& v;  // the direction in the state
  const Eigen::Matrix<double, N, 1>& u;  // reads the component along v
};

/// Fuses one M-row block whose measurement Jacobian is zero outside columns [col, col + K),
/// given as h (M x K), with diagonal noise variance, into P (p) and the state correction dx,
/// which holds what the blocks before it corrected. innovation is the block's z - h(x) at the
/// linearisation point; nis gets r^T S^-1 r for the innovation r left by the blocks before.
/// Returns false when S = H P H^T + R is not positive definite (p and dx then unchanged).
///
/// Per block: L the Cholesky factor of S, W = H P, V = L^-1 W, dx += W^T S^-1 r, and the
/// symmetric rank-M downdate P -= V^T V. With a blind direction the gain Kb = (I - v u^T) K is
/// used and P follows it exactly: the Joseph form P + Kb S Kb^T - Kb W - W^T Kb^T equals,
/// because K S K^T = K W = V^T V, the optimal update P - V^T V plus |V u|^2 v v^T, a rank-1
/// update; so the blind update costs what the optimal one does.
///
/// Everything N-long is worked on as a column: W^T = P H^T (P is symmetric) is a sum of K of P's
/// columns, V^T = W^T L^-T a few more such sums, and the downdate subtracts M scaled columns of
/// V^T from each column of P, all on contiguous memory; the M x M Cholesky factor and its solves
/// are written out. P stays exactly symmetric: entry (i, c) and (c, i) subtract the same
/// products in the same order.
template <int M, int K, int N>
bool fuseBlock(const Eigen::Matrix<double, M, K>& h, int col,
               const Eigen::Matrix<double, M, 1>& innovation,
               const Eigen::Matrix<double, M, 1>& variance, const BlindDirection<N>* blind,
               Eigen::Matrix<double, N, N>& p, Eigen::Matrix<double, N, 1>& dx, double& nis) {
  using Cols = Eigen::Matrix<double, N, M>;
  using SMat = Eigen::Matrix<double, M, M>;
  using MVec = Eigen::Matrix<double, M, 1>;
  Cols wt;  // W^T = P H^T
  for (int i = 0; i < M; ++i) {
    wt.col(i) = h(i, 0) * p.col(col);
    for (int k = 1; k < K; ++k) wt.col(i) += h(i, k) * p.col(col + k);
  }
  // S = H W^T + R and its Cholesky factor L (lower).
  SMat l = SMat::Zero();
  for (int j = 0; j < M; ++j) {
    for (int i = j; i < M; ++i) {
      double sij = h.row(i).dot(wt.col(j).template segment<K>(col));
      if (i == j) sij += variance(i);
      for (int k = 0; k < j; ++k) sij -= l(i, k) * l(j, k);
      if (i == j) {
        if (!(sij > 0.0)) return false;
        l(j, j) = std::sqrt(sij);
      } else {
        l(i, j) = sij / l(j, j);
      }
    }
  }
  // r, y = L^-1 r and S^-1 r = L^-T y.
  const MVec r = innovation - h * dx.template segment<K>(col);
  MVec sr;
  for (int i = 0; i < M; ++i) {
    double y = r(i);
    for (int k = 0; k < i; ++k) y -= l(i, k) * sr(k);
    sr(i) = y / l(i, i);
  }
  for (int i = M - 1; i >= 0; --i) {
    double y = sr(i);
    for (int k = i + 1; k < M; ++k) y -= l(k, i) * sr(k);
    sr(i) = y / l(i, i);
  }
  nis = r.dot(sr);
  // V^T = W^T L^-T, column by column.
  Cols vt;
  for (int j = 0; j < M; ++j) {
    vt.col(j) = wt.col(j);
    for (int k = 0; k < j; ++k) vt.col(j) -= l(j, k) * vt.col(k);
    vt.col(j) /= l(j, j);
  }
  Eigen::Matrix<double, N, 1> g = wt.col(0) * sr(0);  // K r = W^T S^-1 r
  for (int i = 1; i < M; ++i) g += wt.col(i) * sr(i);
  if (!blind) {
    for (int c = 0; c < N; ++c)
      for (int m = 0; m < M; ++m) p.col(c) -= vt(c, m) * vt.col(m);
    dx += g;
    return true;
  }
  dx += g - blind->v * blind->u.dot(g);
  // P - V^T V + a a^T with a = |V u| v.
  const Eigen::Matrix<double, N, 1> a = (vt.transpose() * blind->u).norm() * blind->v;
  for (int c = 0; c < N; ++c) {
    for (int m = 0; m < M; ++m) p.col(c) -= vt(c, m) * vt.col(m);
    p.col(c) += a(c) * a;
  }
  return true;
}

}  // namespace armtrack
