#include "core/orientation/OrientationFilter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace armtrack {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
// Coefficients are rebuilt when dt differs from the one they were made for by more than this
// fraction; timestamp rounding alone should not trigger a rebuild on every sample.
constexpr double kDtTolerance = 1e-4;
// Without updates the bias variance grows by kForgettingSigma^2 per biasForgettingTime.
constexpr double kForgettingSigma = 0.1 * kDegToRad;

// Second-order Butterworth low-pass by the bilinear transform with pre-warping. The cut-off is
// chosen so that the decaying (non-oscillating) part of the step response has time constant tau:
// the analogue poles sit at wc * exp(+-3i pi / 4), whose real part is wc / sqrt(2) = 1 / tau.
LowPassCoeffs butterworth(double tau, double dt) {
  const double wc = std::numbers::sqrt2 / tau;
  // For dt of the order of tau the tangent runs off towards pi / 2; cap the warped frequency so
  // that long gaps still give a stable filter.
  const double k = std::tan(std::min(0.5 * wc * dt, 1.2));
  const double k2 = k * k;
  const double d = k2 + std::numbers::sqrt2 * k + 1.0;
  LowPassCoeffs c;
  c.b0 = k2 / d;
  c.b1 = 2.0 * c.b0;
  c.b2 = c.b0;
  c.a1 = 2.0 * (k2 - 1.0) / d;
  c.a2 = (k2 - std::numbers::sqrt2 * k + 1.0) / d;
  return c;
}

// Steady state of the transposed direct form II for a constant input equal to the output y:
// s0 = (1 - b0) y and s1 = (b2 - a2) y. When the coefficients change, shift the memory by the
// change of that steady state.
template <int N>
void retune(LowPassState<N>& f, const LowPassCoeffs& from, const LowPassCoeffs& to) {
  if (!f.running) return;
  for (int i = 0; i < N; ++i) {
    f.s0[i] += (from.b0 - to.b0) * f.y[i];
    f.s1[i] += ((to.b2 - to.a2) - (from.b2 - from.a2)) * f.y[i];
  }
}

// One step of the low-pass; the output is f.y. During the first tau seconds the output is the
// running mean, which then seeds the steady state.
template <int N>
inline void lowPass(LowPassState<N>& f, const double* x, const LowPassCoeffs& c, double tau,
                    double dt) {
  if (f.running) [[likely]] {
    for (int i = 0; i < N; ++i) {
      const double y = c.b0 * x[i] + f.s0[i];
      f.s0[i] = c.b1 * x[i] - c.a1 * y + f.s1[i];
      f.s1[i] = c.b2 * x[i] - c.a2 * y;
      f.y[i] = y;
    }
    return;
  }
  ++f.warmupCount;
  f.warmupTime += dt;
  const double w = 1.0 / f.warmupCount;
  for (int i = 0; i < N; ++i) f.y[i] += w * (x[i] - f.y[i]);
  if (f.warmupTime >= tau) {
    for (int i = 0; i < N; ++i) {
      f.s0[i] = (1.0 - c.b0) * f.y[i];
      f.s1[i] = (c.b2 - c.a2) * f.y[i];
    }
    f.running = true;
  }
}

inline double clampAbs(double v, double limit) {
  return std::clamp(v, -limit, limit);
}

}  // namespace

OrientationFilter::OrientationFilter(const OrientationParams& params) : m_p(params) {
  const auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw std::invalid_argument(std::string("OrientationParams::") + name + " must be > 0");
  };
  positive(m_p.tauAcc, "tauAcc");
  positive(m_p.biasSigmaInit, "biasSigmaInit");
  positive(m_p.biasForgettingTime, "biasForgettingTime");
  positive(m_p.biasClip, "biasClip");
  positive(m_p.biasSigmaMotion, "biasSigmaMotion");
  positive(m_p.biasSigmaRest, "biasSigmaRest");
  positive(m_p.restFilterTau, "restFilterTau");
  positive(m_p.restThGyr, "restThGyr");
  positive(m_p.restThAcc, "restThAcc");
  positive(m_p.gyrMax, "gyrMax");
  positive(m_p.accMax, "accMax");
  positive(m_p.gapSeconds, "gapSeconds");
  m_gyrMax = m_p.gyrMax * kDegToRad;
  if (!(m_p.restMinT >= 0.0) || !std::isfinite(m_p.restMinT))
    throw std::invalid_argument("OrientationParams::restMinT must be >= 0");
  if (!(m_p.biasVerticalForgettingFactor >= 0.0))
    throw std::invalid_argument("OrientationParams::biasVerticalForgettingFactor must be >= 0");
  reset();
}

