// Smoothness of a movement from its speed profile or its path: SPARC (spectral arc length) and
// LDLJ (log dimensionless jerk), as defined by Balasubramanian, Melendez-Calderon, Roby-Brami and
// Burdet, "On the analysis of movement smoothness", J NeuroEng Rehabil 12:112 (2015), and their
// reference code (github.com/siva82kb/SPARC, scripts/smoothness.py). See docs/metrics.md.
// Both are dimensionless and negative; closer to zero = smoother.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "core/kinematics/ArmModel.h"
#include "core/metrics/RangeOfMotion.h"

namespace armtrack {

enum class SmoothnessStatus {
  Ok,
  TooShort,    ///< fewer than 4 samples (LDLJ needs second differences of the velocity)
  NonFinite,   ///< a NaN or infinite sample, or a non-finite or non-positive sample rate
  NoMovement,  ///< the speed is zero throughout: smoothness is undefined
  ZeroJerk,    ///< LDLJ only: no jerk at all (constant velocity), the log is unbounded
};
const char* toString(SmoothnessStatus s);

/// A smoothness value; `value` is meaningful only when status == Ok (it is 0 otherwise).
struct SmoothnessValue {
  double value = 0;
  SmoothnessStatus status = SmoothnessStatus::TooShort;
  bool ok() const { return status == SmoothnessStatus::Ok; }
};

struct SparcParams {
  double maxCutoffHz = 10.0;         ///< fc_max of the paper (10 Hz = 20 pi rad/s)
  double amplitudeThreshold = 0.05;  ///< V-bar: the normalised spectrum's threshold
  int padLevel = 4;                  ///< zero padding: FFT length 2^(ceil(log2 N) + padLevel)
};

/// SPARC of a speed profile sampled uniformly at sampleRateHz: the negative arc length of the
/// normalised magnitude spectrum from 0 up to the adaptive cut-off, the last frequency at or
/// below maxCutoffHz where the spectrum is still >= amplitudeThreshold, with the frequency axis
/// divided by that band's width (paper eq. 6 and the reference code).
SmoothnessValue sparc(const std::vector<double>& speed, double sampleRateHz,
                      const SparcParams& params = {});

/// LDLJ of a speed profile (the reference code's log_dimensionless_jerk):
/// -ln( T^3 / v_peak^2 * integral (d^2 v / dt^2)^2 dt ), T = N / sampleRateHz, second
/// differences for d^2v/dt^2 and a rectangle sum for the integral.
SmoothnessValue ldljFromSpeed(const std::vector<double>& speed, double sampleRateHz);

/// LDLJ from a velocity vector (rows = samples, uniform rate): the same with |d^2 v/dt^2|, the
/// magnitude of the jerk vector, as the paper's Table 3 recommends for position data, and
/// v_peak the largest speed. For movement along a line this equals ldljFromSpeed.
SmoothnessValue ldljFromVelocity(const Eigen::MatrixXd& velocity, double sampleRateHz);

struct PathSmoothness {
  SmoothnessValue sparc;
  SmoothnessValue ldlj;       ///< jerk-vector form (ldljFromVelocity)
  double sampleRateHz = 0;    ///< the uniform rate the path was resampled to
  double peakSpeedMPerS = 0;  ///< largest speed of the smoothed path (m/s)
};

struct PathSmoothnessParams {
  /// Differentiation of the positions (local cubic fit, 0.03 s half-width). Narrower than for
  /// the joint angles, so the speed's spectrum stays intact up to the 10 Hz cut-off; the gap
  /// length is not used here.
  SmoothingParams smoothing{.halfWindowSeconds = 0.03,
                            .polynomialOrder = 3,
                            .maxSamplesPerFit = 100,
                            .maxGapSeconds = 0.25};
  SparcParams sparc;
  /// Uniform rate the velocity is resampled to (Hz); 0 = the inverse of the mean time step,
  /// counting only steps up to twice the median (so a gap does not lower the rate).
  double resampleHz = 0;
  /// A path whose peak speed stays below this (m/s) did not move: status NoMovement, rather
  /// than a smoothness of rounding noise. Default 1 mm/s.
  double minPeakSpeedMPerS = 1e-3;
};

/// Velocity of a path on a uniform time grid: positions (rows = samples, any dimension, m) at
/// times t (s, strictly increasing, finite); at each grid time t0 + k / sampleRateHz the local
/// polynomial of params.smoothing is fitted to the samples within +-halfWindowSeconds and
/// differentiated. A grid time with fewer than two samples in reach (a gap) gets velocity 0.
struct UniformVelocity {
  double t0 = 0;             ///< s, time of row 0
  double sampleRateHz = 0;   ///< grid rate
  Eigen::MatrixXd velocity;  ///< m/s, rows = grid times
};
/// Throws std::invalid_argument when sizes differ, times do not increase strictly, or a
/// parameter is out of range.
UniformVelocity uniformVelocity(const std::vector<double>& t, const Eigen::MatrixXd& positions,
                                const PathSmoothnessParams& params = {});

/// The grid uniformVelocity() evaluates on (t0 and the rate), without the velocity. Checks and
/// throws as uniformVelocity(); rate 0 for fewer than two times.
UniformVelocity uniformGrid(const std::vector<double>& t, const PathSmoothnessParams& params = {});
/// The rows of uniformVelocity() whose grid times lie in [fromS, toS] (grid from uniformGrid()):
/// the same numbers, but only the part asked for is computed and held, so a long session, or
/// one with a long gap, costs no more than the movements it holds. Returns a UniformVelocity
/// whose t0 is the first grid time in the interval.
UniformVelocity uniformVelocityBetween(const std::vector<double>& t,
                                       const Eigen::MatrixXd& positions,
                                       const PathSmoothnessParams& params,
                                       const UniformVelocity& grid, double fromS, double toS);

/// SPARC (of the speed) and LDLJ (jerk-vector form) of a uniformly sampled velocity.
PathSmoothness velocitySmoothness(const Eigen::MatrixXd& velocity, double sampleRateHz,
                                  const PathSmoothnessParams& params = {});

/// uniformVelocity() then velocitySmoothness(): the smoothness of one movement's path.
/// Non-finite positions give status NonFinite; fewer than 4 grid samples TooShort.
PathSmoothness pathSmoothness(const std::vector<double>& t, const Eigen::MatrixXd& positions,
                              const PathSmoothnessParams& params = {});

/// Wrist positions (m, shoulder frame of docs/arm-model.md, rows = samples) of the arm model
/// for clinical angles (rad), by forward kinematics with the given segment lengths.
Eigen::MatrixXd wristPath(const std::vector<ClinicalRow>& anglesRad, const ArmGeometry& geometry);

}  // namespace armtrack
