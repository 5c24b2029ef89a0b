#include "app/cli/SimulateTrunk.h"

#include <numbers>
#include <optional>
#include <string>

#include "core/simulation/TrunkOptions.h"

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
  using O = TrunkSimOptions;
  const auto inRange = [&](std::string_view name, double lo, double hi) -> std::optional<double> {
    if (!a.flag(name)) return std::nullopt;
    const double v = a.number(name, 0.0);
    if (v < lo || v > hi)
      a.fail(std::string(name) + ": must be between " + std::to_string(static_cast<int>(lo)) +
             " and " + std::to_string(static_cast<int>(hi)) + ", got " + *a.value(name));
    return v;
  };
  TrunkSimOptions o;
  o.leanDeg = inRange("--trunk-lean", 0.0, O::kMaxLeanDeg);
  o.lateralRatio = inRange("--trunk-lateral", -O::kMaxRatio, O::kMaxRatio);
  o.rotationRatio = inRange("--trunk-rotation", -O::kMaxRatio, O::kMaxRatio);
  o.swayDeg = inRange("--trunk-sway", 0.0, O::kMaxSwayDeg);
  if (!o.leanDeg) {
    for (std::string_view opt : {"--trunk-lateral", "--trunk-rotation", "--trunk-sway"}) {
      if (a.flag(opt)) err << "warning: " << opt << " only applies with --trunk-lean; ignored\n";
    }
  }
  o.trunkImu = a.flag("--trunk-imu");
  if (a.flag("--kinect-shoulder") && a.flag("--no-kinect-shoulder"))
    a.fail("--kinect-shoulder and --no-kinect-shoulder contradict each other; give one");
  if (a.flag("--kinect-shoulder")) o.kinectShoulder = true;
  if (a.flag("--no-kinect-shoulder")) o.kinectShoulder = false;
  if (o.kinectShoulder && !sim.kinect.enabled)
    err << "warning: the Kinect's shoulder only applies with a Kinect; ignored\n";
  applyTrunkSimOptions(o, sim, misalignmentDeg * kDeg);
}

}  // namespace armtrack::cli
