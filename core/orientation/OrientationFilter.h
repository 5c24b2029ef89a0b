// 6D orientation filter for one IMU (gyroscope + accelerometer) in the manner of VQF
// (Laidig & Seel, Information Fusion 2023): strapdown gyroscope integration, accelerometer
// low-pass filtering in an almost-inertial frame, and gyroscope bias estimation at rest and in
// motion. Heading about the vertical is not observable and drifts. See docs/orientation.md.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace armtrack {

/// Tuning of OrientationFilter. The defaults are VQF's published defaults; they do not depend on
/// the sampling rate.
struct OrientationParams {
  /// Time constant of the accelerometer low-pass in the almost-inertial frame (s). Larger trusts
  /// the gyroscope more. Default 3.
  double tauAcc = 3.0;

  /// Estimate the gyroscope bias while rest is detected. Default true.
  bool restBiasEstEnabled = true;
  /// Estimate the horizontal gyroscope bias during motion from the inclination correction.
  /// Default true.
  bool motionBiasEstEnabled = true;

  /// Standard deviation of the initial bias estimate (deg/s). Default 0.5.
  double biasSigmaInit = 0.5;
  /// Time in which the bias uncertainty grows from 0 to 0.1 deg/s without updates (s).
  /// Default 100.
  double biasForgettingTime = 100.0;
  /// Largest bias estimate and largest bias disagreement per update, per axis (deg/s).
  /// Default 2.
  double biasClip = 2.0;
  /// Steady-state bias uncertainty reached during motion (deg/s). Default 0.1.
  double biasSigmaMotion = 0.1;
  /// Weight of the motion update along the world vertical, relative to the horizontal axes
  /// (the vertical bias is unobservable in motion; this only slowly pulls it towards 0).
  /// Dimensionless, default 1e-4.
  double biasVerticalForgettingFactor = 1e-4;
  /// Steady-state bias uncertainty reached at rest (deg/s). Default 0.03.
  double biasSigmaRest = 0.03;

  /// Time the rest criteria must hold before rest is declared (s). Default 1.5.
  double restMinT = 1.5;
  /// Time constant of the low-pass filters used for rest detection (s). Default 0.5.
  double restFilterTau = 0.5;
  /// Rest threshold on the deviation of the gyroscope from its low-passed value (deg/s).
  /// Default 2.
  double restThGyr = 2.0;
  /// Rest threshold on the deviation of the accelerometer from its low-passed value (m/s^2).
  /// Default 0.5.
  double restThAcc = 0.5;

  /// Plausibility of the gyroscope, per axis (deg/s): a reading at or beyond it (the usual full
  /// scale of MEMS gyroscopes, so also a saturated one) is rejected. Default 2000.
  double gyrMax = 2000.0;
  /// Plausibility of the accelerometer, per axis (m/s^2): a reading at or beyond it (16 g, the
  /// usual full scale) is rejected. Default 156.9064 (16 x 9.80665).
  double accMax = 16.0 * 9.80665;
  /// A time step without usable samples longer than this is a gap (s): the gyroscope is not
  /// integrated across it, the inclination starts again from the accelerometer as at start-up and
  /// the motion bias estimation waits until the accelerometer low-pass has settled again. Must
  /// exceed the sampling interval (e.g. use 0.5 below 20 Hz). Default 0.1.
  double gapSeconds = 0.1;
};

/// What update() did with a sample (also written per sample by updateBatch()).
enum class OrientationStatus : std::uint8_t {
  Accepted = 0,  ///< used
  Rejected = 1,  ///< refused (implausible value or bad dt); the estimate is unchanged
  AfterGap = 2,  ///< used, first sample after a gap: the inclination starts again from here
};

/// Coefficients of a second-order IIR low-pass, normalised to a0 = 1.
struct LowPassCoeffs {
  double b0 = 0, b1 = 0, b2 = 0, a1 = 0, a2 = 0;
};

/// Second-order Butterworth low-pass over N channels (transposed direct form II). While warming
/// up (less than the filter's time constant of input seen) it outputs the running mean, then
/// continues from that mean as a steady state, so the start does not hinge on one sample.
template <int N>
struct LowPassState {
  std::array<double, N> s0{};  ///< filter memory, first delay
  std::array<double, N> s1{};  ///< filter memory, second delay
  std::array<double, N> y{};   ///< last output
  double warmupTime = 0.0;     ///< s of input averaged so far
  std::uint32_t warmupCount = 0;
  bool running = false;  ///< past the warm-up
};

/// Everything the filter carries from sample to sample (plain data; copy it to save/restore).
struct OrientationState {
  /// Gyroscope strapdown integration: sensor frame -> almost-inertial frame.
  Eigen::Quaterniond gyrQuat = Eigen::Quaterniond::Identity();
  /// Inclination correction: almost-inertial frame -> world frame (z up).
  Eigen::Quaterniond accQuat = Eigen::Quaterniond::Identity();

