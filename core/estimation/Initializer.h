// Start-up pose from a single instant: gravity seen by the accelerometers, optical positions when
// present, a weak prior toward the neutral posture for what neither observes (the heading).
#pragma once

#include <optional>

#include "core/ArmSample.h"
#include "core/estimation/ArmFilter.h"

namespace armtrack {

struct InitialPose {
  JointVector th = JointVector::Zero();   ///< rad
  JointVector thd = JointVector::Zero();  ///< rad/s, least squares on the gyroscopes
  double cost = 0.0;                      ///< final least-squares cost (dimensionless)
};

/// Solves for the joint angles that best explain the gravity direction in each present IMU's
/// accelerometer, the optical positions and the rays through the marker pixels (Levenberg-Marquardt
/// from several starts), then the joint rates that best explain the gyroscopes. Inactive joints
/// stay at params.fixedAngles.
InitialPose initialPose(const EstimatorParams& params, const ArmSample& sample);

/// The posture the weak prior pulls toward: arm hanging, elbow slightly flexed (rad).
JointVector neutralPosture();

}  // namespace armtrack
