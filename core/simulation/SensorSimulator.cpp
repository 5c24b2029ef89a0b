#include "core/simulation/SensorSimulator.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "core/camera/PinholeCamera.h"

namespace armtrack {
namespace {

// Independent noise streams per sensor, so that e.g. switching the Kinect on or off leaves the
// IMU noise unchanged. Each is an mt19937_64 seeded from (seed, stream id).
enum class NoiseStream : std::uint32_t {
  kUpperArm = 1,
  kForearm = 2,
  kKinect = 3,
  kCamera = 4,
  kTrunk = 5,
  kShoulder = 6,
  // The error models of the IMUs (only with ImuSimParams::errors on).
  kUpperArmErrors = 7,
  kForearmErrors = 8,
  kTrunkErrors = 9
};

class Noise {
 public:
  Noise(std::uint64_t seed, NoiseStream stream) {
    std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                      static_cast<std::uint32_t>(stream)};
    m_rng.seed(seq);
  }
  /// Three independent N(0, std^2) draws (always drawn, so the sequence does not depend on std).
  Eigen::Vector3d vec3(double std) {
    const double x = m_normal(m_rng), y = m_normal(m_rng), z = m_normal(m_rng);
    return std * Eigen::Vector3d(x, y, z);
  }
  double uniform() { return m_uniform(m_rng); }

 private:
  std::mt19937_64 m_rng;
  std::normal_distribution<double> m_normal{0.0, 1.0};
  std::uniform_real_distribution<double> m_uniform{0.0, 1.0};
};

/// Sample times k / rate for k = 0 .. count-1, with t <= duration.
struct Clock {
  bool active = false;
  double rate = 0.0;  // Hz
  std::size_t count = 0;
  std::size_t next = 0;
  double nextTime() const {
    return next < count ? static_cast<double>(next) / rate
                        : std::numeric_limits<double>::infinity();
  }
};

Clock makeClock(bool enabled, double rateHz, double duration) {
  Clock c;
  if (!enabled) return c;
  c.active = true;
  c.rate = rateHz;
  // The tiny slack keeps a sample that lands on the duration despite rounding of duration*rate.
  c.count = std::isfinite(duration)
                ? static_cast<std::size_t>(std::floor(duration * rateHz + 1e-9)) + 1
                : std::numeric_limits<std::size_t>::max();
  return c;
}

void checkNonNegative(double v, const char* what) {
  if (!(v >= 0.0) || !std::isfinite(v))
    throw std::invalid_argument(std::string("simulateRecording: ") + what + " must be >= 0");
}

void checkImu(const ImuSimParams& p, const char* name) {
  if (!p.enabled) return;
  if (!(p.rateHz > 0.0) || !std::isfinite(p.rateHz))
    throw std::invalid_argument(std::string("simulateRecording: ") + name + " rate must be > 0");
  checkNonNegative(p.gyroNoiseStd, "gyro noise std");
  checkNonNegative(p.accelNoiseStd, "accel noise std");
  if (!p.gyroBias.allFinite() || !p.accelBias.allFinite())
    throw std::invalid_argument("simulateRecording: IMU biases must be finite");
  const Eigen::Matrix3d m = p.misalignment;
  if (!m.allFinite() || !(m.transpose() * m).isIdentity(1e-9) || m.determinant() < 0.0)
    throw std::invalid_argument(std::string("simulateRecording: ") + name +
                                " misalignment must be a rotation matrix");
  checkImuErrors(p.errors, p.rateHz, std::string("simulateRecording: ") + name);
}

ImuReading simulateImu(const ImuPrediction& ideal, const ImuSimParams& p, Noise& noise) {
  ImuReading r;
  r.gyr = p.misalignment.transpose() * ideal.gyr + p.gyroBias + noise.vec3(p.gyroNoiseStd);
  r.acc = p.misalignment.transpose() * ideal.acc + p.accelBias + noise.vec3(p.accelNoiseStd);
  return r;
}

}  // namespace

double Table5::gyroStd() {
  return std::sqrt(0.1) * std::numbers::pi / 180.0;
}
double Table5::accelStd() {
  return std::sqrt(0.01);
}
double Table5::posStd() {
  return std::sqrt(1e-4);
}

