#include "core/simulation/DoublePendulum.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "core/simulation/ImuErrors.h"
#include "core/simulation/SensorSimulator.h"

namespace armtrack {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("pendulum: " + what);
}

}  // namespace

DoublePendulum::DoublePendulum(const PendulumParams& params, double duration)
    : m_p(params), m_duration(duration) {
  require(m_p.upperLength > 0 && m_p.lowerLength > 0 && std::isfinite(m_p.upperLength) &&
              std::isfinite(m_p.lowerLength),
          "the rods' lengths must be positive");
  require(m_p.upperMass > 0 && m_p.lowerMass > 0 && std::isfinite(m_p.upperMass) &&
              std::isfinite(m_p.lowerMass),
          "the rods' masses must be positive");
  require(m_p.pivotDamping >= 0 && m_p.hingeDamping >= 0 && std::isfinite(m_p.pivotDamping) &&
              std::isfinite(m_p.hingeDamping),
          "damping must be zero or positive");
  require(m_p.g > 0 && std::isfinite(m_p.g), "g must be positive");
  require(std::isfinite(m_p.swing0) && std::isfinite(m_p.hinge0),
          "the release pose must be finite");
  require(m_p.holdSeconds >= 0 && std::isfinite(m_p.holdSeconds), "the hold must be >= 0 s");
  require(m_p.step > 0 && m_p.step <= 0.01, "the integration step must be in (0, 0.01] s");
  require(duration >= 0 && std::isfinite(duration), "the duration must be a finite length >= 0");
  const int perGrid = std::max(1, static_cast<int>(std::lround(1e-3 / m_p.step)));
  m_gridStep = perGrid * m_p.step;
  const double free = std::max(0.0, m_duration - m_p.holdSeconds);
  const auto n = static_cast<std::size_t>(std::ceil(free / m_gridStep)) + 1;
  m_grid.reserve(n);
  Abs s{m_p.swing0, m_p.swing0 + m_p.hinge0, 0.0, 0.0};
  m_grid.push_back(s);
  for (std::size_t i = 1; i < n; ++i) {
    for (int k = 0; k < perGrid; ++k) s = rk4(s, m_p.step);
    m_grid.push_back(s);
  }
}

void DoublePendulum::accelerations(const Abs& s, double& a1, double& a2) const {
  // Lagrange's equations of two uniform rods (centres of mass at half length, I = m l^2 / 12)
  // in absolute angles from the downward vertical:
  //   M11 a1 + M12 a2 = -m2 L1 c2 sin(p1 - p2) w2^2 - (m1 c1 + m2 L1) g sin p1 + t1
  //   M12 a1 + M22 a2 =  m2 L1 c2 sin(p1 - p2) w1^2 - m2 c2 g sin p2 + t2
  // with t1 = -b1 w1 + b2 (w2 - w1), t2 = -b2 (w2 - w1) the dampers' generalised forces.
  const double m1 = m_p.upperMass, m2 = m_p.lowerMass;
  const double l1 = m_p.upperLength, l2 = m_p.lowerLength;
  const double c1 = l1 / 2, c2 = l2 / 2;
  const double i1 = m1 * l1 * l1 / 12, i2 = m2 * l2 * l2 / 12;
  const double d = s.p1 - s.p2;
  const double m11 = i1 + m1 * c1 * c1 + m2 * l1 * l1;
  const double m12 = m2 * l1 * c2 * std::cos(d);
  const double m22 = i2 + m2 * c2 * c2;
  const double hinge = s.w2 - s.w1;
  const double t1 = -m_p.pivotDamping * s.w1 + m_p.hingeDamping * hinge;
  const double t2 = -m_p.hingeDamping * hinge;
  const double r1 =
      -m2 * l1 * c2 * std::sin(d) * s.w2 * s.w2 - (m1 * c1 + m2 * l1) * m_p.g * std::sin(s.p1) + t1;
  const double r2 =
      m2 * l1 * c2 * std::sin(d) * s.w1 * s.w1 - m2 * c2 * m_p.g * std::sin(s.p2) + t2;
  const double det = m11 * m22 - m12 * m12;  // > 0: the mass matrix is positive definite
  a1 = (m22 * r1 - m12 * r2) / det;
  a2 = (m11 * r2 - m12 * r1) / det;
}

