#include "core/simulation/TrunkMotion.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace armtrack {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

bool finite(double v) {
  return std::isfinite(v);
}

// The quintic smoothstep of x = (u - lo) / span and its first two time derivatives, given u's.
struct Ramp {
  double s = 0.0, sd = 0.0, sdd = 0.0;
};
Ramp smoothstep(double u, double ud, double udd, double lo, double span) {
  const double x = (u - lo) / span;
  Ramp r;
  if (x >= 1.0) {
    r.s = 1.0;
  } else if (x > 0.0) {
    const double xd = ud / span, xdd = udd / span;
    const double s1 = 30.0 * x * x * (1.0 - x) * (1.0 - x);    // S'(x)
    const double s2 = 60.0 * x * (1.0 - x) * (1.0 - 2.0 * x);  // S''(x)
    r.s = x * x * x * (10.0 + x * (-15.0 + 6.0 * x));
    r.sd = s1 * xd;
    r.sdd = s2 * xd * xd + s1 * xdd;
  }
  return r;
}

}  // namespace

Eigen::Vector3d defaultHip(Side side) {
  return {0.45, 0.0, side == Side::Left ? 0.15 : -0.15};
}

TrunkMotion::TrunkMotion(const TrunkSimParams& p) : m_params(p) {
  if (!finite(p.leanDeg) || !finite(p.lateralRatio) || !finite(p.rotationRatio) ||
      !finite(p.reachStartDeg) || !finite(p.fullReachDeg) || !finite(p.swayDeg) ||
      !finite(p.swayMinHz) || !finite(p.swayMaxHz) || !finite(p.startSeconds) ||
      !finite(p.followSeconds) ||
      (p.hip && !p.hip->allFinite()))
    throw std::invalid_argument("trunk motion: every value must be finite");
  if (std::abs(p.lateralSign) != 1.0 || std::abs(p.rotationSign) != 1.0)
    throw std::invalid_argument("trunk motion: the lateral and rotation signs must be +1 or -1");
  if (!(p.fullReachDeg > p.reachStartDeg))
    throw std::invalid_argument(
        "trunk motion: the fullest reach must be a larger shoulder flexion than the lean's start");
  if (p.swayDeg < 0.0) throw std::invalid_argument("trunk motion: the sway must be >= 0 deg");
  if (p.startSeconds < 0.0)
    throw std::invalid_argument("trunk motion: the lean's start must be >= 0 s");
  if (p.followSeconds < 0.0 || p.followSeconds > 10.0)
    throw std::invalid_argument("trunk motion: the trunk's following time must be 0-10 s");
  if (!(p.swayMinHz > 0.0) || !(p.swayMaxHz >= p.swayMinHz))
    throw std::invalid_argument("trunk motion: sway frequencies must satisfy 0 < min <= max");
  // One sway component per angle, drawn in a fixed order (frequency, then phase).
  std::mt19937_64 rng(p.swaySeed);
  std::uniform_real_distribution<double> freq(p.swayMinHz, p.swayMaxHz);
  std::uniform_real_distribution<double> phase(0.0, kTwoPi);
  for (Sway& s : m_sway) {
    s.amplitude = 0.5 * p.swayDeg * kDeg;
    s.frequency = freq(rng);
    s.phase = phase(rng);
  }
  // Raised-cosine weights at the taps' midpoints: the newest and oldest count least.
  double sum = 0.0;
  for (int i = 0; i < kFollowTaps; ++i) {
    const double x = std::sin(std::numbers::pi * (i + 0.5) / kFollowTaps);
    m_weight[static_cast<std::size_t>(i)] = x * x;
    sum += x * x;
  }
  for (double& w : m_weight) w /= sum;
}

TrunkMotion::Reach TrunkMotion::target(double t, const JointMotion& arm) const {
  const TrunkSimParams& p = m_params;
  const Ramp reach = smoothstep(arm.th(0), arm.thd(0), arm.thdd(0), p.reachStartDeg * kDeg,
                                (p.fullReachDeg - p.reachStartDeg) * kDeg);
  const Ramp start =
      p.startSeconds > 0.0 ? smoothstep(t, 1.0, 0.0, 0.0, p.startSeconds) : Ramp{1.0, 0.0, 0.0};
  return {reach.s * start.s, reach.sd * start.s + reach.s * start.sd,
          reach.sdd * start.s + 2.0 * reach.sd * start.sd + reach.s * start.sdd};
}

