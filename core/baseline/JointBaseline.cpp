#include "core/baseline/JointBaseline.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace armtrack {

namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

Eigen::Matrix4d rowTransform(const DhRow& row) {
  return dhTransform<double>(row.gammaOffset, row.lambda, row.beta, row.delta);
}

Eigen::Matrix3d rotZ(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

Eigen::Matrix3d rotX(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix();
}

bool finite(const ImuReading& r) {
  return r.gyr.allFinite() && r.acc.allFinite();
}

}  // namespace

ElbowModel::ElbowModel(const ArmGeometry& geometry) {
  const auto u = upperImuTable(geometry);
  const auto f = forearmImuTable(geometry);
  // Rows 4-6 of Table 1 (the upper IMU in frame 3), row 4 of Table 3 (frame 4 in frame 3), rows
  // 7-9 of Table 3 (the forearm IMU in frame 6). None of them holds a joint angle.
  const Eigen::Matrix4d t3u = rowTransform(u[3]) * rowTransform(u[4]) * rowTransform(u[5]);
  const Eigen::Matrix4d t34 = rowTransform(f[3]);
  const Eigen::Matrix4d t6f = rowTransform(f[6]) * rowTransform(f[7]) * rowTransform(f[8]);
  const Eigen::Matrix3d r3u = t3u.topLeftCorner<3, 3>();
  const Eigen::Vector3d p3u = t3u.topRightCorner<3, 1>();
  A = r3u.transpose() * t34.topLeftCorner<3, 3>();
  B = t6f.topLeftCorner<3, 3>();
  elbowFromUpper = r3u.transpose() * (t34.topRightCorner<3, 1>() - p3u);
  elbowFromFore = -B.transpose() * t6f.topRightCorner<3, 1>();
  shoulderFromUpper = -r3u.transpose() * p3u;
  humerus = r3u.transpose() * Eigen::Vector3d::UnitZ();
}

Eigen::Matrix3d ElbowModel::relative(double th4, double th5) const {
  return A * rotZ(th4) * rotX(kHalfPi) * rotZ(th5) * B;
}

Eigen::Vector3d ElbowModel::flexionAxis() const {
  return A.col(2);
}

Eigen::Vector3d ElbowModel::pronationAxis(double th4) const {
  return A * rotZ(th4) * rotX(kHalfPi) * Eigen::Vector3d::UnitZ();
}

Eigen::Vector3d leverArmShift(const Eigen::Vector3d& specificForce, const Eigen::Vector3d& omega,
                              const Eigen::Vector3d& omegaDot, const Eigen::Vector3d& r) {
  return specificForce + omegaDot.cross(r) + omega.cross(omega.cross(r));
}

ElbowAccelStep elbowAccelStep(const ElbowModel& model, double th4, double th5,
                              const Eigen::Vector3d& fUpper, const Eigen::Vector3d& fFore,
                              double mu) {
  ElbowAccelStep s;
  const Eigen::Vector3d v = model.relative(th4, th5) * fFore.normalized();
  s.residual = fUpper.normalized() - v;
  s.jacobian.col(0) = model.flexionAxis().cross(v);
  s.jacobian.col(1) = model.pronationAxis(th4).cross(v);
  const Eigen::Matrix2d n = s.jacobian.transpose() * s.jacobian + mu * Eigen::Matrix2d::Identity();
  s.step = n.ldlt().solve(s.jacobian.transpose() * s.residual);
  return s;
}

double humerusElevation(const JointVector& th, const Eigen::Vector3d& up) {
  const Eigen::Vector3d humerus = forwardKinematics(ArmGeometry{}, th).elbow.normalized();
  return std::acos(std::clamp(-humerus.dot(up.normalized()), -1.0, 1.0));
}

// ---------------------------------------------------------------------------------------------

JointBaseline::JointBaseline(const BaselineParams& params) : m_p(params), m_model(params.geometry) {
  if (!(m_p.timeConstant > 0.0) || !std::isfinite(m_p.timeConstant))
    throw std::invalid_argument("baseline: the time constant must be a positive number of seconds");
  if (!(m_p.maxGap > 0.0))
    throw std::invalid_argument("baseline: the longest gap must be positive");
  if (!(m_p.gUp.norm() > 0.0) || !m_p.gUp.allFinite())
    throw std::invalid_argument("baseline: gravity (g times up) must be a finite, non-zero vector");
  if (!(m_p.omegaDotTau >= 0.0) || !(m_p.damping > 0.0) || !(m_p.accelTolerance > 0.0))
    throw std::invalid_argument("baseline: filter constants must be positive");
  if (m_p.side == Side::Left) m_p.gUp = mirrorPoint(m_p.gUp);
  if (m_p.elbowFromForearm) {
    if (!m_p.elbowFromForearm->allFinite())
      throw std::invalid_argument("baseline: the forearm lever arm must be finite");
    m_model.elbowFromFore = *m_p.elbowFromForearm;
  }
}

