#include "core/simulation/Trajectory.h"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace armtrack {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// Multi-joint motion: centre posture, the summed amplitude at amplitudeScale = 1, and a hard cap
// on the summed amplitude that keeps the motion anatomical for any scale (all rad). The caps keep
// th1 within [-20, 80] deg (away from the +-90 deg gimbal singularity) and th4 within [-120, 0].
constexpr std::array<double, kNumJoints> kCentre{40 * kDeg, 30 * kDeg, 0.0, -60 * kDeg, 0.0};
constexpr std::array<double, kNumJoints> kAmplitude{40 * kDeg, 25 * kDeg, 35 * kDeg, 45 * kDeg,
                                                    50 * kDeg};
constexpr std::array<double, kNumJoints> kAmplitudeCap{80 * kDeg, 50 * kDeg, 60 * kDeg, 60 * kDeg,
                                                       80 * kDeg};
constexpr double kMinFrequencyHz = 0.1;

// Unit vector at angle a in the (x0, y0) plane and its derivative with respect to a.
Eigen::Vector2d dir(double a) {
  return {std::cos(a), std::sin(a)};
}
Eigen::Vector2d dirPrime(double a) {
  return {-std::sin(a), std::cos(a)};
}

}  // namespace

JointMotion SinusoidTrajectory::at(double t) const {
  JointMotion m;
  for (int j = 0; j < kNumJoints; ++j) {
    const double w = kTwoPi * frequency(j);
    const double s = std::sin(w * t + phase(j)), c = std::cos(w * t + phase(j));
    m.th(j) = offset(j) + amplitude(j) * s;
    m.thd(j) = amplitude(j) * w * c;
    m.thdd(j) = -amplitude(j) * w * w * s;
  }
  return m;
}

MultiJointTrajectory::MultiJointTrajectory(std::uint64_t seed, double maxFrequencyHz,
                                           double amplitudeScale) {
  if (!(maxFrequencyHz >= kMinFrequencyHz) || !std::isfinite(maxFrequencyHz))
    throw std::invalid_argument("MultiJointTrajectory: maxFrequencyHz must be >= 0.1 Hz");
  if (!(amplitudeScale >= 0.0) || !std::isfinite(amplitudeScale))
    throw std::invalid_argument("MultiJointTrajectory: amplitudeScale must be >= 0");

  for (int j = 0; j < kNumJoints; ++j) m_centre(j) = kCentre[j];

  // Draw order is fixed: per joint, the component count, then per component weight, frequency
  // and phase. The first component is the dominant one.
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> count(2, 3);
  std::uniform_real_distribution<double> minorWeight(0.2, 0.6);
  std::uniform_real_distribution<double> freq(kMinFrequencyHz, maxFrequencyHz);
  std::uniform_real_distribution<double> phase(0.0, kTwoPi);
  for (int j = 0; j < kNumJoints; ++j) {
    const int n = count(rng);
    const std::size_t first = m_components.size();
    double weightSum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double weight = i == 0 ? 1.0 : minorWeight(rng);
      weightSum += weight;
      const double f = freq(rng);
      m_components.push_back({j, weight, f, phase(rng)});
    }
    // Amplitudes sum to the joint's total, so |th - centre| never exceeds it.
    const double total = std::min(kAmplitude[j] * amplitudeScale, kAmplitudeCap[j]);
    for (std::size_t i = first; i < m_components.size(); ++i)
      m_components[i].amplitude *= total / weightSum;
  }
}

JointMotion MultiJointTrajectory::at(double t) const {
  JointMotion m;
  m.th = m_centre;
  for (const Component& c : m_components) {
    const double w = kTwoPi * c.frequency;
    const double s = std::sin(w * t + c.phase), co = std::cos(w * t + c.phase);
    m.th(c.joint) += c.amplitude * s;
    m.thd(c.joint) += c.amplitude * w * co;
    m.thdd(c.joint) -= c.amplitude * w * w * s;
  }
  return m;
}