TrunkMotionState TrunkMotion::at(double t, const Trajectory& arm) const {
  const TrunkSimParams& p = m_params;
  // The trunk's reach w: the target's average over the last followSeconds (before t = 0 the
  // target holds its value at 0, so its derivatives there are 0).
  Reach avg;
  if (p.followSeconds <= 0.0) {
    avg = target(t, arm.at(t));
  } else {
    for (int i = 0; i < kFollowTaps; ++i) {
      const double u = t - p.followSeconds * (i + 0.5) / kFollowTaps;
      const Reach r = u > 0.0 ? target(u, arm.at(u)) : Reach{target(0.0, arm.at(0.0)).w, 0.0, 0.0};
      const double c = m_weight[static_cast<std::size_t>(i)];
      avg.w += c * r.w;
      avg.wd += c * r.wd;
      avg.wdd += c * r.wdd;
    }
  }
  const double w = avg.w, wd = avg.wd, wdd = avg.wdd;
  const double lean = p.leanDeg * kDeg;
  const Eigen::Vector3d full(lean, p.lateralSign * p.lateralRatio * lean,
                             p.rotationSign * p.rotationRatio * lean);
  TrunkMotionState out;
  for (int i = 0; i < 3; ++i) {
    const Sway& s = m_sway[static_cast<std::size_t>(i)];
    const double om = kTwoPi * s.frequency, arg = om * t + s.phase;
    const double sw = s.amplitude * (std::sin(arg) - std::sin(s.phase));
    const double swd = s.amplitude * om * std::cos(arg);
    const double swdd = -s.amplitude * om * om * std::sin(arg);
    out.angles(i) = full(i) * w + (1.0 - w) * sw;
    out.rates(i) = full(i) * wd - wd * sw + (1.0 - w) * swd;
    out.accels(i) = full(i) * wdd - wdd * sw - 2.0 * wd * swd + (1.0 - w) * swdd;
  }
  return out;
}

TrunkPose trunkPose(const TrunkMotionState& m, Side side) {
  // trunkRotation = Rz(al) Ry(be) Rx(ga) with al = -flexion, be = s lateral, ga = -s rotation.
  const double s = side == Side::Left ? -1.0 : 1.0;
  const Eigen::Vector3d k(-1.0, s, -s);
  const Eigen::Vector3d ang = k.cwiseProduct(m.angles), rate = k.cwiseProduct(m.rates),
                        acc = k.cwiseProduct(m.accels);
  const Eigen::Matrix3d rz = Eigen::AngleAxisd(ang(0), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d ry = Eigen::AngleAxisd(ang(1), Eigen::Vector3d::UnitY()).toRotationMatrix();
  // The three rotation axes in world coordinates: z, then y turned by Rz, then x turned by Rz Ry.
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d u = rz * Eigen::Vector3d::UnitY();
  const Eigen::Vector3d v = rz * ry * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d wz = rate(0) * z;        // the first rotation's rate
  const Eigen::Vector3d wzy = wz + rate(1) * u;  // the first two
  const Eigen::Vector3d ud = wz.cross(u), vd = wzy.cross(v);
  TrunkPose pose;
  pose.rotation = trunkRotation(m.angles, side);
  pose.omega = wzy + rate(2) * v;
  pose.omegaDot = acc(0) * z + acc(1) * u + rate(1) * ud + acc(2) * v + rate(2) * vd;
  return pose;
}

FrameState<double> trunkBase(const TrunkPose& pose, const Eigen::Vector3d& hip,
                             const Eigen::Vector3d& gUpWorld) {
  // The shoulder centre s = h - R h turns about the hip: s'' = w. x (-R h) + w x (w x (-R h)).
  const Eigen::Vector3d r = -(pose.rotation * hip);
  const Eigen::Vector3d acc = pose.omegaDot.cross(r) + pose.omega.cross(pose.omega.cross(r));
  const Eigen::Matrix3d rt = pose.rotation.transpose();
  FrameState<double> base;
  base.omega = rt * pose.omega;
  base.omegaDot = rt * pose.omegaDot;  // d/dt (R^T w) = R^T w. since R'^T w = -R^T (w x w) = 0
  base.accel = rt * acc;
  base.up = rt * gUpWorld;
  return base;
}

}  // namespace armtrack