DoublePendulum::Abs DoublePendulum::rk4(const Abs& s, double h) const {
  const auto f = [this](const Abs& x) {
    Abs d{x.w1, x.w2, 0.0, 0.0};
    accelerations(x, d.w1, d.w2);
    return d;
  };
  const auto add = [](const Abs& x, const Abs& d, double k) {
    return Abs{x.p1 + k * d.p1, x.p2 + k * d.p2, x.w1 + k * d.w1, x.w2 + k * d.w2};
  };
  const Abs k1 = f(s);
  const Abs k2 = f(add(s, k1, h / 2));
  const Abs k3 = f(add(s, k2, h / 2));
  const Abs k4 = f(add(s, k3, h));
  return Abs{s.p1 + h / 6 * (k1.p1 + 2 * k2.p1 + 2 * k3.p1 + k4.p1),
             s.p2 + h / 6 * (k1.p2 + 2 * k2.p2 + 2 * k3.p2 + k4.p2),
             s.w1 + h / 6 * (k1.w1 + 2 * k2.w1 + 2 * k3.w1 + k4.w1),
             s.w2 + h / 6 * (k1.w2 + 2 * k2.w2 + 2 * k3.w2 + k4.w2)};
}

DoublePendulum::Abs DoublePendulum::absAt(double t) const {
  const double tau = std::clamp(t, 0.0, m_duration) - m_p.holdSeconds;
  if (tau <= 0.0) return m_grid.front();
  const auto i = std::min(m_grid.size() - 1, static_cast<std::size_t>(tau / m_gridStep));
  Abs s = m_grid[i];
  double left = tau - static_cast<double>(i) * m_gridStep;
  while (left > 1e-12) {
    const double h = std::min(left, m_p.step);
    s = rk4(s, h);
    left -= h;
  }
  return s;
}

DoublePendulum::State DoublePendulum::at(double t) const {
  const Abs s = absAt(t);
  State out;
  out.swing = s.p1;
  out.hinge = s.p2 - s.p1;
  if (std::clamp(t, 0.0, m_duration) <= m_p.holdSeconds) return out;  // held still
  out.swingRate = s.w1;
  out.hingeRate = s.w2 - s.w1;
  double a1 = 0, a2 = 0;
  accelerations(s, a1, a2);
  out.swingAccel = a1;
  out.hingeAccel = a2 - a1;
  return out;
}

double DoublePendulum::energy(double t) const {
  const Abs s = absAt(t);
  const double m1 = m_p.upperMass, m2 = m_p.lowerMass;
  const double l1 = m_p.upperLength, l2 = m_p.lowerLength;
  const double c1 = l1 / 2, c2 = l2 / 2;
  const double i1 = m1 * l1 * l1 / 12, i2 = m2 * l2 * l2 / 12;
  const double kinetic = 0.5 * (i1 + m1 * c1 * c1 + m2 * l1 * l1) * s.w1 * s.w1 +
                         m2 * l1 * c2 * std::cos(s.p1 - s.p2) * s.w1 * s.w2 +
                         0.5 * (i2 + m2 * c2 * c2) * s.w2 * s.w2;
  const double potential =
      -m1 * m_p.g * c1 * std::cos(s.p1) - m2 * m_p.g * (l1 * std::cos(s.p1) + c2 * std::cos(s.p2));
  return kinetic + potential;
}

// ---------------------------------------------------------------------------------------------

PendulumTrajectory::PendulumTrajectory(const DoublePendulum& pendulum, double zeroOffset)
    : m_pendulum(pendulum), m_zero(zeroOffset) {}

JointMotion PendulumTrajectory::at(double t) const {
  // Frame 0: x down, y forward, z lateral. th0 turns the upper arm forward about z0; the elbow's
  // axis z4 is -z0 there, so a forward turn of the forearm is a negative th4 (flexion).
  const DoublePendulum::State s = m_pendulum.at(t);
  JointMotion m;
  m.th(0) = s.swing;
  m.th(3) = -(s.hinge + m_zero);
  m.thd(0) = s.swingRate;
  m.thd(3) = -s.hingeRate;
  m.thdd(0) = s.swingAccel;
  m.thdd(3) = -s.hingeAccel;
  return m;
}

ArmGeometry pendulumGeometry(const PendulumParams& pendulum) {
  ArmGeometry geo;
  geo.l3 = pendulum.upperLength;
  geo.l6 = pendulum.lowerLength;
  geo.lu3 = pendulum.upperLength / 2;
  geo.lf6 = 0.75 * pendulum.lowerLength;
  return geo;
}

