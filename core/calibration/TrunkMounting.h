// The sternum sensor's mounting from the upright start pose (docs/calibration.md, "The sternum
// sensor"): with the patient sitting upright and still, the sensor's accelerometer reads gravity
// alone, which fixes two of its three axes' directions (its tilt). The third, the heading about
// the vertical, is not seen by gravity: it is kept from the mounting one starts from (the
// device's, or the default flat on the sternum). The position is kept too. Plain C++ and Eigen.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>

#include "core/ArmSample.h"
#include "core/io/Recording.h"

namespace armtrack {

/// The mounting whose sensor reads accAtRest (its specific force at rest, sensor axes, any
/// length) with the trunk upright: initial turned by the smallest rotation that takes the
/// direction initial predicts for gravity onto the one read. That rotation's axis is horizontal,
/// so the sensor's heading about the vertical stays initial's. up: unit, frame 0. Returns
/// initial when accAtRest is zero or not finite.
TrunkMount levelTrunkMount(const TrunkMount& initial, const Eigen::Vector3d& accAtRest,
                           const Eigen::Vector3d& up);

struct TrunkMountingParams {
  Eigen::Vector3d up{-1.0, 0.0, 0.0};  ///< unit, frame 0 of the arm's side
  double g = 9.81;                     ///< m/s^2
  double fromS = 0.3;                  ///< s: the start pose is judged from here...
  double toS = 2.0;                    ///< ...to here (the calibration's startStillSeconds)
  double stillRateRadS = 0.25;         ///< |gyro| below this counts as still
  double minStillS = 0.5;              ///< s of stillness needed
};

struct TrunkMounting {
  std::optional<TrunkMount> mount;  ///< empty when the start pose could not be used
  double tiltDeg = 0;               ///< how far the sensor sits from initial's tilt (deg)
  double stillSeconds = 0;          ///< still readings found in [fromS, toS]
  std::string problem;              ///< why there is no mount (English, for logs)
};

/// The sternum sensor's mounting from the samples' trunk readings (ArmSample::trunk, its own
/// axes; times from the start of the recording) while the patient sits upright and still at the
/// start. Needs minStillS of still readings whose specific force is within 20 % of g. Never
/// throws.
TrunkMounting calibrateTrunkMount(std::span<const ArmSample> samples, const TrunkMount& initial,
                                  const TrunkMountingParams& params);

}  // namespace armtrack
