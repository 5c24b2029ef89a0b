// The replay device through a live session at 4x: every sample of the file comes out, in order,
// with its own timing, and the estimates are as good as offline.
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <chrono>
#include <cmath>
#include <numbers>
#include <thread>

#include "core/estimation/ArmFilter.h"
#include "core/session/Session.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "devices/api/Options.h"
#include "tests/support/LoadPlugin.h"

namespace armtrack {
namespace {

namespace fs = std::filesystem;

TEST(Replay, FourTimesFasterKeepsEverySampleAndItsTiming) {
  QTemporaryDir dir;
  const fs::path source = fs::path(dir.path().toStdString()) / "source.csv";
  SimulationParams p = defaultSimulation();
  p.duration = 8.0;
  const MultiJointTrajectory traj(2);
  const Recording original = simulateRecording(traj, p);
  writeRecording(source, original);

  devices::DevicePlugin* plugin = test::loadPlugin(QStringLiteral("replay"));
  ASSERT_NE(plugin, nullptr);
  QString why;
  auto device = plugin->create(
      devices::Options::parse(QStringLiteral("file=%1,speed=4").arg(QString::fromStdString(source.string()))),
      &why);
  ASSERT_NE(device, nullptr) << why.toStdString();
  EXPECT_EQ(device->timeScale(), 4.0);

  session::SessionParams params;
  params.recordingPath = fs::path(dir.path().toStdString()) / "replayed.csv";
  session::Session s(params);
  s.addDevice(std::move(device), QStringLiteral("replay"));
  ASSERT_TRUE(s.start().isEmpty());
  std::this_thread::sleep_for(std::chrono::milliseconds(2300));  // 8 s at 4x, plus margin
  s.stop();
  const session::SessionStats st = s.stats();
  EXPECT_EQ(st.lost(), 0u);
  EXPECT_EQ(st.deviceStates[0], devices::DeviceState::Disconnected);

  const Recording replayed = readRecording(params.recordingPath);
  std::vector<const ArmSample*> a, b;
  for (const ArmSample& x : original.samples)
    if (x.upperArm) a.push_back(&x);
  for (const ArmSample& x : replayed.samples)
    if (x.upperArm) b.push_back(&x);
  ASSERT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i]->upperArm->gyr, b[i]->upperArm->gyr) << i;
    ASSERT_EQ(a[i]->forearm->acc, b[i]->forearm->acc) << i;
    // Session time is the recording's time as the synchroniser maps it: intervals are kept up to
    // the refinements of its clock fit, which at 4x see four times the timer jitter.
    worst = std::max(worst, std::abs((b[i]->t - b[0]->t) - (a[i]->t - a[0]->t)));
  }
  EXPECT_LT(worst, 0.015) << "timing distorted by " << worst << " s";
  std::size_t kinectA = 0, kinectB = 0;
  for (const ArmSample& x : original.samples) kinectA += x.wrist.has_value();
  for (const ArmSample& x : replayed.samples) kinectB += x.wrist.has_value();
  EXPECT_EQ(kinectA, kinectB);

  // The live estimates at 4x are as accurate as the offline ones (the truth rode along).
  double sq = 0.0;
  int n = 0;
  for (const ArmSample& x : replayed.samples) {
    if (!x.estimate || !x.trueAngles || x.t - replayed.samples.front().t < 3.0) continue;
    sq += std::pow(std::remainder((*x.estimate)(0) - (*x.trueAngles)(0), 2 * std::numbers::pi), 2);
    ++n;
  }
  ASSERT_GT(n, 3000);
  EXPECT_LT(std::sqrt(sq / n), 1.0 * std::numbers::pi / 180.0);
}

TEST(Replay, BadFilesAreClearErrors) {
  devices::DevicePlugin* plugin = test::loadPlugin(QStringLiteral("replay"));
  ASSERT_NE(plugin, nullptr);
  QString why;
  EXPECT_EQ(plugin->create({}, &why), nullptr);
  EXPECT_NE(why.indexOf(QStringLiteral("file=REC.csv")), -1) << why.toStdString();
  EXPECT_EQ(plugin->create(devices::Options::parse(QStringLiteral("file=/no/such.csv")), &why),
            nullptr);
  EXPECT_NE(why.indexOf(QStringLiteral("/no/such.csv")), -1) << why.toStdString();
  QTemporaryDir dir;
  const QString bad = dir.path() + QStringLiteral("/bad.csv");
  {
    std::FILE* f = std::fopen(bad.toLocal8Bit().constData(), "w");
    std::fputs("t,ua_gx\n0,1\n", f);
    std::fclose(f);
  }
  EXPECT_EQ(plugin->create(devices::Options::parse(QStringLiteral("file=") + bad + QStringLiteral(",speed=1000")), &why), nullptr);
  EXPECT_NE(why.indexOf(QStringLiteral("speed")), -1) << why.toStdString();
  EXPECT_EQ(plugin->create(devices::Options::parse(QStringLiteral("file=") + bad), &why), nullptr);
  EXPECT_NE(why.indexOf(QStringLiteral("bad.csv:1")), -1) << why.toStdString();
}

}  // namespace
}  // namespace armtrack
