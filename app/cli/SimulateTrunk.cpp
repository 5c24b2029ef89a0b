#include "app/cli/SimulateTrunk.h"

#include <cmath>
#include <numbers>
#include <string>

namespace armtrack::cli {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}  // namespace

const std::string_view kTrunkOptionsHelp =
    R"(  --trunk-lean DEG     the trunk leans forward DEG at the fullest reach (shoulder flexion
                       90 deg and beyond; it starts at 20 deg) and turns about a hip point 45 cm
                       below and 15 cm medial to the shoulder; optical data are then in the world
                       frame (0-45; default: a still trunk)
  --trunk-lateral R    lateral bending at the fullest reach per degree of lean (default 0.5;
                       negative: towards the patient's left)
  --trunk-rotation R   axial rotation at the fullest reach per degree of lean (default 0.5;
                       negative: the left shoulder comes forward)
  --trunk-sway DEG     the trunk's own slow sway, 0.1-0.3 Hz, at most DEG per angle (0-5,
                       default 1)
  --trunk-imu          add the sternum IMU (tr_* columns; the arm IMUs' rate, noise and bias)
  --kinect-shoulder    the Kinect also reports the shoulder (default: when the trunk moves)
  --no-kinect-shoulder the Kinect does not report the shoulder
)";

std::vector<OptionSpec> trunkOptionSpecs() {
  return {{"--trunk-lean", true},         {"--trunk-lateral", true}, {"--trunk-rotation", true},
          {"--trunk-sway", true},         {"--trunk-imu", false},    {"--kinect-shoulder", false},
          {"--no-kinect-shoulder", false}};
}

void applyTrunkOptions(const Args& a, SimulationParams& sim, double misalignmentDeg,
                       std::ostream& err) {
  const auto inRange = [&](std::string_view name, double fallback, double lo, double hi) {
    const double v = a.number(name, fallback);
    if (v < lo || v > hi)
      a.fail(std::string(name) + ": must be between " + std::to_string(static_cast<int>(lo)) +
             " and " + std::to_string(static_cast<int>(hi)) + ", got " + *a.value(name));
    return v;
  };
  TrunkSimParams& trunk = sim.trunk;
  trunk.enabled = a.flag("--trunk-lean");
  trunk.leanDeg = inRange("--trunk-lean", trunk.leanDeg, 0.0, 45.0);
  const double lateral = inRange("--trunk-lateral", trunk.lateralRatio, -2.0, 2.0);
  const double rotation = inRange("--trunk-rotation", trunk.rotationRatio, -2.0, 2.0);
  trunk.lateralRatio = std::abs(lateral);
  trunk.lateralSign = lateral < 0.0 ? -1.0 : 1.0;
  trunk.rotationRatio = std::abs(rotation);
  trunk.rotationSign = rotation < 0.0 ? -1.0 : 1.0;
  trunk.swayDeg = inRange("--trunk-sway", trunk.swayDeg, 0.0, 5.0);
  trunk.swaySeed = sim.seed;
  if (!trunk.enabled) {
    for (std::string_view o : {"--trunk-lateral", "--trunk-rotation", "--trunk-sway"}) {
      if (a.flag(o)) err << "warning: " << o << " only applies with --trunk-lean; ignored\n";
    }
  }

  ImuSimParams& imu = sim.trunkImu;
  imu = sim.upperArm;
  imu.enabled = a.flag("--trunk-imu");
  imu.misalignment = Eigen::Matrix3d::Identity();
  if (misalignmentDeg != 0.0)
    imu.misalignment = randomMisalignment(misalignmentDeg * kDeg, 2 * sim.seed + 3);

  if (a.flag("--kinect-shoulder") && a.flag("--no-kinect-shoulder"))
    a.fail("--kinect-shoulder and --no-kinect-shoulder contradict each other; give one");
  if (a.flag("--kinect-shoulder")) sim.kinect.shoulder = true;
  if (a.flag("--no-kinect-shoulder")) sim.kinect.shoulder = false;
  if ((a.flag("--kinect-shoulder") || a.flag("--no-kinect-shoulder")) && !sim.kinect.enabled)
    err << "warning: the Kinect's shoulder only applies with a Kinect; ignored\n";
}

}  // namespace armtrack::cli