ShoulderWheelTrajectory::ShoulderWheelTrajectory(const ArmGeometry& geometry, double periodSeconds,
                                                 double w, double h, double r, double s)
    : m_geometry(geometry), m_period(periodSeconds), m_w(w), m_h(h), m_r(r), m_s(s) {
  if (!(periodSeconds > 0.0) || !std::isfinite(periodSeconds))
    throw std::invalid_argument("ShoulderWheelTrajectory: period must be > 0 s");
  if (!(r >= 0.0)) throw std::invalid_argument("ShoulderWheelTrajectory: radius must be >= 0");
  // Every handle position must be strictly inside the reachable annulus (no straight or fully
  // folded arm, where the IK is singular), and the circle must not enclose the shoulder.
  const double l1 = geometry.l3, l2 = geometry.l6 + s;
  const double c = std::hypot(h, w);
  if (!(c - r > std::abs(l1 - l2)) || !(c + r < l1 + l2) || !(l1 > 0.0) || !(l2 > 0.0))
    throw std::invalid_argument("ShoulderWheelTrajectory: wheel handle not reachable everywhere");
}

JointVector ShoulderWheelTrajectory::anglesAt(double phi) const {
  const double l1 = m_geometry.l3, l2 = m_geometry.l6 + m_s;
  const Eigen::Vector2d centre(m_h, m_w);
  const Eigen::Vector2d p = centre + m_r * dir(phi);
  // Elbow flexion q = -th4 >= 0 from the law of cosines.
  const double cq = (p.squaredNorm() - l1 * l1 - l2 * l2) / (2.0 * l1 * l2);
  const double q = std::acos(std::clamp(cq, -1.0, 1.0));
  // Direction of p measured from the centre's direction: continuous because the circle does not
  // enclose the shoulder.
  const double centreAngle = std::atan2(centre.y(), centre.x());
  const double pAngle =
      centreAngle + std::atan2(centre.x() * p.y() - centre.y() * p.x(), centre.dot(p));
  JointVector th = JointVector::Zero();
  th(0) = pAngle - std::atan2(l2 * std::sin(q), l1 + l2 * std::cos(q));
  th(3) = -q;
  return th;
}

JointMotion ShoulderWheelTrajectory::at(double t) const {
  const double omega = kTwoPi / m_period;  // wheel rate, rad/s
  const double phi = omega * t;
  const double l1 = m_geometry.l3, l2 = m_geometry.l6 + m_s;
  JointMotion m;
  m.th = anglesAt(phi);
  // Planar chain p = l1 e(a) + l2 e(a + q), a = th0, q = -th4. Differentiate twice:
  //   p'  = J [a' q']^T,  J = [l1 e'(a) + l2 e'(a+q), l2 e'(a+q)]
  //   p'' = J [a'' q'']^T - l1 e(a) a'^2 - l2 e(a+q) (a' + q')^2
  const double a = m.th(0), q = -m.th(3);
  Eigen::Matrix2d jac;
  jac.col(1) = l2 * dirPrime(a + q);
  jac.col(0) = l1 * dirPrime(a) + jac.col(1);
  const Eigen::Vector2d pd = m_r * omega * dirPrime(phi);
  const Eigen::Vector2d pdd = -m_r * omega * omega * dir(phi);
  const Eigen::Vector2d rate = jac.partialPivLu().solve(pd);
  const Eigen::Vector2d rhs =
      pdd + l1 * dir(a) * rate(0) * rate(0) + l2 * dir(a + q) * std::pow(rate(0) + rate(1), 2);
  const Eigen::Vector2d acc = jac.partialPivLu().solve(rhs);
  m.thd(0) = rate(0);
  m.thd(3) = -rate(1);
  m.thdd(0) = acc(0);
  m.thdd(3) = -acc(1);
  return m;
}

