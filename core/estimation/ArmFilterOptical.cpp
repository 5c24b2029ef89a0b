// ArmFilter's optical rows before an update: the gate that drops mis-detected markers and
// positions, and the heading variance matched to the turn the optics ask for. See
// ArmFilterImpl.h and docs/estimator.md.
#include "core/estimation/ArmFilterImpl.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "core/estimation/MeasurementJacobian.h"

namespace armtrack::detail {

// Innovation gating of the optical measurements at the predicted state: a mis-detected marker
// (in the webcam image, or in the Kinect's colour image before depth is added) lands far from
// where the arm can be. Gated and unseeable measurements are removed from b and counted.
// Start-up is not gated: the first pose may be far off and the optics are what corrects it.
// Returns false when the state could not be linearised.
template <int N>
bool ArmFilter<N>::gateOptical(BlockList& b) {
  const bool anyCamera = m_camera && (b.has(kCamWrist) || b.has(kCamElbow));
  const bool anyPosition = m_p.positionGate > 0.0 && (b.has(kElbow) || b.has(kWrist));
  if (!anyCamera && !anyPosition) return true;
  const bool startup = m_t - m_t0 < m_p.startupSeconds;
  const Eigen::Matrix<double, kModelRows, 1>& all = priorPrediction().readings;
  const Eigen::Matrix<double, kModelRows, kBase>& allJac = priorPrediction().jacobian;
  for (int i = b.count - 1; i >= 0; --i) {
    const int blk = b.block[i];
    if (blk == kElbow || blk == kWrist) {
      if (!anyPosition) continue;
      int& inARow = m_gatedInARow[blk == kWrist ? 2 : 3];
      if (startup || inARow >= m_p.positionGateResetFrames) {
        if (!startup) m_opticalDisagrees = true;
        inARow = 0;
        continue;
      }
      const Eigen::Vector3d r = b.z.template segment<3>(b.offset[i]) - all.segment<3>(3 * blk);
      // Positions read the angles only (columns 10-14 of the Jacobian).
      const Eigen::Matrix<double, 3, kNumJoints> jac = allJac.block<3, kNumJoints>(3 * blk, 10);
      Eigen::Matrix3d sm = jac.lazyProduct(m_P.template block<kNumJoints, kNumJoints>(10, 10))
                               .lazyProduct(jac.transpose());
      sm.diagonal().array() += m_p.positionVariance;
      const Eigen::LLT<Eigen::Matrix3d> llt(sm);
      if (llt.info() != Eigen::Success) return false;
      // Both far in metres and improbable: a small stated variance alone must not turn a
      // model error's systematic innovation into an "outlier".
      if (r.norm() > m_p.positionGateMinDistance && r.dot(llt.solve(r)) > m_p.positionGate) {
        ++m_counters.rejectedOutliers;
        ++m_counters.gatedPositions;
        ++inARow;
        b = b.without(i);
      } else {
        inARow = 0;
      }
      continue;
    }
    if (!isCamera(blk) || !anyCamera) continue;
    Eigen::Vector2d px;
    Eigen::Matrix<double, 2, kBase> jac;
    const int posBlock = blk == kCamWrist ? kWrist : kElbow;
    const Eigen::Matrix<double, 3, kBase> dp = allJac.middleRows<3>(3 * posBlock);
    if (!markerPixel(*m_camera, m_p.side == Side::Left, all.segment<3>(3 * posBlock), &dp, px,
                     &jac)) {
      ++m_counters.cameraNotVisible;
      b = b.without(i);
      continue;
    }
    int& inARow = m_gatedInARow[blk == kCamWrist ? 0 : 1];
    if (startup || inARow >= m_p.pixelGateResetFrames) {
      if (!startup) m_opticalDisagrees = true;
      inARow = 0;
      continue;
    }
    const Eigen::Vector2d r = b.z.template segment<2>(b.offset[i]) - px;
    const Eigen::Matrix<double, 2, kNumJoints> ja = jac.rightCols<kNumJoints>();  // angles only
    Eigen::Matrix2d sm = ja.lazyProduct(m_P.template block<kNumJoints, kNumJoints>(10, 10))
                             .lazyProduct(ja.transpose());
    sm.diagonal().array() += m_p.pixelVariance;
    const Eigen::LLT<Eigen::Matrix2d> llt(sm);
    if (llt.info() != Eigen::Success) return false;
    const double d2 = r.dot(llt.solve(r));
    if (d2 > m_p.pixelGate) {
      ++m_counters.rejectedOutliers;
      ++inARow;
      b = b.without(i);
    } else {
      inARow = 0;
    }
  }
  return true;
}

template <int N>
auto ArmFilter<N>::priorPrediction() -> const Prediction& {
  if (!m_prior) {
    m_prior.emplace();
    m_prior->at = m_x.template head<kBase>();
    predictReadings(m_p.geometry, m_base, m_p.model == MeasurementModel::AccelGyro, m_prior->at,
                    m_prior->readings, &m_prior->jacobian);
  }
  return *m_prior;
}

// Heading matching (covariance matching along the one direction the IMUs cannot see): the
// turn about the vertical that the optical rows ask for at the predicted state, by weighted
// least squares, less what their noise alone would give, averaged over headingMatchTime, is
// the heading variance the filter should have. After a fast movement has turned the estimate
// about the vertical, P's heading variance is far smaller than the error, the optics pull at a
// few percent per frame and the angles stay off for seconds; with the matched variance the
// next frames correct it, and the reported standard deviation says the heading was uncertain.
// Returns false when the optical rows could not be evaluated.
template <int N>
bool ArmFilter<N>::matchOpticalHeading(const BlockList& b, bool positionsOnly) {
  if (!(m_p.headingMatchTime > 0.0)) return true;
  const Vec u = headingAngles(m_x);
  const Vec15 u15 = u.template head<kBase>();
  const Eigen::Matrix<double, kModelRows, 1>& all = priorPrediction().readings;
  const Eigen::Matrix<double, kModelRows, kBase>& allJac = priorPrediction().jacobian;
  double info = 0.0, score = 0.0;
  for (int i = 0; i < b.count; ++i) {
    const int blk = b.block[i];
    if (blk == kElbow || blk == kWrist) {
      const Eigen::Vector3d r = b.z.template segment<3>(b.offset[i]) - all.segment<3>(3 * blk);
      const Eigen::Vector3d jh = allJac.middleRows<3>(3 * blk) * u15;
      info += jh.squaredNorm() / m_p.positionVariance;
      score += jh.dot(r) / m_p.positionVariance;
    } else if (isCamera(blk) && m_camera && !positionsOnly) {
      const int posBlock = blk == kCamWrist ? kWrist : kElbow;
      const Eigen::Matrix<double, 3, kBase> dp = allJac.middleRows<3>(3 * posBlock);
      Eigen::Vector2d px;
      Eigen::Matrix<double, 2, kBase> jac;
      if (!markerPixel(*m_camera, m_p.side == Side::Left, all.segment<3>(3 * posBlock), &dp, px,
                       &jac))
        continue;
      const Eigen::Vector2d r = b.z.template segment<2>(b.offset[i]) - px;
      const Eigen::Vector2d jh = jac * u15;
      info += jh.squaredNorm() / m_p.pixelVariance;
      score += jh.dot(r) / m_p.pixelVariance;
    }
  }
  if (!std::isfinite(info) || !std::isfinite(score)) return false;
  if (!(info > 0.0)) return true;
  const double turn = score / info;  // rad about the vertical
  const double since = std::isfinite(m_lastMatchT) ? m_t - m_lastMatchT : m_p.headingMatchTime;
  m_lastMatchT = m_t;
  const double w = std::clamp(since / m_p.headingMatchTime, 0.0, 1.0);
  m_turnSquared += w * (turn * turn - m_turnSquared);
  m_turnNoise += w * (1.0 / info - m_turnNoise);
  // Only a turn well beyond what the optical noise gives (2 sigma) counts: below that the
  // filter's own heading variance is the better judge, and matching the noise would make the
  // estimate follow it.
  m_headingMatch = std::clamp(m_turnSquared - 4.0 * m_turnNoise, 0.0, kMaxHeadingMatch);
  return true;
}

// Both state sizes: 15, and 21 with Method B's body-acceleration states.
template bool ArmFilter<kBase>::gateOptical(BlockList& b);
template auto ArmFilter<kBase>::priorPrediction() -> const Prediction&;
template bool ArmFilter<kBase>::matchOpticalHeading(const BlockList& b, bool positionsOnly);
template bool ArmFilter<kBase + 6>::gateOptical(BlockList& b);
template auto ArmFilter<kBase + 6>::priorPrediction() -> const Prediction&;
template bool ArmFilter<kBase + 6>::matchOpticalHeading(const BlockList& b, bool positionsOnly);

}  // namespace armtrack::detail
