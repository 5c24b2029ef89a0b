// A moving trunk (docs/estimator.md, "Trunk"): the sternum IMU and the optical shoulder feed the
// trunk tracker; frame 0's motion goes into the arm's predicted readings, and the optical data,
// which are in the world frame, are brought into frame 0 before the filter sees them.
#include <cmath>

#include "core/estimation/ArmFilterImpl.h"

namespace armtrack::detail {

namespace {

// What a sternum IMU can read: beyond a MEMS sensor's usual full scale (2000 deg/s, 16 g) a
// reading is a fault.
constexpr double kMaxTrunkGyro = 2000.0 * kDeg;
constexpr double kMaxTrunkAccel = 16.0 * 9.80665;
// An optical shoulder further than this from the start (m) is not a shoulder.
constexpr double kMaxShoulderDistance = 1.5;

bool plausible(const ImuReading& r) {
  return r.gyr.allFinite() && r.acc.allFinite() && r.gyr.cwiseAbs().maxCoeff() < kMaxTrunkGyro &&
         r.acc.cwiseAbs().maxCoeff() < kMaxTrunkAccel;
}

}  // namespace

template <int N>
void ArmFilter<N>::applyTrunk(ArmSample& s) {
  if (!s.trunk && !s.shoulder && !m_trunk) return;
  auto tracker = [&]() -> TrunkTracker& {
    if (!m_trunk) {
      TrunkTrackerParams tp;
      if (m_p.trunk) tp.mount = *m_p.trunk;
      tp.gUp = m_p.gUp;
      tp.hipPrior = m_p.hipPivot;
      tp.gyroVariance = m_p.gyroVariance;
      tp.accelVariance = m_p.accelVariance;
      tp.shoulderVariance = m_p.positionVariance;
      tp.side = m_p.side;
      m_trunk.emplace(tp);
    }
    return *m_trunk;
  };
  if (s.trunk) {
    if (m_p.trunk && plausible(*s.trunk))
      tracker().addImu(s.t, *s.trunk);
    else
      ++m_counters.rejectedTrunk;
    s.trunk.reset();
  }
  if (s.shoulder) {
    if (s.shoulder->allFinite() && s.shoulder->norm() < kMaxShoulderDistance)
      tracker().addShoulder(s.t, *s.shoulder);
    else
      ++m_counters.rejectedTrunk;
    s.shoulder.reset();
  }
  if (!m_trunk) return;
  const TrunkState& ts = m_trunk->state();
  if (ts.haveImu) {
    m_base = ts.base;
    const Eigen::Vector3d up = m_base.up.normalized();
    if (up != m_up) {
      m_up = up;
      m_heading.reset();
      m_geometry.reset();
    }
  }
  // World to frame 0: p0 = R^T (p - s).
  const Eigen::Matrix3d rt = ts.rotation.transpose();
  if (s.elbow) s.elbow = rt * (*s.elbow - ts.shoulder);
  if (s.wrist) s.wrist = rt * (*s.wrist - ts.shoulder);
  if (m_camera && m_p.camera && (s.camWrist || s.camElbow)) {
    // The camera stays in the world; seen from frame 0 it moves: p_cam = Rc (s + R p0) + tc.
    // It sees the real arm, which for a left arm is the mirror image of this one.
    Eigen::Matrix3d rot = ts.rotation;
    Eigen::Vector3d shoulder = ts.shoulder;
    if (m_p.side == Side::Left) {
      rot = mirrorRotation(rot);
      shoulder = mirrorPoint(shoulder);
    }
    CameraParams c = *m_p.camera;
    c.R = m_p.camera->R * rot;
    c.t = m_p.camera->R * shoulder + m_p.camera->t;
    m_camera.emplace(c);
  }
}

// The variance a point at p (frame 0) gains from the trunk's uncertain pose, per axis (m^2).
template <int N>
double ArmFilter<N>::trunkPositionVariance(const Eigen::Vector3d& p) const {
  if (!m_trunk) return 0.0;
  const TrunkState& ts = m_trunk->state();
  return ts.shoulderVariance + p.squaredNorm() * ts.rotationCov.trace() / 3.0;
}

template <int N>
std::optional<TrunkEstimate> ArmFilter<N>::trunk() const {
  if (!m_trunk) return std::nullopt;
  TrunkEstimate e;
  e.measured = m_trunk->seenImu();
  if (e.measured) {
    e.angles = m_trunk->angles();
    e.angleStd = m_trunk->angleStd();
  }
  e.shoulder = m_trunk->state().shoulder;
  if (m_p.side == Side::Left) e.shoulder = mirrorPoint(e.shoulder);
  return e;
}

template void ArmFilter<kBase>::applyTrunk(ArmSample& s);
template double ArmFilter<kBase>::trunkPositionVariance(const Eigen::Vector3d& p) const;
template std::optional<TrunkEstimate> ArmFilter<kBase>::trunk() const;
template void ArmFilter<kBase + 6>::applyTrunk(ArmSample& s);
template double ArmFilter<kBase + 6>::trunkPositionVariance(const Eigen::Vector3d& p) const;
template std::optional<TrunkEstimate> ArmFilter<kBase + 6>::trunk() const;

}  // namespace armtrack::detail
