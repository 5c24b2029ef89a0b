// The virtual arm with real sensors' errors (sensor-errors=realistic, core/simulation/ImuErrors.h):
// the plugin's option, its default and its words for a bad value, and the source delivering
// exactly what the simulator gives for the same preset.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/simulation/ImuErrors.h"
#include "devices/api/Options.h"
#include "devices/virtual_arm/VirtualArmSource.h"
#include "tests/support/LoadPlugin.h"

using namespace armtrack;
using namespace armtrack::devices::virtualarm;

namespace {

const StreamInfo* infoNamed(const devices::Device& device, const std::string& name) {
  for (const StreamInfo& s : device.streams())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace

TEST(VirtualArmSensors, PluginOption) {
  devices::DevicePlugin* plugin = test::loadPlugin(QStringLiteral("virtual-arm"));
  ASSERT_NE(plugin, nullptr);
  QString why;
  // Default: ideal sensors at 1 kHz.
  auto device = plugin->create(devices::Options::parse(QStringLiteral("duration=2")), &why);
  ASSERT_NE(device, nullptr) << why.toStdString();
  EXPECT_EQ(infoNamed(*device, "upper")->nominalRateHz, 1000.0);
  // Realistic: the logger's 90 Hz clock, or the rate asked for.
  device = plugin->create(
      devices::Options::parse(QStringLiteral("sensor-errors=realistic,duration=2")), &why);
  ASSERT_NE(device, nullptr) << why.toStdString();
  EXPECT_EQ(infoNamed(*device, "upper")->nominalRateHz, 90.0);
  EXPECT_EQ(infoNamed(*device, "forearm")->nominalRateHz, 90.0);
  device = plugin->create(devices::Options::parse(QStringLiteral(
                              "sensor-errors=realistic,imu-rate=200,sensors=upper+forearm+trunk")),
                          &why);
  ASSERT_NE(device, nullptr) << why.toStdString();
  EXPECT_EQ(infoNamed(*device, "trunk")->nominalRateHz, 200.0);
  device = plugin->create(devices::Options::parse(QStringLiteral("sensor-errors=ideal,duration=2")),
                          &why);
  ASSERT_NE(device, nullptr) << why.toStdString();
  EXPECT_EQ(infoNamed(*device, "upper")->nominalRateHz, 1000.0);

  why.clear();
  EXPECT_EQ(plugin->create(devices::Options::parse(QStringLiteral("sensor-errors=bogus")), &why),
            nullptr);
  EXPECT_TRUE(why.contains(QStringLiteral("sensor-errors=bogus"))) << why.toStdString();
  EXPECT_TRUE(why.contains(QStringLiteral("ideal or realistic"))) << why.toStdString();
}

// The source's IMU samples are the simulator's rows for the same preset and seed: the held
// values, the jitter and the wobble reach the session as they are.
TEST(VirtualArmSensors, SourceDeliversThePresetsReadings) {
  VirtualArmParams p;
  p.sim = defaultSimulation();
  p.sim.seed = 6;
  p.sim.duration = 4.0;
  p.sim.kinect.enabled = false;
  p.trajectoryOptions.seed = 6;
  applySensorModel(SensorModel::Realistic, p.sim);
  const auto traj = makeTrajectory(p.trajectory, p.trajectoryOptions);
  const Recording rec = simulateRecording(*traj, p.sim);

  VirtualArmSource source(p);
  std::vector<VirtualSample> out;
  std::vector<SourceEvent> events;
  source.advance(p.sim.duration + 0.1, out, events);
  std::vector<ImuReading> forearm;
  for (const VirtualSample& s : out)
    if (source.streams()[static_cast<std::size_t>(s.stream)].role == StreamRole::ForearmImu)
      forearm.push_back(std::get<ImuReading>(s.payload));
  std::vector<ImuReading> expected;
  for (const ArmSample& s : rec.samples)
    if (s.forearm) expected.push_back(*s.forearm);
  ASSERT_EQ(forearm.size(), expected.size());
  ASSERT_EQ(forearm.size(), 4u * 90u + 1u);
  int repeats = 0;
  for (std::size_t i = 0; i < forearm.size(); ++i) {
    EXPECT_EQ(forearm[i].gyr, expected[i].gyr) << i;
    EXPECT_EQ(forearm[i].acc, expected[i].acc) << i;
    if (i > 0) repeats += forearm[i].gyr == forearm[i - 1].gyr;
  }
  EXPECT_GT(repeats, 100);  // 44 % of 360
}
