// ArmFilter's heading: the turn of the whole arm about the vertical, which no IMU reading sees.
// Its symmetry, the heading-blind IMU update's directions, the heading floor and the matching of
// its variance to what the optics ask for. See ArmFilterImpl.h and docs/estimator.md, "Heading".
#include "core/estimation/ArmFilterImpl.h"

#include <algorithm>
#include <cmath>

#include "core/estimation/Heading.h"
#include "core/estimation/MeasurementJacobian.h"

namespace armtrack::detail {

// headingSymmetry at x, remembered for the last state asked: predict(), the heading-blind
// update and the projection of the first iteration all ask at the same predicted state.
template <int N>
const Vec15& ArmFilter<N>::headingSymmetryAt(const Vec15& x) {
  if (!m_heading || m_heading->first != x)
    m_heading.emplace(x, headingSymmetry(x, m_up, geometryAt(x.template segment<5>(10))));
  return m_heading->second;
}

template <int N>
void ArmFilter<N>::prepareHeadingBlind() {
  m_headingBlind.active = headingBlind();
  if (!m_headingBlind.active) return;
  m_headingBlind.v.setZero();
  m_headingBlind.v.template head<kBase>() = headingSymmetryAtState();
  // What stays put is the arm's turn about the vertical, read by the covector w (up . J_s dth),
  // not the angles' Euclidean component along the heading direction: a correction that only
  // tilts the arm (w . dx = 0) may still have such a component when the shoulder axes are not
  // orthogonal, and reading that as heading made every tilt correction turn the arm a little.
  const JointVector w = headingCovector(geometryAt(m_x.template segment<5>(10)), m_up);
  m_headingBlind.u.setZero();
  m_headingBlind.u.template segment<5>(10) = w / w.dot(m_headingBlind.v.template segment<5>(10));
}

namespace {
// rows -= (rows v) w^T over the first 15 columns (v is zero beyond them), column by column.
template <int R, typename Rows, typename Vec>
void projectRows(Rows&& rows, const Vec& v, const Vec& w) {
  Eigen::Matrix<double, R, 1, 0, R == Eigen::Dynamic ? kMaxRows : R, 1> hv = rows.col(0) * v(0);
  for (int j = 1; j < kBase; ++j) hv += rows.col(j) * v(j);
  for (int j = 0; j < kBase; ++j) rows.col(j) -= hv * w(j);
}
}  // namespace

// Observability constraint: IMU rows must not see the heading (turning the whole arm about the
// vertical changes no IMU reading). Linearisation at a moving state would otherwise make the
// heading look observable and its variance collapse. Returns whether any row was changed.
template <int N>
bool ArmFilter<N>::projectHeading(const Vec& x, const BlockList& b, Jac& jac) {
  if (trunkTurning()) return false;
  Vec v = Vec::Zero();
  v.template head<kBase>() = headingSymmetryAt(x.template head<kBase>());
  const double vv = v.squaredNorm();
  if (vv <= 0.0) return false;
  // Each run of consecutive IMU blocks at once (gather() puts them all first), column by column
  // on contiguous memory: rows -= (rows v) (v / |v|^2)^T.
  const Vec w = v / vv;
  bool changed = false;
  for (int i = 0; i < b.count;) {
    if (isOptical(b.block[i])) {
      ++i;
      continue;
    }
    int end = i;
    while (end < b.count && !isOptical(b.block[end])) ++end;
    const int first = b.offset[i];
    const int n = (end < b.count ? b.offset[end] : b.rows()) - first;
    // Two IMUs' four blocks (the usual case) with the row count fixed, so the loops unroll.
    if (n == 12)
      projectRows<12>(jac.template middleRows<12>(first), v, w);
    else
      projectRows<Eigen::Dynamic>(jac.middleRows(first, n), v, w);
    changed = true;
    i = end;
  }
  return changed;
}

// Unit heading direction among the angles at x: the rotation of the whole arm about the
// vertical, rates and accelerations held (zero elsewhere).
template <int N>
auto ArmFilter<N>::headingAngles(const Vec& x) const -> Vec {
  Vec u = Vec::Zero();
  const JointVector& d = generatorAt(x.template segment<5>(10));  // headingDirection, cached
  const double n = d.norm();
  u.template segment<5>(10) = n > 0 ? JointVector(d / n) : d;
  return u;
}

// headingGenerator at th, remembered for the last angles asked: a step asks at the predicted
// angles (process noise, heading symmetry, heading matching, the optical and heading-blind
// updates) and then at the updated ones (heading floor, estimate()) up to eight times.
template <int N>
const JointVector& ArmFilter<N>::generatorAt(const JointVector& th) const {
  return geometryAt(th).generator;
}

// headingGeometry at th, remembered for the last angles asked (generatorAt, the heading symmetry
// and the heading-blind update's covector all start from it).
template <int N>
const HeadingGeometry& ArmFilter<N>::geometryAt(const JointVector& th) const {
  if (!m_geometry || m_geometry->first != th) m_geometry.emplace(th, headingGeometry(th, m_up));
  return m_geometry->second;
}

// P holds the heading's variance to first order: a turn of the whole arm about the vertical
// moves the shoulder angles along hu. Far from small, the turn bends through joint space (near
// the gimbal lock a 40 deg turn can move flexion 14 deg where the first-order step says 1), so
// when the heading is uncertain by more than a degree the reported variance takes the joints'
// mean squared excursion under the exact turn, over the heading's distribution, in place of the
// first-order part. (Half the excursion at two standard deviations each way, used before,
// overstated it: IMU-only abduction had 99.8-100 % of its errors inside two sd.)
template <int N>
void ArmFilter<N>::addHeadingCurvature(const JointVector& th, double headingVar,
                                       const JointVector& hu, JointVector& var) const {
  const double rate = generatorAt(th).norm();  // joint rad per rad of turn
  if (!(rate > 0.0) || !(headingVar > 0.0)) return;
  const double turnStd = std::sqrt(headingVar) / rate;
  constexpr double kFirstOrderEnough = 1.0 * kDeg;
  if (turnStd < kFirstOrderEnough) return;
  const JointVector moment = turnSecondMoment(th, turnStd, m_up);
  for (int j = 0; j < 3; ++j) var(j) += std::max(0.0, moment(j) - headingVar * hu(j) * hu(j));
}

// Heading honesty. The projection of the IMU rows keeps IMU-only updates from moving the
// heading, but information still leaks in (through correlations, and because the linearisation
// point moves with the noisy joint accelerations), so P's heading variance shrinks below what
// is known. The filter therefore tracks a floor beside P: the heading variance start-up (or the
// last optical fix) left, plus the heading random walk since. The reported angle uncertainty
// includes it, and the first optical update after IMU-only data gets it back into P, so the
// optical heading correction is taken at once. Changing P during IMU-only updates instead makes
// the filter unstable.
template <int N>
double ArmFilter<N>::headingShortfall(const Vec& u) const {
  // Heading-blind IMU updates keep P's heading variance honest by themselves; the floor is for
  // Methods B and C, whose IMU updates leak information into it.
  const double floor = headingBlind() ? 0.0 : m_headingFloor;
  return std::max(0.0, std::max(floor, m_headingMatch) - headingVariance(u));
}

template <int N>
void ArmFilter<N>::beforeOpticalUpdate() {
  m_headingFloor = std::max(m_headingFloor, m_headingMatch);
  const Vec u = headingAngles(m_x);
  // u is zero outside the angles: only P's angle block changes, and only by a shortfall.
  const double shortfall = headingShortfall(u);
  if (shortfall == 0.0) return;
  const JointVector hu = u.template segment<5>(10);
  m_P.template block<5, 5>(10, 10) += shortfall * hu * hu.transpose();
}

// Both state sizes: 15, and 21 with Method B's body-acceleration states.
template const Vec15& ArmFilter<kBase>::headingSymmetryAt(const Vec15& x);
template void ArmFilter<kBase>::prepareHeadingBlind();
template bool ArmFilter<kBase>::projectHeading(const Vec& x, const BlockList& b, Jac& jac);
template auto ArmFilter<kBase>::headingAngles(const Vec& x) const -> Vec;
template const JointVector& ArmFilter<kBase>::generatorAt(const JointVector& th) const;
template const HeadingGeometry& ArmFilter<kBase>::geometryAt(const JointVector& th) const;
template void ArmFilter<kBase>::addHeadingCurvature(const JointVector& th, double headingVar,
                                                    const JointVector& hu, JointVector& var) const;
template double ArmFilter<kBase>::headingShortfall(const Vec& u) const;
template void ArmFilter<kBase>::beforeOpticalUpdate();
template const Vec15& ArmFilter<kBase + 6>::headingSymmetryAt(const Vec15& x);
template void ArmFilter<kBase + 6>::prepareHeadingBlind();
template bool ArmFilter<kBase + 6>::projectHeading(const Vec& x, const BlockList& b, Jac& jac);
template auto ArmFilter<kBase + 6>::headingAngles(const Vec& x) const -> Vec;
template const JointVector& ArmFilter<kBase + 6>::generatorAt(const JointVector& th) const;
template const HeadingGeometry& ArmFilter<kBase + 6>::geometryAt(const JointVector& th) const;
template void ArmFilter<kBase + 6>::addHeadingCurvature(const JointVector& th, double headingVar,
                                                        const JointVector& hu,
                                                        JointVector& var) const;
template double ArmFilter<kBase + 6>::headingShortfall(const Vec& u) const;
template void ArmFilter<kBase + 6>::beforeOpticalUpdate();

}  // namespace armtrack::detail