void OrientationFilter::reset() {
  m_s = OrientationState{};
  const double sigma0 = m_p.biasSigmaInit * kDegToRad;
  m_s.biasP = Eigen::Matrix3d::Identity() * (sigma0 * sigma0);
  m_c = Coefficients{};
}

void OrientationFilter::setCoefficients(double dt) {
  const LowPassCoeffs acc = butterworth(m_p.tauAcc, dt);
  const LowPassCoeffs rest = butterworth(m_p.restFilterTau, dt);
  if (m_c.dt > 0.0) {
    retune(m_s.accLp, m_c.acc, acc);
    retune(m_s.rotLp, m_c.acc, acc);
    retune(m_s.biasLp, m_c.acc, acc);
    retune(m_s.restGyrLp, m_c.rest, rest);
    retune(m_s.restAccLp, m_c.rest, rest);
  }
  m_c.dt = dt;
  m_c.acc = acc;
  m_c.rest = rest;

  // Bias Kalman filter. Process noise per step V; the measurement noise W of each update kind is
  // chosen so that the scalar filter with repeated updates settles at the wanted uncertainty p:
  // p = (p + V) W / (p + V + W) gives W = p^2 / V + p.
  const double sigma0 = m_p.biasSigmaInit * kDegToRad;
  m_c.biasP0 = sigma0 * sigma0;
  m_c.biasV = kForgettingSigma * kForgettingSigma * dt / m_p.biasForgettingTime;
  const double pMotion = std::pow(m_p.biasSigmaMotion * kDegToRad, 2);
  m_c.biasMotionW = pMotion * pMotion / m_c.biasV + pMotion;
  m_c.biasVerticalW = m_c.biasMotionW / std::max(m_p.biasVerticalForgettingFactor, 1e-10);
  const double pRest = std::pow(m_p.biasSigmaRest * kDegToRad, 2);
  m_c.biasRestW = pRest * pRest / m_c.biasV + pRest;
}

bool OrientationFilter::reject(const Eigen::Vector3d& gyr, const Eigen::Vector3d& acc, double dt) {
  ++m_s.rejected;
  m_s.last = OrientationStatus::Rejected;
  if (gyr.allFinite() && acc.allFinite()) {
    if (gyr.cwiseAbs().maxCoeff() >= m_gyrMax || acc.cwiseAbs().maxCoeff() >= m_p.accMax)
      ++m_s.outOfRange;
  }
  // The time of a refused sample still passes: the next accepted sample covers it.
  if (dt > 0.0 && std::isfinite(dt)) m_s.pendingDt += dt;
  return false;
}

// Nothing is known about the motion during a gap: keep the last orientation (its heading is the
// best there is), but let the inclination start again from the accelerometer as at start-up,
// and forget every low-passed quantity, since the almost-inertial frame may have turned.
void OrientationFilter::restartAfterGap(double gap) {
  ++m_s.gaps;
  m_s.gapTime += gap;
  m_s.accLp = {};
  m_s.rotLp = {};
  m_s.biasLp = {};
  m_s.restGyrLp = {};
  m_s.restAccLp = {};
  m_s.restTime = 0.0;
  m_s.rest = false;
  m_s.biasHold = true;
  m_s.last = OrientationStatus::AfterGap;
}

