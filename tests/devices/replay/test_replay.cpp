// The replay device through a live session at 4x: every sample of the file comes out, in order,
// with its own timing, and the estimates are as good as offline.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QTemporaryDir>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
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
      devices::Options::parse(
          QStringLiteral("file=%1,speed=4").arg(QString::fromStdString(source.string()))),
      &why);
  ASSERT_NE(device, nullptr) << why.toStdString();
  EXPECT_EQ(device->timeScale(), 4.0);

  session::SessionParams params;
  params.recordingPath = fs::path(dir.path().toStdString()) / "replayed.csv";
  session::Session s(params);
  s.addDevice(test::hosted(std::move(device), QStringLiteral("replay")), QStringLiteral("replay"));
  ASSERT_TRUE(s.start().isEmpty());
  std::this_thread::sleep_for(std::chrono::milliseconds(2300));  // 8 s at 4x, plus margin
  s.stop();
  const session::SessionStats st = s.stats();
  EXPECT_EQ(st.lost(), 0u);
  EXPECT_EQ(st.deviceStates[0], DeviceState::Disconnected);

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
    // Session time is the recording's time as the synchroniser maps it. The replay stamps each
    // row's arrival with when it was due, so the clock fit sees no timer jitter; what remains is
    // the row assembler putting an IMU sample into the row of a Kinect sample less than its
    // 0.5 ms merge window before it (an IMU row at 0.067 s joins the Kinect's at 0.0667 s).
    worst = std::max(worst, std::abs((b[i]->t - b[0]->t) - (a[i]->t - a[0]->t)));
  }
  std::cout << "replay at 4x: intervals kept to " << worst * 1e6 << " us\n";
  EXPECT_LE(worst, 0.5e-3 + 1e-9) << "timing distorted by " << worst << " s";
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
  EXPECT_EQ(plugin->create(devices::Options::parse(QStringLiteral("file=") + bad +
                                                   QStringLiteral(",speed=1000")),
                           &why),
            nullptr);
  EXPECT_NE(why.indexOf(QStringLiteral("speed")), -1) << why.toStdString();
  EXPECT_EQ(plugin->create(devices::Options::parse(QStringLiteral("file=") + bad), &why), nullptr);
  EXPECT_NE(why.indexOf(QStringLiteral("bad.csv:1")), -1) << why.toStdString();
}

namespace {

// A replay device run in this thread's event loop until it leaves Streaming (or `seconds` pass).
struct Played {
  std::vector<DeviceSample> samples;
  QStringList problems;
  DeviceState state = DeviceState::Disconnected;
  QString reason;
};

Played play(const QString& options, double seconds) {
  Played out;
  QString why;
  auto device =
      test::loadPlugin(QStringLiteral("replay"))->create(devices::Options::parse(options), &why);
  EXPECT_NE(device, nullptr) << why.toStdString();
  if (!device) return out;
  QObject::connect(device.get(), &devices::Device::samplesReady, [&](const SampleBatch& b) {
    out.samples.insert(out.samples.end(), b.begin(), b.end());
  });
  QObject::connect(device.get(), &devices::Device::problem,
                   [&](const QString& m) { out.problems << m; });
  QObject::connect(device.get(), &devices::Device::stateChanged,
                   [&](DeviceState st, const QString& r) {
                     out.state = st;
                     out.reason = r;
                   });
  device->start();
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end &&
         (out.state == DeviceState::Streaming || out.state == DeviceState::Connecting))
    QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
  const DeviceState last = out.state;
  const QString lastReason = out.reason;
  device->stop();
  out.state = last;  // as it was before stop()
  out.reason = lastReason;
  return out;
}

Recording shortRecording(double duration) {
  SimulationParams p = defaultSimulation();
  p.duration = duration;
  return simulateRecording(MultiJointTrajectory(2), p);
}

}  // namespace

TEST(Replay, BadRowMidFilePlaysTheRowsBeforeItThenStopsWithTheLine) {
  QTemporaryDir dir;
  const fs::path path = fs::path(dir.path().toStdString()) / "broken.csv";
  // Past the first 10 s, which the device reads when it is created (for the stream rates): an
  // error there would refuse the file at once.
  const Recording rec = shortRecording(15.0);
  writeRecording(path, rec);
  // Break the data row on line 12002, at 12 s (line 1 is a comment, line 2 the header).
  std::string text;
  {
    std::ifstream in(path, std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::size_t at = 0;
  for (int line = 1; line < 12002; ++line) at = text.find('\n', at) + 1;
  text.insert(at, "oops");
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;

  const Played r =
      play(QStringLiteral("speed=20,file=") + QString::fromStdString(path.string()), 5.0);
  EXPECT_EQ(r.state, DeviceState::Error);
  EXPECT_TRUE(r.reason.contains(QStringLiteral("broken.csv:12002:1"))) << r.reason.toStdString();
  EXPECT_TRUE(r.reason.contains(QStringLiteral("rows before it were played")))
      << r.reason.toStdString();
  // Rows 1-11999 were published: their IMU samples, in order.
  const std::size_t before = static_cast<std::size_t>(
      std::count_if(rec.samples.begin(), rec.samples.begin() + 11999,
                    [](const ArmSample& x) { return x.upperArm.has_value(); }));
  std::vector<double> upper;
  for (const DeviceSample& s : r.samples)
    if (std::holds_alternative<ImuReading>(s.payload) && s.stream == 0)
      upper.push_back(s.deviceTime);
  EXPECT_EQ(upper.size(), before);
  EXPECT_TRUE(std::is_sorted(upper.begin(), upper.end()));
}

TEST(Replay, LoopPlaysAgainWithDeviceTimeMovingOn) {
  QTemporaryDir dir;
  const fs::path path = fs::path(dir.path().toStdString()) / "short.csv";
  const Recording rec = shortRecording(0.5);
  writeRecording(path, rec);  // no sidecar problems: writeRecording writes one
  const Played r =
      play(QStringLiteral("speed=10,loop=1,file=") + QString::fromStdString(path.string()), 0.4);
  EXPECT_EQ(r.state, DeviceState::Streaming) << r.reason.toStdString();  // still looping
  EXPECT_TRUE(r.problems.isEmpty()) << r.problems.join(u'\n').toStdString();
  std::vector<double> upper;
  for (const DeviceSample& s : r.samples)
    if (s.stream == 0) upper.push_back(s.deviceTime);
  std::size_t rows = 0;
  for (const ArmSample& x : rec.samples) rows += x.upperArm.has_value();
  // 0.4 s at 10x is eight passes of 0.5 s; at least five came out, each after the last.
  ASSERT_GT(upper.size(), 5 * rows);
  for (std::size_t i = 1; i < upper.size(); ++i) ASSERT_GT(upper[i], upper[i - 1]) << i;
  // The n-th pass repeats the first, shifted by whole passes.
  const double pass = upper[rows] - upper[0];
  // A pass lasts the recording's span plus one mean row step (docs/devices/replay.md).
  const double span = rec.samples.back().t - rec.samples.front().t;
  EXPECT_NEAR(pass, span + span / static_cast<double>(rec.samples.size() - 1), 1e-9);
  for (std::size_t i = 0; i < rows; i += 37)
    EXPECT_NEAR(upper[4 * rows + i] - upper[i], 4 * pass, 1e-9) << i;
}

}  // namespace
}  // namespace armtrack
