// The virtual arm worn wrongly, as the home window's sensor check must find it: the two IMUs'
// readings exchanged (swap-imus), a sensor strapped end over end (upside-down), and the movements
// of a home session (trajectory=sensor-check, trajectory=exercise); the plugin's options for
// them, with the plugin's own words for bad values.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

#include "core/calibration/SensorCheck.h"
#include "core/kinematics/ClinicalAngles.h"
#include "devices/api/Options.h"
#include "devices/virtual_arm/VirtualArmSource.h"
#include "tests/support/LoadPlugin.h"

using namespace armtrack;
using namespace armtrack::devices::virtualarm;

namespace {

VirtualArmParams checkParams() {
  VirtualArmParams p;
  p.sim = defaultSimulation();
  p.sim.kinect.enabled = false;
  p.sim.upperArm.rateHz = p.sim.forearm.rateHz = 200;
  p.sim.duration = SensorCheckTrajectory::duration();
  p.trajectory = "sensor-check";
  p.truth = false;
  return p;
}

// The source's samples for the whole check, put back into rows by stream role as the session's
// assembler would.
std::vector<ArmSample> play(const VirtualArmParams& p) {
  VirtualArmSource source(p);
  std::vector<VirtualSample> out;
  std::vector<SourceEvent> events;
  source.advance(p.sim.duration + 0.1, out, events);
  std::vector<ArmSample> rows;
  for (const VirtualSample& s : out) {
    const StreamRole role = source.streams()[static_cast<std::size_t>(s.stream)].role;
    if (rows.empty() || rows.back().t != s.deviceTime) {
      rows.emplace_back();
      rows.back().t = s.deviceTime;
    }
    if (role == StreamRole::UpperArmImu) rows.back().upperArm = std::get<ImuReading>(s.payload);
    if (role == StreamRole::ForearmImu) rows.back().forearm = std::get<ImuReading>(s.payload);
  }
  return rows;
}

}  // namespace

TEST(VirtualArmWearing, SwappedAndUpsideDownAreWhatTheCheckFinds) {
  VirtualArmParams p = checkParams();
  SensorCheckResult r = checkSensors(play(p), {});
  EXPECT_TRUE(r.ok()) << r.explanation;
  p.swapImus = true;
  r = checkSensors(play(p), {});
  EXPECT_EQ(r.findings, std::vector<SensorFinding>{SensorFinding::Swapped}) << r.explanation;
  p.swapImus = false;
  p.sim.upperArm.misalignment =
      Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  r = checkSensors(play(p), {});
  EXPECT_EQ(r.findings, std::vector<SensorFinding>{SensorFinding::UpperArmUpsideDown})
      << r.explanation;
}

TEST(VirtualArmWearing, TheExerciseTrajectoryReachesItsRange) {
  VirtualArmParams p = checkParams();
  p.trajectory = "exercise";
  p.truth = true;
  p.trajectoryOptions.exercise.angle = 0;
  p.trajectoryOptions.exercise.fromDeg = 15;
  p.trajectoryOptions.exercise.toDeg = 105;
  p.sim.duration = 8;
  VirtualArmSource source(p);
  std::vector<VirtualSample> out;
  std::vector<SourceEvent> events;
  source.advance(8, out, events);
  double lo = 1e9, hi = -1e9;
  for (const VirtualSample& s : out)
    if (const auto* truth = std::get_if<TruthAngles>(&s.payload)) {
      const double flexion = toClinical(truth->th).shoulderFlexion;
      lo = std::min(lo, flexion);
      hi = std::max(hi, flexion);
    }
  EXPECT_NEAR(lo, 15, 1e-6);
  EXPECT_NEAR(hi, 105, 1e-3);
}

TEST(VirtualArmWearing, PluginOptionsAndTheirRefusals) {
  devices::DevicePlugin* plugin = test::loadPlugin(QStringLiteral("virtual-arm"));
  ASSERT_NE(plugin, nullptr);
  const auto make = [&](const QString& options, QString* why) {
    return plugin->create(devices::Options::parse(options), why);
  };
  QString why;
  for (const char* good :
       {"trajectory=sensor-check,swap-imus=on,upside-down=forearm",
        "trajectory=exercise,exercise=shoulder_flexion,exercise-range=10:110,exercise-period=3,"
        "exercise-compensation=30",
        "trajectory=exercise,exercise=forearm_pronation,exercise-range=-40:60,upside-down=both"})
    EXPECT_NE(make(QString::fromLatin1(good), &why), nullptr) << good << ": " << why.toStdString();
  const std::pair<const char*, const char*> bad[] = {
      {"upside-down=left", "upside-down=left: use upper, forearm or both"},
      {"trajectory=exercise,exercise=knee_flexion",
       "exercise=knee_flexion is not a clinical angle"},
      {"trajectory=exercise,exercise-range=abc", "exercise-range=abc: write FROM:TO"},
      {"trajectory=exercise,exercise-range=10:1e6", "exercise-range=10:1e6"},
      {"trajectory=exercise,exercise-period=0", "exercise-period"},
      {"swap-imus=perhaps", "swap-imus"},
  };
  for (const auto& [options, says] : bad) {
    why.clear();
    EXPECT_EQ(make(QString::fromLatin1(options), &why), nullptr) << options;
    EXPECT_TRUE(why.contains(QString::fromLatin1(says))) << options << ": " << why.toStdString();
  }
}