TrunkMount defaultSimulatedTrunkMount(Side side) {
  TrunkMount m;
  m.imuPosition = {0.10, 0.08, side == Side::Left ? 0.18 : -0.18};
  m.imuRotation << -1, 0, 0,  //
      0, 0, 1,                //
      0, 1, 0;
  return m;
}

SimulationParams defaultSimulation() {
  SimulationParams p;
  p.duration = 10.0;
  for (ImuSimParams* imu : {&p.upperArm, &p.forearm, &p.trunkImu}) {
    imu->enabled = true;
    imu->rateHz = 1000.0;
    imu->gyroNoiseStd = Table5::gyroStd();
    imu->accelNoiseStd = Table5::accelStd();
  }
  p.trunkImu.enabled = false;
  p.kinect.enabled = true;
  p.kinect.rateHz = 30.0;
  p.kinect.noiseStd = Table5::posStd();
  p.webcam.camera = frontCamera(2.0);
  return p;
}

namespace {

void checkParams(const SimulationParams& params) {
  if (!(params.duration >= 0.0) || std::isnan(params.duration))
    throw std::invalid_argument("simulateRecording: duration must be >= 0");
  checkImu(params.upperArm, "upper-arm IMU");
  checkImu(params.forearm, "forearm IMU");
  checkImu(params.trunkImu, "sternum IMU");
  if (params.trunkMount) {
    const Eigen::Matrix3d m = params.trunkMount->imuRotation;
    if (!params.trunkMount->imuPosition.allFinite() || !m.allFinite() ||
        !(m.transpose() * m).isIdentity(1e-9) || m.determinant() < 0.0)
      throw std::invalid_argument(
          "simulateRecording: the sternum IMU's mounting needs a finite position and a rotation "
          "matrix");
  }
  if (params.kinect.enabled) {
    if (!(params.kinect.rateHz > 0.0) || !std::isfinite(params.kinect.rateHz))
      throw std::invalid_argument("simulateRecording: Kinect rate must be > 0");
    checkNonNegative(params.kinect.noiseStd, "Kinect noise std");
  }
  const CameraSimParams& cam = params.webcam;
  if (cam.enabled) {
    if (!(cam.rateHz > 0.0) || !std::isfinite(cam.rateHz))
      throw std::invalid_argument("simulateRecording: webcam rate must be > 0");
    checkNonNegative(cam.noiseStdPx, "webcam noise std");
    if (!(cam.outlierProbability >= 0.0 && cam.outlierProbability <= 1.0))
      throw std::invalid_argument("simulateRecording: outlier probability must be in [0, 1]");
    if (cam.width <= 0 || cam.height <= 0)
      throw std::invalid_argument("simulateRecording: webcam image size must be positive");
  }
  if (!std::isfinite(params.g) || std::abs(params.up.norm() - 1.0) > 1e-6)
    throw std::invalid_argument("simulateRecording: up must be a unit vector and g finite");
}

}  // namespace

