// The virtual arm's trunk: the sternum IMU as a stream of its own ("trunk", StreamRole::TrunkImu),
// the Kinect's shoulder, the true trunk angles on the truth stream, the mounting the session
// writes into the sidecar, and the trunk-* options mapped as `armtrack-cli simulate` maps its
// --trunk-* flags (core/simulation/TrunkOptions.h).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "core/simulation/TrunkOptions.h"
#include "devices/api/Options.h"
#include "devices/virtual_arm/VirtualArmSource.h"
#include "tests/support/LoadPlugin.h"

using namespace armtrack;
using namespace armtrack::devices::virtualarm;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

VirtualArmParams leaningParams(double leanDeg, bool trunkImu) {
  VirtualArmParams p;
  p.sim = defaultSimulation();
  p.sim.duration = 12.0;
  p.sim.upperArm.rateHz = p.sim.forearm.rateHz = 200;
  p.sim.seed = 7;
  p.trajectory = "reaching";
  p.trajectoryOptions.seed = 7;
  TrunkSimOptions o;
  if (leanDeg > 0) o.leanDeg = leanDeg;
  o.trunkImu = trunkImu;
  applyTrunkSimOptions(o, p.sim);
  return p;
}

const VirtualStream* streamNamed(const VirtualArmSource& source, const std::string& name) {
  for (const VirtualStream& s : source.streams())
    if (s.name == name) return &s;
  return nullptr;
}