bool OrientationFilter::update(const Eigen::Vector3d& gyr, const Eigen::Vector3d& acc,
                               double dtIn) {
  // Plausibility at the door. The largest magnitude propagates NaN (Eigen's default maxCoeff
  // may skip it) and the comparisons are false for NaN, so they also refuse non-finite values
  // (infinity is at or beyond any limit).
  if (!(dtIn > 0.0) || !(dtIn < std::numeric_limits<double>::infinity()) ||
      !(gyr.cwiseAbs().maxCoeff<Eigen::PropagateNaN>() < m_gyrMax) ||
      !(acc.cwiseAbs().maxCoeff<Eigen::PropagateNaN>() < m_p.accMax)) [[unlikely]] {
    return reject(gyr, acc, dtIn);
  }
  double dt = dtIn;
  m_s.last = OrientationStatus::Accepted;
  if (m_s.pendingDt > 0.0) [[unlikely]] {
    dt += m_s.pendingDt;
    m_s.pendingDt = 0.0;
  }
  if (dt > m_p.gapSeconds) [[unlikely]] {
    if (m_s.accepted > 0) {
      restartAfterGap(dt);
      // The gyroscope reading belongs to the end of the gap: integrate it over one ordinary step.
      dt = m_c.dt;
    } else {
      dt = std::min(dt, m_p.gapSeconds);  // the first sample: nothing to integrate yet
    }
  }
  if (std::abs(dt - m_c.dt) > kDtTolerance * m_c.dt) [[unlikely]]
    setCoefficients(dt);
  ++m_s.accepted;
  const bool restEnabled = m_p.restBiasEstEnabled;

  // Rest detection, gyroscope part: the gyroscope must stay close to its low-passed value, and
  // that value must be small enough to be a bias.
  if (restEnabled) {
    lowPass(m_s.restGyrLp, gyr.data(), m_c.rest, m_p.restFilterTau, dt);
    const Eigen::Map<const Eigen::Vector3d> gyrLp(m_s.restGyrLp.y.data());
    const double th = m_p.restThGyr * kDegToRad;
    const double clip = m_p.biasClip * kDegToRad;
    if ((gyr - gyrLp).squaredNorm() >= th * th || gyrLp.cwiseAbs().maxCoeff() > clip) {
      m_s.restTime = 0.0;
      m_s.rest = false;
    }
  }

  // Strapdown integration of the bias-corrected rate over dt (body-frame increment on the right).
  const Eigen::Vector3d w = gyr - m_s.bias;
  const double rate = w.norm();
  if (rate > 1e-15) {
    const double half = 0.5 * rate * dt;
    const double s = std::sin(half) / rate;
    const Eigen::Quaterniond step(std::cos(half), s * w.x(), s * w.y(), s * w.z());
    m_s.gyrQuat = m_s.gyrQuat * step;
    m_s.gyrQuat.normalize();
  }

  if (acc.x() == 0.0 && acc.y() == 0.0 && acc.z() == 0.0) {
    ++m_s.noAcc;
    return true;
  }

  // Rest detection, accelerometer part; rest needs both criteria for restMinT.
  if (restEnabled) {
    lowPass(m_s.restAccLp, acc.data(), m_c.rest, m_p.restFilterTau, dt);
    const Eigen::Map<const Eigen::Vector3d> accLp(m_s.restAccLp.y.data());
    if ((acc - accLp).squaredNorm() >= m_p.restThAcc * m_p.restThAcc) {
      m_s.restTime = 0.0;
      m_s.rest = false;
    } else {
      m_s.restTime += dt;
      if (m_s.restTime >= m_p.restMinT) m_s.rest = true;
    }
  }

  // Low-pass the accelerometer in the almost-inertial frame: there gravity is (nearly) constant
  // while rotation does not smear it, and body acceleration averages out.
  const Eigen::Vector3d accInertial = m_s.gyrQuat * acc;
  lowPass(m_s.accLp, accInertial.data(), m_c.acc, m_p.tauAcc, dt);

  // Inclination correction: rotate the world frame estimate so that the low-passed gravity
  // direction becomes +z. For a unit g the shortest rotation taking g to z has axis g x z =
  // (gy, -gx, 0) and cos(angle) = gz, i.e. q = (sqrt((1 + gz) / 2), gy / 2qw, -gx / 2qw, 0).
  Eigen::Vector3d g = m_s.accQuat * Eigen::Map<const Eigen::Vector3d>(m_s.accLp.y.data());
  const double gNorm = g.norm();
  if (gNorm > 1e-12) {
    g /= gNorm;
    const double qw = std::sqrt(0.5 * (1.0 + g.z()));
    Eigen::Quaterniond corr;
    if (qw > 1e-6) {
      corr = Eigen::Quaterniond(qw, 0.5 * g.y() / qw, -0.5 * g.x() / qw, 0.0);
    } else {
      corr = Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0);  // upside down: half turn about x
    }
    m_s.accQuat = corr * m_s.accQuat;
    m_s.accQuat.normalize();
    estimateBias(g, dt);
  }
  return true;
}

