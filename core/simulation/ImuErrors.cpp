#include "core/simulation/ImuErrors.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/simulation/SensorSimulator.h"

namespace armtrack {
namespace {

[[noreturn]] void fail(const std::string& who, const char* name, const std::string& rule,
                       double value) {
  std::ostringstream o;
  o << who << ": errors." << name << " " << rule << ", got " << value;
  throw std::invalid_argument(o.str());
}

void finite(const std::string& who, const char* name, double v) {
  if (!std::isfinite(v)) fail(who, name, "must be finite", v);
}

template <typename M>
void allFinite(const std::string& who, const char* name, const M& m) {
  for (Eigen::Index i = 0; i < m.size(); ++i) finite(who, name, m.data()[i]);
}

void within(const std::string& who, const char* name, double v, double lo, double hi) {
  finite(who, name, v);
  if (v < lo || v > hi) {
    std::ostringstream rule;
    rule << "must be between " << lo << " and " << hi;
    fail(who, name, rule.str(), v);
  }
}

void positive(const std::string& who, const char* name, double v) {
  finite(who, name, v);
  if (!(v > 0.0)) fail(who, name, "must be > 0", v);
}

void unit(const std::string& who, const char* name, const Eigen::Vector3d& v) {
  allFinite(who, name, v);
  if (std::abs(v.norm() - 1.0) > 1e-6)
    fail(who, name, "must be a unit vector; its length is", v.norm());
}

void crossAxis(const std::string& who, const char* name, const Eigen::Matrix3d& m) {
  allFinite(who, name, m);
  for (int i = 0; i < 3; ++i) {
    if (m(i, i) != 0.0)
      fail(who, name, "must have a zero diagonal (the scale is separate)", m(i, i));
    for (int j = 0; j < 3; ++j) within(who, name, m(i, j), -0.5, 0.5);
  }
}

Eigen::Vector3d clampRound(Eigen::Vector3d v, double range, double lsb) {
  for (int k = 0; k < 3; ++k) {
    if (lsb > 0.0) v[k] = std::round(v[k] / lsb) * lsb;
    if (range > 0.0) v[k] = std::clamp(v[k], -range, range);
  }
  return v;
}

}  // namespace

void checkImuErrors(const ImuErrorParams& p, double outputRateHz, const std::string& who) {
  if (!p.enabled) return;
  for (int k = 0; k < 3; ++k) {
    within(who, "gyroScale", p.gyroScale[k], -0.5, 0.5);
    within(who, "accelScale", p.accelScale[k], -0.5, 0.5);
  }
  crossAxis(who, "gyroCrossAxis", p.gyroCrossAxis);
  crossAxis(who, "accelCrossAxis", p.accelCrossAxis);
  allFinite(who, "gyroGSensitivity", p.gyroGSensitivity);
  for (Eigen::Index i = 0; i < 9; ++i)
    within(who, "gyroGSensitivity", p.gyroGSensitivity.data()[i], -0.1, 0.1);
  within(who, "gyroBiasWalk", p.gyroBiasWalk, 0.0, 1.0);
  within(who, "accelBiasWalk", p.accelBiasWalk, 0.0, 10.0);
  within(who, "temperatureRiseK", p.temperatureRiseK, -100.0, 100.0);
  positive(who, "temperatureTauS", p.temperatureTauS);
  allFinite(who, "gyroBiasPerK", p.gyroBiasPerK);
  allFinite(who, "accelBiasPerK", p.accelBiasPerK);
  std::ostringstream atMost;
  atMost << "must be > 0 and at most the output rate " << outputRateHz << " Hz";
  for (const auto& [name, rate] :
       {std::pair{"gyroRateHz", p.gyroRateHz}, std::pair{"accelRateHz", p.accelRateHz}}) {
    if (rate && (!std::isfinite(*rate) || !(*rate > 0.0) || *rate > outputRateHz * (1.0 + 1e-12)))
      fail(who, name, atMost.str(), *rate);
  }
  const double fastest =
      std::max(p.gyroRateHz.value_or(outputRateHz), p.accelRateHz.value_or(outputRateHz));
  within(who, "jitterStdS", p.jitterStdS, 0.0, 0.5 / (3.0 * fastest));
  within(who, "clockOffsetS", p.clockOffsetS, -0.1, 0.1);
  within(who, "gyroRange", p.gyroRange, 0.0, 1e4);
  within(who, "accelRange", p.accelRange, 0.0, 1e5);
  within(who, "gyroLsb", p.gyroLsb, 0.0, 1.0);
  within(who, "accelLsb", p.accelLsb, 0.0, 10.0);
  within(who, "wobbleFrequencyHz", p.wobbleFrequencyHz, 0.1, 200.0);
  within(who, "wobbleDamping", p.wobbleDamping, 1e-3, 2.0);
  within(who, "wobbleTiltPerAccel", p.wobbleTiltPerAccel, 0.0, 0.01);
  within(who, "wobbleTranslationGain", p.wobbleTranslationGain, 0.0, 1.0);
  unit(who, "skinNormal", p.skinNormal);
  within(who, "slipMaxRad", p.slipMaxRad, -std::numbers::pi / 2, std::numbers::pi / 2);
  positive(who, "slipTauS", p.slipTauS);
  unit(who, "slipAxis", p.slipAxis);
}

ImuErrorModel::ImuErrorModel(const ImuSimParams& imu, std::uint64_t seed, std::uint32_t stream,
                             const std::string& who)
    : m_p(imu.errors),
      m_misalignment(imu.misalignment),
      m_gyroBias0(imu.gyroBias),
      m_accelBias0(imu.accelBias),
      m_gyroNoise(imu.gyroNoiseStd),
      m_accelNoise(imu.accelNoiseStd) {
  if (!(imu.rateHz > 0.0) || !std::isfinite(imu.rateHz))
    throw std::invalid_argument(who + ": the output rate must be > 0");
  ImuErrorParams p = m_p;
  p.enabled = true;
  checkImuErrors(p, imu.rateHz, who);
  m_gyro.rate = m_p.gyroRateHz.value_or(imu.rateHz);
  m_accel.rate = m_p.accelRateHz.value_or(imu.rateHz);
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    stream, 0x1e44u};
  m_rng.seed(seq);
}

