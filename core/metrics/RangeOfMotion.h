// Range of motion, angular velocity and movement time of the five clinical angles over a session
// or any part of it (docs/metrics.md). SI inside: radians, seconds; degrees only through
// inDegrees() for display.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <numbers>
#include <vector>

#include "core/kinematics/ArmModel.h"
#include "core/metrics/Smoothing.h"

namespace armtrack {

/// Number of clinical angles, in the order of clinicalAngleInfo() (core/kinematics).
inline constexpr int kNumClinicalAngles = 5;
using ClinicalRow = std::array<double, kNumClinicalAngles>;

/// A session's clinical angles over time: row i holds the five angles (rad, order and signs of
/// ClinicalAngles) at time t[i] (s). Times should increase strictly.
struct AngleSeries {
  std::vector<double> t;           ///< s
  std::vector<ClinicalRow> angle;  ///< rad
};

/// Clinical angles (rad) of DH joint vectors, with the sign conventions of toClinical().
AngleSeries angleSeriesFromJoints(const std::vector<double>& t,
                                  const std::vector<JointVector>& joints);
/// The DH joint vector (rad) of one row of clinical angles (rad).
JointVector jointsFromClinical(const ClinicalRow& clinicalRad);

struct MotionParams {
  SmoothingParams smoothing;
  /// An angle is moving while the magnitude of its smoothed rate is at least this (rad/s).
  /// Default 10 deg/s: well above what estimator noise gives after smoothing (about 1 deg/s) and
  /// well below the rates of a deliberate exercise movement (tens of deg/s and more).
  double movingThresholdRadPerS = 10.0 * std::numbers::pi / 180.0;
};

/// A validated, smoothed series ready for metrics. Build it with prepareSeries().
struct PreparedSeries {
  std::vector<double> t;              ///< s, strictly increasing, finite
  Eigen::MatrixXd angle;              ///< rad, smoothed; rows = samples, 5 columns
  Eigen::MatrixXd rate;               ///< rad/s, derivative of the local fit
  std::vector<double> weight;         ///< s each sample stands for (sampleWeights())
  std::vector<Segment> segments;      ///< gap-free runs
  std::size_t inputRows = 0;          ///< rows given
  std::size_t rejectedNonFinite = 0;  ///< rows dropped for a NaN or infinite time or angle
  MotionParams params;
  std::size_t size() const { return t.size(); }
};

/// Drops (and counts) rows with a non-finite time or angle, then smooths and differentiates.
/// Throws std::invalid_argument when the angle and time columns differ in length, when no
/// usable row is left (empty input, or every row non-finite), when the kept times do not
/// increase strictly (the error names the first offending row), or when a parameter is not
/// positive and finite.
PreparedSeries prepareSeries(const AngleSeries& series, const MotionParams& params = {});

/// One clinical angle over an interval, SI units.
struct AngleMetrics {
  double minRad = 0;               ///< smallest smoothed angle
  double maxRad = 0;               ///< largest smoothed angle
  double romRad = 0;               ///< maxRad - minRad
  double peakVelocityRadPerS = 0;  ///< largest |rate|
  double meanVelocityRadPerS = 0;  ///< time-weighted mean of |rate| over the covered time
  double movementTimeS = 0;        ///< time with |rate| >= the moving threshold
};

/// The same, in degrees, for display and reports.
struct AngleMetricsDeg {
  double minDeg, maxDeg, romDeg, peakVelocityDegPerS, meanVelocityDegPerS, movementTimeS;
};
AngleMetricsDeg inDegrees(const AngleMetrics& m);

/// Metrics of the five angles over samples [begin, end) of a prepared series, plus the time
/// those samples cover (gaps excluded). A single sample gives its angle as min and max and zero
/// rates and times. Throws std::out_of_range unless begin < end <= series.size().
struct IntervalMetrics {
  std::array<AngleMetrics, kNumClinicalAngles> angle;
  double coveredTimeS = 0;  ///< s of data inside the interval, gaps excluded
  std::size_t samples = 0;
};
IntervalMetrics intervalMetrics(const PreparedSeries& series, std::size_t begin, std::size_t end);

inline constexpr double kRadToDeg = 180.0 / std::numbers::pi;
inline constexpr double kDegToRad = std::numbers::pi / 180.0;

}  // namespace armtrack
