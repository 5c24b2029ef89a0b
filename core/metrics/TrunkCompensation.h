// Trunk compensation (docs/metrics.md, "Trunk compensation"): how far the patient leaned and
// turned the trunk, and how far the shoulder moved, over a session and in each repetition.
// SI units in, degrees and centimetres out (the numbers a therapist reads and `session show
// --json` writes); a value that cannot be measured is empty, never 0 or NaN.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/kinematics/Trunk.h"
#include "core/metrics/Repetitions.h"
#include "core/metrics/Smoothing.h"

namespace armtrack {

/// One row of a session: the trunk's angles and/or the shoulder's position at time t.
struct TrunkRow {
  double t = 0;  ///< s, increasing from row to row
  /// Trunk flexion, lateral bending, axial rotation (rad, patient terms, relative to the start
  /// pose; core/kinematics/Trunk.h). Empty when this row has none.
  std::optional<TrunkAngles> angle;
  /// Shoulder centre in the world frame (m). Empty when this row has none.
  std::optional<Eigen::Vector3d> shoulder;
  /// The row is not to be used (e.g. its estimate's status flags it); counted in leftOut.
  bool leaveOut = false;
};

/// A repetition's time span [startS, endS] (s, the rows' clock), both ends included.
struct TimeSpan {
  double startS = 0;
  double endS = 0;
};

/// The spans of detected repetitions (Repetition::startS, endS), in order.
std::vector<TimeSpan> repetitionSpans(const RepetitionResult& result);

struct TrunkCompensationParams {
  /// Smoothing of the angles before their extremes are taken (the raw extremes would add the
  /// noise's). Default: the clinical angles' (+-0.15 s cubic, docs/metrics.md).
  SmoothingParams angleSmoothing;
  /// Smoothing of the shoulder position, after a running median of 5 samples that removes single
  /// and double wild frames. Default +-0.4 s quadratic, gaps over 0.5 s: a trunk leans over
  /// seconds, while 1 cm of Kinect noise per axis at 30 Hz needs the wide window (the largest
  /// displacement of a still trunk then stays near 1 cm instead of 2).
  SmoothingParams shoulderSmoothing{0.4, 2, 100, 0.5};
  /// The shoulder's start position: the mean of its median-filtered positions over the first this
  /// many seconds of shoulder data (trunk upright and still there). Default 1 s (30 Kinect
  /// frames: the start to about 2 mm per axis).
  double shoulderReferenceSeconds = 1.0;
  /// A repetition whose largest |flexion| exceeds this (deg) was made with compensation.
  /// Empty (the default) = no limit, and no count.
  std::optional<double> flexionLimitDeg;
};

/// The largest values over a session or one repetition; empty when not measurable (no row with
/// trunk angles, resp. no shoulder position, inside it).
struct TrunkExtremes {
  std::optional<double> maxFlexionDeg;              ///< largest |flexion| (deg)
  std::optional<double> maxLateralDeg;              ///< largest |lateral bending| (deg)
  std::optional<double> maxRotationDeg;             ///< largest |axial rotation| (deg)
  std::optional<double> maxShoulderDisplacementCm;  ///< largest distance from the start (cm)
  /// maxFlexionDeg > flexionLimitDeg; empty without a limit or without flexion.
  std::optional<bool> compensated;
};

struct TrunkCompensation {
  TrunkExtremes session;
  std::vector<TrunkExtremes> repetitions;  ///< one per span given, in that order
  /// Repetitions made with compensation; empty without a limit or when the session has no
  /// trunk angles at all.
  std::optional<std::size_t> repetitionsWithCompensation;
  std::size_t inputRows = 0;           ///< rows given
  std::size_t leftOut = 0;             ///< rows marked leaveOut
  std::size_t refusedNonFinite = 0;    ///< rows with a NaN or infinite time, angle or position
  std::size_t refusedImplausible = 0;  ///< an |angle| over 180 deg or a shoulder over 2 m away
  std::size_t refusedOutOfOrder = 0;   ///< rows whose time is not after the previous kept row's
  std::size_t invalidSpans = 0;        ///< spans with a non-finite end or end < start (all empty)
};

/// Takes the rows in order, refuses (and counts) what it cannot use, smooths the angles and the
/// shoulder track separately (each on its own rows, never across a gap), and returns the largest
/// |smoothed value| over the session and over the samples inside each span. Throws
/// std::invalid_argument for a flexion limit that is not positive and finite. Empty input gives
/// empty values and zero counts.
TrunkCompensation computeTrunkCompensation(const std::vector<TrunkRow>& rows,
                                           const std::vector<TimeSpan>& repetitions = {},
                                           const TrunkCompensationParams& params = {});

}  // namespace armtrack