ArmGeometry pendulumMountingOnRod(const ArmGeometry& geometry, double zeroOffset) {
  // The forearm IMU in frame 6 (origin at the elbow): lf8 out along (cos thf7, sin thf7, 0),
  // lf6 along z6. A turn of the elbow by the zero is, in frame 6 at pronation 0, a turn about y6.
  const Eigen::Vector3d p0(geometry.lf8 * std::cos(geometry.thf7),
                           geometry.lf8 * std::sin(geometry.thf7), geometry.lf6);
  const Eigen::Vector3d p = Eigen::AngleAxisd(zeroOffset, Eigen::Vector3d::UnitY()) * p0;
  ArmGeometry g = geometry;
  g.lf6 = p.z();
  g.lf8 = std::hypot(p.x(), p.y());
  g.thf7 = std::atan2(p.y(), p.x());
  return g;
}

namespace {

/// The tick of a sensor of rate hz that a row at time t holds: its last reading at or before t.
/// Returns the reading's index and time; every row is its own reading at rate 0.
std::pair<std::int64_t, double> heldTick(double t, double hz, std::int64_t row) {
  if (hz <= 0.0) return {row, t};
  const auto k = static_cast<std::int64_t>(std::floor(t * hz + 1e-9));
  return {k, static_cast<double>(k) / hz};
}

struct Readings {
  ImuReading upper, fore;
};

// What each IMU feels at time t (the wobble's input): rate, specific force, and the acceleration
// without gravity.
struct Truths {
  ImuTruth upper, fore;
};

Truths truthsAt(const PendulumTrajectory& traj, const ArmGeometry& geo, const Eigen::Vector3d& gUp,
                double zero, double t) {
  const JointMotion m = traj.at(t);
  const ArmKinematics<double> k = armKinematics<double>(geo, m.th, m.thd, m.thdd, gUp);
  Truths r;
  r.upper = {k.upperImu.omega, k.upperImu.up + k.upperImu.accel, k.upperImu.accel};
  r.fore = {k.forearmImu.omega, k.forearmImu.up + k.forearmImu.accel, k.forearmImu.accel};
  if (zero != 0.0) {
    // The sensor sits on the rod, which is turned by the zero from the model's forearm about the
    // elbow's axis: its lever arm from the elbow differs from the model's by dr (forearm axes).
    const ArmPose model = forwardKinematics(geo, m.th);
    JointVector real = m.th;
    real(3) += zero;
    const ArmPose onRod = forwardKinematics(geo, real);
    const Eigen::Matrix3d rf = model.forearmImu.topLeftCorner<3, 3>();
    const Eigen::Vector3d dr = rf.transpose() * (onRod.forearmImu.topRightCorner<3, 1>() -
                                                 model.forearmImu.topRightCorner<3, 1>());
    const Eigen::Vector3d& w = k.forearmImu.omega;
    const Eigen::Vector3d lever = k.forearmImu.omegaDot.cross(dr) + w.cross(w.cross(dr));
    r.fore.acc += lever;
    r.fore.linAcc += lever;
  }
  return r;
}

Readings readingsAt(const PendulumTrajectory& traj, const ArmGeometry& geo,
                    const Eigen::Vector3d& gUp, double zero, double t) {
  const Truths k = truthsAt(traj, geo, gUp, zero, t);
  return {{k.upper.gyr, k.upper.acc}, {k.fore.gyr, k.fore.acc}};
}

}  // namespace

