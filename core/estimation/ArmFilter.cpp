#include "core/estimation/ArmFilter.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <unsupported/Eigen/AutoDiff>
#include <utility>

#include "core/Strings.h"
#include "core/camera/PinholeCamera.h"
#include "core/estimation/ArmFilterImpl.h"
#include "core/estimation/BlockUpdate.h"
#include "core/estimation/Heading.h"
#include "core/estimation/Initializer.h"
#include "core/estimation/MeasurementJacobian.h"
#include "core/estimation/Transition.h"
#include "core/estimation/WindowFit.h"

namespace armtrack {

MeasurementModel parseMethod(const std::string& name) {
  const std::string s = asciiLower(name);
  if (s == "a") return MeasurementModel::AccelGyro;
  if (s == "b") return MeasurementModel::AugmentedBodyAccel;
  if (s == "c") return MeasurementModel::InclinometerGyro;
  if (s == "inclinometer") return MeasurementModel::Inclinometer;
  throw std::invalid_argument("unknown method \"" + name + "\": expected A, B, C or inclinometer");
}

std::string methodName(MeasurementModel m) {
  switch (m) {
    case MeasurementModel::AccelGyro:
      return "A";
    case MeasurementModel::AugmentedBodyAccel:
      return "B";
    case MeasurementModel::InclinometerGyro:
      return "C";
    case MeasurementModel::Inclinometer:
      return "inclinometer";
  }
  return "?";
}

MeasurementModel startupModel(const EstimatorParams& p) {
  const bool kinematic = (p.model == MeasurementModel::InclinometerGyro ||
                          p.model == MeasurementModel::AugmentedBodyAccel) &&
                         p.kinematicStartup;
  return kinematic ? MeasurementModel::AccelGyro : p.model;
}

namespace detail {

template <int N>
void ArmFilter<N>::reset() {
  m_x.setZero();
  m_P.setIdentity();
  m_initialised = false;
  m_t = m_t0 = 0.0;
  m_lastSeenT = -std::numeric_limits<double>::infinity();
  m_lastOpticalT = -std::numeric_limits<double>::infinity();
  m_pendingOptical.reset();
  m_gatedInARow = {0, 0, 0, 0};
  m_gate.reset();
  m_timing = {};
  m_rowStep = 0.0;
  for (RestBias& b : m_restBias) b.reset();
  m_matchedQ.setZero();
  m_jerkSquared = 0.0;
  m_jerkFrom.reset();
  m_headingMatch = m_turnSquared = m_turnNoise = 0.0;
  m_lastMatchT = -std::numeric_limits<double>::infinity();
  m_recent.clear();
  m_recentStates.clear();
  m_recentFrames.clear();
  m_frameCamera.reset();
  m_badSince.reset();
  m_opticalDisagrees = false;
  m_fitAt.reset();
  m_counters = {};
  m_trunk.reset();
  m_trunkSens.setZero();
  m_base = FrameState<double>{};
  m_base.up = m_p.gUp;
  m_up = m_p.gUp.normalized();
  m_heading.reset();
  m_geometry.reset();
  if (m_p.camera && m_p.useCamera) m_camera.emplace(*m_p.camera);
}

template <int N>
JointEstimate ArmFilter<N>::estimate() const {
  JointEstimate e;
  e.t = m_t;
  e.thdd = m_x.template segment<5>(0);
  e.thd = m_x.template segment<5>(5);
  e.th = m_x.template segment<5>(10);
  const Vec u = headingAngles(m_x);
  const JointVector hu = u.template segment<5>(10);
  const double shortfall = headingShortfall(u);
  JointVector var = m_P.diagonal().template segment<5>(10) + shortfall * hu.cwiseAbs2();
  addHeadingCurvature(e.th, headingVariance(u) + shortfall, hu, var);
  addTrunkVariance(e.th, var);
  e.thStd = var.cwiseMax(0.0).cwiseSqrt();
  return e;
}

template <int N>
UpdateResult ArmFilter<N>::update(const ArmSample& s) {
  ++m_counters.samples;
  if (!std::isfinite(s.t) || s.t < m_lastSeenT) {
    ++m_counters.rejectedTime;
    return UpdateResult::Rejected;
  }
  const double rowStep = s.t - m_lastSeenT;
  m_lastSeenT = s.t;

  ArmSample in = m_p.side == Side::Left ? mirrorSample(s) : s;
  applyTrunk(in);  // a moving trunk: its motion, and the optical data into frame 0
  ArmSample clean = sanitise(in);
  trackSampleTiming(clean, rowStep);
  const bool hasImu = clean.upperArm || clean.forearm;
  const bool hasOptical = clean.elbow || clean.wrist || clean.camWrist || clean.camElbow;
  if (!hasImu && !hasOptical) {
    // Readings refused at the door: coast through a short stretch, so the row still gets an
    // estimate (its standard deviation grows with the prediction).
    if (m_initialised && m_gate.lastRefused() && s.t - m_lastDataT <= m_p.maxCoastSeconds) {
      predict(s.t - m_t);
      m_t = s.t;
      finishUpdate();
      ++m_counters.coasted;
      return UpdateResult::Predicted;
    }
    return UpdateResult::Rejected;
  }

  if (m_initialised && s.t - m_lastDataT > m_p.maxGap) {
    ++m_counters.restarts;
    m_initialised = false;
  }
  if (!m_initialised) {
    if (!hasImu) {
      m_pendingOptical = clean;
      return UpdateResult::Waiting;
    }
    initialise(clean);
    remember(clean);
    return UpdateResult::Initialised;
  }

  if (m_p.model != m_model && s.t - m_t0 >= m_p.startupSeconds) handOver();
  // Only the optical gate can refuse a sample after the prediction (an IMU block always passes
  // it), so P before the prediction is kept for samples with optical data alone.
  const Vec xPrior = m_x;
  Mat pPrior;
  if (hasOptical) pPrior = m_P;
  const TrunkSensitivity sensPrior = m_trunkSens;
  const double tPrior = m_t, floorPrior = m_headingFloor;
  // New readings of slow sensors were taken, on average, half a row before the row: the update
  // is made there, and the state predicted on to the row's time after it (ArmFilterTiming.cpp).
  const double tMeasured = std::max(m_t, s.t - sampleDelay(clean));
  predict(tMeasured - m_t);
  m_t = tMeasured;
  m_prior.reset();
  BlockList blocks = gather(clean);
  if (blocks.count == 0 && !hasOptical) {
    // Every IMU value repeated the sensor's last one: nothing new was measured, and the
    // prediction to this time is the estimate.
    m_lastDataT = s.t;
    finishUpdate();
    return UpdateResult::Accepted;
  }
  const Vec xBefore = m_x;
  const Mat pBefore = m_P;
  const TrunkSensitivity sensBefore = m_trunkSens;
  const bool optical = blocks.anyOptical();
  if (optical) beforeOpticalUpdate();
  const int offered = blocks.count;
  const bool gated = gateOptical(blocks);
  if (!gated || blocks.count == 0) {
    // Nothing left to fuse (e.g. a single mis-detected marker), or the gate could not be
    // evaluated: the sample changes nothing. (Only a sample with optical data gets here.)
    if (!gated) ++m_counters.skippedUpdates;
    m_x = xPrior;
    m_P = pPrior;
    m_trunkSens = sensPrior;
    m_t = tPrior;
    m_headingFloor = floorPrior;
    return UpdateResult::Rejected;
  }
  // The gate saw the heading variance restored; when it dropped every optical block, this is
  // an IMU-only update and P goes back to what it was.
  const bool fuseOptical = blocks.anyOptical();
  if (optical && !fuseOptical) m_P = pBefore;
  // Heading matching reads only frames whose optical rows all passed the gate: a mis-detected
  // marker must not open the heading up, nor its partner in the same frame. Nothing is gated
  // during start-up, so there it reads Kinect positions only, not marker pixels, whose
  // detector mis-detects far more often (5 % of frames in test_camera_fusion).
  const bool startup = m_t - m_t0 < m_p.startupSeconds;
  if (fuseOptical && blocks.count == offered) {
    if (!matchOpticalHeading(blocks, startup)) m_headingMatch = 0.0;
    beforeOpticalUpdate();
  }
  // Both filters start with the iterated EKF update: a UKF's sigma points spread over the
  // start-up uncertainty (tens of degrees) wrap around and lose the arm.
  bool ok = false;
  if (m_p.filter == FilterKind::Ekf || startup) {
    ok = ekfUpdate(blocks);
  } else {
    bool sigmaOutOfView = false;
    ok = ukfUpdate(blocks, sigmaOutOfView);
    // A sigma point the camera cannot see has no pixel: linearise instead for this sample.
    if (!ok && sigmaOutOfView) {
      m_x = xBefore;
      m_P = pBefore;
      m_trunkSens = sensBefore;
      if (fuseOptical) beforeOpticalUpdate();
      ok = ekfUpdate(blocks);
    }
  }
  if (!ok || !allFiniteFast(m_x) || !allFiniteFast(m_P)) {
    m_x = xBefore;
    m_P = pBefore;
    m_trunkSens = sensBefore;
    ++m_counters.skippedUpdates;
    // Updates that keep failing are a lost filter too, not something to skip for ever.
    if (!m_badSince) m_badSince = s.t;
    if (s.t - *m_badSince >= m_p.lostAfterSeconds) return recover(clean);
    return UpdateResult::Rejected;
  }
  if (fuseOptical) {
    m_lastOpticalT = s.t;
    for (int i = 0; i < blocks.count; ++i) {
      if (isCamera(blocks.block[i]))
        ++m_counters.cameraUpdates;
      else if (isOptical(blocks.block[i]))
        ++m_counters.opticalUpdates;
    }
  }
  m_lastDataT = s.t;
  afterUpdate(fuseOptical);
  matchProcessNoise(xBefore, s.t - tPrior);
  if (blocks.has(kUaAcc) || blocks.has(kFaAcc)) trackJerk();
  if (m_t < s.t) {
    predict(s.t - m_t);
    m_t = s.t;
  }
  finishUpdate();
  remember(clean);
  if (m_fitAt && m_t >= *m_fitAt) {
    m_fitAt.reset();
    if (refitFromWindow(m_t - m_p.fitWindowSeconds)) return UpdateResult::Recovered;
    // Not taken: the window may have held the tail of a fault, or the motion was too fast for
    // the seeds. Try the next window while start-up lasts.
    if (m_t + m_p.fitWindowSeconds - m_t0 < m_p.startupSeconds)
      m_fitAt = m_t + m_p.fitWindowSeconds;
  }
  if (lost()) return recover(clean);
  return UpdateResult::Accepted;
}

// The blocks this filter uses, each checked at the door: implausible ones are dropped and
// counted (SampleGate), so no reading a sensor cannot produce reaches the update.
template <int N>
ArmSample ArmFilter<N>::sanitise(const ArmSample& s) {
  ArmSample c = s;
  if (!m_p.useOptical) c.elbow.reset(), c.wrist.reset();
  if (!m_camera) c.camWrist.reset(), c.camElbow.reset();
  c = m_gate.check(c);
  if (m_gate.lastRefused() || m_gate.counters().totalHeld() != m_counters.implausible.totalHeld()) {
    m_counters.implausible = m_gate.counters();
    m_counters.rejectedNonFinite = m_counters.implausible.byReason(Implausible::NonFinite);
  }
  if (m_p.gyroBiasAtRest) {
    std::optional<ImuReading>* imus[2] = {&c.upperArm, &c.forearm};
    for (int i = 0; i < 2; ++i) {
      if (!*imus[i]) continue;
      RestBias& rb = m_restBias[i];
      const std::uint64_t before = rb.windows();
      rb.add(c.t, **imus[i]);
      (*imus[i])->gyr -= rb.bias();
      if (rb.windows() != before) {
        m_counters.restBias[i] = rb.bias();
        m_counters.restWindows[i] = rb.windows();
      }
    }
  }
  return c;
}

template <int N>
BlockList ArmFilter<N>::gather(const ArmSample& s) const {
  BlockList b;
  const bool gyro = m_p.model != MeasurementModel::Inclinometer;
  // After start-up, Method A's accelerometers also carry the model error of a lagging joint
  // acceleration, which grows with the squared jerk (accelJerkVariance).
  const bool jerkModelled =
      m_p.model == MeasurementModel::AccelGyro && m_t - m_t0 >= m_p.startupSeconds;
  const double accelVar =
      m_p.accelVariance *
          (gyro && m_t - m_t0 < m_p.gyroFirstSeconds ? m_p.gyroFirstAccelGain : 1.0) +
      (jerkModelled ? m_p.accelJerkVariance * m_jerkSquared : 0.0);
  // A moving trunk adds the noise of its own readings (frame 0's rates and the shoulder's
  // acceleration) and of its pose (optical data brought into frame 0).
  const TrunkState* trunk = m_trunk && m_trunk->state().haveImu ? &m_trunk->state() : nullptr;
  const double gyroVar = m_p.gyroVariance + (trunk ? trunk->baseGyroVariance : 0.0);
  const double armAccelVar = accelVar + (trunk ? trunk->baseAccelVariance : 0.0);
  // A held value (the logger repeating the sensor's last sample) is not a new measurement; a
  // new one from a slow sensor was taken up to a row earlier (timingVariance).
  if (s.upperArm) {
    if (gyro && !s.upperArm->gyrHeld)
      b.add(kUaGyr, s.upperArm->gyr, gyroVar + timingVariance(kUaGyr));
    if (!s.upperArm->accHeld) b.add(kUaAcc, s.upperArm->acc, armAccelVar + timingVariance(kUaAcc));
  }
  if (s.forearm) {
    if (gyro && !s.forearm->gyrHeld)
      b.add(kFaGyr, s.forearm->gyr, gyroVar + timingVariance(kFaGyr));
    if (!s.forearm->accHeld) b.add(kFaAcc, s.forearm->acc, armAccelVar + timingVariance(kFaAcc));
  }
  if (s.elbow) b.add(kElbow, *s.elbow, m_p.positionVariance + trunkPositionVariance(*s.elbow));
  if (s.wrist) b.add(kWrist, *s.wrist, m_p.positionVariance + trunkPositionVariance(*s.wrist));
  // A marker's pixel moves by about fx / depth per metre the point moves (depth: the camera's
  // distance from the shoulder).
  double pixelVar = m_p.pixelVariance;
  if (m_trunk && m_p.camera) {
    const double perMetre = m_p.camera->fx / std::max(0.5, m_p.camera->t.norm());
    const double reach = m_p.geometry.l3 + m_p.geometry.l6;
    pixelVar += perMetre * perMetre * trunkPositionVariance(Eigen::Vector3d(reach, 0.0, 0.0));
  }
  if (s.camWrist) b.add(kCamWrist, *s.camWrist, pixelVar);
  if (s.camElbow) b.add(kCamElbow, *s.camElbow, pixelVar);
  return b;
}

// x <- F x, P <- F P F^T + Q for step dt (eqs. 3-4 with the time step taken from the data).
template <int N>
void ArmFilter<N>::predict(double dt) {
  if (dt <= 0.0) return;
  const double phi = std::isfinite(m_p.jointAccelCorrelationTime)
                         ? std::exp(-dt / m_p.jointAccelCorrelationTime)
                         : 1.0;
  const double phiB = kAugmented ? std::exp(-dt / m_p.bodyAccelCorrelationTime) : 0.0;
  transitionRows(m_x, dt, phi, phiB);
  for (int j = 0; j < kNumJoints; ++j) m_x(10 + j) = wrapAngle(m_x(10 + j));
  transitionCovariance(m_P, dt, phi, phiB);
  if (tracksTrunkSensitivity()) transitionRows(m_trunkSens, dt, phi, phiB);

  const double var = m_t - m_t0 < m_p.startupSeconds
                         ? std::max(m_p.jointAccelVariance, m_p.startupJointAccelVariance)
                         : m_p.jointAccelVariance;
  for (int j = 0; j < kNumJoints; ++j)
    if (m_p.activeJoints[j]) m_P(j, j) += std::max(var, m_matchedQ(j)) * dt / m_p.referenceStep;
  // Method A's lag turns the upper arm about every axis (shoulderPathVarianceRate; the turn
  // about the vertical is the heading's walk below).
  if (m_p.model == MeasurementModel::AccelGyro && m_t - m_t0 >= m_p.startupSeconds) {
    const double lagWalk = m_p.shoulderPathVarianceRate * m_x.template segment<3>(5).norm() * dt;
    for (int j = 0; j < 3; ++j)
      if (m_p.activeJoints[j]) m_P(10 + j, 10 + j) += lagWalk;
  }
  // The heading random walk is a turn of the whole arm about the vertical: in joint space its
  // variance grows with the squared joint-space length of a unit turn, which is large near the
  // shoulder's gimbal lock (abduction 90 deg), where a small turn moves flexion and rotation far.
  const Vec15 v = headingSymmetryAtState();
  const double turnRate = (headingTurnRate() + headingSpeedTurnRate()) *
                          generatorAt(m_x.template segment<5>(10)).squaredNorm();
  m_P.template topLeftCorner<kBase, kBase>() += turnRate * dt * v * v.transpose();
  m_headingFloor += turnRate * dt;
  if constexpr (kAugmented) {
    const double qb = m_p.bodyAccelVariance * (1.0 - phiB * phiB);
    for (int i = kBase; i < N; ++i) m_P(i, i) += qb;
  }
}

// Predicted measurement (and Jacobian) for the present blocks at state x. Returns false when a
// marker is out of the camera's view at x.
template <int N>
bool ArmFilter<N>::measure(const Vec& x, const BlockList& b, MeasVec& h, Jac* jac) const {
  Eigen::Matrix<double, kModelRows, 1> own;
  Eigen::Matrix<double, kModelRows, kBase> ownJac;
  const Eigen::Matrix<double, kModelRows, 1>* readings = &own;
  const Eigen::Matrix<double, kModelRows, kBase>* derivatives = &ownJac;
  const Vec15 base = x.template head<kBase>();
  if (jac && m_prior && m_prior->at == base) {
    readings = &m_prior->readings;  // the first iteration linearises where the gate did
    derivatives = &m_prior->jacobian;
  } else if (jac) {
    // Optical rows (positions, and marker pixels through them) read the position rows.
    predictReadings(m_p.geometry, m_base, m_p.model == MeasurementModel::AccelGyro, base, own,
                    &ownJac, b.anyOptical());
  } else {
    predictBase<double>(m_p, base, own, &m_base);
  }
  const Eigen::Matrix<double, kModelRows, 1>& all = *readings;
  const Eigen::Matrix<double, kModelRows, kBase>& allJac = *derivatives;
  h.resize(b.rows());
  if (jac) {
    jac->resize(b.rows(), N);
    // Every block below writes its rows' first 15 columns; only Method B's are wider.
    if constexpr (kAugmented) jac->setZero();
  }
  for (int i = 0; i < b.count; ++i) {
    const int blk = b.block[i];
    const int row = b.offset[i];
    if (isCamera(blk)) {
      const int posBlock = blk == kCamWrist ? kWrist : kElbow;
      Eigen::Vector2d px;
      Eigen::Matrix<double, 2, kBase> pxJac;
      Eigen::Matrix<double, 3, kBase> dp;
      if (jac) dp = allJac.template middleRows<3>(3 * posBlock);
      if (!markerPixel(*m_camera, m_p.side == Side::Left, all.template segment<3>(3 * posBlock),
                       jac ? &dp : nullptr, px, jac ? &pxJac : nullptr))
        return false;
      h.template segment<2>(row) = px;
      if (jac) jac->template block<2, kBase>(row, 0) = pxJac;
      continue;
    }
    h.template segment<3>(row) = all.template segment<3>(3 * blk);
    if (jac) jac->template block<3, kBase>(row, 0) = allJac.template middleRows<3>(3 * blk);
    if constexpr (kAugmented) {
      // Method B: the accelerometer also reads the augmented body-acceleration state.
      if ((blk == kUaAcc || blk == kFaAcc) && m_p.model == MeasurementModel::AugmentedBodyAccel) {
        const int off = kBase + (blk == kUaAcc ? 0 : 3);
        h.template segment<3>(row) += x.template segment<3>(off);
        if (jac) jac->template block<3, 3>(row, off).setIdentity();
      }
    }
  }
  return true;
}

// The joints' squared jerk, summed over the joints: the estimate's joint accelerations
// change from one accelerometer update to the next (optical rows between two IMU rows are part
// of the step, so its length is the IMU's sampling however the rows interleave), squared and
// averaged over adaptationTime, after start-up only (its corrections are convergence, not
// motion). It sets the accelerometers' model error (accelJerkVariance). Each change holds the
// update's noise-driven correction as well as the motion: at rest between fast reaches it
// reads about 30 times the true squared jerk, and widens the accelerometers by 2-9 times their
// noise variance. A smoothed jerk (the accelerations less their running
// mean) that reads the motion alone left the shoulder less honest (docs/estimator.md).
template <int N>
void ArmFilter<N>::trackJerk() {
  const JointVector thdd = m_x.template head<5>();
  if (m_t - m_t0 >= m_p.startupSeconds && m_jerkFrom && m_p.adaptationTime > 0.0) {
    const double dt = m_t - m_jerkFrom->first;
    if (dt > 0.0) {
      const double w = std::min(1.0, dt / m_p.adaptationTime);
      const double j2 = (thdd - m_jerkFrom->second).squaredNorm() / (dt * dt);
      m_jerkSquared += w * (j2 - m_jerkSquared);
    }
  }
  m_jerkFrom.emplace(m_t, thdd);
}

template <int N>
void ArmFilter<N>::finishUpdate() {
  for (int j = 0; j < kNumJoints; ++j) m_x(10 + j) = wrapAngle(m_x(10 + j));
  mirrorLower(m_P);
  keepInAnatomicalRange();
  freezeInactive();
  // A negative or vanishing variance means round-off has eaten positive definiteness.
  if ((m_P.diagonal().array() <= 0.0).any()) repairCovariance();
}

// P's upper triangle set to its lower one. The EKF's block updates keep P exactly symmetric;
// the prediction (F P F^T in place, the rank-1 heading noise) leaves the two halves apart by
// round-off, and this ends it at each step. Copying one half costs a third of averaging the two
// (symmetrise, for the UKF's updates, which are not symmetric by construction).
template <int N>
void ArmFilter<N>::mirrorLower(Mat& p) {
  for (int c = 1; c < N; ++c)
    for (int r = 0; r < c; ++r) p(r, c) = p(c, r);
}

// P = (P + P^T) / 2 in place, pair by pair: each entry gets the 0.5 (a + b) of the whole
// expression (the diagonal is unchanged), without its 15x15 temporary.
template <int N>
void ArmFilter<N>::symmetrise(Mat& p) {
  for (int c = 0; c < N; ++c)
    for (int r = c + 1; r < N; ++r) p(r, c) = p(c, r) = 0.5 * (p(r, c) + p(c, r));
}

// Both state sizes: 15, and 21 with Method B's body-acceleration states.
template void ArmFilter<kBase>::reset();
template JointEstimate ArmFilter<kBase>::estimate() const;
template UpdateResult ArmFilter<kBase>::update(const ArmSample& s);
template ArmSample ArmFilter<kBase>::sanitise(const ArmSample& s);
template BlockList ArmFilter<kBase>::gather(const ArmSample& s) const;
template void ArmFilter<kBase>::predict(double dt);
template bool ArmFilter<kBase>::measure(const Vec& x, const BlockList& b, MeasVec& h,
                                        Jac* jac) const;
template void ArmFilter<kBase>::trackJerk();
template void ArmFilter<kBase>::finishUpdate();
template void ArmFilter<kBase>::symmetrise(Mat& p);
template void ArmFilter<kBase>::mirrorLower(Mat& p);
template void ArmFilter<kBase + 6>::reset();
template JointEstimate ArmFilter<kBase + 6>::estimate() const;
template UpdateResult ArmFilter<kBase + 6>::update(const ArmSample& s);
template ArmSample ArmFilter<kBase + 6>::sanitise(const ArmSample& s);
template BlockList ArmFilter<kBase + 6>::gather(const ArmSample& s) const;
template void ArmFilter<kBase + 6>::predict(double dt);
template bool ArmFilter<kBase + 6>::measure(const Vec& x, const BlockList& b, MeasVec& h,
                                            Jac* jac) const;
template void ArmFilter<kBase + 6>::trackJerk();
template void ArmFilter<kBase + 6>::finishUpdate();
template void ArmFilter<kBase + 6>::symmetrise(Mat& p);
template void ArmFilter<kBase + 6>::mirrorLower(Mat& p);

}  // namespace detail

std::unique_ptr<JointEstimator> makeEstimator(const EstimatorParams& params) {
  if (params.model == MeasurementModel::AugmentedBodyAccel)
    return std::make_unique<detail::ArmFilter<detail::kBase + 6>>(params);
  return std::make_unique<detail::ArmFilter<detail::kBase>>(params);
}

EstimatorParams recordingParams(const RecordingMeta& meta) {
  EstimatorParams p;
  p.geometry = meta.geometry;
  p.gUp = meta.gUp();
  p.trunk = meta.trunk;
  p.side = meta.side;
  p.camera = meta.camera;
  return p;
}

BatchResult estimateSamples(const std::vector<ArmSample>& samples, const EstimatorParams& params) {
  BatchResult out;
  auto filter = makeEstimator(params);
  out.estimates.reserve(samples.size());
  for (const ArmSample& s : samples) {
    const UpdateResult r = filter->update(s);
    if (hasEstimate(r) && s.hasImu()) out.estimates.push_back(filter->estimate());
  }
  out.counters = filter->counters();
  return out;
}

Eigen::Matrix<double, 18, 1> predictAll(const EstimatorParams& params,
                                        const Eigen::Matrix<double, 15, 1>& x) {
  Eigen::Matrix<double, detail::kModelRows, 1> out;
  detail::predictBase<double>(params, x, out);
  return out;
}

Eigen::Matrix<double, 18, 15> predictAllJacobian(const EstimatorParams& params,
                                                 const Eigen::Matrix<double, 15, 1>& x) {
  Eigen::Matrix<double, detail::kModelRows, 1> h;
  Eigen::Matrix<double, detail::kModelRows, detail::kBase> jac;
  detail::predictBaseWithJacobian(params, x, h, jac);
  return jac;
}

bool predictMarkerPixel(const EstimatorParams& params, const Eigen::Matrix<double, 15, 1>& x,
                        bool wrist, Eigen::Vector2d& pixel, Eigen::Matrix<double, 2, 15>* jac) {
  if (!params.camera) return false;
  const PinholeCamera camera(*params.camera);
  const int block = wrist ? detail::kWrist : detail::kElbow;
  Eigen::Matrix<double, detail::kModelRows, 1> h;
  Eigen::Matrix<double, detail::kModelRows, detail::kBase> all;
  detail::predictBaseWithJacobian(params, x, h, all);
  const Eigen::Matrix<double, 3, detail::kBase> dp = all.middleRows<3>(3 * block);
  return detail::markerPixel(camera, params.side == Side::Left, h.segment<3>(3 * block), &dp, pixel,
                             jac);
}

}  // namespace armtrack
