// ArmFilter's EKF update: the iterated EKF over a sample's blocks, fused one block at a time.
// See ArmFilterImpl.h and docs/estimator.md.
#include "core/estimation/ArmFilterImpl.h"

#include <algorithm>

#include "core/estimation/BlockUpdate.h"

namespace armtrack::detail {

// The Kalman update for a given linearisation, one block at a time. R is block-diagonal, so
// this equals the batch update exactly, at a third of the cost: per block an MxM Cholesky
// factor L of S = H P H^T + R, the gain applied to the innovation left by the blocks before,
// and the symmetric rank-M downdate P -= V^T V with V = L^-1 H P, which keeps P symmetric.
// Returns false when some S is not positive definite.
template <int N>
bool ArmFilter<N>::sequentialUpdate(const Jac& jac, const MeasVec& innov, const BlockList& b,
                                    Mat& p, Vec& dx) {
  dx.setZero();
  m_updateNis = 0.0;
  m_updateDof = 0;
  PaddedCovariance<N> padded(p);  // the blocks work on P padded (BlockUpdate.h)
  for (int i = 0; i < b.count; ++i) {
    const bool ok = b.size[i] == 3 ? blockUpdate<3>(jac, innov, b, i, padded, dx)
                                   : blockUpdate<2>(jac, innov, b, i, padded, dx);
    if (!ok) return false;
  }
  padded.store(p);
  return true;
}

template <int N>
template <int M>
bool ArmFilter<N>::blockUpdate(const Jac& jac, const MeasVec& innov, const BlockList& b, int i,
                               PaddedCovariance<N>& p, Vec& dx) {
  const int row = b.offset[i];
  // Optical rows (positions, marker pixels) read the angles only: their Jacobian is zero left
  // of column 10 and right of 15, and the products skip those columns.
  if (isOptical(b.block[i]))
    return updateBlock<M, kNumJoints>(jac.template block<M, kNumJoints>(row, 10), 10, innov, b, i,
                                      p, dx);
  return updateBlock<M, N>(jac.template middleRows<M>(row), 0, innov, b, i, p, dx);
}

// The update for block i whose Jacobian rows are zero outside columns [col, col + K), given as
// hj (M x K); the arithmetic is fuseBlock's (BlockUpdate.h).
template <int N>
template <int M, int K>
bool ArmFilter<N>::updateBlock(const Eigen::Matrix<double, M, K>& hj, int col, const MeasVec& innov,
                               const BlockList& b, int i, PaddedCovariance<N>& p, Vec& dx) {
  const int row = b.offset[i];
  // Heading-blind IMU update (a Schmidt, or "consider", update along one direction): IMU rows
  // say nothing about the turn of the arm about the vertical, so their gain must not move the
  // state along it. The optimal gain would, through P's correlations, whenever the motion
  // outruns the process model (at the start and end of a fast reach the joint accelerations
  // jump), and every such step stays, because nothing but optics can undo it. The gain has
  // its heading component removed, and P follows that gain exactly.
  const BlindDirection<N> heading{m_headingBlind.v, m_headingBlind.u};
  const bool blind = m_headingBlind.active && !isOptical(b.block[i]);
  double nis = 0.0;
  TrunkSensitivity* sens = m_sensInUpdate ? &m_trunkSens : nullptr;
  Eigen::Matrix<double, M, 6, Eigen::RowMajor> d;
  if (sens && isOptical(b.block[i])) d = m_trunkRows[i].template topRows<M>();
  if (!fuseBlock<M, K, N>(hj, col, innov.template segment<M>(row),
                          b.variance.template segment<M>(row), blind ? &heading : nullptr, p, dx,
                          nis, sens, sens && isOptical(b.block[i]) ? &d : nullptr))
    return false;
  if (watched(b.block[i])) m_updateNis += nis, m_updateDof += M;
  return true;
}

template <int N>
bool ArmFilter<N>::ekfUpdate(const BlockList& b) {
  const int iterations = m_t - m_t0 < m_p.startupSeconds ? std::max(1, m_p.startupIterations) : 1;
  prepareHeadingBlind();
  const Vec x0 = m_x;
  Vec xi = m_x, dx;
  MeasVec h;
  Jac jac;
  // The iterations start from the prior P each time; a single one updates m_P in place (on
  // failure the caller restores m_P).
  Mat p;
  Mat& updated = iterations > 1 ? p : m_P;
  // A single iteration carries the trunk's sensitivity (the iterations would each redo it).
  m_sensInUpdate = iterations == 1 && tracksTrunkSensitivity();
  if (m_sensInUpdate && b.anyOptical()) trunkMeasurementRows(xi, b);
  for (int it = 0; it < iterations; ++it) {
    if (!measure(xi, b, h, &jac)) return false;
    projectHeading(xi, b, jac);
    // Gauss-Newton step of the iterated EKF, from the prior each time; one iteration is the
    // plain EKF.
    // At the first iteration xi = x0 and the Jacobian term is zero.
    const MeasVec innov = it == 0 ? MeasVec(b.z - h) : MeasVec(b.z - h - jac * (x0 - xi));
    if (iterations > 1) p = m_P;
    if (!sequentialUpdate(jac, innov, b, updated, dx)) return false;
    const Vec next = x0 + dx;
    const double change = (next - xi).norm();
    xi = next;
    if (change < 1e-9) break;
  }
  m_x = xi;
  if (iterations > 1) m_P = p;
  return true;
}

// Both state sizes: 15, and 21 with Method B's body-acceleration states.
template bool ArmFilter<kBase>::sequentialUpdate(const Jac& jac, const MeasVec& innov,
                                                 const BlockList& b, Mat& p, Vec& dx);
template bool ArmFilter<kBase>::ekfUpdate(const BlockList& b);
template bool ArmFilter<kBase + 6>::sequentialUpdate(const Jac& jac, const MeasVec& innov,
                                                     const BlockList& b, Mat& p, Vec& dx);
template bool ArmFilter<kBase + 6>::ekfUpdate(const BlockList& b);

}  // namespace armtrack::detail
