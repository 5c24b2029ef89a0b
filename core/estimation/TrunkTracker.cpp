#include "core/estimation/TrunkTracker.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "core/kinematics/Trunk.h"

namespace armtrack::detail {

namespace {

Eigen::Matrix3d expRotation(const Eigen::Vector3d& v) {
  const double a = v.norm();
  if (a < 1e-12) return Eigen::Matrix3d::Identity() + skew(v);
  return Eigen::AngleAxisd(a, v / a).toRotationMatrix();
}

// Start-up uncertainty of the trunk's inclination (the recording starts upright, within this).
constexpr double kStartTiltStd = 2.0 * 3.14159265358979323846 / 180.0;
// The accelerometer's part the pivot model leaves unexplained besides noise (m/s^2): the trunk
// is not a rigid body turning about one point.
constexpr double kModelAccelStd = 0.05;
// The optical shoulder's reference: its mean over the first frames (the start pose).
constexpr int kReferenceFrames = 15;
// The fit's own variance of the shoulder, scaled for what its model leaves out (the rotation
// in (I - R) is the tracker's estimate, not the truth, and the trunk is not rigid): chosen on
// simulations (seeds 301-306 and 401-410; 2 left the left arms at 79-87 % inside two sd).
constexpr double kShoulderModelFactor = 4.0;
// Low-pass of the optical shoulder without a trunk IMU (s).
constexpr double kShoulderTau = 0.1;

}  // namespace

TrunkTracker::TrunkTracker(const TrunkTrackerParams& p) : m_p(p) {
  // The world is the trunk's start pose, so the start leaves no doubt about the heading: only
  // the inclination (how gUp sits in frame 0) is uncertain.
  const Eigen::Vector3d u = p.gUp.normalized();
  m_P = (Eigen::Matrix3d::Identity() - u * u.transpose()) * kStartTiltStd * kStartTiltStd;
  const double info = 1.0 / (p.hipPriorStd * p.hipPriorStd);
  const double offsetInfo = 1.0 / (p.shoulderOffsetStd * p.shoulderOffsetStd);
  m_fitInfo.setZero();
  m_fitInfo.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() * info;
  m_fitInfo.bottomRightCorner<3, 3>() = Eigen::Matrix3d::Identity() * offsetInfo;
  m_fitVec.setZero();
  m_fitVec.head<3>() = p.hipPrior * info;
  m_hip = p.hipPrior;
  m_hipCov = Eigen::Matrix3d::Identity() * (p.hipPriorStd * p.hipPriorStd);
  for (auto& pr : m_rateP) pr = Eigen::Matrix2d::Identity() * 1.0;
  m_state.base.up = p.gUp;
}

void TrunkTracker::addImu(double t, const ImuReading& r) {
  const Eigen::Matrix3d& mount = m_p.mount.imuRotation;
  const Eigen::Vector3d omegaMeas = mount * r.gyr;  // frame-0 axes
  const Eigen::Vector3d force = mount * r.acc;      // specific force of the sternum, frame 0
  const double dt = t - m_t;
  const bool step = m_haveImu && dt > 0.0 && dt <= m_p.maxGap;
  if (!step) {
    // Start, or after a gap: the rates start again from this reading.
    for (int i = 0; i < 3; ++i) {
      m_rate(0, i) = omegaMeas(i);
      m_rate(1, i) = 0.0;
      m_rateP[i] << m_p.gyroVariance, 0.0, 0.0, 25.0;
    }
  } else {
    // Orientation: frame 0 turns by the mean rate over the step.
    const Eigen::Vector3d omegaMid = 0.5 * (m_rate.row(0).transpose() + omegaMeas);
    m_state.rotation = m_state.rotation * expRotation(omegaMid * dt);
    m_P += Eigen::Matrix3d::Identity() * (m_p.gyroVariance * dt * dt);
    // Rates: [omega, alpha] per axis, alpha a random walk driven by the trunk's jerk.
    Eigen::Matrix2d f;
    f << 1.0, dt, 0.0, 1.0;
    Eigen::Matrix2d q;
    q << dt * dt * dt / 3.0, dt * dt / 2.0, dt * dt / 2.0, dt;
    q *= m_p.jerkSpectralDensity;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector2d x = f * m_rate.col(i);
      Eigen::Matrix2d pr = f * m_rateP[i] * f.transpose() + q;
      const double s = pr(0, 0) + m_p.gyroVariance;
      const Eigen::Vector2d k = pr.col(0) / s;
      x += k * (omegaMeas(i) - x(0));
      pr -= k * pr.row(0);
      m_rate.col(i) = x;
      m_rateP[i] = 0.5 * (pr + pr.transpose());
    }
  }
  m_t = t;
  m_haveImu = true;
  const Eigen::Vector3d omega = m_rate.row(0).transpose();
  const Eigen::Vector3d alpha = m_rate.row(1).transpose();
  const Eigen::Matrix3d lever = skew(alpha) + skew(omega) * skew(omega);

