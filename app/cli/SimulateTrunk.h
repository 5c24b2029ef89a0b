// The simulate command's trunk options: a trunk that leans and turns as the arm reaches, the
// sternum IMU and the Kinect's shoulder (core/simulation/TrunkMotion.h).
#pragma once

#include <ostream>
#include <string_view>
#include <vector>

#include "app/cli/Args.h"
#include "core/simulation/SensorSimulator.h"

namespace armtrack::cli {

/// The options, for the simulate command's Args.
std::vector<OptionSpec> trunkOptionSpecs();

/// Their lines in simulate --help.
extern const std::string_view kTrunkOptionsHelp;

/// Sets sim's trunk, sternum IMU and Kinect shoulder from the options. Call after the arm IMUs
/// are set: the sternum IMU takes their rate, noise and bias (and a misalignment of the same
/// size about its own random axis, misalignmentDeg). Throws UsageError on values out of range;
/// warns on err about options that do not apply.
void applyTrunkOptions(const Args& a, SimulationParams& sim, double misalignmentDeg,
                       std::ostream& err);

}  // namespace armtrack::cli
