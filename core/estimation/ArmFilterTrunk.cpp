// A moving trunk (docs/estimator.md, "Trunk"): the sternum IMU and the optical shoulder feed the
// trunk tracker; frame 0's motion goes into the arm's predicted readings, and the optical data,
// which are in the world frame, are brought into frame 0 before the filter sees them.
#include <Eigen/Cholesky>
#include <cmath>

#include "core/estimation/ArmFilterImpl.h"
#include "core/estimation/MeasurementJacobian.h"

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

// The camera stays in the world; seen from frame 0 it moves: p_cam = Rc (s + R p0) + tc. It
// sees the real arm, which for a left arm is the mirror image of the one the filter works on.
CameraParams cameraInFrame0(const CameraParams& world, const TrunkState& ts, Side side) {
  Eigen::Matrix3d rot = ts.rotation;
  Eigen::Vector3d shoulder = ts.shoulder;
  if (side == Side::Left) {
    rot = mirrorRotation(rot);
    shoulder = mirrorPoint(shoulder);
  }
  CameraParams c = world;
  c.R = world.R * rot;
  c.t = world.R * shoulder + world.t;
  return c;
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
  if (ts.haveImu && !m_trunk->seenShoulder() && m_initialised) fitHipFromArm(s);
  // World to frame 0: p0 = R^T (p - s).
  const Eigen::Matrix3d rt = ts.rotation.transpose();
  if (s.elbow) s.elbow = rt * (*s.elbow - ts.shoulder);
  if (s.wrist) s.wrist = rt * (*s.wrist - ts.shoulder);
  if (m_camera && m_p.camera && (s.camWrist || s.camElbow)) {
    m_frameCamera = cameraInFrame0(*m_p.camera, ts, m_p.side);
    m_camera.emplace(*m_frameCamera);
  }
}

// The variance a point at p (frame 0) gains from the trunk's uncertain pose, per axis (m^2).
template <int N>
double ArmFilter<N>::trunkPositionVariance(const Eigen::Vector3d& p) const {
  if (!m_trunk) return 0.0;
  const TrunkState& ts = m_trunk->state();
  return ts.shoulderVariance + p.squaredNorm() * ts.rotationCov.trace() / 3.0;
}

namespace {

// Elbow and wrist (frame 0) at th, and their joint Jacobian: the measurement model's own rows
// (predictReadings), at rest, where gravity does not enter the positions.
void pointsAndJacobian(const ArmGeometry& geometry, const JointVector& th,
                       Eigen::Matrix<double, 6, 1>& p, Eigen::Matrix<double, 6, 5>& jac) {
  Eigen::Matrix<double, kMeasurementStates, 1> x =
      Eigen::Matrix<double, kMeasurementStates, 1>::Zero();
  x.segment<5>(10) = th;
  ModelReadings h;
  ModelJacobian full;
  predictReadings(geometry, Eigen::Vector3d::Zero(), false, x, h, &full);
  p = h.segment<6>(12);
  jac = full.block<6, 5>(12, 10);
}

// The hip fit from the arm's points: what the arm's predicted positions leave out besides their
// own uncertainty and the sensor's noise (their errors are correlated from frame to frame, as
// the filter bends the joints to follow the points).
constexpr double kHipFromArmFactor = 4.0;
// A residual this large is an arm the filter has lost, or an outlier, not the hip.
constexpr double kHipGateMetres = 0.10;
constexpr double kHipGatePixels = 40.0;
// Below this |I - R| (about 3 deg of lean) the points say nothing about the hip.
constexpr double kHipMinTurn = 0.05;

}  // namespace