namespace {

// Key poses of the calibration protocol, deg [th0 th1 th2 th4 th5], with the time to move there
// and the time to hold it (s). docs/calibration.md gives the therapist's version.
struct ProtocolStep {
  std::array<double, kNumJoints> poseDeg;
  double moveSeconds, holdSeconds;
};

std::vector<ProtocolStep> protocolSteps() {
  constexpr std::array<double, kNumJoints> kStart{0, 0, 0, -90, 0};
  std::vector<ProtocolStep> steps;
  steps.push_back({kStart, 0.0, 4.0});  // start pose, held still
  // Static poses.
  steps.push_back({{90, 0, 0, -10, 0}, 2.0, 2.0});       // arm forward, elbow almost straight
  steps.push_back({{20, 60, 0, -10, 0}, 2.0, 2.0});      // arm out to the side
  steps.push_back({{45, 20, 45, -90, 60}, 2.0, 2.0});    // hand across, palm down
  steps.push_back({{0, 10, -30, -100, -60}, 2.0, 2.0});  // hand out, palm up
  // Elbow flexion/extension with pronation/supination, four times.
  for (int i = 0; i < 4; ++i) {
    steps.push_back({{30, 15, 0, -20, -70}, i == 0 ? 1.5 : 1.0, 0.0});
    steps.push_back({{30, 15, 0, -130, 70}, 1.0, 0.0});
  }
  // Shoulder internal/external rotation with the elbow at 90 deg, three times.
  for (int i = 0; i < 3; ++i) {
    steps.push_back({{20, 20, -50, -90, 0}, i == 0 ? 1.5 : 1.0, 0.0});
    steps.push_back({{20, 20, 50, -90, 0}, 1.0, 0.0});
  }
  // Reach forward and up, then hand to mouth, three times.
  for (int i = 0; i < 3; ++i) {
    steps.push_back({{100, 20, 0, -20, -30}, 1.2, 0.0});
    steps.push_back({{40, 10, 60, -140, 40}, 1.2, 0.0});
  }
  // Abduction/adduction, three times.
  for (int i = 0; i < 3; ++i) {
    steps.push_back({{0, 70, 20, -40, 0}, 1.0, 0.0});
    steps.push_back({{30, -10, -20, -60, 20}, 1.0, 0.0});
  }
  steps.push_back({kStart, 2.0, 3.0});  // back to the start pose
  return steps;
}

}  // namespace

void MinimumJerkPath::add(double t, const JointVector& th) {
  if (!m_keys.empty() && !(t >= m_keys.back().t))
    throw std::invalid_argument("MinimumJerkPath: keys must be in time order");
  m_keys.push_back({t, th});
}

void MinimumJerkPath::hold(double seconds) {
  add(endTime() + seconds, lastPosture());
}

double MinimumJerkPath::endTime() const {
  return m_keys.empty() ? 0.0 : m_keys.back().t;
}

const JointVector& MinimumJerkPath::lastPosture() const {
  static const JointVector kZero = JointVector::Zero();
  return m_keys.empty() ? kZero : m_keys.back().th;
}

JointMotion MinimumJerkPath::at(double t) const {
  JointMotion m;
  if (m_keys.empty()) return m;
  if (!(t > m_keys.front().t)) {
    m.th = m_keys.front().th;
    return m;
  }
  if (t >= m_keys.back().t) {
    m.th = m_keys.back().th;
    return m;
  }
  // The segment [k-1, k] that holds t.
  const auto it = std::upper_bound(m_keys.begin(), m_keys.end(), t,
                                   [](double v, const Key& k) { return v < k.t; });
  const Key& b = *it;
  const Key& a = *(it - 1);
  const double T = b.t - a.t;
  const double u = (t - a.t) / T;
  const double s = u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
  const double sd = 30.0 * u * u * (1.0 - u) * (1.0 - u) / T;
  const double sdd = 60.0 * u * (1.0 - u) * (1.0 - 2.0 * u) / (T * T);
  const JointVector d = b.th - a.th;
  m.th = a.th + s * d;
  m.thd = sd * d;
  m.thdd = sdd * d;
  return m;
}

CalibrationProtocolTrajectory::CalibrationProtocolTrajectory() {
  double t = 0.0;
  for (const ProtocolStep& step : protocolSteps()) {
    JointVector th;
    for (int j = 0; j < kNumJoints; ++j) th(j) = step.poseDeg[j] * kDeg;
    t += step.moveSeconds;
    m_path.add(t, th);
    if (step.holdSeconds > 0.0) {
      t += step.holdSeconds;
      m_path.add(t, th);
    }
  }
}

