// Detects a trunk that moved away from its start pose when no trunk IMU measures it
// (docs/trunk.md). Fed sample by sample, it says for every sample whether the trunk is displaced
// NOW and by how much the shoulder seems to have moved, and keeps the spans of time in which it
// was. Two cues, in this order of preference:
//   1. an optical shoulder (Kinect skeleton, shoulder marker) in the world frame: its smoothed
//      displacement from its own start position;
//   2. without one, the optical elbow and wrist against the filter's predicted elbow and wrist:
//      a trunk that moves carries both optical points by the same translation (the shoulder's),
//      which the filter, whose shoulder stays at the origin, cannot follow. Only a residual that
//      is common to both points counts; see docs/trunk.md for what this cue cannot see.
// Plain C++ and Eigen, no allocation beyond small buffers, no I/O. Not thread-safe.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace armtrack {

struct TrunkMotionParams {
  /// Cue data from the first referenceSeconds (s) of cue samples, trunk assumed still and upright
  /// there, set the start pose (their mean, outliers removed). No decision before it is complete.
  /// Default 1 s (30 Kinect frames: the start position to about 2 mm).
  double referenceSeconds = 1.0;
  /// Cue samples averaged for the current position (after outlier removal). Default 9 (0.3 s at
  /// 30 Hz: 1 cm of noise per axis becomes 3.3 mm, at a lag of 0.13 s).
  int windowSamples = 9;
  /// Samples older than this (s) leave the average even if fewer than windowSamples remain.
  double windowSeconds = 0.4;
  /// A decision needs at least this many samples in the average. Default 5.
  int minSamples = 5;
  /// A shoulder sample farther than this (m) from the current average is an outlier, and left
  /// out. Default 0.15 m: 1 cm of Kinect noise per axis stays under 6 cm, which leaves 9 cm for
  /// the average's lag of 0.13 s (0.7 m/s of trunk speed, beyond a seated patient's lean). A gate
  /// within reach of the noise would bias the average: the samples it cuts are all on one side.
  double gateM = 0.15;
  /// The same for the arm cue's six numbers (common residual and wrist-minus-elbow residual,
  /// whose noise is sqrt(2) x the optical noise per axis). Default 0.2 m.
  double armGateM = 0.20;
  /// After this many outliers in a row that agree with one another (within the gate of their
  /// median), the average restarts from them: the point really is elsewhere now. Default 5.
  int relockSamples = 5;
  /// No cue sample for longer than this (s): the average restarts (the old one is stale).
  double maxGapSeconds = 0.5;
  /// The decision holds this long (s) after the latest cue sample (between Kinect frames, across
  /// short dropouts); after that nothing is known and the trunk is not reported as moving.
  double holdSeconds = 0.5;
  /// A position farther than this (m) from the world origin (the shoulder at the start) is not
  /// a shoulder, elbow or wrist of this patient: refused and counted. Default 2 m.
  double maxAbsM = 2.0;
  /// Shoulder cue: moving when the displacement reaches enterM (m), still again below exitM.
  /// Defaults 2.5 cm and 1.5 cm: a 5 deg lean about a hip 0.47 m below moves the shoulder 4.1 cm,
  /// and 2.5 cm is more than 6 sigma of the averaged noise (3.8 mm per axis, start position
  /// included).
  double enterM = 0.025;
  double exitM = 0.015;
  /// Arm cue: moving when the common residual of elbow and wrist reaches armEnterM (m), still
  /// again below armExitM. Defaults 3 cm and 2 cm (the filter's own errors add to the noise).
  double armEnterM = 0.03;
  double armExitM = 0.02;
  /// Arm cue: the elbow's and wrist's residuals must agree: |r_wrist - r_elbow| (averaged) at most
  /// armConsistency x |common residual| + armToleranceM. A shoulder-angle error of the filter
  /// moves the wrist about twice as far as the elbow (ratio 0.6 or more) and is not a trunk.
  double armConsistency = 0.35;
  double armToleranceM = 0.005;
};

/// Which cue a decision came from.
enum class TrunkCue : std::uint8_t {
  None,      ///< no usable cue right now (nothing known; not reported as moving)
  Shoulder,  ///< the optical shoulder
  Arm,       ///< optical elbow and wrist against the filter's prediction
};
const char* trunkCueName(TrunkCue cue);

