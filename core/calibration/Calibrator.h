// Batch sensor-to-segment calibration: nonlinear least squares (Ceres) over a short calibration
// recording, on the same measurement model as the joint-angle filter. The joint trajectory is a
// cubic B-spline fitted jointly with the calibration. docs/calibration.md.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/calibration/Calibration.h"
#include "core/estimation/SampleGate.h"
#include "core/io/Recording.h"

namespace armtrack {

/// Calibration settings. Noise defaults are the paper's Table 5.
struct CalibrationOptions {
  /// Pose held at the start of the recording (rad); the protocol's start pose by default.
  JointVector startPose = protocolStartPose();
  /// The first startStillSeconds of the recording are taken as the still start pose: the gyro
  /// mean there is the first bias guess, and the start pose is imposed at its middle (s). The
  /// start pose fixes what no reading sees: pronation th5 (only th5 + thf7 is observable) and,
  /// without optical data, the heading about the vertical. An error of the patient's pose there
  /// goes one to one into those two.
  double startStillSeconds = 2.0;
  double knotSpacing = 0.04;      ///< s, B-spline knot spacing of the joint trajectory
  double residualRateHz = 100.0;  ///< IMU readings are averaged into bins at this rate
  double gyroStd = 0.005518;      ///< rad/s per reading, Table 5: sqrt(0.1) deg/s
  double accelStd = 0.1;          ///< m/s^2 per reading, Table 5
  double positionStd = 0.01;      ///< m, optical positions, Table 5 (Kinect)
  bool useOptical = true;         ///< fit optical elbow/wrist positions when present
  /// With optical positions, also estimate the segment lengths l3 and l6.
  bool estimateSegmentLengths = true;
  // Weak priors toward the recording's values (what nothing in the data settles stays there).
  double lengthPriorStd = 0.05;             ///< m, every length
  double strapAnglePriorStd = 60.0 * kDeg;  ///< rad, thu4 (thf7 has none: the start pose fixes it)
  double tiltPriorStd = 20.0 * kDeg;        ///< rad, each residual-rotation component
  double biasPriorStd = 5.0 * kDeg;         ///< rad/s, each gyro-bias component
  int maxIterations = 20;                   ///< of the final solve over the whole recording
  /// Without optical data the data enter in stages of this length (s), each solved with up to
  /// stageIterations iterations, so the wandering heading of the first trajectory can be
  /// re-anchored; 0 solves everything at once.
  double stageSeconds = 8.0;
  int stageIterations = 8;
  /// Iterations after the gauges (heading, th5) are put back on the start pose at the end.
  int polishIterations = 10;
  int threads = 2;
  /// Joint-acceleration std of the EKF run that gives the first trajectory (rad/s^2).
  double initialFilterJointAccelStd = 10.0 * kDeg;
};

/// The fit and how well it went.
struct CalibrationResult {
  Calibration calibration;
  int iterations = 0;
  bool converged = false;
  double initialCost = 0.0, finalCost = 0.0;  ///< Ceres cost (half the sum of squares)
  double seconds = 0.0;                       ///< wall time of the whole calibration
  /// RMS of the whitened residuals per kind after the fit (about 1 when the model explains the
  /// data to the noise level; 0 when the kind is absent): upper-arm gyro, upper-arm
  /// accelerometer, forearm gyro, forearm accelerometer, optical positions.
  double rmsUpperGyro = 0, rmsUpperAcc = 0, rmsForearmGyro = 0, rmsForearmAcc = 0, rmsPosition = 0;
  std::size_t imuBins = 0, opticalPoints = 0;  ///< residual epochs used
  /// Sensor blocks refused by the plausibility gate (core/estimation/SampleGate.h, limits from
  /// the sidecar's segment lengths) before anything else: they took no part in the fit.
  GateCounters implausible;
  /// The fitted joint trajectory at residualRateHz over the recording (th, thd, thdd; thStd is
  /// zero), in the recording's time.
  std::vector<JointEstimate> trajectory;
  std::vector<std::string> warnings;  ///< e.g. the start was not held still
};

/// One progress line (for stderr); called from the calling thread.
using CalibrationProgress = std::function<void(const std::string& line)>;

/// Estimates the calibration from a recording made with the protocol of docs/calibration.md.
/// The recording's sidecar geometry is the starting point; a left arm is mirrored onto its
/// right-arm twin for the fit and the result is given in the real sensors' axes. Every sample
/// first passes the plausibility gate (SampleGate with PlausibilityLimits::forGeometry of the
/// sidecar's l3 and l6): implausible sensor blocks are dropped, counted in
/// CalibrationResult::implausible and reported through progress. Ceres and glog write nothing to
/// the process's output while it runs (glog's threshold is raised to FATAL for that time).
/// Throws std::invalid_argument when the recording cannot be used (no upper-arm or forearm IMU,
/// shorter than 10 s) and std::runtime_error, with a one-line message, when the solver fails
/// (e.g. the model cannot be evaluated on the data) or the fitted calibration is outside
/// physical limits (calibrationProblem, core/calibration/Calibration.h): such a result is never
/// returned.
CalibrationResult calibrate(const Recording& recording, const CalibrationOptions& options = {},
                            const CalibrationProgress& progress = {});

/// The sensor's whole mounting rotation relative to a reference strap angle: the residual
/// rotation preceded by the turn about the segment's long axis (the IMU frame's y axis) by
/// strapAngle - referenceStrapAngle. With the reference at the simulated geometry's value, this
/// is what ImuSimParams::misalignment describes.
Eigen::Matrix3d mountingRotation(double strapAngle, double referenceStrapAngle,
                                 const Eigen::Matrix3d& residual);

}  // namespace armtrack