double CalibrationProtocolTrajectory::duration() const {
  return m_path.endTime();
}

JointVector CalibrationProtocolTrajectory::startPose() {
  JointVector th;
  th << 0.0, 0.0, 0.0, -90.0 * kDeg, 0.0;
  return th;
}

JointMotion CalibrationProtocolTrajectory::at(double t) const {
  return m_path.at(t);
}

namespace {
// Reaching postures (rad): anatomical ranges that keep th1 away from the +-90 deg gimbal lock.
constexpr std::array<double, kNumJoints> kReachLow{-40 * kDeg, -20 * kDeg, -60 * kDeg, -120 * kDeg,
                                                   -80 * kDeg};
constexpr std::array<double, kNumJoints> kReachHigh{120 * kDeg, 80 * kDeg, 60 * kDeg, 0.0,
                                                    80 * kDeg};
constexpr double kMinReach = 60 * kDeg;  // the largest joint change of every move
}  // namespace

ReachingTrajectory::ReachingTrajectory(std::uint64_t seed, double peakRate, double peakAccel,
                                       double durationSeconds) {
  if (!(peakRate > 0.0) || !std::isfinite(peakRate) || !(peakAccel > 0.0) ||
      !std::isfinite(peakAccel))
    throw std::invalid_argument("ReachingTrajectory: peak rate and acceleration must be > 0");
  if (!(durationSeconds >= 0.0) || !std::isfinite(durationSeconds))
    throw std::invalid_argument("ReachingTrajectory: duration must be >= 0 s");
  std::mt19937_64 rng(seed);
  std::array<std::uniform_real_distribution<double>, kNumJoints> joint;
  for (int j = 0; j < kNumJoints; ++j)
    joint[j] = std::uniform_real_distribution<double>(kReachLow[j], kReachHigh[j]);
  std::uniform_real_distribution<double> pause(0.1, 0.4);
  auto posture = [&] {
    JointVector th;
    for (int j = 0; j < kNumJoints; ++j) th(j) = joint[j](rng);
    return th;
  };
  m_path.add(0.0, posture());
  m_path.hold(pause(rng));
  while (m_path.endTime() < durationSeconds) {
    JointVector next = posture();
    while ((next - m_path.lastPosture()).cwiseAbs().maxCoeff() < kMinReach) next = posture();
    const double reach = (next - m_path.lastPosture()).cwiseAbs().maxCoeff();
    const double seconds =
        std::max(1.875 * reach / peakRate, std::sqrt(5.7735 * reach / peakAccel));
    m_path.add(m_path.endTime() + seconds, next);
    m_path.hold(pause(rng));
  }
}

JointMotion ReachingTrajectory::at(double t) const {
  return m_path.at(t);
}

JointVector SessionTrajectory::restPose() {
  // The start pose the patient is told to rest in (protocolStartPose(), docs/calibration.md,
  // "The rest pose"): upper arm hanging, elbow at a right angle, forearm forward, thumb up; the
  // upper arm leaning 15 deg forward, as when the forearm rests on the thigh.
  JointVector th;
  th << 15 * kDeg, 0.0, 0.0, -90 * kDeg, 0.0;
  return th;
}

SessionRest SessionRest::startPose() {
  return {SessionTrajectory::restPose(), SessionTrajectory::restScatter(), true};
}

SessionRest SessionRest::handOnLap() {
  JointVector th;
  th << 15 * kDeg, 10 * kDeg, 0.0, -80 * kDeg, 0.0;
  return {th, 5 * kDeg, false};
}

