// One block of a sequential Kalman update, on fixed-size matrices: the arithmetic of ArmFilter's
// EKF update, where R is block-diagonal and the blocks are fused one after another (exactly the
// batch update, at a third of the cost). Qt-free; no allocation.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

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
template <int M, int K, int N>
bool fuseBlock(const Eigen::Matrix<double, M, K>& h, int col,
               const Eigen::Matrix<double, M, 1>& innovation,
               const Eigen::Matrix<double, M, 1>& variance, const BlindDirection<N>* blind,
               Eigen::Matrix<double, N, N>& p, Eigen::Matrix<double, N, 1>& dx, double& nis) {
  using SMat = Eigen::Matrix<double, M, M>;
  // Thin products: coefficient-based evaluation beats Eigen's blocked kernels at these sizes.
  const Eigen::Matrix<double, M, N> w = h.lazyProduct(p.template middleRows<K>(col));  // H P
  SMat s = w.template middleCols<K>(col).lazyProduct(h.transpose());
  s.diagonal() += variance;
  const Eigen::LLT<SMat> llt(s);
  if (llt.info() != Eigen::Success) return false;
  const Eigen::Matrix<double, M, 1> r = innovation - h.lazyProduct(dx.template segment<K>(col));
  const Eigen::Matrix<double, M, 1> sr = llt.solve(r);
  nis = r.dot(sr);
  const Eigen::Matrix<double, M, N> v = llt.matrixL().solve(w);
  // P -= V^T V, the lower triangle computed and mirrored: half the work, exactly symmetric.
  for (int c = 0; c < N; ++c)
    for (int i = c; i < N; ++i) p(i, c) = p(c, i) = p(i, c) - v.col(i).dot(v.col(c));
  if (blind) {
    const Eigen::Matrix<double, N, 1> g = w.transpose() * sr;  // K r
    dx.noalias() += g - blind->v * blind->u.dot(g);
    const Eigen::Matrix<double, N, 1> a = (v * blind->u).norm() * blind->v;
    p.noalias() += a * a.transpose();
    return true;
  }
  dx.noalias() += w.transpose() * sr;
  return true;
}

}  // namespace armtrack
