// Internals of the calibration from movement: the forearm sensor's roll about the forearm from the
// rests that look like a known pose (MovementCalibrationParams::expectedRestPose;
// docs/calibration.md, "The rest pose"). Internal to armtrack_core.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/calibration/MovementFit.h"
#include "core/calibration/MovementReadings.h"

namespace armtrack::movecal {

/// What the rests said about the forearm's roll.
struct PoseRoll {
  int rests = 0;               ///< still stretches looked at
  int matching = 0;            ///< those that look like the pose
  int agreeing = 0;            ///< of those, the ones whose rolls agree (and were used)
  std::optional<double> roll;  ///< rad: the forearm mounting is Ry(roll) * its tilt
  double sd = 0.0;             ///< rad
  std::string why;             ///< when no roll: why, in plain words (no full stop)
};

/// One rest against the pose: gravity in the upper-arm sensor (m1 * accelerometer, m1 the fitted
/// mounting) against where the pose puts it; the forearm's inclination from its sensor's gravity
/// (the forearm mounting's tilt m2Tilt) against the pose's; the elbow's flexion of the axes fit at
/// the rest's middle (theta, one per `stride` grid steps from grid index 1) against the pose's.
/// Every test within p.restPoseTolerance makes a match; the matches' rolls ("thumb up": the
/// forearm sensor's gravity across the forearm where the pose puts it) are combined, weighted by
/// the rests' lengths, after the ones further than p.poseRollSpread from their median are left
/// out.
PoseRoll rollFromRestPose(const Grid& g, const std::vector<Rest>& rests,
                          const std::vector<Eigen::Vector2d>& theta, std::size_t stride,
                          const Mat3& m1, const Mat3& m2Tilt, const ArmGeometry& geometry,
                          const Vec3& up, const JointVector& pose,
                          const MovementCalibrationParams& p);

}  // namespace armtrack::movecal