/// One sample's inputs, all positions in the world frame (frame 0 as it was with the trunk upright
/// at the start), metres. Leave empty whatever this sample does not have.
struct TrunkMotionInput {
  double t = 0;                             ///< s, must not decrease
  std::optional<Eigen::Vector3d> shoulder;  ///< optical shoulder
  std::optional<Eigen::Vector3d> elbow;     ///< optical elbow
  std::optional<Eigen::Vector3d> wrist;     ///< optical wrist
  /// The filter's predicted elbow and wrist for this time (before using this sample's optical
  /// points), computed with the shoulder at the origin and the trunk still. The arm cue needs all
  /// four of elbow, wrist, predictedElbow and predictedWrist.
  std::optional<Eigen::Vector3d> predictedElbow;
  std::optional<Eigen::Vector3d> predictedWrist;
};

/// The decision for one sample.
struct TrunkMotionStatus {
  bool moving = false;       ///< the trunk is displaced from its start pose now
  double displacementM = 0;  ///< estimated shoulder displacement (m); 0 with TrunkCue::None
  TrunkCue cue = TrunkCue::None;
};

/// A span of time in which the trunk was reported moving.
struct TrunkMotionSpan {
  double startS = 0;              ///< time of the first sample reported moving (s)
  double endS = 0;                ///< time of the last sample reported moving (s)
  double maxDisplacementM = 0;    ///< largest displacement estimated inside the span (m)
  TrunkCue cue = TrunkCue::None;  ///< the cue that opened the span
  bool open = false;              ///< still moving at the latest sample (endS = that sample)
};

/// What was left out, per cue.
struct TrunkMotionCounters {
  std::uint64_t refusedTime = 0;      ///< samples with a non-finite or decreasing time (ignored)
  std::uint64_t refusedShoulder = 0;  ///< non-finite or absurd shoulder positions
  std::uint64_t outlierShoulder = 0;  ///< shoulder positions left out as outliers
  std::uint64_t refusedArm = 0;       ///< samples whose arm-cue points were non-finite or absurd
  std::uint64_t outlierArm = 0;       ///< arm-cue residuals left out as outliers
};

class TrunkMotionDetector {
 public:
  explicit TrunkMotionDetector(const TrunkMotionParams& params = {});

  /// Feeds one sample (any rate: IMU-only samples just carry the decision forward) and returns
  /// the decision for it.
  TrunkMotionStatus update(const TrunkMotionInput& in);

  /// The spans so far, closed ones and (last, open = true) the current one.
  std::vector<TrunkMotionSpan> spans() const;
  const TrunkMotionCounters& counters() const { return m_counters; }
  const TrunkMotionParams& params() const { return m_params; }
  void reset();

 private:
  /// A cue's robust running average of a vector, relative to its start value (docs/trunk.md).
  template <int N>
  class Level {
   public:
    using Vec = Eigen::Matrix<double, N, 1>;
    Level(const TrunkMotionParams& p, double gateM) : m_p(p), m_gate(gateM) {}
    /// Adds a sample; returns false when it was left out as an outlier.
    bool add(double t, const Vec& x);
    /// Whether the average is fresh at time t, has enough samples and the start value is known.
    bool valid(double t) const;
    /// The averaged value minus the start value (valid() only).
    Vec displacement() const;
    std::uint64_t outliers() const { return m_outliers; }
    void reset();

   private:
    struct Entry {
      double t;
      Vec x;
      bool counted;  // already counted as an outlier
    };
    void accept(const Entry& e);
    bool relockFrom(int needed);

    TrunkMotionParams m_p;
    double m_gate;
    std::deque<Entry> m_window, m_pending;
    Vec m_refSum = Vec::Zero();
    int m_refCount = 0;
    std::optional<double> m_refStartT;
    bool m_refDone = false;
    double m_lastT = 0;
    bool m_any = false;
    std::uint64_t m_outliers = 0;
  };

  void decide(double t, TrunkMotionStatus& s);

  TrunkMotionParams m_params;
  Level<3> m_shoulder;
  Level<6> m_arm;  // common residual (3) and wrist-minus-elbow residual (3)
  TrunkMotionCounters m_counters;
  std::vector<TrunkMotionSpan> m_spans;
  TrunkMotionStatus m_last;
  std::optional<double> m_lastT;
  bool m_open = false;
};

}  // namespace armtrack