// Without an optical shoulder the hip pivot was left at its prior, and a real hip 4 cm away
// put the shoulder 1-2 cm off on a 20 deg lean: with a webcam the arm was lost (12-17 deg). The
// arm's own points see it: with the trunk turned, a hip error moves the shoulder by (I - R) dh,
// and the elbow and wrist with it, where the arm's angles (from its IMUs, and the points over
// many poses) predict them. Each optical frame's residual, taken before the filter's update, is
// a linear observation of the hip.
template <int N>
void ArmFilter<N>::fitHipFromArm(const ArmSample& s) {
  const TrunkState& ts = m_trunk->state();
  const Eigen::Matrix3d lever = Eigen::Matrix3d::Identity() - ts.rotation;  // d shoulder / d hip
  if (lever.norm() < kHipMinTurn) return;
  const bool hasPoints = s.elbow || s.wrist;
  const bool hasPixels = m_p.camera && m_p.useCamera && (s.camElbow || s.camWrist);
  if (!hasPoints && !hasPixels) return;
  const JointVector th = m_x.template segment<5>(10);
  Eigen::Matrix<double, 6, 1> p;
  Eigen::Matrix<double, 6, 5> jac;
  pointsAndJacobian(m_p.geometry, th, p, jac);
  const Eigen::Matrix<double, 6, 6> pointCov =
      jac * m_P.template block<5, 5>(10, 10) * jac.transpose();
  const std::optional<Eigen::Vector3d> points[2] = {s.elbow, s.wrist};
  for (int k = 0; k < 2; ++k) {
    if (!points[k] || !points[k]->allFinite()) continue;
    const Eigen::Vector3d predicted = ts.shoulder + ts.rotation * p.segment<3>(3 * k);
    const Eigen::Vector3d r = *points[k] - predicted;
    if (r.norm() > kHipGateMetres) continue;
    const double var = kHipFromArmFactor *
                       (m_p.positionVariance + pointCov.block<3, 3>(3 * k, 3 * k).trace() / 3.0);
    m_trunk->addHipObservation(lever, r, var);
  }
  if (!hasPixels) return;
  // The camera in frame 0 for the current pose; M mirrors a left arm's points.
  const Eigen::Matrix3d mirror = m_p.side == Side::Left
                                     ? Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal().toDenseMatrix()
                                     : Eigen::Matrix3d::Identity();
  const CameraParams c = cameraInFrame0(*m_p.camera, ts, m_p.side);
  const PinholeCamera camera(c);
  const std::optional<Eigen::Vector2d> pixels[2] = {s.camElbow, s.camWrist};
  for (int k = 0; k < 2; ++k) {
    if (!pixels[k] || !pixels[k]->allFinite()) continue;
    Eigen::Vector2d predicted;
    Eigen::Matrix<double, 2, 3> dPixel;  // per m of the (mirrored) frame-0 point
    if (!camera.project(mirror * p.segment<3>(3 * k), predicted, dPixel)) continue;
    const Eigen::Vector2d r = *pixels[k] - predicted;
    if (r.norm() > kHipGatePixels) continue;
    // d pixel / d p_cam, then p_cam = Rc M (R p + (I - R) h): d p_cam / d h = Rc M (I - R).
    const Eigen::Matrix<double, 2, 3> perCam = dPixel * c.R.transpose();
    const Eigen::Matrix<double, 2, 3> a = perCam * m_p.camera->R * mirror * lever;
    const Eigen::Matrix<double, 2, 3> perPoint = dPixel * mirror;
    const double pointVar =
        (perPoint * pointCov.block<3, 3>(3 * k, 3 * k) * perPoint.transpose()).trace() / 2.0;
    m_trunk->addHipObservation(a, r, kHipFromArmFactor * (m_p.pixelVariance + pointVar));
  }
}

// How an error of the trunk's pose, [e0, dh], moves each optical block's measurement, at state
// x: the points are brought into frame 0 by the estimated pose, p0 = R^T (p - h) + h, so a
// rotation error e0 (frame 0) moves them by (p0 - h) x e0 and a hip error dh by (I - R^T) dh;
// a marker pixel moves as its frame-0 point does, through the camera as frame 0 sees it.
template <int N>
void ArmFilter<N>::trunkMeasurementRows(const Vec& x, const BlockList& b) {
  const TrunkState& ts = m_trunk->state();
  // The points at x: the gate's prediction has them when it was made at x (positions read the
  // angles alone).
  const Vec15 base = x.template head<kBase>();
  const Eigen::Matrix<double, kModelRows, 1>& h = priorPrediction().readings;
  Eigen::Matrix<double, kModelRows, 1> own;
  const Eigen::Matrix<double, kModelRows, 1>* readings = &h;
  if (m_prior->at.template segment<5>(10) != base.template segment<5>(10)) {
    predictBase<double>(m_p, base, own, &m_base);
    readings = &own;
  }
  const Eigen::Matrix3d hipRows = Eigen::Matrix3d::Identity() - ts.rotation.transpose();
  for (int i = 0; i < b.count; ++i) {
    const int blk = b.block[i];
    if (!isOptical(blk)) continue;
    const int point = blk == kElbow || blk == kCamElbow ? kElbow : kWrist;
    const Eigen::Vector3d p0 = readings->template segment<3>(3 * point);
    Eigen::Matrix<double, 3, 6, Eigen::RowMajor> d;
    d.leftCols<3>() = skew(p0 - ts.hip);
    d.rightCols<3>() = hipRows;
    if (isCamera(blk)) {
      Eigen::Matrix<double, 3, kBase> unit = Eigen::Matrix<double, 3, kBase>::Zero();
      unit.leftCols<3>().setIdentity();
      Eigen::Vector2d px;
      Eigen::Matrix<double, 2, kBase> perPoint;
      if (!m_camera || !markerPixel(*m_camera, m_p.side == Side::Left, p0, &unit, px, &perPoint)) {
        m_trunkRows[i].setZero();
        continue;
      }
      m_trunkRows[i].topRows<2>() = perPoint.leftCols<3>() * d;
      m_trunkRows[i].row(2).setZero();
    } else {
      m_trunkRows[i] = d;
    }
  }
}