// Gyroscope bias Kalman filter (state: bias in sensor axes; random-walk process noise).
// At rest the measurement is the low-passed gyroscope itself. In motion it is the inclination
// correction expressed as an angular rate: a bias b makes the estimate drift at -R b in the world
// frame (R = sensor->world), which the correction must undo, so the horizontal correction rate
// measures R b. R and R b are low-passed like the accelerometer, matching the correction's lag.
void OrientationFilter::estimateBias(const Eigen::Vector3d& accWorld, double dt) {
  const bool rest = m_p.restBiasEstEnabled && m_s.rest;
  if (m_s.biasHold && m_s.accLp.running) m_s.biasHold = false;
  const bool motionEnabled = m_p.motionBiasEstEnabled;
  const bool motion = motionEnabled && !m_s.biasHold;
  if (!m_p.restBiasEstEnabled && !motionEnabled) return;
  Eigen::Vector3d& bias = m_s.bias;
  Eigen::Matrix3d& P = m_s.biasP;

  // Predict: the uncertainty grows (up to its initial value) whether or not an update follows.
  for (int i = 0; i < 3; ++i) {
    if (P(i, i) < m_c.biasP0) P(i, i) += m_c.biasV;
  }

  Eigen::Matrix3d H;
  Eigen::Vector3d e;
  double w0, w1, w2;
  if (motionEnabled) {
    // Low-pass even at rest and while held, so the filters are settled when updates start.
    Eigen::Matrix3d R = orientation().toRotationMatrix();
    const Eigen::Vector3d rb = R * bias;
    lowPass(m_s.rotLp, R.data(), m_c.acc, m_p.tauAcc, dt);
    lowPass(m_s.biasLp, rb.data(), m_c.acc, m_p.tauAcc, dt);
  }
  if (!rest && !motion) return;
  if (motion) {
    H = Eigen::Map<const Eigen::Matrix3d>(m_s.rotLp.y.data());
    const Eigen::Vector3d hb = H * bias;
    e.x() = -accWorld.y() / dt + m_s.biasLp.y[0] - hb.x();
    e.y() = accWorld.x() / dt + m_s.biasLp.y[1] - hb.y();
    e.z() = -hb.z();
    w0 = w1 = m_c.biasMotionW;
    w2 = m_c.biasVerticalW;
  }
  if (rest) {
    H.setIdentity();
    e = Eigen::Map<const Eigen::Vector3d>(m_s.restGyrLp.y.data()) - bias;
    w0 = w1 = w2 = m_c.biasRestW;
  }

  // Update. Large disagreements (e.g. the very first correction) are clipped.
  const double clip = m_p.biasClip * kDegToRad;
  for (int i = 0; i < 3; ++i) e(i) = clampAbs(e(i), clip);
  const Eigen::Matrix3d PHt = P * H.transpose();
  Eigen::Matrix3d S = H * PHt;
  S(0, 0) += w0;
  S(1, 1) += w1;
  S(2, 2) += w2;
  const Eigen::Matrix3d K = PHt * S.inverse();
  bias += K * e;
  P -= K * (H * P);
  for (int i = 0; i < 3; ++i) bias(i) = clampAbs(bias(i), clip);
}

std::size_t OrientationFilter::updateBatch(std::span<const double> gyr, std::span<const double> acc,
                                           std::span<const double> dt, std::span<double> quatOut,
                                           std::span<OrientationStatus> statusOut) {
  const std::size_t n = dt.size();
  if (gyr.size() != 3 * n || acc.size() != 3 * n || (!quatOut.empty() && quatOut.size() != 4 * n) ||
      (!statusOut.empty() && statusOut.size() != n))
    throw std::invalid_argument("OrientationFilter::updateBatch: sizes do not match");
  std::size_t accepted = 0;
  for (std::size_t i = 0; i < n; ++i) {
    accepted += update(Eigen::Vector3d(gyr[3 * i], gyr[3 * i + 1], gyr[3 * i + 2]),
                       Eigen::Vector3d(acc[3 * i], acc[3 * i + 1], acc[3 * i + 2]), dt[i]);
    if (!statusOut.empty()) statusOut[i] = m_s.last;
    if (!quatOut.empty()) {
      const Eigen::Quaterniond q = orientation();
      double* o = quatOut.data() + 4 * i;
      o[0] = q.w();
      o[1] = q.x();
      o[2] = q.y();
      o[3] = q.z();
    }
  }
  return accepted;
}

double OrientationFilter::biasSigma() const {
  // The largest absolute row sum bounds the largest eigenvalue (Gershgorin).
  const double bound = m_s.biasP.cwiseAbs().rowwise().sum().maxCoeff();
  const double p0 = std::pow(m_p.biasSigmaInit * kDegToRad, 2);
  return std::sqrt(std::min(bound, p0));
}

double inclinationError(const Eigen::Quaterniond& estimate, const Eigen::Quaterniond& truth) {
  // World z in sensor axes: R^T z, i.e. the conjugate rotation applied to z.
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d upEst = estimate.normalized().conjugate() * z;
  const Eigen::Vector3d upTrue = truth.normalized().conjugate() * z;
  return std::atan2(upEst.cross(upTrue).norm(), upEst.dot(upTrue));
}

}  // namespace armtrack
