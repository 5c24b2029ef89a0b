// Simulates the two arm IMUs, the Kinect, a webcam and (optionally) a moving trunk with a sternum
// IMU, from a trajectory and the arm model.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>

#include "core/io/Recording.h"
#include "core/simulation/ImuErrors.h"
#include "core/simulation/Trajectory.h"
#include "core/simulation/TrunkMotion.h"

namespace armtrack {

/// The paper's Table 5 noise, as standard deviations in SI units.
struct Table5 {
  static double gyroStd();   ///< sqrt(0.1) deg/s in rad/s
  static double accelStd();  ///< 0.1 m/s^2
  static double posStd();    ///< 0.01 m
};

struct ImuSimParams {
  bool enabled = true;
  double rateHz = 1000.0;
  double gyroNoiseStd = 0.0;                            ///< white noise, rad/s
  double accelNoiseStd = 0.0;                           ///< white noise, m/s^2
  Eigen::Vector3d gyroBias = Eigen::Vector3d::Zero();   ///< constant, rad/s
  Eigen::Vector3d accelBias = Eigen::Vector3d::Zero();  ///< constant, m/s^2
  /// Rotation of the physical sensor's axes relative to the model's IMU frame: the sensor reads
  /// misalignment^T * (model reading). Identity = perfectly mounted.
  Eigen::Matrix3d misalignment = Eigen::Matrix3d::Identity();
  /// A real sensor's errors (scale, cross-axis, walking and drifting bias, g-sensitivity,
  /// sample-and-hold, jitter, clock offset, range, LSB, wobble, slip; core/simulation/ImuErrors.h).
  /// Off by default: the reading is then exactly the ideal one plus noise and bias. On, the white
  /// noise is drawn per internal sample and rateHz is the output clock.
  ImuErrorParams errors;
};

struct OpticalSimParams {
  bool enabled = true;
  double rateHz = 30.0;
  double noiseStd = 0.01;  ///< per axis, m
  /// Whether the Kinect also reports the shoulder centre (ArmSample::shoulder, world frame, the
  /// same noise). Unset: reported when the trunk moves (SimulationParams::trunk.enabled).
  std::optional<bool> shoulder;
};

/// A webcam tracking coloured markers on the elbow and the wrist (Tao & Hu): pixel positions
/// through the pinhole model of core/camera. A marker that projects outside the image or behind
/// the camera is absent from that frame.
struct CameraSimParams {
  bool enabled = false;
  double rateHz = 30.0;
  double noiseStdPx = 1.0;          ///< per pixel axis
  CameraParams camera;              ///< intrinsics, distortion and pose; frontCamera(2) by default
  int width = 640, height = 480;    ///< image size (pixels); markers outside are dropped
  bool wrist = true, elbow = true;  ///< which markers are tracked
  /// Probability that a marker is mis-detected: its pixel is then drawn uniformly over the image
  /// (to exercise innovation gating).
  double outlierProbability = 0.0;
};

struct SimulationParams {
  double duration = 10.0;  ///< s
  ArmGeometry geometry;    ///< the true arm (may differ from what a filter assumes)
  Eigen::Vector3d up{-1.0, 0.0, 0.0};
  double g = 9.81;
  ImuSimParams upperArm;
  ImuSimParams forearm;
  OpticalSimParams kinect;
  CameraSimParams webcam;  ///< off by default
  std::uint64_t seed = 1;
  bool includeTruth = true;  ///< fill ArmSample::trueAngles on IMU rows
  /// Which arm. A left arm is the mirror image of the right one (core/kinematics/Side.h): its
  /// data come out in the left shoulder's frame, with `up` given in that frame.
  Side side = Side::Right;
  /// The trunk's motion (off: a still trunk, and every other reading exactly as without it).
  /// When it moves, frame 0 turns with the thorax about the hip; the optical points (and the
  /// webcam's pixels) are in the world frame, frame 0 as it was upright at the start, the IMUs
  /// feel the thorax's motion, trueAngles stay relative to the thorax and trueTrunk holds the
  /// trunk's angles (core/kinematics/Trunk.h).
  TrunkSimParams trunk;
  /// The sternum IMU, off unless asked for; defaultSimulation() gives it Table 5 noise at 1 kHz.
  /// Its rows carry ArmSample::trunk, and the sidecar its mounting (RecordingMeta::trunk).
  ImuSimParams trunkImu = [] {
    ImuSimParams p;
    p.enabled = false;
    return p;
  }();
  /// Where the sternum IMU sits, in the arm's frame 0 with the trunk upright (the sidecar's
  /// "trunk" block). Unset: defaultSimulatedTrunkMount(side).
  std::optional<TrunkMount> trunkMount;
};

/// The sternum IMU's default mounting: 0.10 m below, 0.08 m forward of and 0.18 m medial to the
/// shoulder centre, x axis up, y axis to the patient's right, z axis forward (out of the chest).
/// For a right arm: position (0.10, 0.08, -0.18), rotation [[-1 0 0] [0 0 1] [0 1 0]] (columns:
/// the IMU's axes in frame 0); a left arm's frame 0 has the same axes, the sternum on its other
/// side: (0.10, 0.08, 0.18), the same rotation.
TrunkMount defaultSimulatedTrunkMount(Side side);

/// Table 5 noise on both IMUs (1 kHz) and a 30 Hz Kinect with 1 cm noise; the webcam is off
/// (frontCamera(2), 30 Hz, 1 px noise when switched on). The trunk is still and the sternum IMU
/// off (Table 5 noise at 1 kHz when switched on).
SimulationParams defaultSimulation();

/// Returns a recording: one row per IMU sample (both IMUs share the IMU clock when their rates
/// are equal), Kinect and webcam rows at their own times, merged in time order. With the webcam
/// on, the sidecar carries its camera block. Deterministic given seed.
/// Sample times are k / rate while t <= duration; rows at the same instant are merged. Each
/// sensor has its own noise stream, so enabling one sensor does not change another's noise.
/// trueAngles (wrapped to (-pi, pi]) are set on rows with an IMU reading, and trueTrunk on those
/// rows when the trunk moves or the sternum IMU is on. Throws
/// std::invalid_argument on bad parameters (rate <= 0, negative std or duration, up not a unit
/// vector, misalignment not a rotation, bad trunk motion or mounting, an IMU's bad error
/// parameters: checkImuErrors names them).
Recording simulateRecording(const Trajectory& trajectory, const SimulationParams& params);

/// The same simulation, one row at a time, for live sources (the virtual-arm device). With an
/// infinite duration it never ends. simulateRecording(t, p).samples equals the rows next() returns
/// for the same trajectory and parameters. The trajectory must outlive the stream. Not
/// thread-safe.
class SensorStream {
 public:
  /// Throws std::invalid_argument on bad parameters, as simulateRecording does. The duration may
  /// be +infinity.
  SensorStream(const Trajectory& trajectory, const SimulationParams& params);
  ~SensorStream();
  SensorStream(SensorStream&&) noexcept;
  SensorStream& operator=(SensorStream&&) noexcept;

  /// Time (s) of the row next() will return; +infinity when the stream has ended.
  double nextTime() const;
  /// The next row in time order, or nothing once past the duration.
  std::optional<ArmSample> next();
  /// Skips the rows before time t (s) without simulating them (a live source joining a shared
  /// time base late). The noise streams are not advanced.
  void skipTo(double t);
  /// The sidecar of the simulated recording (geometry, up, g, side, camera).
  const RecordingMeta& meta() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m;
};

/// Rotation about a random axis by angleRad, drawn from seed: a misalignment perturbation.
Eigen::Matrix3d randomMisalignment(double angleRad, std::uint64_t seed);

}  // namespace armtrack