// The arm's angles relative to the thorax rest on the trunk's estimated pose: the optical points
// are brought into frame 0 by it (p0 = R^T (p - s), s = (I - R) h). An error rotation e of the
// trunk (world axes, e0 = R^T e in frame 0) and an error dh of the hip move every optical point
// by dp0 = [p0 - h]x e0 - R^T (I - R) dh: a turn about the hip, not the shoulder, so the points
// also shift, and the filter bends the joints to follow them. P treats the same error as white
// noise on each optical frame; the variance it gives the angles comes on top.
//
// The EKF carries the state's sensitivity to [e0, dh] through every block's own gain
// (m_trunkSens, a consider or Schmidt analysis): how far the optical updates moved the angles
// for a given pose error, less what the IMUs held against them, and for how long it stays. Its
// variance is S Pp S^T with Pp the tracker's present covariances. The UKF, whose update has no
// block gains, takes the joint change that best explains the shifted elbow and wrist (least
// squares on their positions at the current angles), as if the estimate followed the optical
// points alone: on the acceptance set that gave 100 % coverage on the elbow, whose flexion
// the IMUs hold (sd 0.5 deg for an error of 0.05 deg); the sensitivity gives 96-99 %.
// Without either, a sternum IMU on a still trunk left the shoulder's squared errors 1.1-1.8
// times their variance (seeds 501-505, Kinect).
template <int N>
void ArmFilter<N>::addTrunkVariance(const JointVector& th, JointVector& var) const {
  if (!m_trunk || !m_trunk->state().haveImu) return;
  // Without optical data the trunk's pose reaches the arm's angles through gravity alone (the
  // inclination, tracked to a few hundredths of a degree), not through any point: nothing to add.
  if (!std::isfinite(m_lastOpticalT)) return;
  const TrunkState& ts = m_trunk->state();
  const Eigen::Matrix3d rt = ts.rotation.transpose();
  const Eigen::Matrix3d rotCov = rt * ts.rotationCov * ts.rotation;  // frame 0
  if (m_p.filter == FilterKind::Ekf) {
    // The EKF carried the angles' sensitivity to the pose through its own gains (m_trunkSens):
    // what the optical updates took in and what the IMUs held against them, and how long the
    // error stays after the trunk is upright again.
    const Eigen::Matrix<double, 5, 6> sens = m_trunkSens.template middleRows<5>(10);
    var += (sens.template leftCols<3>() * rotCov * sens.template leftCols<3>().transpose() +
            sens.template rightCols<3>() * ts.hipCov * sens.template rightCols<3>().transpose())
               .diagonal()
               .cwiseMax(0.0);
    return;
  }
  const Eigen::Matrix3d shift = rt * (Eigen::Matrix3d::Identity() - ts.rotation);
  const Eigen::Matrix3d hipCov = shift * ts.hipCov * shift.transpose();
  Eigen::Matrix<double, 6, 1> p;
  Eigen::Matrix<double, 6, 5> jac;
  pointsAndJacobian(m_p.geometry, th, p, jac);
  Eigen::Matrix<double, 6, 3> turn, offset;
  for (int k = 0; k < 2; ++k) {
    turn.block<3, 3>(3 * k, 0) = skew(p.segment<3>(3 * k) - ts.hip);
    offset.block<3, 3>(3 * k, 0) = Eigen::Matrix3d::Identity();
  }
  const Eigen::Matrix<double, 6, 6> posCov =
      turn * rotCov * turn.transpose() + offset * hipCov * offset.transpose();
  const Eigen::Matrix<double, 5, 5> normal =
      jac.transpose() * jac + Eigen::Matrix<double, 5, 5>::Identity() * 1e-8;
  const Eigen::Matrix<double, 5, 6> fit = normal.ldlt().solve(jac.transpose());
  var += (fit * posCov * fit.transpose()).diagonal().cwiseMax(0.0);
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
template void ArmFilter<kBase>::fitHipFromArm(const ArmSample& s);
template void ArmFilter<kBase>::addTrunkVariance(const JointVector& th, JointVector& var) const;
template std::optional<TrunkEstimate> ArmFilter<kBase>::trunk() const;
template void ArmFilter<kBase>::trunkMeasurementRows(const Vec& x, const BlockList& b);
template void ArmFilter<kBase + 6>::applyTrunk(ArmSample& s);
template double ArmFilter<kBase + 6>::trunkPositionVariance(const Eigen::Vector3d& p) const;
template void ArmFilter<kBase + 6>::fitHipFromArm(const ArmSample& s);
template void ArmFilter<kBase + 6>::addTrunkVariance(const JointVector& th, JointVector& var) const;
template std::optional<TrunkEstimate> ArmFilter<kBase + 6>::trunk() const;
template void ArmFilter<kBase + 6>::trunkMeasurementRows(const Vec& x, const BlockList& b);

}  // namespace armtrack::detail
