// ArmFilter's start, start-up window fits, consistency watch and recovery, and the limits it
// keeps the state in. See ArmFilterImpl.h and docs/estimator.md.
#include "core/estimation/ArmFilterImpl.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/estimation/Heading.h"
#include "core/estimation/Initializer.h"
#include "core/estimation/MeasurementJacobian.h"
#include "core/estimation/WindowFit.h"

namespace armtrack::detail {

template <int N>
void ArmFilter<N>::initialise(const ArmSample& s) {
  ArmSample first = s;
  constexpr double kOpticalWindow = 0.1;  // s an earlier optical sample may lag the first IMU
  if (m_pendingOptical && s.t - m_pendingOptical->t <= kOpticalWindow) {
    if (!first.elbow) first.elbow = m_pendingOptical->elbow;
    if (!first.wrist) first.wrist = m_pendingOptical->wrist;
    if (!first.camWrist) first.camWrist = m_pendingOptical->camWrist;
    if (!first.camElbow) first.camElbow = m_pendingOptical->camElbow;
  }
  m_pendingOptical.reset();
  m_p.model = m_model;  // every (re)start begins on the start-up model, until handOver()
  m_p.model = startupModel(m_p);
  const InitialPose pose = initialPose(paramsInFrame(), first);
  m_x.setZero();
  m_x.template segment<5>(5) = pose.thd;
  m_x.template segment<5>(10) = pose.th;
  // Two marker pixels pin the arm like two positions do (up to the depth along each ray, which
  // the arm's lengths fix); one pixel alone does not.
  const bool optical = (first.elbow || first.wrist) || (first.camWrist && first.camElbow);
  startCovariance(optical);
  m_t = m_t0 = m_lastDataT = s.t;
  m_recent.clear();
  m_recentStates.clear();
  m_recentFrames.clear();
  m_badSince.reset();
  m_opticalDisagrees = false;
  m_matchedQ.setZero();
  m_jerkSquared = 0.0;
  m_jerkFrom.reset();
  m_headingMatch = m_turnSquared = m_turnNoise = 0.0;
  m_lastMatchT = -std::numeric_limits<double>::infinity();
  m_fitAt =
      m_p.fitWindowSeconds > 0.0 ? std::optional<double>(s.t + m_p.fitWindowSeconds) : std::nullopt;
  m_lastOpticalT = optical ? s.t : -std::numeric_limits<double>::infinity();
  m_headingFloor = headingAngles(m_x).dot(m_P * headingAngles(m_x));
  m_initialised = true;
  freezeInactive();
  keepInAnatomicalRange();
}

// The start-up covariance around the present state.
template <int N>
void ArmFilter<N>::startCovariance(bool optical) {
  m_P.setZero();
  m_trunkSens.setZero();  // a new start owes nothing to the trunk's pose so far
  const double angleStd = optical ? m_p.initialAngleStdOptical : m_p.initialAngleStd;
  for (int j = 0; j < kNumJoints; ++j) {
    m_P(j, j) = m_p.initialAccelStd * m_p.initialAccelStd;
    m_P(5 + j, 5 + j) = m_p.initialRateStd * m_p.initialRateStd;
    m_P(10 + j, 10 + j) = angleStd * angleStd;
  }
  // A start pose without optical data has its heading from the prior alone: say so in P.
  if (!optical) {
    const Vec15 v = headingSymmetry(m_x.template head<kBase>(), m_up);
    m_P.template topLeftCorner<kBase, kBase>() +=
        m_p.initialHeadingStd * m_p.initialHeadingStd * v * v.transpose();
  }
  if constexpr (kAugmented) {
    for (int i = kBase; i < N; ++i) m_P(i, i) = m_p.bodyAccelVariance;
  }
  m_headingFloor = headingAngles(m_x).dot(m_P * headingAngles(m_x));
}

// The recent past, for the window fit: fused readings only, in the right-arm frame.
template <int N>
void ArmFilter<N>::remember(const ArmSample& clean) {
  ArmSample kept = clean;
  kept.trueAngles.reset();
  kept.estimate.reset();
  m_recent.push_back(std::move(kept));
  m_recentStates.push_back(m_x.template head<kBase>());
  if (m_trunk && m_trunk->state().haveImu) {
    // Samples remembered before the trunk IMU spoke were fused for a still trunk.
    WindowFrame still;
    still.base.up = m_p.gUp;
    while (m_recentFrames.size() + 1 < m_recent.size()) m_recentFrames.push_front(still);
    m_recentFrames.push_back({m_base, m_frameCamera});
  }
  while (!m_recent.empty() && m_recent.front().t < m_t - m_p.fitWindowSeconds) {
    m_recent.pop_front();
    m_recentStates.pop_front();
  }
  while (m_recentFrames.size() > m_recent.size()) m_recentFrames.pop_front();
}

// The parameters as frame 0 is now: gravity along the trunk's present up, and the camera as
// the trunk sees it. For a still trunk, the parameters themselves.
template <int N>
EstimatorParams ArmFilter<N>::paramsInFrame() const {
  EstimatorParams p = m_p;
  if (!m_trunk || !m_trunk->state().haveImu) return p;
  p.gUp = m_base.up;
  if (m_frameCamera) p.camera = m_frameCamera;
  return p;
}

template <int N>
std::vector<ArmSample> ArmFilter<N>::recentSince(double t, std::vector<Vec15>* states,
                                                 std::vector<WindowFrame>* frames) const {
  std::vector<ArmSample> w;
  const bool haveFrames = m_recentFrames.size() == m_recent.size();
  for (std::size_t i = 0; i < m_recent.size(); ++i) {
    if (m_recent[i].t < t) continue;
    w.push_back(m_recent[i]);
    if (states) states->push_back(m_recentStates[i]);
    if (frames && haveFrames) frames->push_back(m_recentFrames[i]);
  }
  return w;
}

// Seeds for a window fit at the latest sample: the running state, and the single-sample
// start pose there (rates from the gyroscopes). When the window holds no optical data but an
// optical fix set the heading, only the running state: the fit cannot see the heading, and
// the single-sample pose would bring the start-up prior's heading back.
template <int N>
bool ArmFilter<N>::anyOptical(const std::vector<ArmSample>& w) {
  for (const ArmSample& r : w)
    if (r.elbow || r.wrist || r.camWrist || r.camElbow) return true;
  return false;
}

template <int N>
std::vector<Vec15> ArmFilter<N>::fitSeeds(const ArmSample& last,
                                          const std::vector<ArmSample>& w) const {
  std::vector<Vec15> seeds{m_x.template head<kBase>()};
  if (!anyOptical(w) && std::isfinite(m_lastOpticalT)) return seeds;
  const EstimatorParams now = paramsInFrame();
  const InitialPose pose = initialPose(now, last);
  Vec15 x = Vec15::Zero();
  x.template segment<5>(5) = pose.thd;
  x.template segment<5>(10) = pose.th;
  seeds.push_back(x);
  // The pose at the window's latest optical frame, with the IMU readings just before it, carried
  // to the window's end at its gyroscope rates: optical positions pin the upper arm and the
  // elbow where a single IMU sample in fast motion (gravity hidden in body acceleration) cannot.
  for (auto it = w.rbegin(); it != w.rend(); ++it) {
    if (!(it->elbow || it->wrist || it->camWrist || it->camElbow)) continue;
    ArmSample merged = *it;
    for (auto imu = it; imu != w.rend(); ++imu) {
      if (!imu->hasImu()) continue;
      merged.upperArm = imu->upperArm;
      merged.forearm = imu->forearm;
      break;
    }
    if (!merged.hasImu()) break;
    const InitialPose at = initialPose(now, merged);
    Vec15 y = Vec15::Zero();
    y.template segment<5>(5) = at.thd;
    y.template segment<5>(10) = at.th + at.thd * (last.t - it->t);
    seeds.push_back(y);
    break;
  }
  return seeds;
}

// Start-up in mid-motion: once fitWindowSeconds of data are in, a batch fit of one smooth
// motion to all of them replaces the running state when it explains the data clearly better.
template <int N>
bool ArmFilter<N>::refitFromWindow(double since) {
  std::vector<Vec15> states;
  std::vector<WindowFrame> frames;
  const std::vector<ArmSample> w = recentSince(since, &states, &frames);
  if (w.size() < 2) return false;
  const std::vector<WindowFrame>* moving = frames.empty() ? nullptr : &frames;
  const EstimatorParams now = paramsInFrame();
  // A window without optical data: the fit cannot see the heading, so it holds the running
  // state's (an optical fix's, or the start pose's), and the heading keeps the variance it had.
  // Left free, it would take whichever heading its seed had.
  std::optional<JointVector> anchor;
  if (!anyOptical(w)) anchor = m_x.template segment<5>(10);
  const WindowFitResult fit = fitWindow(now, w, fitSeeds(w.back(), w), anchor, 60, moving);
  if (!fit.explains(kGoodFitRms) || !inAnatomicalRange(fit.x)) return false;
  if (!(fit.rms < kRefitGain * trajectoryRms(now, w, states, moving))) return false;
  const Vec u = headingAngles(m_x);
  const double headingVar = u.dot(m_P * u) + headingShortfall(u);
  takeFit(fit, w);
  if (anchor) {
    // The start covariance without optics spreads the heading over the start-up prior's 30 deg;
    // the anchored fit kept the fix's heading, so P keeps the fix's heading variance instead.
    startCovariance(true);
    Vec v = Vec::Zero();
    v.template head<kBase>() = headingSymmetry(m_x.template head<kBase>(), m_up);
    m_P += headingVar * v * v.transpose();
    m_headingFloor = headingVar;
    finishUpdate();
  }
  ++m_counters.startupRefits;
  return true;
}

// A fitted state replaces the running one with the start-up covariance: the fit is good to a
// few degrees, and the filter must stay ready to take the next corrections.
template <int N>
void ArmFilter<N>::takeFit(const WindowFitResult& fit, const std::vector<ArmSample>& w) {
  m_x.template head<kBase>() = fit.x;
  bool optical = false;
  for (const ArmSample& r : w)
    optical = optical || r.elbow || r.wrist || (r.camWrist && r.camElbow);
  startCovariance(optical);
  finishUpdate();
}

// Consistency watch: IMU innovations far beyond their covariance for lostAfterSeconds in a
// row, or a state no arm can be in, mean the filter has lost the arm.
template <int N>
bool ArmFilter<N>::lost() {
  if (!allFiniteFast(m_x) ||
      m_x.template segment<5>(5).cwiseAbs().maxCoeff() > m_p.plausibility.gyroRange)
    return true;
  if (m_t - m_t0 < m_p.startupSeconds) return false;
  // The optics kept contradicting the state (a gated point, frame after frame): the IMUs alone
  // cannot fix a wrong heading or branch, so start again from the window. Methods B and C open
  // their angles up instead (reopenAngles).
  if (m_opticalDisagrees) {
    m_opticalDisagrees = false;
    if (inclinometerRealSensors()) {
      reopenAngles();
      return false;
    }
    return true;
  }
  if (m_updateDof == 0) return false;
  if (m_updateNis / m_updateDof <= m_p.lostNis) {
    m_badSince.reset();
    return false;
  }
  if (!m_badSince) m_badSince = m_t;
  return m_t - *m_badSince >= m_p.lostAfterSeconds;
}

// Re-initialises from the recent window (or, when that fails, from the sample alone), counts it
// and reports it: the estimate jumps here without the arm having moved.
template <int N>
UpdateResult ArmFilter<N>::recover(const ArmSample& last) {
  ++m_counters.recoveries;
  m_badSince.reset();
  std::vector<WindowFrame> frames;
  const std::vector<ArmSample> w = recentSince(m_t - m_p.fitWindowSeconds, nullptr, &frames);
  const std::vector<Vec15> seeds = fitSeeds(last, w);
  const EstimatorParams now = paramsInFrame();
  initialise(last);  // fresh covariance, start-up noise and iterations, a new start-up fit
  if (w.size() >= 2) {
    const WindowFitResult fit =
        fitWindow(now, w, seeds, std::nullopt, 60, frames.empty() ? nullptr : &frames);
    if (fit.explains(kGoodFitRms) && inAnatomicalRange(fit.x)) takeFit(fit, w);
  }
  remember(last);
  return UpdateResult::Recovered;
}

// Covariance matching: the squared correction an update makes to each joint acceleration,
// per reference step and averaged over adaptationTime, is the process noise the motion needs.
template <int N>
void ArmFilter<N>::matchProcessNoise(const Vec& xPredicted, double dt) {
  if (!m_p.adaptiveProcessNoise || m_p.model != MeasurementModel::AccelGyro || !(dt > 0.0) ||
      !(m_p.adaptationTime > 0.0))
    return;
  const double w = std::min(1.0, dt / m_p.adaptationTime);
  for (int j = 0; j < kNumJoints; ++j) {
    const double d = m_x(j) - xPredicted(j);
    m_matchedQ(j) += w * (d * d * m_p.referenceStep / dt - m_matchedQ(j));
    m_matchedQ(j) = std::min(m_matchedQ(j), m_p.maxJointAccelVariance);
  }
}

// A window fit that ends outside the anatomical range has found the other Euler branch (the
// same arm, which the sensors cannot tell apart) or a wrong minimum: not taken.
template <int N>
bool ArmFilter<N>::inAnatomicalRange(const Vec15& x) const {
  for (int j = 0; j < kNumJoints; ++j) {
    const double th = wrapAngle(x(10 + j));
    if (m_p.activeJoints[j] && (th < m_p.jointLower(j) || th > m_p.jointUpper(j))) return false;
  }
  return true;
}

// Estimate projection (Simon & Chia 2002) onto each violated limit in turn: the joint goes to
// the nearest limit (wrapped), and every state correlated with it moves by the gain P e / P_ii.
// The covariance is kept: the limit is knowledge about the arm, not a measurement.
template <int N>
void ArmFilter<N>::keepInAnatomicalRange() {
  for (int j = 0; j < kNumJoints; ++j) {
    const int i = 10 + j;
    const double th = m_x(i), lo = m_p.jointLower(j), hi = m_p.jointUpper(j);
    if (!m_p.activeJoints[j] || (th >= lo && th <= hi) || !(m_P(i, i) > 0.0)) continue;
    const double toLo = std::isfinite(lo) ? wrapAngle(lo - th) : kInf;
    const double toHi = std::isfinite(hi) ? wrapAngle(hi - th) : kInf;
    const double step = std::abs(toLo) < std::abs(toHi) ? toLo : toHi;
    if (!std::isfinite(step)) continue;
    m_x += m_P.col(i) * (step / m_P(i, i));
    for (int k = 0; k < kNumJoints; ++k) m_x(10 + k) = wrapAngle(m_x(10 + k));
    ++m_counters.limitedStates;
  }
}

template <int N>
void ArmFilter<N>::repairCovariance() {
  ++m_counters.covarianceRepairs;
  Eigen::SelfAdjointEigenSolver<Mat> es(0.5 * (m_P + m_P.transpose()));
  Vec ev = es.eigenvalues().cwiseMax(1e-12);
  m_P = es.eigenvectors() * ev.asDiagonal() * es.eigenvectors().transpose();
}

// Methods B and C, when the optics kept contradicting the state: each angle's variance grows by
// the start-up's (initialAngleStdOptical, 5 deg) so the next frames pull the state over, where a
// re-initialisation from the window would make it jump (their inclinometer model reads body
// acceleration as tilt, so the window fit lands tens of degrees off, or on the other branch).
template <int N>
void ArmFilter<N>::reopenAngles() {
  const double reopen = m_p.initialAngleStdOptical * m_p.initialAngleStdOptical;
  for (int j = 0; j < kNumJoints; ++j)
    if (m_p.activeJoints[j]) m_P(10 + j, 10 + j) += reopen;
}

// Inactive joints are held at their fixed value with a tiny variance (keeps P positive definite).
template <int N>
void ArmFilter<N>::freezeInactive() {
  for (int j = 0; j < kNumJoints; ++j) {
    if (m_p.activeJoints[j]) continue;
    for (int d = 0; d < 3; ++d) {
      const int i = 5 * d + j;
      m_P.row(i).setZero();
      m_P.col(i).setZero();
      m_P(i, i) = 1e-12;
      m_x(i) = d == 2 ? m_p.fixedAngles(j) : 0.0;
    }
  }
}

// The end of a kinematic start-up (startupModel): the state and covariance carry over to the
// model asked for; Method A's matched process noise does not, nor its heading floor.
template <int N>
void ArmFilter<N>::handOver() {
  m_p.model = m_model;
  m_matchedQ.setZero();
  m_jerkSquared = 0.0;
  m_jerkFrom.reset();
  if constexpr (kAugmented) {
    // Method B's body-acceleration states start from what the kinematics say they are.
    Eigen::Matrix<double, kModelRows, 1> with, without;
    const Vec15 base = m_x.template head<kBase>();
    predictReadings(m_p.geometry, m_base, true, base, with, nullptr);
    predictReadings(m_p.geometry, m_base, false, base, without, nullptr);
    m_x.template segment<3>(kBase) = (with - without).template segment<3>(3 * kUaAcc);
    m_x.template segment<3>(kBase + 3) = (with - without).template segment<3>(3 * kFaAcc);
  }
  const Vec u = headingAngles(m_x);
  m_headingFloor = u.dot(m_P * u);
}

// Both state sizes: 15, and 21 with Method B's body-acceleration states.
template void ArmFilter<kBase>::initialise(const ArmSample& s);
template void ArmFilter<kBase>::startCovariance(bool optical);
template void ArmFilter<kBase>::remember(const ArmSample& clean);
template std::vector<ArmSample> ArmFilter<kBase>::recentSince(
    double t, std::vector<Vec15>* states, std::vector<WindowFrame>* frames) const;
template EstimatorParams ArmFilter<kBase>::paramsInFrame() const;
template bool ArmFilter<kBase>::anyOptical(const std::vector<ArmSample>& w);
template std::vector<Vec15> ArmFilter<kBase>::fitSeeds(const ArmSample& last,
                                                       const std::vector<ArmSample>& w) const;
template bool ArmFilter<kBase>::refitFromWindow(double since);
template void ArmFilter<kBase>::takeFit(const WindowFitResult& fit,
                                        const std::vector<ArmSample>& w);
template bool ArmFilter<kBase>::lost();
template UpdateResult ArmFilter<kBase>::recover(const ArmSample& last);
template void ArmFilter<kBase>::matchProcessNoise(const Vec& xPredicted, double dt);
template bool ArmFilter<kBase>::inAnatomicalRange(const Vec15& x) const;
template void ArmFilter<kBase>::keepInAnatomicalRange();
template void ArmFilter<kBase>::repairCovariance();
template void ArmFilter<kBase>::freezeInactive();
template void ArmFilter<kBase>::reopenAngles();
template void ArmFilter<kBase>::handOver();
template void ArmFilter<kBase + 6>::initialise(const ArmSample& s);
template void ArmFilter<kBase + 6>::startCovariance(bool optical);
template void ArmFilter<kBase + 6>::remember(const ArmSample& clean);
template std::vector<ArmSample> ArmFilter<kBase + 6>::recentSince(
    double t, std::vector<Vec15>* states, std::vector<WindowFrame>* frames) const;
template EstimatorParams ArmFilter<kBase + 6>::paramsInFrame() const;
template bool ArmFilter<kBase + 6>::anyOptical(const std::vector<ArmSample>& w);
template std::vector<Vec15> ArmFilter<kBase + 6>::fitSeeds(const ArmSample& last,
                                                           const std::vector<ArmSample>& w) const;
template bool ArmFilter<kBase + 6>::refitFromWindow(double since);
template void ArmFilter<kBase + 6>::takeFit(const WindowFitResult& fit,
                                            const std::vector<ArmSample>& w);
template bool ArmFilter<kBase + 6>::lost();
template UpdateResult ArmFilter<kBase + 6>::recover(const ArmSample& last);
template void ArmFilter<kBase + 6>::matchProcessNoise(const Vec& xPredicted, double dt);
template bool ArmFilter<kBase + 6>::inAnatomicalRange(const Vec15& x) const;
template void ArmFilter<kBase + 6>::keepInAnatomicalRange();
template void ArmFilter<kBase + 6>::repairCovariance();
template void ArmFilter<kBase + 6>::freezeInactive();
template void ArmFilter<kBase + 6>::reopenAngles();
template void ArmFilter<kBase + 6>::handOver();

}  // namespace armtrack::detail
