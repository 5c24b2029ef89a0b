#include "core/simulation/TrunkOptions.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace armtrack {

namespace {

double within(const std::optional<double>& v, double fallback, double lo, double hi,
              const char* what) {
  if (!v) return fallback;
  if (!std::isfinite(*v) || *v < lo || *v > hi)
    throw std::invalid_argument(std::string(what) + " must be between " + std::to_string(lo) +
                                " and " + std::to_string(hi) + ", got " + std::to_string(*v));
  return *v;
}

}  // namespace

void applyTrunkSimOptions(const TrunkSimOptions& o, SimulationParams& sim, double misalignmentRad) {
  using O = TrunkSimOptions;
  TrunkSimParams& trunk = sim.trunk;
  trunk.enabled = o.leanDeg.has_value();
  trunk.leanDeg = within(o.leanDeg, trunk.leanDeg, 0.0, O::kMaxLeanDeg, "the trunk's lean (deg)");
  const double lateral = within(o.lateralRatio, trunk.lateralSign * trunk.lateralRatio,
                                -O::kMaxRatio, O::kMaxRatio, "the trunk's lateral ratio");
  const double rotation = within(o.rotationRatio, trunk.rotationSign * trunk.rotationRatio,
                                 -O::kMaxRatio, O::kMaxRatio, "the trunk's rotation ratio");
  trunk.lateralRatio = std::abs(lateral);
  trunk.lateralSign = lateral < 0.0 ? -1.0 : 1.0;
  trunk.rotationRatio = std::abs(rotation);
  trunk.rotationSign = rotation < 0.0 ? -1.0 : 1.0;
  trunk.swayDeg = within(o.swayDeg, trunk.swayDeg, 0.0, O::kMaxSwayDeg, "the trunk's sway (deg)");
  trunk.swaySeed = sim.seed;

  ImuSimParams& imu = sim.trunkImu;
  imu = sim.upperArm;
  imu.enabled = o.trunkImu;
  imu.misalignment = Eigen::Matrix3d::Identity();
  if (misalignmentRad != 0.0)
    imu.misalignment = randomMisalignment(misalignmentRad, 2 * sim.seed + 3);

  if (o.kinectShoulder) sim.kinect.shoulder = *o.kinectShoulder;
}

}  // namespace armtrack