void JointBaseline::restart() {
  m_upper = Imu{};
  m_fore = Imu{};
  m_up.reset();
  m_elbow.reset();
  m_restarted = true;
  m_shoulderWait = m_elbowWait = 0.0;
}

void JointBaseline::take(Imu& imu, const ImuReading& r, double t) {
  const bool repeatGyr = m_p.repeatsAreStale && imu.seen && r.gyr == imu.gyr;
  const bool repeatAcc = m_p.repeatsAreStale && imu.seen && r.acc == imu.acc;
  m_counters.repeatedGyro += repeatGyr;
  m_counters.repeatedAccel += repeatAcc;
  if (!repeatGyr) {
    if (imu.seen && t > imu.tGyr) {
      // Over the time since the last new reading, but no more than two rows: after a still spell
      // of repeated readings the change happened in the last row, not over the whole spell.
      const double dt = std::min(t - imu.tGyr, 2.0 * (t - m_lastT));
      const Eigen::Vector3d raw = (r.gyr - imu.gyr) / dt;
      imu.gyrDot += dt / (m_p.omegaDotTau + dt) * (raw - imu.gyrDot);
    } else {
      imu.gyrDot.setZero();
    }
    imu.tGyr = t;
    imu.gyr = r.gyr;
  }
  imu.newAcc = !repeatAcc;
  imu.acc = r.acc;
  imu.seen = true;
}

bool JointBaseline::push(const ArmSample& given, BaselineRow& row) {
  ++m_counters.rows;
  const ArmSample mirrored = m_p.side == Side::Left ? mirrorSample(given) : ArmSample{};
  const ArmSample& sample = m_p.side == Side::Left ? mirrored : given;
  if (!sample.hasImu()) return false;  // optical rows: nothing for the baseline
  if (!std::isfinite(sample.t) || !(sample.t > m_lastT)) {
    ++m_counters.rejectedTime;
    return false;
  }
  const bool upperOk = sample.upperArm && finite(*sample.upperArm);
  const bool foreOk = sample.forearm && finite(*sample.forearm);
  if (sample.upperArm && !upperOk) ++m_counters.nonFinite;
  if (sample.forearm && !foreOk) ++m_counters.nonFinite;
  if (!upperOk && !foreOk) return false;

  double dt = 0.0;
  if (std::isfinite(m_lastT)) {
    dt = sample.t - m_lastT;
    if (dt > m_p.maxGap) {
      ++m_counters.restarts;
      restart();
      dt = 0.0;
    }
  }
  m_upper.newAcc = m_fore.newAcc = false;
  if (upperOk) take(m_upper, *sample.upperArm, sample.t);
  if (foreOk) take(m_fore, *sample.forearm, sample.t);
  m_lastT = sample.t;

  if (m_upper.seen) {
    if (!m_up) {
      const Eigen::Vector3d fs = leverArmShift(m_upper.acc, m_upper.gyr, Eigen::Vector3d::Zero(),
                                               m_model.shoulderFromUpper);
      if (fs.norm() > 0.0) m_up = fs.normalized();
    } else {
      stepShoulder(dt);
    }
  }
  if (m_upper.seen && m_fore.seen) {
    if (!m_elbow)
      initElbow();
    else
      stepElbow(dt);
  } else if (m_upper.seen) {
    ++m_counters.withoutForearm;
  } else {
    ++m_counters.withoutUpper;
  }
  if (!m_up && !m_elbow) return false;

  row = BaselineRow{};
  row.t = sample.t;
  row.restarted = m_restarted;
  m_restarted = false;
  if (m_elbow) {
    row.flexion = (*m_elbow)(0);
    row.pronation = (*m_elbow)(1);
  }
  if (m_up) row.elevation = std::acos(std::clamp(-m_up->dot(m_model.humerus), -1.0, 1.0));
  ++m_counters.estimates;
  return true;
}