double ImuErrorModel::normal() {
  return m_normal(m_rng);
}

Eigen::Vector3d ImuErrorModel::normal3() {
  const double x = normal(), y = normal(), z = normal();
  return {x, y, z};
}

double ImuErrorModel::slipAngle() const {
  return m_p.slipMaxRad * (1.0 - std::exp(-m_time / m_p.slipTauS));
}

Eigen::Vector3d ImuErrorModel::gyroBias() const {
  const double dT = m_p.temperatureRiseK * (1.0 - std::exp(-m_time / m_p.temperatureTauS));
  return m_gyroBias0 + m_walkGyro + m_p.gyroBiasPerK * dT;
}

Eigen::Vector3d ImuErrorModel::accelBias() const {
  const double dT = m_p.temperatureRiseK * (1.0 - std::exp(-m_time / m_p.temperatureTauS));
  return m_accelBias0 + m_walkAccel + m_p.accelBiasPerK * dT;
}

void ImuErrorModel::skipTo(double t) {
  if (!(t > 0.0) || m_started) return;
  m_time = t;
  // The last internal sample at or before t is the first one taken: a row right after t holds a
  // real reading, not an empty one.
  for (Channel* c : {&m_gyro, &m_accel})
    c->next = static_cast<std::uint64_t>(std::max(0.0, std::floor(t * c->rate + 1e-9)));
}

namespace {

struct Wobble {
  Eigen::Vector3d phi, phiDot, x, xDot;
};

}  // namespace

