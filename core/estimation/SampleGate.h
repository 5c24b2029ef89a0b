// Plausibility at the door: every sensor block of an ArmSample is checked against what the
// sensor and a human arm can produce before it may reach a filter or a calibration fit. A block
// that fails is removed from the sample and counted with its kind and time; nothing else in the
// sample is touched. See docs/estimator.md, "Plausibility at the door".
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>

#include "core/ArmSample.h"

namespace armtrack {

/// What a sensor and an arm can produce. Defaults fit the IMUs the project supports (the widest
/// usual full scales, 2000 deg/s and 16 g) and any adult arm.
struct PlausibilityLimits {
  /// Gyroscope full scale per axis (rad/s): 2000 deg/s. A reading beyond it cannot come from
  /// the sensor; one within saturationFraction of it is taken as clipped.
  double gyroRange = 2000.0 * std::numbers::pi / 180.0;
  /// Accelerometer full scale per axis (m/s^2): 16 g.
  double accelRange = 16.0 * 9.80665;
  /// A reading at or beyond this fraction of full scale on any axis is saturated: the true value
  /// is unknown, so the block is dropped.
  double saturationFraction = 0.98;
  /// An IMU block whose six values repeat bit for bit this many times in a row is stuck (a real
  /// sensor's noise changes at least one least significant bit). 0 turns the check off.
  int stuckSamples = 50;
  /// A gyroscope or accelerometer value that repeats the sensor's previous one bit for bit,
  /// within this many seconds of its last change, is held: a logger that repeats its last
  /// sample when the sensor had nothing new (a 25 Hz accelerometer on a 90 Hz clock repeats
  /// for up to 40 ms). It is kept in the sample but marked (ImuReading::gyrHeld, accHeld) so
  /// the filter takes it as absent. A repeat that lasts longer is a constant signal (an ideal
  /// simulation at rest) and stays a measurement until stuckSamples. 0 turns the check off.
  double heldSeconds = 0.05;
  /// Optical points (Kinect elbow and wrist) farther than this from the shoulder (m) are not on
  /// the arm. The default is set from the arm's lengths by forGeometry().
  double maxReach = 2.0;
  /// Marker pixels farther than this from the image origin (px) are not in any image.
  double maxPixel = 1e5;

  /// Limits with maxReach = 1.5 x (upper arm + forearm) + 0.2 m: generous for optical noise
  /// and mis-detections near the arm, which the filter's innovation gates handle.
  static PlausibilityLimits forGeometry(double upperArmLength, double forearmLength);
};

/// The sensor blocks of an ArmSample, in a fixed order.
enum class SensorBlock : std::uint8_t { UpperArm, Forearm, Elbow, Wrist, CamWrist, CamElbow };
inline constexpr int kNumSensorBlocks = 6;
const char* sensorBlockName(SensorBlock b);

/// Why a block was refused.
enum class Implausible : std::uint8_t {
  NonFinite,    ///< NaN or infinity
  BeyondRange,  ///< beyond the sensor's full scale, or an optical point far from the arm
  Saturated,    ///< at the sensor's full scale: clipped
  AllZero,      ///< exactly zero on every axis: an accelerometer (which always feels gravity
                ///< on an arm), an optical point (the shoulder itself) or a pixel: a dead link
  Stuck,        ///< the same reading repeated bit for bit (a frozen sensor)
};
inline constexpr int kNumImplausible = 5;
const char* implausibleName(Implausible why);

/// Everything the gate refused, by block and reason, with the first and last time.
struct GateCounters {
  std::array<std::array<std::uint64_t, kNumImplausible>, kNumSensorBlocks> refused{};
  std::uint64_t samplesWithRefusal = 0;  ///< samples that lost at least one block
  double firstT = 0.0;                   ///< s, time of the first refusal (valid when total() > 0)
  double lastT = 0.0;                    ///< s, time of the latest refusal
  SensorBlock firstBlock = SensorBlock::UpperArm;
  Implausible firstWhy = Implausible::NonFinite;
  /// Held (repeated) values marked absent, not refused: upper-arm gyroscope, upper-arm
  /// accelerometer, forearm gyroscope, forearm accelerometer. Not in total().
  std::array<std::uint64_t, 4> held{};

  std::uint64_t total() const;
  std::uint64_t byReason(Implausible why) const;
  std::uint64_t byBlock(SensorBlock b) const;
  /// One line for people, e.g. "refused 200 readings (saturated 200: upper-arm IMU 100,
  /// forearm IMU 100) between 5.000 s and 5.199 s"; empty when nothing was refused.
  std::string summary() const;
  std::uint64_t totalHeld() const;
  /// e.g. "took 4021 repeated (held) readings as absent: upper-arm gyroscope 1200, upper-arm
  /// accelerometer 2100, ..."; empty when there were none.
  std::string heldSummary() const;
};

/// Checks samples one at a time (it keeps a little state for the stuck check). Not thread-safe.
class SampleGate {
 public:
  explicit SampleGate(const PlausibilityLimits& limits = {});
  /// The sample with every implausible block removed (time and truth columns kept).
  ArmSample check(const ArmSample& sample);
  /// Whether the last check() removed anything.
  bool lastRefused() const { return m_lastRefused; }
  const GateCounters& counters() const { return m_counters; }
  const PlausibilityLimits& limits() const { return m_limits; }
  void reset();

 private:
  std::optional<Implausible> checkImu(int slot, const ImuReading& r);
  void markHeld(int slot, double t, ImuReading& r);
  void count(SensorBlock b, Implausible why, double t);

  PlausibilityLimits m_limits;
  GateCounters m_counters;
  std::array<ImuReading, 2> m_previous{};
  std::array<int, 2> m_repeats{0, 0};
  std::array<bool, 2> m_havePrevious{false, false};
  // Held check: each sensor's last value and when it last changed (gyroscope, accelerometer).
  struct Last {
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
    double changedT = 0.0;
    bool have = false;
  };
  std::array<std::array<Last, 2>, 2> m_last{};
  bool m_lastRefused = false;
};

}  // namespace armtrack