  // Inclination from the accelerometer: it reads R^T g up plus the sternum's acceleration, of
  // which a turn about the hip explains lever (p_imu - h).
  const Eigen::Matrix3d& rot = m_state.rotation;
  const Eigen::Vector3d predicted =
      rot.transpose() * m_p.gUp + lever * (m_p.mount.imuPosition - m_hip);
  const double leverScale = alpha.squaredNorm() + omega.squaredNorm() * omega.squaredNorm();
  const double var = m_p.accelVariance + kModelAccelStd * kModelAccelStd +
                     leverScale * m_p.hipPriorStd * m_p.hipPriorStd;
  const Eigen::Vector3d innov = force - predicted;
  if (innov.norm() < 3.0) {  // a knock or a fault is not the trunk's inclination
    const Eigen::Matrix3d h = rot.transpose() * skew(m_p.gUp);
    const Eigen::Matrix3d s = h * m_P * h.transpose() + Eigen::Matrix3d::Identity() * var;
    const Eigen::Matrix3d k = m_P * h.transpose() * s.inverse();
    m_state.rotation = expRotation(k * innov) * rot;
    const Eigen::Matrix3d ikh = Eigen::Matrix3d::Identity() - k * h;
    m_P = ikh * m_P * ikh.transpose() + k * (var * Eigen::Matrix3d::Identity()) * k.transpose();
    m_P = 0.5 * (m_P + m_P.transpose()).eval();
  }

  // Frame 0's motion for the arm: up + accel is the shoulder's specific force, the sternum's
  // carried over the lever arm from the sternum to the shoulder centre (at frame 0's origin).
  FrameState<double>& base = m_state.base;
  base.omega = omega;
  base.omegaDot = alpha;
  base.up = m_state.rotation.transpose() * m_p.gUp;
  base.accel = force - lever * m_p.mount.imuPosition - base.up;
  double alphaVar = 0.0, omegaVar = 0.0;
  for (int i = 0; i < 3; ++i) {
    omegaVar += m_rateP[i](0, 0) / 3.0;
    alphaVar += m_rateP[i](1, 1) / 3.0;
  }
  m_state.baseGyroVariance = omegaVar;
  // The sternum accelerometer's noise, and the angular acceleration's at an arm IMU's lever.
  constexpr double kArmLever = 0.4;  // m, a forearm IMU's distance from the shoulder
  m_state.baseAccelVariance = m_p.accelVariance + alphaVar * kArmLever * kArmLever;
  m_state.haveImu = true;
  m_state.rotationCov = m_P;
  updateShoulder();
}