const StreamInfo* infoNamed(const devices::Device& device, const std::string& name) {
  for (const StreamInfo& s : device.streams())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace

// Every value the source delivers is the simulator's, at the simulator's time: the sternum
// IMU's readings, the Kinect's shoulder and the true trunk angles (simulateRecording is the
// independent reference: the same trajectory and parameters in one batch).
TEST(VirtualArmTrunk, StreamsCarryTheSimulatedTrunk) {
  const VirtualArmParams p = leaningParams(15.0, true);
  VirtualArmSource source(p);
  const VirtualStream* trunk = streamNamed(source, "trunk");
  const VirtualStream* kinect = streamNamed(source, "kinect");
  const VirtualStream* truth = streamNamed(source, "truth");
  ASSERT_NE(trunk, nullptr);
  ASSERT_NE(kinect, nullptr);
  ASSERT_NE(truth, nullptr);
  EXPECT_EQ(trunk->role, StreamRole::TrunkImu);
  EXPECT_EQ(trunk->rateHz, 200.0);
  EXPECT_TRUE(kinect->shoulder);
  EXPECT_TRUE(truth->trueTrunk);
  ASSERT_TRUE(source.meta().trunk.has_value());
  EXPECT_TRUE(source.meta().trunk->imuPosition.isApprox(
      defaultSimulatedTrunkMount(Side::Right).imuPosition));

  std::vector<VirtualSample> out;
  std::vector<SourceEvent> events;
  source.advance(p.sim.duration + 0.1, out, events);
  const std::unique_ptr<Trajectory> trajectory = makeTrajectory(p.trajectory, p.trajectoryOptions);
  SimulationParams sim = p.sim;
  const Recording reference = simulateRecording(*trajectory, sim);
  std::map<double, const ArmSample*> at;
  for (const ArmSample& s : reference.samples) at[s.t] = &s;

  std::size_t trunkSamples = 0, shoulders = 0, truths = 0;
  double largestFlexion = 0.0;
  const int trunkIndex = static_cast<int>(trunk - source.streams().data());
  for (const VirtualSample& v : out) {
    const auto it = at.find(v.deviceTime);
    ASSERT_NE(it, at.end()) << "no simulated row at " << v.deviceTime;
    const ArmSample& row = *it->second;
    if (v.stream == trunkIndex) {
      ASSERT_TRUE(row.trunk.has_value());
      const auto& imu = std::get<ImuReading>(v.payload);
      EXPECT_EQ(imu.gyr, row.trunk->gyr);
      EXPECT_EQ(imu.acc, row.trunk->acc);
      ++trunkSamples;
    } else if (const auto* o = std::get_if<OpticalPositions>(&v.payload)) {
      ASSERT_TRUE(row.shoulder.has_value());
      ASSERT_TRUE(o->shoulder.has_value());
      EXPECT_EQ(*o->shoulder, *row.shoulder);
      ++shoulders;
    } else if (const auto* t = std::get_if<TruthAngles>(&v.payload)) {
      ASSERT_TRUE(t->trunk.has_value());
      ASSERT_TRUE(row.trueTrunk.has_value());
      EXPECT_EQ(*t->trunk, *row.trueTrunk);
      largestFlexion = std::max(largestFlexion, (*t->trunk)(0));
      ++truths;
    }
  }
  EXPECT_GE(trunkSamples, 2400u);
  EXPECT_GE(shoulders, 360u);
  EXPECT_GE(truths, 2400u);
  // The reaches take the trunk near its full lean (15 deg at the fullest reach).
  EXPECT_GT(largestFlexion, 10.0 * kDeg);
  EXPECT_LE(largestFlexion, 15.0 * kDeg + 1.0 * kDeg);
}

// A still trunk (the default) is what the virtual arm was before the trunk existed: no trunk
// stream, no shoulder, no trunk truth.
TEST(VirtualArmTrunk, StillTrunkByDefault) {
  VirtualArmParams p = leaningParams(0.0, false);
  VirtualArmSource source(p);
  EXPECT_EQ(streamNamed(source, "trunk"), nullptr);
  EXPECT_FALSE(streamNamed(source, "kinect")->shoulder);
  EXPECT_FALSE(streamNamed(source, "truth")->trueTrunk);
  EXPECT_FALSE(source.meta().trunk.has_value());
  std::vector<VirtualSample> out;
  std::vector<SourceEvent> events;
  source.advance(3.0, out, events);
  ASSERT_FALSE(out.empty());
  for (const VirtualSample& v : out) {
    if (const auto* o = std::get_if<OpticalPositions>(&v.payload)) {
      EXPECT_FALSE(o->shoulder);
    }
    if (const auto* t = std::get_if<TruthAngles>(&v.payload)) {
      EXPECT_FALSE(t->trunk);
    }
  }
}

// The sternum IMU takes faults like the arm's IMUs.
TEST(VirtualArmTrunk, TrunkStreamTakesFaults) {
  VirtualArmParams p = leaningParams(10.0, true);
  p.faults.dropouts = parseDropouts("trunk@1+1");
  p.faults.saturations = parseStreamWindows("trunk@4+0.5", "saturation");
  VirtualArmSource source(p);
  std::vector<VirtualSample> out;
  std::vector<SourceEvent> events;
  source.advance(6.0, out, events);
  const int k = static_cast<int>(streamNamed(source, "trunk") - source.streams().data());
  std::size_t inDropout = 0, saturated = 0;
  for (const VirtualSample& v : out) {
    if (v.stream != k) continue;
    inDropout += v.deviceTime >= 1.0 && v.deviceTime < 2.0;
    saturated += std::get<ImuReading>(v.payload).gyr.x() == kGyroFullScale;
  }
  EXPECT_EQ(inDropout, 0u);
  EXPECT_EQ(source.dropped(k), 200u);
  EXPECT_EQ(saturated, 100u);
}

// The plugin's trunk options, the streams its device publishes (the session writes the sidecar's
// trunk block and the shoulder_* and true_trunk_* columns from them), and its words for bad
// values.
TEST(VirtualArmTrunk, PluginOptions) {
  devices::DevicePlugin* plugin = test::loadPlugin(QStringLiteral("virtual-arm"));
  ASSERT_NE(plugin, nullptr);
  QString why;
  auto device = plugin->create(
      devices::Options::parse(QStringLiteral("sensors=upper+forearm+kinect+trunk,trunk-lean=15,"
                                             "trunk-lateral=-0.5,trunk-rotation=0.3,"
                                             "trunk-sway=2,imu-rate=200,duration=5")),
      &why);
  ASSERT_NE(device, nullptr) << why.toStdString();
  const StreamInfo* trunk = infoNamed(*device, "trunk");
  ASSERT_NE(trunk, nullptr);
  EXPECT_EQ(trunk->role, StreamRole::TrunkImu);
  EXPECT_EQ(trunk->nominalRateHz, 200.0);
  ASSERT_TRUE(trunk->trunkMount.has_value());
  EXPECT_TRUE(
      trunk->trunkMount->imuRotation.isApprox(defaultSimulatedTrunkMount(Side::Right).imuRotation));
  EXPECT_TRUE(infoNamed(*device, "kinect")->shoulder);
  EXPECT_TRUE(infoNamed(*device, "truth")->trueTrunk);

  // No lean: a still trunk, the shoulder only when asked for.
  device =
      plugin->create(devices::Options::parse(QStringLiteral("sensors=upper+forearm+kinect")), &why);
  ASSERT_NE(device, nullptr) << why.toStdString();
  EXPECT_EQ(infoNamed(*device, "trunk"), nullptr);
  EXPECT_FALSE(infoNamed(*device, "kinect")->shoulder);
  EXPECT_FALSE(infoNamed(*device, "truth")->trueTrunk);
  device = plugin->create(devices::Options::parse(QStringLiteral("kinect-shoulder=on")), &why);
  ASSERT_NE(device, nullptr) << why.toStdString();
  EXPECT_TRUE(infoNamed(*device, "kinect")->shoulder);
  device = plugin->create(
      devices::Options::parse(QStringLiteral("trunk-lean=20,kinect-shoulder=off")), &why);
  ASSERT_NE(device, nullptr) << why.toStdString();
  EXPECT_FALSE(infoNamed(*device, "kinect")->shoulder);
  EXPECT_TRUE(infoNamed(*device, "truth")->trueTrunk);

  const std::pair<const char*, const char*> bad[] = {
      {"trunk-lean=50", "option 'trunk-lean' must be a number from 0 to 45, not '50'"},
      {"trunk-lean=-5", "option 'trunk-lean' must be a number from 0 to 45"},
      {"trunk-lean=forward", "option 'trunk-lean'"},
      {"trunk-lean=15,trunk-lateral=3", "option 'trunk-lateral' must be a number from -2 to 2"},
      {"trunk-lean=15,trunk-rotation=nan", "option 'trunk-rotation'"},
      {"trunk-lean=15,trunk-sway=9", "option 'trunk-sway' must be a number from 0 to 5"},
      {"kinect-shoulder=perhaps", "kinect-shoulder"},
      {"sensors=upper+sternum", "unknown sensor 'sternum' in sensors= (use upper, forearm, trunk"},
      {"sensors=upper+trunk,saturate=kinect@1+1", "saturation of 'kinect'"},
  };
  for (const auto& [options, says] : bad) {
    why.clear();
    EXPECT_EQ(plugin->create(devices::Options::parse(QString::fromLatin1(options)), &why), nullptr)
        << options;
    EXPECT_TRUE(why.contains(QString::fromLatin1(says))) << options << ": " << why.toStdString();
  }
}

// The mapping both front ends use: signs from the ratios, the sway's seed, the sternum IMU a
// copy of the upper-arm IMU, and the Kinect's shoulder left to the simulator unless asked.
TEST(TrunkSimOptions, MapsOntoTheSimulation) {
  SimulationParams sim = defaultSimulation();
  sim.seed = 42;
  sim.upperArm.rateHz = 250;
  sim.upperArm.gyroBias = Eigen::Vector3d::Constant(0.01);
  TrunkSimOptions o;
  o.leanDeg = 12;
  o.lateralRatio = -0.25;
  o.rotationRatio = 1.5;
  o.swayDeg = 0;
  o.trunkImu = true;
  applyTrunkSimOptions(o, sim, 2.0 * kDeg);
  EXPECT_TRUE(sim.trunk.enabled);
  EXPECT_EQ(sim.trunk.leanDeg, 12);
  EXPECT_EQ(sim.trunk.lateralRatio, 0.25);
  EXPECT_EQ(sim.trunk.lateralSign, -1.0);
  EXPECT_EQ(sim.trunk.rotationRatio, 1.5);
  EXPECT_EQ(sim.trunk.rotationSign, 1.0);
  EXPECT_EQ(sim.trunk.swayDeg, 0.0);
  EXPECT_EQ(sim.trunk.swaySeed, 42u);
  EXPECT_TRUE(sim.trunkImu.enabled);
  EXPECT_EQ(sim.trunkImu.rateHz, 250);
  EXPECT_EQ(sim.trunkImu.gyroBias, sim.upperArm.gyroBias);
  EXPECT_TRUE(sim.trunkImu.misalignment.isApprox(randomMisalignment(2.0 * kDeg, 87)));
  EXPECT_FALSE(sim.kinect.shoulder.has_value());

  SimulationParams still = defaultSimulation();
  applyTrunkSimOptions({}, still);
  EXPECT_FALSE(still.trunk.enabled);
  EXPECT_FALSE(still.trunkImu.enabled);
  for (auto breakIt : {+[](TrunkSimOptions& x) { x.leanDeg = 46; },
                       +[](TrunkSimOptions& x) { x.lateralRatio = -2.5; },
                       +[](TrunkSimOptions& x) { x.swayDeg = NAN; }}) {
    TrunkSimOptions bad;
    breakIt(bad);
    SimulationParams s = defaultSimulation();
    EXPECT_THROW(applyTrunkSimOptions(bad, s), std::invalid_argument);
  }
}