SessionTrajectory::SessionTrajectory(std::uint64_t seed, double peakRate, double peakAccel,
                                     double durationSeconds, double startSeconds,
                                     const SessionRest& restAt) {
  if (!(peakRate > 0.0) || !std::isfinite(peakRate) || !(peakAccel > 0.0) ||
      !std::isfinite(peakAccel))
    throw std::invalid_argument("SessionTrajectory: peak rate and acceleration must be > 0");
  if (!(durationSeconds >= 0.0) || !std::isfinite(durationSeconds) || !(startSeconds >= 0.0) ||
      !std::isfinite(startSeconds))
    throw std::invalid_argument("SessionTrajectory: durations must be >= 0 s");
  if (!restAt.pose.allFinite() || !(restAt.scatter >= 0.0) || !std::isfinite(restAt.scatter))
    throw std::invalid_argument("SessionTrajectory: the rest pose and its scatter must be finite");
  std::mt19937_64 rng(seed);
  std::array<std::uniform_real_distribution<double>, kNumJoints> joint;
  for (int j = 0; j < kNumJoints; ++j)
    joint[j] = std::uniform_real_distribution<double>(kReachLow[j], kReachHigh[j]);
  std::uniform_real_distribution<double> hold(0.3, 0.8), rest(1.0, 3.0),
      jitter(-restAt.scatter, restAt.scatter);
  // The first rest's scatter from a generator of its own: the reaches stay those of the seed.
  std::mt19937_64 startRng(seed ^ 0x5eed5ca77e7ULL);
  auto moveTo = [&](const JointVector& next) {
    const double reach = (next - m_path.lastPosture()).cwiseAbs().maxCoeff();
    const double seconds =
        std::max({1.875 * reach / peakRate, std::sqrt(5.7735 * reach / peakAccel), 0.2});
    m_path.add(m_path.endTime() + seconds, next);
  };
  JointVector start = restAt.pose;
  if (restAt.scatterFirst)
    for (int j = 0; j < kNumJoints; ++j) start(j) += jitter(startRng);
  m_path.add(0.0, start);
  m_path.hold(startSeconds);
  while (m_path.endTime() < durationSeconds) {
    JointVector target;
    do {
      for (int j = 0; j < kNumJoints; ++j) target(j) = joint[j](rng);
    } while ((target - m_path.lastPosture()).cwiseAbs().maxCoeff() < kMinReach);
    moveTo(target);
    m_path.hold(hold(rng));
    JointVector back = restAt.pose;
    for (int j = 0; j < kNumJoints; ++j) back(j) += jitter(rng);
    moveTo(back);
    m_path.hold(rest(rng));
  }
}

JointMotion SessionTrajectory::at(double t) const {
  return m_path.at(t);
}

std::vector<std::string> trajectoryNames() {
  return {"sinusoid", "multi-joint", "shoulder-wheel", "calibration",
          "reaching", "session",     "sensor-check",   "exercise"};
}

std::unique_ptr<Trajectory> makeTrajectory(const std::string& name, const TrajectoryOptions& opts) {
  if (name == "sinusoid") {
    auto traj = std::make_unique<SinusoidTrajectory>();
    traj->offset = opts.offset;
    traj->amplitude = opts.amplitude;
    traj->frequency = opts.frequency;
    return traj;
  }
  if (name == "multi-joint")
    return std::make_unique<MultiJointTrajectory>(opts.seed, opts.maxFrequencyHz,
                                                  opts.amplitudeScale);
  if (name == "shoulder-wheel")
    return std::make_unique<ShoulderWheelTrajectory>(opts.geometry, opts.wheelPeriod);
  if (name == "calibration") return std::make_unique<CalibrationProtocolTrajectory>();
  if (name == "sensor-check") return std::make_unique<SensorCheckTrajectory>();
  if (name == "exercise") return std::make_unique<ExerciseTrajectory>(opts.exercise);
  if (name == "reaching")
    return std::make_unique<ReachingTrajectory>(opts.seed, opts.peakRate, opts.peakAccel,
                                                opts.duration);
  if (name == "session")
    return std::make_unique<SessionTrajectory>(opts.seed, opts.peakRate, opts.peakAccel,
                                               opts.duration);
  std::string valid;
  for (const std::string& n : trajectoryNames()) valid += (valid.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown trajectory '" + name + "'; valid names: " + valid);
}

}  // namespace armtrack