  Eigen::Vector3d bias = Eigen::Vector3d::Zero();   ///< gyroscope bias estimate, sensor (rad/s)
  Eigen::Matrix3d biasP = Eigen::Matrix3d::Zero();  ///< its covariance ((rad/s)^2)

  LowPassState<3> accLp;      ///< accelerometer in the almost-inertial frame (tauAcc)
  LowPassState<9> rotLp;      ///< sensor->world rotation matrix, column-major (tauAcc)
  LowPassState<2> biasLp;     ///< world x, y of the rotated bias estimate (tauAcc)
  LowPassState<3> restGyrLp;  ///< gyroscope for rest detection (restFilterTau)
  LowPassState<3> restAccLp;  ///< accelerometer for rest detection (restFilterTau)

  double restTime = 0.0;  ///< s for which the accelerometer rest criterion has held
  bool rest = false;      ///< rest detected

  /// s of refused samples since the last accepted one: added to the next accepted sample's dt,
  /// so that a run of refused samples longer than gapSeconds is a gap.
  double pendingDt = 0.0;
  /// After a gap: no motion bias updates until the accelerometer low-pass has warmed up again,
  /// so the re-initialisation of the inclination is not taken for a gyroscope bias.
  bool biasHold = false;
  OrientationStatus last = OrientationStatus::Accepted;  ///< status of the last sample

  std::uint64_t accepted = 0;  ///< samples used
  /// Samples refused: non-finite or implausible values (see outOfRange) or dt not > 0.
  std::uint64_t rejected = 0;
  std::uint64_t outOfRange = 0;  ///< of those, finite but at or beyond gyrMax or accMax
  std::uint64_t noAcc = 0;       ///< accepted samples with acc = (0,0,0): gyroscope only
  std::uint64_t gaps = 0;        ///< gaps (steps longer than gapSeconds) after the first sample
  double gapTime = 0.0;          ///< s spent in those gaps
};

/// VQF-style 6D orientation filter. update() does no heap allocation and no I/O.
class OrientationFilter {
 public:
  /// Throws std::invalid_argument for non-positive time constants or thresholds.
  explicit OrientationFilter(const OrientationParams& params = {});

  /// One sample: gyr (rad/s) and acc (m/s^2) in sensor axes, dt (s) since the previous sample.
  /// Returns false and counts the sample in state().rejected when any value is not finite, a
  /// gyroscope or accelerometer axis is at or beyond gyrMax or accMax, or dt is not > 0; the
  /// estimate is then untouched, and a valid dt is carried over to the next accepted sample.
  /// A step (with carried-over time) longer than gapSeconds is a gap, see OrientationParams.
  /// acc = (0,0,0) means "no accelerometer sample": the gyroscope is still integrated.
  bool update(const Eigen::Vector3d& gyr, const Eigen::Vector3d& acc, double dt);

  /// update() over n samples. gyr and acc hold x,y,z per sample (3n values), dt one value per
  /// sample, quatOut (if not empty) receives w,x,y,z of orientation() after each sample (4n
  /// values; a rejected sample repeats the previous orientation), statusOut (if not empty) the
  /// OrientationStatus of each sample (n values). Returns the number of samples accepted. Throws
  /// std::invalid_argument when the sizes do not match.
  std::size_t updateBatch(std::span<const double> gyr, std::span<const double> acc,
                          std::span<const double> dt, std::span<double> quatOut,
                          std::span<OrientationStatus> statusOut = {});

  /// Sensor-to-world rotation (world z up; heading arbitrary and drifting).
  Eigen::Quaterniond orientation() const { return m_s.accQuat * m_s.gyrQuat; }
  const Eigen::Vector3d& bias() const { return m_s.bias; }  ///< rad/s, sensor axes
  /// Upper bound of the bias estimate's standard deviation (rad/s).
  double biasSigma() const;
  bool restDetected() const { return m_s.rest; }
  /// What the last update() did with its sample.
  OrientationStatus lastStatus() const { return m_s.last; }

  const OrientationParams& params() const { return m_p; }
  const OrientationState& state() const { return m_s; }
  void setState(const OrientationState& s) { m_s = s; }
  /// Back to the initial state (identity orientation, zero bias).
  void reset();

 private:
  struct Coefficients {
    double dt = 0.0;  ///< s the coefficients were made for
    LowPassCoeffs acc, rest;
    double biasP0 = 0, biasV = 0, biasMotionW = 0, biasVerticalW = 0, biasRestW = 0;
  };

  void setCoefficients(double dt);
  bool reject(const Eigen::Vector3d& gyr, const Eigen::Vector3d& acc, double dt);
  void restartAfterGap(double gap);
  void estimateBias(const Eigen::Vector3d& accWorld, double dt);

  OrientationParams m_p;
  double m_gyrMax = 0.0;  // rad/s, from m_p.gyrMax
  Coefficients m_c;
  OrientationState m_s;
};

/// Angle (rad) between the world vertical as seen in the sensor frame by two sensor-to-world
/// orientations, i.e. the inclination error; heading is ignored.
double inclinationError(const Eigen::Quaterniond& estimate, const Eigen::Quaterniond& truth);

}  // namespace armtrack
