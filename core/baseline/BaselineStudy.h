// The baseline beside the DH filter (docs/baseline.md, "The study"): both run on the same
// recordings (the double pendulum with ideal sensors and with 50/25 Hz readings held on a 90 Hz
// clock with Table 5 noise, for several placements of the elbow's zero, both methods told where
// the forearm IMU sits on the rod and both not; the reaching simulation with Table 5 noise,
// IMUs only), and their hinge, pronation and swing errors against the truth. The DH filter runs
// through its public path (core/estimation/RecordingEstimator.h), as `estimate` does.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/baseline/JointBaseline.h"
#include "core/io/Recording.h"

namespace armtrack {

/// RMSE and peak of one angle's error (rad in, deg out).
struct AngleError {
  std::size_t count = 0;
  double sumSq = 0.0;  ///< rad^2
  double peak = 0.0;   ///< rad
  void add(double error);
  double rmseDeg() const;
  double peakDeg() const;
};

/// The three angles both methods estimate: the hinge (th4), pronation (th5) and the swing as the
/// humerus' elevation from the downward vertical (humerusElevation).
struct JointErrors {
  AngleError hinge, pronation, swing;
  /// One estimate against the true joint angles (NaN estimates are left out). up: the sidecar's.
  void add(const JointVector& truth, double flexion, double pronation, double elevation,
           const Eigen::Vector3d& up);
};

/// The baseline's parameters for a recording: geometry and gravity from its sidecar.
BaselineParams baselineParamsFor(const RecordingMeta& meta);

/// Runs the baseline over a recording; each output row goes to sink (when given). The errors
/// leave out the first second after each (re)start, as `estimate`'s do.
using BaselineSink = std::function<void(const BaselineRow&)>;
struct BaselineRun {
  BaselineCounters counters;
  JointErrors errors;  ///< empty when the recording has no true angles
};
BaselineRun runBaseline(const Recording& recording, const BaselineParams& params,
                        const BaselineSink& sink = {});

/// The DH filter (EKF, default settings, IMUs only) over the same recording, scored the same way.
/// freeElbow lifts the filter's anatomical limits on th4 (-170 to 20 deg by default), which a
/// pendulum's hinge passes: the study's pendulum rows give the filter the hinge's range that way.
/// Everything else stays at its default.
JointErrors runDhFilter(const Recording& recording, bool freeElbow = false);

/// Where the elbow really is seen from the forearm IMU of simulatePendulum (forearm axes, m) when
/// the model's zero is put zeroOffset (rad) from the pendulum's straight hinge.
Eigen::Vector3d pendulumElbowFromForearm(const ArmGeometry& geometry, double zeroOffset);

struct BaselineStudySetup {
  double pendulumSeconds = 60.0;
  double reachingSeconds = 30.0;
  int reachingRuns = 3;                              ///< seeds 1..runs
  std::vector<double> zerosDeg = {0.0, 35.0, 90.0};  ///< the model's flexion at the straight hinge
};

struct BaselineStudyRow {
  std::string recording;  ///< e.g. "pendulum, ideal"
  double zeroDeg = 0.0;   ///< NaN for the reaching simulation
  std::string method;     ///< "DH filter" or "baseline"
  JointErrors errors;
  double trueHingeMinDeg = 0.0, trueHingeMaxDeg = 0.0;  ///< the range of the true th4
};

using BaselineStudyProgress = std::function<void(int done, int total)>;
std::vector<BaselineStudyRow> runBaselineStudy(const BaselineStudySetup& setup,
                                               const BaselineStudyProgress& progress = {});
std::string formatBaselineStudy(const std::vector<BaselineStudyRow>& rows,
                                const BaselineStudySetup& setup);

}  // namespace armtrack