struct SensorStream::Impl {
  Impl(const Trajectory& traj, const SimulationParams& p)
      : trajectory(&traj),
        params(p),
        upperNoise(p.seed, NoiseStream::kUpperArm),
        forearmNoise(p.seed, NoiseStream::kForearm),
        kinectNoise(p.seed, NoiseStream::kKinect),
        cameraNoise(p.seed, NoiseStream::kCamera),
        trunkNoise(p.seed, NoiseStream::kTrunk),
        shoulderNoise(p.seed, NoiseStream::kShoulder) {
    checkParams(p);
    if (p.trunk.enabled) trunkMotion.emplace(p.trunk);      // throws on bad trunk motion
    if (p.webcam.enabled) camera.emplace(p.webcam.camera);  // throws on bad intrinsics
    meta.geometry = p.geometry;
    meta.up = p.up;
    meta.g = p.g;
    meta.side = p.side;
    if (camera) meta.camera = p.webcam.camera;
    left = p.side == Side::Left;
    // Both IMUs on one clock when they share a rate, else each on its own.
    shared = p.upperArm.enabled && p.forearm.enabled && p.upperArm.rateHz == p.forearm.rateHz;
    upperClock = makeClock(p.upperArm.enabled, p.upperArm.rateHz, p.duration);
    forearmClock = makeClock(p.forearm.enabled && !shared, p.forearm.rateHz, p.duration);
    kinectClock = makeClock(p.kinect.enabled, p.kinect.rateHz, p.duration);
    cameraClock = makeClock(p.webcam.enabled, p.webcam.rateHz, p.duration);
    // A left arm is simulated as its right-arm mirror image, then mirrored back sample by sample.
    gUp = p.g * (left ? mirrorPoint(p.up) : p.up);
    trunkClock = makeClock(p.trunkImu.enabled, p.trunkImu.rateHz, p.duration);
    kinectShoulder = p.kinect.shoulder.value_or(p.trunk.enabled);
    trueTrunk = p.trunk.enabled || p.trunkImu.enabled;
    // The hip and the sternum IMU in the mirror image's frame: points p -> S p, a sensor's axes
    // F -> S F D (docs/arm-model.md, "Left arm"), so mirrorSample gives the left arm's readings.
    hip = p.trunk.hip.value_or(defaultHip(p.side));
    const TrunkMount mount = p.trunkMount.value_or(defaultSimulatedTrunkMount(p.side));
    const TrunkMount twin = left ? mirrorMount(mount) : mount;
    if (left) hip = mirrorPoint(hip);
    mountPosition = twin.imuPosition;
    mountRotation = twin.imuRotation;
    if (p.trunkImu.enabled) meta.trunk = mount;
    const auto model = [&](const ImuSimParams& imu, NoiseStream stream, const char* who) {
      std::optional<ImuErrorModel> m;
      if (imu.enabled && imu.errors.enabled)
        m.emplace(imu, p.seed, static_cast<std::uint32_t>(stream), who);
      return m;
    };
    upperErrors = model(p.upperArm, NoiseStream::kUpperArmErrors, "upper-arm IMU");
    forearmErrors = model(p.forearm, NoiseStream::kForearmErrors, "forearm IMU");
    trunkErrors = model(p.trunkImu, NoiseStream::kTrunkErrors, "sternum IMU");
  }

  // What an IMU's frame truly feels at time t (the error models' input): 0 upper arm, 1 forearm,
  // 2 sternum, in the (mirror image's) model frames.
  ImuTruth imuTruth(double t, int which) const {
    const JointMotion m = trajectory->at(t);
    FrameState<double> base;
    base.up = gUp;
    TrunkPose pose;
    if (trunkMotion) {
      pose = trunkPose(trunkMotion->at(t, *trajectory), params.side);
      base = trunkBase(pose, hip, gUp);
    }
    if (which == 2) {
      const ImuPrediction s = sternumPrediction(pose);
      const Eigen::Matrix3d axes = pose.rotation * mountRotation;
      return {s.gyr, s.acc, s.acc - axes.transpose() * gUp};
    }
    const ArmKinematics<double> k =
        armKinematics<double>(params.geometry, m.th, m.thd, m.thdd, base);
    const FrameState<double>& f = which == 0 ? k.upperImu : k.forearmImu;
    return {f.omega, f.up + f.accel, f.accel};
  }

  ImuReading imuReading(std::optional<ImuErrorModel>& model, int which, double t,
                        const ImuPrediction& ideal, const ImuSimParams& p, Noise& noise) {
    if (!model) return simulateImu(ideal, p, noise);
    return model->reading(t, [this, which](double tt) { return imuTruth(tt, which); });
  }

  double nextTime() const {
    return std::min({upperClock.nextTime(), forearmClock.nextTime(), kinectClock.nextTime(),
                     cameraClock.nextTime(), trunkClock.nextTime()});
  }

  // One marker's pixel: the projection plus noise, a uniform outlier, or nothing when the marker
  // is outside the image. The draws are made every time, so the stream does not depend on
  // visibility.
  std::optional<Eigen::Vector2d> markerPixel(const Eigen::Vector3d& p) {
    const CameraSimParams& cam = params.webcam;
    const Eigen::Vector3d n = cameraNoise.vec3(cam.noiseStdPx);
    const double pick = cameraNoise.uniform();
    const Eigen::Vector2d anywhere(cameraNoise.uniform() * cam.width,
                                   cameraNoise.uniform() * cam.height);
    Eigen::Vector2d px;
    if (!camera->project(p, px)) return std::nullopt;
    if (px.x() < 0 || px.y() < 0 || px.x() > cam.width || px.y() > cam.height) return std::nullopt;
    if (pick < cam.outlierProbability) return anywhere;
    return px + n.head<2>();
  }

