// ArmFilter's unscented update (the UKF of Alizadegan & Behzadipour 2016) and its consistency
// watch. See ArmFilterImpl.h.
#include "core/estimation/ArmFilterImpl.h"

#include <Eigen/Cholesky>

namespace armtrack::detail {

template <int N>
bool ArmFilter<N>::ukfUpdate(const BlockList& b, bool& outOfView) {
  // Scaled unscented transform, alpha = 1, beta = 2, kappa = 0: positive weights 1/(2N).
  constexpr int kPoints = 2 * N + 1;
  prepareHeadingBlind();
  // A heading-blind IMU-only update spreads its sigma points without the heading: the state is
  // split as x = d + a v (a = u . x the heading, d the rest, u . d = 0), the readings depend on
  // d alone, and the sigma points follow d's covariance Pi P Pi^T with Pi = I - v u^T. Spread
  // along a straight line in joint space by the tens of degrees an arm without optics has in
  // heading, they would only measure how that line leaves the curved symmetry.
  const bool conditioned = m_headingBlind.active && !b.anyOptical();
  Mat spread = m_P;
  Mat pi = Mat::Identity();
  if (conditioned) {
    pi -= m_headingBlind.v * m_headingBlind.u.transpose();
    spread = pi * m_P * pi.transpose();
    spread.diagonal().array() += 1e-12;
  }
  Eigen::LLT<Mat> llt(static_cast<double>(N) * spread);
  if (llt.info() != Eigen::Success) {
    if (conditioned) return false;
    repairCovariance();
    llt.compute(static_cast<double>(N) * m_P);
    if (llt.info() != Eigen::Success) return false;
  }
  const Mat l = llt.matrixL();
  const int m = b.rows();
  Eigen::Matrix<double, Eigen::Dynamic, kPoints, 0, kMaxRows, kPoints> z(m, kPoints);
  MeasVec h;
  outOfView = false;
  auto sigma = [&](const Vec& x, int col) {
    if (!measure(x, b, h, nullptr)) return false;
    z.col(col) = h;
    return true;
  };
  bool seen = sigma(m_x, 0);
  for (int i = 0; i < N && seen; ++i)
    seen = sigma(m_x + l.col(i), 1 + i) && sigma(m_x - l.col(i), 1 + N + i);
  if (!seen) {
    outOfView = true;
    return false;
  }
  const double w = 1.0 / (2.0 * N);
  const double w0c = 2.0;
  const MeasVec zMean = z.rightCols(2 * N).rowwise().sum() * w;
  MeasMat pzz = w0c * (z.col(0) - zMean) * (z.col(0) - zMean).transpose();
  Gain pxz = Gain::Zero(N, m);
  for (int i = 0; i < N; ++i) {
    const MeasVec dp = z.col(1 + i) - zMean;
    const MeasVec dm = z.col(1 + N + i) - zMean;
    pzz += w * (dp * dp.transpose() + dm * dm.transpose());
    pxz += w * l.col(i) * (dp - dm).transpose();
  }
  // The unscented transform's equivalent linearisation H = Pxz^T P^-1 gets the same heading
  // projection as the EKF's Jacobian; the rest of Pzz (nonlinearity) is kept. (Sigma points
  // conditioned on the heading already see none of it.)
  if (!conditioned) {
    const Eigen::LLT<Mat> pl(m_P);
    if (pl.info() != Eigen::Success) return false;
    Jac hs = pl.solve(pxz).transpose();
    const MeasMat linearPart = hs * m_P * hs.transpose();
    if (projectHeading(m_x, b, hs)) {
      pzz += hs * m_P * hs.transpose() - linearPart;
      pxz = m_P * hs.transpose();
    }
  }
  pzz.diagonal() += b.variance;
  const Eigen::LLT<MeasMat> sl(pzz);
  if (sl.info() != Eigen::Success) return false;
  watchInnovation(b, b.z - zMean, pzz);
  if (conditioned) {
    // pxz is d's cross-covariance; the whole state's follows from the linearisation it implies,
    // H^T = cov(d)^-1 pxz on d, that is P Pi^T H^T. The gain is then d's: the heading stays.
    const Eigen::LLT<Mat> dl(spread);
    if (dl.info() != Eigen::Success) return false;
    const Gain full = m_P * pi.transpose() * dl.solve(pxz);
    const Gain k = sl.solve(pxz.transpose()).transpose();
    m_x += k * (b.z - zMean);
    m_P += k * pzz * k.transpose() - k * full.transpose() - full * k.transpose();
    symmetrise(m_P);
    return true;
  }
  Gain k = sl.solve(pxz.transpose()).transpose();
  if (m_headingBlind.active) {
    // The IMU rows' gain leaves the heading alone (see blockUpdate); P follows the gain used.
    for (int i = 0; i < b.count; ++i) {
      if (isOptical(b.block[i])) continue;
      auto cols = k.middleCols(b.offset[i], b.size[i]);
      cols -= m_headingBlind.v * (m_headingBlind.u.transpose() * cols);
    }
    m_x += k * (b.z - zMean);
    m_P += k * pzz * k.transpose() - k * pxz.transpose() - pxz * k.transpose();
    symmetrise(m_P);
    return true;
  }
  m_x += k * (b.z - zMean);
  m_P -= k * pzz * k.transpose();
  return true;
}

// The UKF's consistency watch: the normalised innovation squared of the watched rows alone, as
// the EKF's block updates count it. With every row, Method C's and B's accelerometers (body
// acceleration left out of their model) read as a lost arm within 0.15 s of any fast motion,
// and the UKF restarted again and again.
template <int N>
void ArmFilter<N>::watchInnovation(const BlockList& b, const MeasVec& nu, const MeasMat& s) {
  std::array<int, kMaxRows> rows{};
  int n = 0;
  for (int i = 0; i < b.count; ++i)
    if (watched(b.block[i]))
      for (int r = 0; r < b.size[i]; ++r) rows[n++] = b.offset[i] + r;
  MeasMat sw(n, n);
  MeasVec nw(n);
  for (int i = 0; i < n; ++i) {
    nw(i) = nu(rows[i]);
    for (int j = 0; j < n; ++j) sw(i, j) = s(rows[i], rows[j]);
  }
  const Eigen::LLT<MeasMat> llt(sw);
  m_updateNis = n > 0 && llt.info() == Eigen::Success ? nw.dot(llt.solve(nw)) : 0.0;
  m_updateDof = llt.info() == Eigen::Success ? n : 0;
}

// Both state sizes: 15, and 21 with Method B's body-acceleration states.
template bool ArmFilter<kBase>::ukfUpdate(const BlockList& b, bool& outOfView);
template void ArmFilter<kBase>::watchInnovation(const BlockList& b, const MeasVec& nu,
                                                const MeasMat& s);
template bool ArmFilter<kBase + 6>::ukfUpdate(const BlockList& b, bool& outOfView);
template void ArmFilter<kBase + 6>::watchInnovation(const BlockList& b, const MeasVec& nu,
                                                    const MeasMat& s);

}  // namespace armtrack::detail