void ImuErrorModel::advance(double to, const TruthFn& truth) {
  if (!(to > m_time)) return;
  const double dt = to - m_time;
  if (m_p.gyroBiasWalk > 0.0) m_walkGyro += m_p.gyroBiasWalk * std::sqrt(dt) * normal3();
  if (m_p.accelBiasWalk > 0.0) m_walkAccel += m_p.accelBiasWalk * std::sqrt(dt) * normal3();
  const bool wobble = m_p.wobbleTiltPerAccel > 0.0 || m_p.wobbleTranslationGain > 0.0;
  if (!wobble) {
    m_time = to;
    return;
  }
  const double w = 2.0 * std::numbers::pi * m_p.wobbleFrequencyHz, z = m_p.wobbleDamping;
  const Eigen::Vector3d n = m_p.skinNormal;
  const double k = m_p.wobbleTiltPerAccel, lambda = m_p.wobbleTranslationGain;
  const auto deriv = [&](const Wobble& s, const Eigen::Vector3d& a, Wobble& d) {
    const Eigen::Vector3d across = a - n * n.dot(a);
    d.phi = s.phiDot;
    d.phiDot = -2.0 * z * w * s.phiDot - w * w * s.phi - w * w * k * n.cross(a);
    d.x = s.xDot;
    d.xDot = -2.0 * z * w * s.xDot - w * w * s.x - lambda * across;
  };
  // Fourth-order Runge-Kutta in steps of at most 0.5 ms (w h <= 0.063 at 20 Hz), the segment's
  // acceleration interpolated linearly within each step.
  const int steps = std::max(1, static_cast<int>(std::ceil(dt / 0.0005)));
  const double h = dt / steps;
  Wobble s{m_phi, m_phiDot, m_x, m_xDot};
  for (int i = 0; i < steps; ++i) {
    const double t1 = i + 1 == steps ? to : m_time + (i + 1) * h;
    const Eigen::Vector3d a0 = m_lastLin, a1 = truth(t1).linAcc, am = 0.5 * (a0 + a1);
    Wobble k1, k2, k3, k4, tmp;
    const auto step = [&](const Wobble& d, double f) {
      return Wobble{s.phi + f * d.phi, s.phiDot + f * d.phiDot, s.x + f * d.x, s.xDot + f * d.xDot};
    };
    deriv(s, a0, k1);
    tmp = step(k1, h / 2);
    deriv(tmp, am, k2);
    tmp = step(k2, h / 2);
    deriv(tmp, am, k3);
    tmp = step(k3, h);
    deriv(tmp, a1, k4);
    s.phi += h / 6 * (k1.phi + 2 * k2.phi + 2 * k3.phi + k4.phi);
    s.phiDot += h / 6 * (k1.phiDot + 2 * k2.phiDot + 2 * k3.phiDot + k4.phiDot);
    s.x += h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x);
    s.xDot += h / 6 * (k1.xDot + 2 * k2.xDot + 2 * k3.xDot + k4.xDot);
    m_lastLin = a1;
  }
  m_phi = s.phi;
  m_phiDot = s.phiDot;
  m_x = s.x;
  m_xDot = s.xDot;
  m_time = to;
}

