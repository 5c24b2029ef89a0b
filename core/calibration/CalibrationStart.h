// Internals of the batch calibration (calibrate(), core/calibration/Calibrator.cpp): its steps 0 to
// 2, the recording on its right-arm twin, the first gyroscope-bias guess and the first trajectory
// (core/calibration/CalibrationStart.cpp; docs/calibration.md, "Formulation").
#pragma once

#include <array>
#include <vector>

#include "core/ArmSample.h"
#include "core/calibration/CalibrationCosts.h"
#include "core/calibration/Calibrator.h"
#include "core/estimation/ArmFilter.h"
#include "core/estimation/SampleGate.h"

namespace armtrack::calib {

/// The recording on its right-arm twin (core/kinematics/Side.h), where everything is fitted.
struct Prepared {
  std::vector<ArmSample> samples;
  bool left = false;
  bool optical = false;  ///< optical positions present and wanted
  ArmGeometry nominal;
  Vec3 up = Vec3::Zero(), gUp = Vec3::Zero();
  double tFirst = 0.0, tLast = 0.0;  ///< s, first and last IMU time
  GateCounters implausible;          ///< what the plausibility gate refused
};

// 0. The recording on the right-arm twin; throws when it cannot be used.
Prepared prepare(const Recording& recording, const CalibrationOptions& options);
// 1. Still start: first gyroscope-bias guess per IMU (upper arm, forearm).
std::array<Vec3, 2> guessGyroBias(const Prepared& in, const CalibrationOptions& options,
                                  CalibrationResult& result, const CalibrationProgress& say);
// 2. First trajectory from the EKF with the nominal mounting and the bias guess.
std::vector<JointEstimate> firstTrajectory(const Prepared& in, const std::array<Vec3, 2>& biasGuess,
                                           const CalibrationOptions& options,
                                           const CalibrationProgress& say);

}  // namespace armtrack::calib
