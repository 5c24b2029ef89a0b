// A recording with a trunk replayed through a live session: the sternum IMU (tr_*), the optical
// shoulder (shoulder_*) and the true trunk angles (true_trunk_*) come out of the replay device on
// their streams and are recorded again, value for value, with the sidecar's trunk block.
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <chrono>
#include <thread>

#include "core/session/Session.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/simulation/TrunkOptions.h"
#include "devices/api/Options.h"
#include "tests/support/LoadPlugin.h"

namespace armtrack {
namespace {

namespace fs = std::filesystem;

template <typename T, typename Get>
std::vector<T> column(const Recording& rec, Get get) {
  std::vector<T> out;
  for (const ArmSample& s : rec.samples)
    if (const auto v = get(s)) out.push_back(*v);
  return out;
}

TEST(ReplayTrunk, TrunkColumnsAreReplayedAndRecordedAgain) {
  QTemporaryDir dir;
  const fs::path source = fs::path(dir.path().toStdString()) / "leaning.csv";
  SimulationParams p = defaultSimulation();
  p.duration = 6.0;
  p.upperArm.rateHz = p.forearm.rateHz = 200;
  TrunkSimOptions trunk;
  trunk.leanDeg = 15;
  trunk.trunkImu = true;
  applyTrunkSimOptions(trunk, p);
  TrajectoryOptions options;
  const Recording original = simulateRecording(*makeTrajectory("reaching", options), p);
  ASSERT_TRUE(original.meta.trunk.has_value());
  writeRecording(source, original);

  devices::DevicePlugin* plugin = test::loadPlugin(QStringLiteral("replay"));
  ASSERT_NE(plugin, nullptr);
  QString why;
  auto device = plugin->create(
      devices::Options::parse(
          QStringLiteral("file=%1,speed=4").arg(QString::fromStdString(source.string()))),
      &why);
  ASSERT_NE(device, nullptr) << why.toStdString();
  bool trunkStream = false;
  for (const StreamInfo& s : device->streams()) {
    if (s.role == StreamRole::TrunkImu) {
      trunkStream = true;
      ASSERT_TRUE(s.trunkMount.has_value());
      EXPECT_EQ(s.trunkMount->imuPosition, original.meta.trunk->imuPosition);
    }
    if (s.role == StreamRole::Optical) {
      EXPECT_TRUE(s.shoulder);
    }
    if (s.role == StreamRole::Truth) {
      EXPECT_TRUE(s.trueTrunk);
    }
  }
  EXPECT_TRUE(trunkStream);

  session::SessionParams params;
  params.recordingPath = fs::path(dir.path().toStdString()) / "replayed.csv";
  session::Session s(params);
  s.addDevice(test::hosted(std::move(device), QStringLiteral("replay")), QStringLiteral("replay"));
  ASSERT_TRUE(s.start().isEmpty());
  std::this_thread::sleep_for(std::chrono::milliseconds(1900));  // 6 s at 4x, plus margin
  s.stop();
  std::vector<session::EstimateRow> results;
  s.takeResults(results);
  EXPECT_EQ(s.stats().lost(), 0u);

  const Recording replayed = readRecording(params.recordingPath);
  // The sidecar's trunk block, as the original's.
  ASSERT_TRUE(replayed.meta.trunk.has_value());
  EXPECT_EQ(replayed.meta.trunk->imuPosition, original.meta.trunk->imuPosition);
  EXPECT_EQ(replayed.meta.trunk->imuRotation, original.meta.trunk->imuRotation);
  // Every value of the three groups, in order.
  const auto trunkA = column<ImuReading>(original, [](const ArmSample& x) { return x.trunk; });
  const auto trunkB = column<ImuReading>(replayed, [](const ArmSample& x) { return x.trunk; });
  ASSERT_EQ(trunkA.size(), trunkB.size());
  ASSERT_GT(trunkA.size(), 1000u);
  for (std::size_t i = 0; i < trunkA.size(); ++i) {
    ASSERT_EQ(trunkA[i].gyr, trunkB[i].gyr) << i;
    ASSERT_EQ(trunkA[i].acc, trunkB[i].acc) << i;
  }
  const auto shoulderA =
      column<Eigen::Vector3d>(original, [](const ArmSample& x) { return x.shoulder; });
  const auto shoulderB =
      column<Eigen::Vector3d>(replayed, [](const ArmSample& x) { return x.shoulder; });
  ASSERT_GT(shoulderA.size(), 150u);
  EXPECT_EQ(shoulderA, shoulderB);
  const auto truthA =
      column<Eigen::Vector3d>(original, [](const ArmSample& x) { return x.trueTrunk; });
  const auto truthB =
      column<Eigen::Vector3d>(replayed, [](const ArmSample& x) { return x.trueTrunk; });
  ASSERT_GT(truthA.size(), 1000u);
  EXPECT_EQ(truthA, truthB);
  // And the session estimated the trunk from the replayed sternum sensor.
  std::size_t withTrunk = 0;
  for (const session::EstimateRow& e : results) withTrunk += e.trunk.has_value();
  EXPECT_GT(withTrunk, results.size() / 2);
}

}  // namespace
}  // namespace armtrack
