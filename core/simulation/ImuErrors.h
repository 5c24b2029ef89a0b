// The errors of a real MEMS IMU, for the simulator (docs/simulation.md, "Realistic sensors"):
// scale factor and cross-axis misalignment, a bias that walks and drifts with the sensor's
// temperature, gyroscope g-sensitivity, sample-and-hold of internal rates below the output clock,
// time-stamp jitter and a clock offset, saturation, quantisation, the sensor wobbling on soft
// tissue and the strap slipping slowly about the segment. Every error is off by default: an
// ImuSimParams whose `errors.enabled` is false is simulated exactly as before.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <string>

#include "core/ArmSample.h"

namespace armtrack {

struct ImuSimParams;
struct SimulationParams;

/// What the model's IMU frame truly feels at one instant (the error model's input), all in the
/// model's IMU frame.
struct ImuTruth {
  Eigen::Vector3d gyr = Eigen::Vector3d::Zero();     ///< angular velocity, rad/s
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();     ///< specific force (gravity included), m/s^2
  Eigen::Vector3d linAcc = Eigen::Vector3d::Zero();  ///< acceleration without gravity, m/s^2
};

/// The errors of one IMU. Units are SI; "relative" means a fraction (0.01 = 1 %). The sensor reads,
/// per internal sample at true time tau (docs/simulation.md):
///   gyr = (I + diag(gyroScale) + gyroCrossAxis) w + gyroGSensitivity f + bg(tau) + noise
///   acc = (I + diag(accelScale) + accelCrossAxis) f + ba(tau) + noise
/// where w and f are the truth's rate and specific force turned into the sensor's axes (the static
/// misalignment of ImuSimParams, the slip and the wobble), bg and ba the biases (ImuSimParams'
/// constant bias + random walk + temperature drift); then clamped to the range and rounded to the
/// LSB. Each output row repeats the last internal sample.
struct ImuErrorParams {
  bool enabled = false;  ///< off: the simulator's ideal sensor (white noise and constant bias)

  // Scale factor and misalignment (non-orthogonality of the sensing axes).
  Eigen::Vector3d gyroScale = Eigen::Vector3d::Zero();   ///< relative, per axis
  Eigen::Vector3d accelScale = Eigen::Vector3d::Zero();  ///< relative, per axis
  /// Cross-axis sensitivity: the off-diagonal terms (relative); the diagonal must be zero.
  Eigen::Matrix3d gyroCrossAxis = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d accelCrossAxis = Eigen::Matrix3d::Zero();
  /// Gyroscope g-sensitivity: rad/s of rate read per m/s^2 of specific force.
  Eigen::Matrix3d gyroGSensitivity = Eigen::Matrix3d::Zero();

  // Bias beyond ImuSimParams' constant bias.
  double gyroBiasWalk = 0.0;   ///< rate random walk, rad/s per sqrt(s): Var(b(t)) = walk^2 t
  double accelBiasWalk = 0.0;  ///< m/s^2 per sqrt(s)
  /// The sensor's temperature rises by temperatureRiseK towards skin temperature with the time
  /// constant temperatureTauS: T(t) - T(0) = rise (1 - exp(-t / tau)).
  double temperatureRiseK = 0.0;                            ///< K
  double temperatureTauS = 300.0;                           ///< s, > 0
  Eigen::Vector3d gyroBiasPerK = Eigen::Vector3d::Zero();   ///< rad/s per K
  Eigen::Vector3d accelBiasPerK = Eigen::Vector3d::Zero();  ///< m/s^2 per K

  // Timing.
  /// Internal sample rates (Hz); each output row repeats the last internal sample. Unset: the
  /// output rate (a new sample on every row). Must be > 0 and at most the output rate.
  std::optional<double> gyroRateHz, accelRateHz;
  double jitterStdS =
      0.0;  ///< s, white jitter of each internal sample's true time (clipped at 3 sigma)
  double clockOffsetS = 0.0;  ///< s, the sensor samples at stamp + offset (|offset| <= 0.1 s)

  // Converter.
  double gyroRange = 0.0;   ///< rad/s full scale (0: none)
  double accelRange = 0.0;  ///< m/s^2 full scale (0: none)
  double gyroLsb = 0.0;     ///< rad/s per count (0: full precision)
  double accelLsb = 0.0;    ///< m/s^2 per count (0: full precision)