Recording simulatePendulum(const PendulumSimParams& p) {
  require(p.outputRateHz > 0 && std::isfinite(p.outputRateHz), "the output rate must be positive");
  require(p.gyroRateHz >= 0 && p.accelRateHz >= 0 && std::isfinite(p.gyroRateHz) &&
              std::isfinite(p.accelRateHz),
          "sensor rates must be >= 0 (0: every row)");
  require(p.gyroNoiseStd >= 0 && p.accelNoiseStd >= 0 && std::isfinite(p.gyroNoiseStd) &&
              std::isfinite(p.accelNoiseStd),
          "noise must be >= 0");
  require(std::isfinite(p.zeroOffset), "the elbow's zero must be finite");
  require(p.wobbleTiltPerAccel >= 0 && p.wobbleTranslationGain >= 0 &&
              std::isfinite(p.wobbleTiltPerAccel) && std::isfinite(p.wobbleTranslationGain),
          "the wobble must be >= 0");
  require(p.duration > 0 && p.duration <= RecordingLimits::kMaxRecordingSeconds,
          "the duration must be positive and at most 12 h");
  const DoublePendulum pendulum(p.pendulum, p.duration);
  const PendulumTrajectory traj(pendulum, p.zeroOffset);

  Recording rec;
  rec.meta.geometry = pendulumGeometry(p.pendulum);
  // On the rod the model is exact: no lever arm left for readingsAt to add.
  if (p.mountingOnRod) rec.meta.geometry = pendulumMountingOnRod(rec.meta.geometry, p.zeroOffset);
  const double leverZero = p.mountingOnRod ? 0.0 : p.zeroOffset;
  rec.meta.g = p.pendulum.g;
  const Eigen::Vector3d gUp = rec.meta.gUp();
  std::mt19937_64 rng(p.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const auto noise = [&](double std) {
    return Eigen::Vector3d(std * normal(rng), std * normal(rng), std * normal(rng));
  };
  // With wobble each IMU goes through the simulator's error model, which then also holds its
  // readings and adds their noise (its own random streams).
  const bool wobble = p.wobbleTiltPerAccel != 0.0 || p.wobbleTranslationGain != 0.0;
  std::optional<ImuErrorModel> wobbling[2];
  if (wobble) {
    ImuSimParams imu;
    imu.rateHz = p.outputRateHz;
    imu.gyroNoiseStd = p.gyroNoiseStd;
    imu.accelNoiseStd = p.accelNoiseStd;
    imu.errors.enabled = true;
    if (p.gyroRateHz > 0.0) imu.errors.gyroRateHz = p.gyroRateHz;
    if (p.accelRateHz > 0.0) imu.errors.accelRateHz = p.accelRateHz;
    imu.errors.wobbleTiltPerAccel = p.wobbleTiltPerAccel;
    imu.errors.wobbleTranslationGain = p.wobbleTranslationGain;
    imu.errors.wobbleFrequencyHz = p.wobbleFrequencyHz;
    imu.errors.wobbleDamping = p.wobbleDamping;
    wobbling[0].emplace(imu, p.seed, 0u, "pendulum upper IMU");
    wobbling[1].emplace(imu, p.seed, 1u, "pendulum forearm IMU");
  }
  std::int64_t gyroTick = -1, accelTick = -1;
  Readings gyro{}, accel{};
  const auto rows = static_cast<std::int64_t>(std::floor(p.duration * p.outputRateHz + 1e-9));
  rec.samples.reserve(static_cast<std::size_t>(rows + 1));
  for (std::int64_t i = 0; i <= rows; ++i) {
    const double t = static_cast<double>(i) / p.outputRateHz;
    if (wobble) {
      ArmSample s;
      s.t = t;
      for (int k = 0; k < 2; ++k) {
        const ImuReading r = wobbling[k]->reading(t, [&](double tau) {
          const Truths tr = truthsAt(traj, rec.meta.geometry, gUp, leverZero, tau);
          return k == 0 ? tr.upper : tr.fore;
        });
        (k == 0 ? s.upperArm : s.forearm) = r;
      }
      JointVector th = traj.at(t).th;
      for (int j = 0; j < kNumJoints; ++j) th(j) = wrapAngle(th(j));
      s.trueAngles = th;
      rec.samples.push_back(s);
      continue;
    }
    const auto [gk, gt] = heldTick(t, p.gyroRateHz, i);
    const auto [ak, at] = heldTick(t, p.accelRateHz, i);
    if (gk != gyroTick) {  // a new gyroscope reading, with its own noise
      gyroTick = gk;
      gyro = readingsAt(traj, rec.meta.geometry, gUp, leverZero, gt);
      gyro.upper.gyr += noise(p.gyroNoiseStd);
      gyro.fore.gyr += noise(p.gyroNoiseStd);
    }
    if (ak != accelTick) {
      accelTick = ak;
      accel = readingsAt(traj, rec.meta.geometry, gUp, leverZero, at);
      accel.upper.acc += noise(p.accelNoiseStd);
      accel.fore.acc += noise(p.accelNoiseStd);
    }
    ArmSample s;
    s.t = t;
    s.upperArm = ImuReading{gyro.upper.gyr, accel.upper.acc};
    s.forearm = ImuReading{gyro.fore.gyr, accel.fore.acc};
    JointVector th = traj.at(t).th;
    for (int j = 0; j < kNumJoints; ++j) th(j) = wrapAngle(th(j));
    s.trueAngles = th;
    rec.samples.push_back(s);
  }
  return rec;
}

}  // namespace armtrack