  // Each row is the earliest pending time; every clock due at exactly that time contributes to
  // the same row.
  std::optional<ArmSample> next() {
    const double t = nextTime();
    if (!std::isfinite(t)) return std::nullopt;
    const bool upperDue = upperClock.nextTime() == t;
    const bool forearmDue = shared ? upperDue : forearmClock.nextTime() == t;
    const bool kinectDue = kinectClock.nextTime() == t;
    const bool cameraDue = cameraClock.nextTime() == t;
    const bool trunkDue = trunkClock.nextTime() == t;
    const JointMotion m = trajectory->at(t);
    // With a still trunk, frame 0 is the world and the arm's prediction is the classic one.
    ArmPrediction ideal;
    TrunkPose pose;
    std::optional<TrunkMotionState> trunkState;
    if (trunkMotion) {
      trunkState = trunkMotion->at(t, *trajectory);
      pose = trunkPose(*trunkState, params.side);
      ideal = movingTrunkPrediction(m, pose);
    } else {
      ideal = predictSensors(params.geometry, m.th, m.thd, m.thdd, gUp);
    }
    ArmSample s;
    if (trunkDue) {
      s.trunk = imuReading(trunkErrors, 2, t, sternumPrediction(pose), params.trunkImu, trunkNoise);
      ++trunkClock.next;
    }
    s.t = t;
    if (upperDue) {
      s.upperArm = imuReading(upperErrors, 0, t, ideal.upper, params.upperArm, upperNoise);
      ++upperClock.next;
    }
    if (forearmDue) {
      s.forearm = imuReading(forearmErrors, 1, t, ideal.forearm, params.forearm, forearmNoise);
      if (!shared) ++forearmClock.next;
    }
    if (kinectDue) {
      s.elbow = ideal.elbow + kinectNoise.vec3(params.kinect.noiseStd);
      s.wrist = ideal.wrist + kinectNoise.vec3(params.kinect.noiseStd);
      if (kinectShoulder)
        s.shoulder = shoulderInWorld(pose) + shoulderNoise.vec3(params.kinect.noiseStd);
      ++kinectClock.next;
    }
    if (params.includeTruth && (upperDue || forearmDue || trunkDue)) {
      JointVector truth;
      for (int j = 0; j < kNumJoints; ++j) truth(j) = wrapAngle(m.th(j));
      s.trueAngles = truth;
      // Patient terms: the same numbers for both sides, so the mirror leaves them alone.
      if (trueTrunk) s.trueTrunk = trunkState ? trunkState->angles : TrunkAngles::Zero();
    }
    if (left) s = mirrorSample(s);
    if (cameraDue) {
      // The camera sees the real arm: a left arm's points in its own shoulder frame.
      const Eigen::Vector3d wrist = left ? mirrorPoint(ideal.wrist) : ideal.wrist;
      const Eigen::Vector3d elbow = left ? mirrorPoint(ideal.elbow) : ideal.elbow;
      if (params.webcam.wrist) s.camWrist = markerPixel(wrist);
      if (params.webcam.elbow) s.camElbow = markerPixel(elbow);
      ++cameraClock.next;
    }
    return s;
  }

  // The arm's readings with frame 0 turning with the thorax (docs/arm-model.md, "Trunk"): the
  // IMUs from the recursion with frame 0's motion as its base, the points carried to the world.
  ArmPrediction movingTrunkPrediction(const JointMotion& m, const TrunkPose& pose) const {
    const FrameState<double> base = trunkBase(pose, hip, gUp);
    const ArmKinematics<double> k =
        armKinematics<double>(params.geometry, m.th, m.thd, m.thdd, base);
    ArmPrediction p;
    p.upper = {k.upperImu.omega, k.upperImu.up + k.upperImu.accel};
    p.forearm = {k.forearmImu.omega, k.forearmImu.up + k.forearmImu.accel};
    p.elbow = trunkPointInWorld(pose, hip, k.elbow);
    p.wrist = trunkPointInWorld(pose, hip, k.wrist);
    return p;
  }