  // Strap wobble: a spring-damper between the sensor and the segment, driven by the segment's
  // acceleration at the sensor. Tilt phi (rad): phi'' + 2 z w phi' + w^2 phi = -w^2 k (n x a);
  // translation x (m): x'' + 2 z w x' + w^2 x = -lambda a_t (a_t: a's part across n).
  double wobbleFrequencyHz = 12.0;     ///< natural frequency w / 2 pi, Hz (> 0)
  double wobbleDamping = 0.3;          ///< damping ratio z, in (0, 2]
  double wobbleTiltPerAccel = 0.0;     ///< k: static tilt, rad per m/s^2 (0: no rotational wobble)
  double wobbleTranslationGain = 0.0;  ///< lambda, 0-1 (0: no translational wobble)
  /// n: the skin's normal (out of the skin) in the model's IMU frame (z in the arm model).
  Eigen::Vector3d skinNormal = Eigen::Vector3d::UnitZ();

  // Slow strap slip about the segment's long axis: psi(t) = slipMaxRad (1 - exp(-t / slipTauS)).
  double slipMaxRad = 0.0;  ///< rad, the angle it creeps towards (signed)
  double slipTauS = 120.0;  ///< s, > 0
  /// The segment's long axis in the model's IMU frame (y in the arm model).
  Eigen::Vector3d slipAxis = Eigen::Vector3d::UnitY();
};

/// Throws std::invalid_argument naming the parameter (e.g. "upper-arm IMU: errors.gyroRateHz must
/// be > 0 and at most the output rate 90 Hz, got 120") for a non-finite value, a rate <= 0 or above
/// outputRateHz, a negative walk, range, LSB or jitter, and so on. who names the sensor.
void checkImuErrors(const ImuErrorParams& p, double outputRateHz, const std::string& who);

/// Simulates one IMU with errors, row by row on its output clock. Deterministic given the seed
/// and stream. Not thread-safe.
class ImuErrorModel {
 public:
  using TruthFn = std::function<ImuTruth(double t)>;
  /// imu: the sensor (output rate, white noise, constant bias, static misalignment, errors).
  /// Throws std::invalid_argument as checkImuErrors. who names the sensor in messages.
  ImuErrorModel(const ImuSimParams& imu, std::uint64_t seed, std::uint32_t stream,
                const std::string& who = "IMU");

  /// The reading logged with time stamp t (s, non-decreasing from call to call): the last
  /// internal gyroscope and accelerometer samples at or before t on the sensor's clock.
  ImuReading reading(double t, const TruthFn& truth);
  /// Starts the sensor's clock and state at t (s) without simulating what came before.
  void skipTo(double t);

  // The state after the last reading (for tests and diagnostics).
  double gyroSampleTime() const { return m_gyro.trueTime; }  ///< true time of the held gyro sample
  double accelSampleTime() const { return m_accel.trueTime; }
  std::uint64_t gyroSamples() const { return m_gyro.next; }  ///< internal gyro samples taken
  std::uint64_t accelSamples() const { return m_accel.next; }
  Eigen::Vector3d gyroBias() const;   ///< rad/s at the state's time (constant + walk + drift)
  Eigen::Vector3d accelBias() const;  ///< m/s^2
  Eigen::Vector3d wobbleTilt() const { return m_phi; }  ///< rad (rotation vector)
  Eigen::Vector3d wobbleShift() const { return m_x; }   ///< m
  double slipAngle() const;                             ///< rad
  double stateTime() const { return m_time; }

 private:
  struct Channel {
    double rate = 0.0;
    std::uint64_t next = 0;  // index of the next internal sample
    double trueTime = 0.0;
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
    bool has = false;
    double jitter = 0.0;  // s, of the next sample
    bool jitterDrawn = false;
  };
  void advance(double to, const TruthFn& truth);
  void sample(bool gyro, double trueTime, const TruthFn& truth);
  double normal();
  Eigen::Vector3d normal3();