void ImuErrorModel::sample(bool gyro, double trueTime, const TruthFn& truth) {
  const ImuTruth tr = truth(trueTime);
  const double w = 2.0 * std::numbers::pi * m_p.wobbleFrequencyHz, z = m_p.wobbleDamping;
  const Eigen::Vector3d n = m_p.skinNormal;
  const Eigen::Vector3d across = tr.linAcc - n * n.dot(tr.linAcc);
  // The sensor's relative acceleration on the tissue (zero without translational wobble).
  const Eigen::Vector3d xDdot =
      -2.0 * z * w * m_xDot - w * w * m_x - m_p.wobbleTranslationGain * across;
  const Eigen::Vector3d shift = m_p.wobbleTranslationGain > 0.0 ? xDdot : Eigen::Vector3d::Zero();
  // The sensor's axes in the model's IMU frame: slip about the long axis, the wobble's tilt, then
  // the sensor's own mounting error.
  const double psi = slipAngle();
  const double psiDot = m_p.slipMaxRad / m_p.slipTauS * std::exp(-m_time / m_p.slipTauS);
  Eigen::Matrix3d tilt = Eigen::Matrix3d::Identity();
  if (m_phi.norm() > 0.0)
    tilt = Eigen::AngleAxisd(m_phi.norm(), m_phi.normalized()).toRotationMatrix();
  const Eigen::Matrix3d slip = Eigen::AngleAxisd(psi, m_p.slipAxis).toRotationMatrix();
  const Eigen::Matrix3d axes = slip * tilt * m_misalignment;
  const Eigen::Vector3d rate =
      axes.transpose() * tr.gyr + m_misalignment.transpose() * (m_phiDot + psiDot * m_p.slipAxis);
  const Eigen::Vector3d force = axes.transpose() * (tr.acc + shift);
  const Eigen::Vector3d noise = normal3();
  Channel& c = gyro ? m_gyro : m_accel;
  if (gyro) {
    const Eigen::Matrix3d scale = Eigen::Matrix3d::Identity() +
                                  Eigen::Matrix3d(m_p.gyroScale.asDiagonal()) + m_p.gyroCrossAxis;
    c.value =
        clampRound(scale * rate + m_p.gyroGSensitivity * force + gyroBias() + m_gyroNoise * noise,
                   m_p.gyroRange, m_p.gyroLsb);
  } else {
    const Eigen::Matrix3d scale = Eigen::Matrix3d::Identity() +
                                  Eigen::Matrix3d(m_p.accelScale.asDiagonal()) + m_p.accelCrossAxis;
    c.value = clampRound(scale * force + accelBias() + m_accelNoise * noise, m_p.accelRange,
                         m_p.accelLsb);
  }
  c.trueTime = trueTime;
  c.has = true;
}

ImuReading ImuErrorModel::reading(double t, const TruthFn& truth) {
  if (!m_started) {
    m_started = true;
    const ImuTruth first = truth(m_time);
    m_lastLin = first.linAcc;
    // The wobble starts at rest on the tissue under the first acceleration (no start transient).
    const double w = 2.0 * std::numbers::pi * m_p.wobbleFrequencyHz;
    const Eigen::Vector3d n = m_p.skinNormal;
    m_phi = -m_p.wobbleTiltPerAccel * n.cross(first.linAcc);
    m_x = -m_p.wobbleTranslationGain * (first.linAcc - n * n.dot(first.linAcc)) / (w * w);
  }
  const auto stamp = [](const Channel& c) { return static_cast<double>(c.next) / c.rate; };
  // Each channel's next sample has its jitter drawn once; the due samples are taken in the order
  // of their true times (the jitter never reorders one channel's samples: it is clipped at 3
  // sigma, below a sixth of the sampling period).
  const auto trueTime = [&](Channel& c) {
    if (!c.jitterDrawn) {
      c.jitter = std::clamp(normal(), -3.0, 3.0) * m_p.jitterStdS;
      c.jitterDrawn = true;
    }
    return stamp(c) + m_p.clockOffsetS + c.jitter;
  };
  for (;;) {
    const bool gyroDue = stamp(m_gyro) <= t + 1e-9, accelDue = stamp(m_accel) <= t + 1e-9;
    if (!gyroDue && !accelDue) break;
    const bool gyro = gyroDue && (!accelDue || trueTime(m_gyro) <= trueTime(m_accel));
    Channel& c = gyro ? m_gyro : m_accel;
    const double when = std::max(m_time, trueTime(c));
    advance(when, truth);
    sample(gyro, when, truth);
    ++c.next;
    c.jitterDrawn = false;
  }
  ImuReading r;
  r.gyr = m_gyro.value;
  r.acc = m_accel.value;
  return r;
}

SensorModel parseSensorModel(const std::string& text) {
  if (text == "ideal") return SensorModel::Ideal;
  if (text == "realistic") return SensorModel::Realistic;
  throw std::invalid_argument("unknown sensor model '" + text + "': use ideal or realistic");
}