  // The sternum IMU: the thorax's angular velocity and the specific force of the sternum point
  // (turning about the hip), in the IMU's axes R * mountRotation.
  ImuPrediction sternumPrediction(const TrunkPose& pose) const {
    const Eigen::Vector3d r = pose.rotation * (mountPosition - hip);
    const Eigen::Vector3d acc = pose.omegaDot.cross(r) + pose.omega.cross(pose.omega.cross(r));
    const Eigen::Matrix3d axes = pose.rotation * mountRotation;
    return {axes.transpose() * pose.omega, axes.transpose() * (acc + gUp)};
  }

  Eigen::Vector3d shoulderInWorld(const TrunkPose& pose) const {
    return trunkPointInWorld(pose, hip, Eigen::Vector3d::Zero());
  }

  const Trajectory* trajectory;
  SimulationParams params;
  std::optional<TrunkMotion> trunkMotion;
  std::optional<PinholeCamera> camera;
  RecordingMeta meta;
  bool left = false, shared = false;
  bool kinectShoulder = false, trueTrunk = false;
  Clock upperClock, forearmClock, kinectClock, cameraClock, trunkClock;
  Noise upperNoise, forearmNoise, kinectNoise, cameraNoise, trunkNoise, shoulderNoise;
  std::optional<ImuErrorModel> upperErrors, forearmErrors, trunkErrors;
  Eigen::Vector3d gUp;
  // The hip pivot and the sternum IMU's mounting in the (mirror image's) frame 0.
  Eigen::Vector3d hip = Eigen::Vector3d::Zero(), mountPosition = Eigen::Vector3d::Zero();
  Eigen::Matrix3d mountRotation = Eigen::Matrix3d::Identity();
};

SensorStream::SensorStream(const Trajectory& trajectory, const SimulationParams& params)
    : m(std::make_unique<Impl>(trajectory, params)) {}
SensorStream::~SensorStream() = default;
SensorStream::SensorStream(SensorStream&&) noexcept = default;
SensorStream& SensorStream::operator=(SensorStream&&) noexcept = default;
double SensorStream::nextTime() const {
  return m->nextTime();
}
std::optional<ArmSample> SensorStream::next() {
  return m->next();
}
void SensorStream::skipTo(double t) {
  for (Clock* c :
       {&m->upperClock, &m->forearmClock, &m->kinectClock, &m->cameraClock, &m->trunkClock}) {
    if (!c->active || !(t > 0.0)) continue;
    const double k = std::ceil(t * c->rate - 1e-9);
    const auto first = k >= static_cast<double>(c->count) ? c->count : static_cast<std::size_t>(k);
    c->next = std::max(c->next, first);
  }
  for (std::optional<ImuErrorModel>* e : {&m->upperErrors, &m->forearmErrors, &m->trunkErrors})
    if (*e) (*e)->skipTo(t);
}
const RecordingMeta& SensorStream::meta() const {
  return m->meta;
}

Recording simulateRecording(const Trajectory& trajectory, const SimulationParams& params) {
  if (!std::isfinite(params.duration))
    throw std::invalid_argument("simulateRecording: duration must be finite");
  SensorStream stream(trajectory, params);
  Recording rec;
  rec.meta = stream.meta();
  const auto count = [&](bool on, double rate) {
    return on ? static_cast<std::size_t>(params.duration * rate) + 1 : 0;
  };
  rec.samples.reserve(count(params.upperArm.enabled, params.upperArm.rateHz) +
                      count(params.forearm.enabled, params.forearm.rateHz) +
                      count(params.kinect.enabled, params.kinect.rateHz) +
                      count(params.webcam.enabled, params.webcam.rateHz) +
                      count(params.trunkImu.enabled, params.trunkImu.rateHz));
  while (auto s = stream.next()) rec.samples.push_back(std::move(*s));
  return rec;
}

Eigen::Matrix3d randomMisalignment(double angleRad, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  // An isotropic Gaussian vector has a uniformly distributed direction.
  Eigen::Vector3d axis;
  do {
    const double x = normal(rng), y = normal(rng), z = normal(rng);
    axis = Eigen::Vector3d(x, y, z);
  } while (axis.norm() < 1e-6);
  return Eigen::AngleAxisd(angleRad, axis.normalized()).toRotationMatrix();
}

}  // namespace armtrack