  ImuErrorParams m_p;
  Eigen::Matrix3d m_misalignment;
  Eigen::Vector3d m_gyroBias0, m_accelBias0;
  double m_gyroNoise = 0.0, m_accelNoise = 0.0;
  Channel m_gyro, m_accel;
  double m_time = 0.0;  // true time of the state below
  bool m_started = false;
  Eigen::Vector3d m_walkGyro = Eigen::Vector3d::Zero(), m_walkAccel = Eigen::Vector3d::Zero();
  Eigen::Vector3d m_phi = Eigen::Vector3d::Zero(), m_phiDot = Eigen::Vector3d::Zero();
  Eigen::Vector3d m_x = Eigen::Vector3d::Zero(), m_xDot = Eigen::Vector3d::Zero();
  Eigen::Vector3d m_xDdot = Eigen::Vector3d::Zero();
  Eigen::Vector3d m_lastLin = Eigen::Vector3d::Zero();
  std::mt19937_64 m_rng;
  std::normal_distribution<double> m_normal{0.0, 1.0};
};

/// The sensors a simulation uses: today's ideal ones, or the realistic preset.
enum class SensorModel { Ideal, Realistic };
/// "ideal" or "realistic"; throws std::invalid_argument naming the text and the choices.
SensorModel parseSensorModel(const std::string& text);

/// The realistic preset's bounds (docs/simulation.md has the datasheet behind each).
struct RealisticBounds {
  static constexpr double kDeg = 3.14159265358979323846 / 180.0;
  static constexpr double kG = 9.80665;
  static constexpr double kGyroScale = 0.03;            ///< |relative| (MPU-9250 +-3 %)
  static constexpr double kGyroCrossAxis = 0.02;        ///< |relative| (MPU-9250, ICM-20948 +-2 %)
  static constexpr double kAccelScale = 0.03;           ///< |relative| (MPU-9250 +-3 %)
  static constexpr double kAccelCrossAxis = 0.02;       ///< |relative| (MPU-9250, ICM-20948 +-2 %)
  static constexpr double kGyroBias = 3.0 * kDeg;       ///< rad/s (BMI160 +-3 deg/s)
  static constexpr double kAccelBias = 0.040 * kG;      ///< m/s^2 (BMI160 +-40 mg)
  static constexpr double kGyroBiasPerK = 0.05 * kDeg;  ///< rad/s/K (BMI160, ICM-20948)
  static constexpr double kAccelBiasPerK = 0.001 * kG;  ///< m/s^2/K (BMI160 +-1 mg/K)
  static constexpr double kGyroGSensitivity = 0.1 * kDeg / kG;  ///< rad/s per m/s^2 (0.1 deg/s/g)
  static constexpr double kGyroWalkMin = 0.001 * kDeg,
                          kGyroWalkMax = 0.004 * kDeg;                 ///< rad/s/sqrt(s)
  static constexpr double kAccelWalkMin = 2e-4, kAccelWalkMax = 1e-3;  ///< m/s^2/sqrt(s)
  static constexpr double kRiseMinK = 5.0, kRiseMaxK = 12.0;           ///< K
  static constexpr double kTempTauMinS = 120.0, kTempTauMaxS = 600.0;  ///< s
  static constexpr double kOutputRateHz = 90.0;                        ///< the logger's clock
  static constexpr double kGyroRateRatio = 50.0 / 90.0;   ///< internal gyro rate / output rate
  static constexpr double kAccelRateRatio = 25.0 / 90.0;  ///< internal accel rate / output rate
  static constexpr double kJitterMinS = 0.0002, kJitterMaxS = 0.001;  ///< s
  static constexpr double kClockOffsetS = 0.005;                      ///< |s|
  static constexpr double kGyroRange = 2000.0 * kDeg;                 ///< rad/s
  static constexpr double kAccelRange = 16.0 * kG;                    ///< m/s^2
  static constexpr double kGyroLsb = kDeg / 16.4;                     ///< rad/s per count
  static constexpr double kAccelLsb = kG / 2048.0;                    ///< m/s^2 per count
  static constexpr double kWobbleMinHz = 8.0, kWobbleMaxHz = 20.0;
  static constexpr double kWobbleDampingMin = 0.2, kWobbleDampingMax = 0.5;
  static constexpr double kTiltPerAccelMin = 0.03 * kDeg,
                          kTiltPerAccelMax = 0.08 * kDeg;  ///< rad per m/s^2
  static constexpr double kTranslationGainMin = 0.1, kTranslationGainMax = 0.4;
  static constexpr double kSlipMinRad = 1.0 * kDeg, kSlipMaxRad = 5.0 * kDeg;  ///< |rad|
  static constexpr double kSlipTauMinS = 60.0, kSlipTauMaxS = 300.0;           ///< s
};

/// The realistic preset for one IMU: every per-sensor constant drawn uniformly within
/// RealisticBounds from (seed, sensor), the converter of a +-2000 deg/s, +-16 g, 16-bit part, and
/// internal rates of 50/90 and 25/90 of outputRateHz (50 Hz gyroscope and 25 Hz accelerometer on a
/// 90 Hz clock, as the logger of issue 27). The same seed and sensor give the same draw.
/// drawnGyroBias and drawnAccelBias receive the constant biases drawn (added to ImuSimParams').
ImuErrorParams realisticImuErrors(std::uint64_t seed, int sensor, double outputRateHz,
                                  Eigen::Vector3d* drawnGyroBias = nullptr,
                                  Eigen::Vector3d* drawnAccelBias = nullptr);

/// Applies a sensor model to sim (after its IMUs' rates, noise, biases and the sternum IMU are
/// set, and sim.seed): Ideal leaves sim as it is; Realistic puts the preset on the upper-arm
/// (sensor 0), forearm (1) and sternum (2) IMUs, adds the drawn biases to their constant biases and
/// sets their output rate to imuRateHz, or 90 Hz when unset.
void applySensorModel(SensorModel model, SimulationParams& sim,
                      std::optional<double> imuRateHz = std::nullopt);

}  // namespace armtrack