ImuErrorParams realisticImuErrors(std::uint64_t seed, int sensor, double outputRateHz,
                                  Eigen::Vector3d* drawnGyroBias, Eigen::Vector3d* drawnAccelBias) {
  using B = RealisticBounds;
  if (!(outputRateHz > 0.0) || !std::isfinite(outputRateHz))
    throw std::invalid_argument("realisticImuErrors: the output rate must be > 0");
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(sensor), 0x7ea1u};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto between = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  const auto sym = [&](double b) { return between(-b, b); };
  const auto vec = [&](double b) {
    const double x = sym(b), y = sym(b), z = sym(b);
    return Eigen::Vector3d(x, y, z);
  };
  const auto cross = [&](double b) {
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (i != j) m(i, j) = sym(b);
    return m;
  };
  ImuErrorParams p;
  p.enabled = true;
  p.gyroScale = vec(B::kGyroScale);
  p.gyroCrossAxis = cross(B::kGyroCrossAxis);
  p.accelScale = vec(B::kAccelScale);
  p.accelCrossAxis = cross(B::kAccelCrossAxis);
  for (Eigen::Index i = 0; i < 9; ++i) p.gyroGSensitivity.data()[i] = sym(B::kGyroGSensitivity);
  const Eigen::Vector3d gyroBias = vec(B::kGyroBias), accelBias = vec(B::kAccelBias);
  if (drawnGyroBias) *drawnGyroBias = gyroBias;
  if (drawnAccelBias) *drawnAccelBias = accelBias;
  p.gyroBiasWalk = between(B::kGyroWalkMin, B::kGyroWalkMax);
  p.accelBiasWalk = between(B::kAccelWalkMin, B::kAccelWalkMax);
  p.temperatureRiseK = between(B::kRiseMinK, B::kRiseMaxK);
  p.temperatureTauS = between(B::kTempTauMinS, B::kTempTauMaxS);
  p.gyroBiasPerK = vec(B::kGyroBiasPerK);
  p.accelBiasPerK = vec(B::kAccelBiasPerK);
  p.gyroRateHz = outputRateHz * B::kGyroRateRatio;
  p.accelRateHz = outputRateHz * B::kAccelRateRatio;
  p.jitterStdS = std::min(between(B::kJitterMinS, B::kJitterMaxS), 0.5 / (3.0 * *p.gyroRateHz));
  p.clockOffsetS = sym(B::kClockOffsetS);
  p.gyroRange = B::kGyroRange;
  p.accelRange = B::kAccelRange;
  p.gyroLsb = B::kGyroLsb;
  p.accelLsb = B::kAccelLsb;
  p.wobbleFrequencyHz = between(B::kWobbleMinHz, B::kWobbleMaxHz);
  p.wobbleDamping = between(B::kWobbleDampingMin, B::kWobbleDampingMax);
  p.wobbleTiltPerAccel = between(B::kTiltPerAccelMin, B::kTiltPerAccelMax);
  p.wobbleTranslationGain = between(B::kTranslationGainMin, B::kTranslationGainMax);
  const double slip = between(B::kSlipMinRad, B::kSlipMaxRad);
  p.slipMaxRad = unit(rng) < 0.5 ? -slip : slip;
  p.slipTauS = between(B::kSlipTauMinS, B::kSlipTauMaxS);
  // The sternum IMU (sensor 2): z out of the chest, x up the trunk's long axis.
  if (sensor == 2) p.slipAxis = Eigen::Vector3d::UnitX();
  return p;
}

void applySensorModel(SensorModel model, SimulationParams& sim, std::optional<double> imuRateHz) {
  if (model == SensorModel::Ideal) return;
  const double rate = imuRateHz.value_or(RealisticBounds::kOutputRateHz);
  int sensor = 0;
  for (ImuSimParams* imu : {&sim.upperArm, &sim.forearm, &sim.trunkImu}) {
    Eigen::Vector3d gyroBias, accelBias;
    imu->rateHz = rate;
    imu->errors = realisticImuErrors(sim.seed, sensor++, rate, &gyroBias, &accelBias);
    imu->gyroBias += gyroBias;
    imu->accelBias += accelBias;
  }
}

}  // namespace armtrack