void TrunkTracker::addShoulder(double t, const Eigen::Vector3d& s) {
  if (!m_haveShoulder) {
    m_haveShoulder = true;
    m_referenceCount = 0;
    m_reference.setZero();
  }
  if (m_haveImu) {
    // The pivot and the offset from the shoulder's path: s = (I - R) h + c, each frame a linear
    // observation of [h; c]. Frames at the upright start fix c; the lean then shows h. Fitting
    // c instead of subtracting a start mean keeps that mean's noise out of h.
    Eigen::Matrix<double, 3, 6> a;
    a.leftCols<3>() = Eigen::Matrix3d::Identity() - m_state.rotation;
    a.rightCols<3>() = Eigen::Matrix3d::Identity();
    m_fitInfo += a.transpose() * a / m_p.shoulderVariance;
    m_fitVec += a.transpose() * s / m_p.shoulderVariance;
    const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(m_fitInfo);
    m_hip = ldlt.solve(m_fitVec).head<3>();
    m_hipCov = ldlt.solve(Eigen::Matrix<double, 6, 6>::Identity()).topLeftCorner<3, 3>();
  }
  if (m_referenceCount < kReferenceFrames) {
    m_reference += (s - m_reference) / double(++m_referenceCount);
    m_shoulderSmooth = m_reference;
    m_shoulderT = t;
    updateShoulder();
    return;
  }
  const double dt = std::max(0.0, t - m_shoulderT);
  const double k = 1.0 - std::exp(-dt / kShoulderTau);
  m_shoulderSmooth += k * (s - m_shoulderSmooth);
  m_shoulderT = t;
  updateShoulder();
}

void TrunkTracker::addHipObservation(const Eigen::Matrix<double, Eigen::Dynamic, 3>& a,
                                     const Eigen::VectorXd& residual, double variance) {
  if (!m_haveImu || !(variance > 0.0) || !a.allFinite() || !residual.allFinite()) return;
  Eigen::Matrix<double, Eigen::Dynamic, 6> a6 =
      Eigen::Matrix<double, Eigen::Dynamic, 6>::Zero(a.rows(), 6);
  a6.leftCols<3>() = a;
  m_fitInfo += a6.transpose() * a6 / variance;
  m_fitVec += a6.transpose() * (residual + a * m_hip) / variance;
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(m_fitInfo);
  m_hip = ldlt.solve(m_fitVec).head<3>();
  m_hipCov = ldlt.solve(Eigen::Matrix<double, 6, 6>::Identity()).topLeftCorner<3, 3>();
  updateShoulder();
}

void TrunkTracker::updateShoulder() {
  if (m_haveImu) {
    const Eigen::Matrix3d& rot = m_state.rotation;
    const Eigen::Matrix3d a = Eigen::Matrix3d::Identity() - rot;
    m_state.shoulder = a * m_hip;
    // Its uncertainty: the pivot's, through (I - R), and the rotation's, through R h.
    const Eigen::Matrix3d turn = skew(rot * m_hip);
    const Eigen::Matrix3d cov = a * m_hipCov * a.transpose() + turn * m_P * turn.transpose();
    m_state.shoulderVariance = kShoulderModelFactor * cov.trace() / 3.0;
    m_state.hip = m_hip;
    m_state.hipCov = m_hipCov;
  } else if (m_haveShoulder) {
    m_state.shoulder = m_shoulderSmooth - m_reference;
    // The low-pass's noise: about tau / dt frames averaged (Kinect at 30 Hz).
    m_state.shoulderVariance = m_p.shoulderVariance / 6.0;
  }
}

Eigen::Vector3d TrunkTracker::angles() const {
  return trunkAngles(m_state.rotation, m_p.side);
}

Eigen::Vector3d TrunkTracker::angleStd() const {
  // d(angles)/d(small world rotation), by central differences.
  Eigen::Matrix3d j;
  constexpr double kStep = 1e-6;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(i) * kStep;
    j.col(i) = (trunkAngles(expRotation(e) * m_state.rotation, m_p.side) -
                trunkAngles(expRotation(-e) * m_state.rotation, m_p.side)) /
               (2.0 * kStep);
  }
  return (j * m_P * j.transpose()).diagonal().cwiseMax(0.0).cwiseSqrt();
}

}  // namespace armtrack::detail