void JointBaseline::stepShoulder(double dt) {
  Eigen::Vector3d up = *m_up;
  const Eigen::Vector3d& w = m_upper.gyr;
  // A vector fixed in the world turns the other way in the sensor's axes: d(up)/dt = -w x up.
  const double angle = w.norm() * dt;
  if (angle > 0.0) up = Eigen::AngleAxisd(-angle, w.normalized()) * up;
  const Eigen::Vector3d fs =
      leverArmShift(m_upper.acc, w, m_upper.gyrDot, m_model.shoulderFromUpper);
  const double g = m_p.gUp.norm();
  // Repeated readings wait for the next new one, which then corrects for the whole wait (no
  // longer than the longest gap: after a still spell the new reading speaks for the present).
  m_shoulderWait = std::min(m_shoulderWait + dt, m_p.maxGap);
  if (m_upper.newAcc) {
    if (std::abs(fs.norm() - g) <= m_p.accelTolerance * g) {
      const double k = m_shoulderWait / (m_p.timeConstant + m_shoulderWait);
      up += k * (fs.normalized() - up);
    }
    m_shoulderWait = 0.0;
  }
  if (up.norm() > 0.0) m_up = up.normalized();
}

void JointBaseline::stepElbow(double dt) {
  Eigen::Vector2d th = *m_elbow;
  // Relative angular velocity in forearm axes, split along the flexion and pronation axes
  // (perpendicular, so the projections are the joint rates).
  const Eigen::Matrix3d r = m_model.relative(th(0), th(1));
  const Eigen::Vector3d dw = m_fore.gyr - r.transpose() * m_upper.gyr;
  const Eigen::Vector3d z4 = r.transpose() * m_model.flexionAxis();
  const Eigen::Vector3d z5 = r.transpose() * m_model.pronationAxis(th(0));
  th += dt * Eigen::Vector2d(z4.dot(dw), z5.dot(dw));

  const Eigen::Vector3d fu =
      leverArmShift(m_upper.acc, m_upper.gyr, m_upper.gyrDot, m_model.elbowFromUpper);
  const Eigen::Vector3d ff =
      leverArmShift(m_fore.acc, m_fore.gyr, m_fore.gyrDot, m_model.elbowFromFore);
  const double g = m_p.gUp.norm();
  const double nu = fu.norm(), nf = ff.norm();
  m_elbowWait = std::min(m_elbowWait + dt, m_p.maxGap);
  if (!m_upper.newAcc && !m_fore.newAcc) {
    // Both accelerometers repeat their last readings: nothing new to correct with.
  } else if (nu > 0.2 * g && nf > 0.2 * g &&
             std::abs(nu - nf) <= m_p.accelTolerance * std::max(nu, nf)) {
    const double k = m_elbowWait / (m_p.timeConstant + m_elbowWait);
    th += k * elbowAccelStep(m_model, th(0), th(1), fu, ff, m_p.damping).step;
    m_elbowWait = 0.0;
  } else {
    ++m_counters.accelSkipped;  // a new reading, refused: the wait starts again
    m_elbowWait = 0.0;
  }
  m_elbow = Eigen::Vector2d(wrapAngle(th(0)), wrapAngle(th(1)));
}

void JointBaseline::initElbow() {
  // The accelerometers alone, from a few starts: the pose nearest neutral pronation among the
  // best fits (one vector pair leaves two solutions; the damping keeps an unobservable angle at
  // its start).
  const Eigen::Vector3d fu =
      leverArmShift(m_upper.acc, m_upper.gyr, Eigen::Vector3d::Zero(), m_model.elbowFromUpper);
  const Eigen::Vector3d ff =
      leverArmShift(m_fore.acc, m_fore.gyr, Eigen::Vector3d::Zero(), m_model.elbowFromFore);
  if (!(fu.norm() > 0.0) || !(ff.norm() > 0.0)) return;
  constexpr std::array<double, 4> kStarts = {0.0, -kHalfPi, kHalfPi, std::numbers::pi};
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector2d bestTh = Eigen::Vector2d::Zero();
  for (double th5 : kStarts) {
    for (double th4 : kStarts) {
      Eigen::Vector2d th(th4, th5);
      for (int i = 0; i < 50; ++i) {
        th += elbowAccelStep(m_model, th(0), th(1), fu, ff, 1e-3).step;
        th = Eigen::Vector2d(wrapAngle(th(0)), wrapAngle(th(1)));
      }
      const double res = elbowAccelStep(m_model, th(0), th(1), fu, ff, 1e-3).residual.norm();
      // Prefer a clearly better fit; among equal fits, the pronation nearest neutral.
      if (res < best - 1e-6 ||
          (res < best + 1e-6 && std::abs(th(1)) < std::abs(bestTh(1)) - 1e-6)) {
        best = std::min(best, res);
        bestTh = th;
      }
    }
  }
  m_elbow = bestTh;
}

}  // namespace armtrack
