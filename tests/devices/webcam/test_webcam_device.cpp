// The webcam plugin, loaded as the application loads it, against generated video files: markers
// on a known path (colour and ArUco), a hidden marker, and broken inputs (truncated, garbage,
// missing). Each file is played as fast as possible (speed=0).
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <filesystem>
#include <fstream>
#include <functional>
#include <opencv2/videoio.hpp>

#include "devices/vision/CameraFile.h"
#include "tests/devices/vision/Synthetic.h"
#include "tests/support/LoadPlugin.h"

using namespace armtrack;
using namespace armtrack::devices;
using namespace armtrack::test::webcam;

namespace {

constexpr int kFrames = 45;
const cv::Scalar kGreen(30, 200, 40);
const cv::Scalar kBlue(210, 60, 20);

/// Frames where the colour video hides its wrist marker.
bool wristHidden(int k) {
  return k >= 10 && k < 15;
}

void writeVideo(const std::string& path, cv::Size size, int frames,
                const std::function<void(cv::Mat&, int)>& draw) {
  cv::VideoWriter w(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30.0, size);
  ASSERT_TRUE(w.isOpened()) << path;
  w.set(cv::VIDEOWRITER_PROP_QUALITY, 95);
  for (int k = 0; k < frames; ++k) {
    cv::Mat img(size, CV_8UC3, cv::Scalar(110, 110, 110));
    draw(img, k);
    w.write(img);
  }
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

class Videos : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir = new TempDir("webcam-videos");
    const Path colourPath;
    writeVideo(dir->file("colour.avi"), {320, 240}, kFrames, [&](cv::Mat& img, int k) {
      if (!wristHidden(k)) drawDisc(img, colourPath.wrist(k), 7, kGreen);
      drawDisc(img, colourPath.elbow(k), 6, kBlue);
    });
    const Path arucoPath{640, 480, 30, true};
    writeVideo(dir->file("aruco.avi"), {640, 480}, 30, [&](cv::Mat& img, int k) {
      drawAruco(img, 0, arucoPath.wrist(k), 56, 3.0 * k);
      drawAruco(img, 1, arucoPath.elbow(k), 48, -2.0 * k);
    });
    const std::string bytes = readBytes(dir->file("colour.avi"));
    std::ofstream(dir->file("truncated.avi"), std::ios::binary)
        .write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
    std::ofstream garbage(dir->file("garbage.avi"), std::ios::binary);
    cv::RNG rng(3);
    for (int i = 0; i < 20000; ++i) garbage.put(static_cast<char>(rng.uniform(0, 256)));
  }
  static void TearDownTestSuite() {
    delete dir;
    dir = nullptr;
  }
  static TempDir* dir;
};
TempDir* Videos::dir = nullptr;

/// A device run to its end: every sample, every state change, every problem.
struct PlayResult {
  std::vector<DeviceSample> samples;
  std::vector<std::pair<DeviceState, QString>> states;
  QStringList problems;
  DeviceHealth health;
  DeviceState finalState = DeviceState::Disconnected;
  QString finalReason;
};

PlayResult play(const QVariantMap& options, int timeoutMs = 10000) {
  PlayResult run;
  DevicePlugin* plugin = test::loadPlugin(QStringLiteral("webcam"));
  if (!plugin) return run;
  QString error;
  std::unique_ptr<Device> device = plugin->create(options, &error);
  EXPECT_TRUE(device) << error.toStdString();
  if (!device) return run;
  EXPECT_EQ(device->streams().size(), 1u);
  EXPECT_EQ(device->streams()[0].role, StreamRole::Camera);
  QObject::connect(device.get(), &Device::samplesReady, [&](const SampleBatch& b) {
    run.samples.insert(run.samples.end(), b.begin(), b.end());
  });
  QObject::connect(device.get(), &Device::stateChanged,
                   [&](DeviceState s, const QString& why) { run.states.emplace_back(s, why); });
  QObject::connect(device.get(), &Device::problem, [&](const QString& p) { run.problems << p; });
  QMetaObject::invokeMethod(device.get(), "start", Qt::DirectConnection);
  QElapsedTimer clock;
  clock.start();
  while (clock.elapsed() < timeoutMs &&
         (device->state() == DeviceState::Connecting || device->state() == DeviceState::Streaming))
    QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
  run.finalState = device->state();
  run.finalReason = run.states.empty() ? QString() : run.states.back().second;
  run.health = device->health();
  QMetaObject::invokeMethod(device.get(), "stop", Qt::DirectConnection);
  return run;
}

const MarkerPixels& pixels(const DeviceSample& s) {
  return std::get<MarkerPixels>(s.payload);
}

}  // namespace

TEST_F(Videos, ColourMarkersFollowThePathInEveryFrame) {
  const PlayResult run =
      play({{"source", QString::fromStdString(dir->file("colour.avi"))}, {"speed", "0"}});
  EXPECT_EQ(run.finalState, DeviceState::Disconnected) << run.finalReason.toStdString();
  EXPECT_TRUE(run.finalReason.contains("end of")) << run.finalReason.toStdString();
  ASSERT_EQ(run.samples.size(), static_cast<std::size_t>(kFrames));
  const Path path;
  double worst = 0.0;
  for (int k = 0; k < kFrames; ++k) {
    const DeviceSample& s = run.samples[static_cast<std::size_t>(k)];
    EXPECT_EQ(s.stream, 0);
    EXPECT_NEAR(s.deviceTime, k / 30.0, 1e-6) << k;
    EXPECT_GT(s.arrivalTime, 0.0);
    const MarkerPixels& p = pixels(s);
    ASSERT_TRUE(p.elbow) << k;
    const double de = (*p.elbow - Eigen::Vector2d(path.elbow(k).x, path.elbow(k).y)).norm();
    EXPECT_LT(de, 1.0) << k;
    worst = std::max(worst, de);
    if (wristHidden(k)) {
      EXPECT_FALSE(p.wrist) << "frame " << k << " has no wrist marker";
      continue;
    }
    ASSERT_TRUE(p.wrist) << k;
    const double dw = (*p.wrist - Eigen::Vector2d(path.wrist(k).x, path.wrist(k).y)).norm();
    EXPECT_LT(dw, 1.0) << k;
    worst = std::max(worst, dw);
  }
  std::printf("colour video: worst marker error %.3f px\n", worst);
  EXPECT_EQ(run.health.streams[0].samples, static_cast<std::uint64_t>(kFrames));
  EXPECT_EQ(run.health.streams[0].corrupt, 0u);
  ASSERT_GE(run.states.size(), 3u);
  EXPECT_EQ(run.states[0].first, DeviceState::Connecting);
  EXPECT_EQ(run.states[1].first, DeviceState::Streaming);
}

TEST_F(Videos, ArucoMarkersFollowThePathInEveryFrame) {
  const PlayResult run = play({{"source", QString::fromStdString(dir->file("aruco.avi"))},
                               {"markers", "aruco"},
                               {"speed", "0"}});
  EXPECT_EQ(run.finalState, DeviceState::Disconnected) << run.finalReason.toStdString();
  ASSERT_EQ(run.samples.size(), 30u);
  const Path path{640, 480, 30, true};
  double worst = 0.0;
  for (int k = 0; k < 30; ++k) {
    const MarkerPixels& p = pixels(run.samples[static_cast<std::size_t>(k)]);
    ASSERT_TRUE(p.wrist && p.elbow) << k;
    const double dw = (*p.wrist - Eigen::Vector2d(path.wrist(k).x, path.wrist(k).y)).norm();
    const double de = (*p.elbow - Eigen::Vector2d(path.elbow(k).x, path.elbow(k).y)).norm();
    EXPECT_LT(dw, 1.0) << k;
    EXPECT_LT(de, 1.0) << k;
    worst = std::max({worst, dw, de});
  }
  std::printf("aruco video: worst marker error %.3f px\n", worst);
}

TEST_F(Videos, SwappedIdsSwapTheMarkers) {
  const PlayResult run = play({{"source", QString::fromStdString(dir->file("aruco.avi"))},
                               {"markers", "aruco"},
                               {"wrist-id", "1"},
                               {"elbow-id", "0"},
                               {"speed", "0"}});
  ASSERT_EQ(run.samples.size(), 30u);
  const Path path{640, 480, 30, true};
  const MarkerPixels& p = pixels(run.samples[5]);
  ASSERT_TRUE(p.wrist);
  EXPECT_LT((*p.wrist - Eigen::Vector2d(path.elbow(5).x, path.elbow(5).y)).norm(), 1.0);
}

TEST_F(Videos, RealTimePlaybackIsPacedAndLoops) {
  // 45 frames at 30 fps, twice as fast: 0.75 s for a pass; with loop the time keeps growing.
  QElapsedTimer clock;
  clock.start();
  const PlayResult run = play(
      {{"source", QString::fromStdString(dir->file("colour.avi"))}, {"speed", "2"}, {"loop", "on"}},
      1000);
  const double seconds = clock.elapsed() / 1000.0;
  EXPECT_EQ(run.finalState, DeviceState::Streaming);  // still playing when the run was cut
  // About 60 frames in 1 s at twice 30 fps.
  EXPECT_GT(run.samples.size(), 45u);
  EXPECT_LT(run.samples.size(), 75u);
  for (std::size_t i = 1; i < run.samples.size(); ++i)
    EXPECT_NEAR(run.samples[i].deviceTime - run.samples[i - 1].deviceTime, 1.0 / 30.0, 1e-6) << i;
  EXPECT_LT(seconds, 3.0);
}

TEST_F(Videos, TruncatedFileKeepsItsGoodFramesThenErrors) {
  const std::string file = dir->file("truncated.avi");
  // What OpenCV itself can read from the truncated file.
  int readable = 0;
  {
    cv::VideoCapture cap(file, cv::CAP_FFMPEG);
    ASSERT_TRUE(cap.isOpened());
    cv::Mat f;
    while (cap.read(f)) ++readable;
  }
  ASSERT_GT(readable, 5);
  ASSERT_LT(readable, kFrames);
  const PlayResult run = play({{"source", QString::fromStdString(file)}, {"speed", "0"}});
  EXPECT_EQ(run.finalState, DeviceState::Error);
  EXPECT_TRUE(run.finalReason.contains("breaks off")) << run.finalReason.toStdString();
  EXPECT_TRUE(run.finalReason.contains("re-encode")) << run.finalReason.toStdString();
  EXPECT_EQ(run.samples.size(), static_cast<std::size_t>(readable));
  const Path path;
  for (std::size_t k = 0; k < run.samples.size(); ++k) {
    const MarkerPixels& p = pixels(run.samples[k]);
    ASSERT_TRUE(p.elbow);
    const cv::Point2d e = path.elbow(static_cast<int>(k));
    EXPECT_LT((*p.elbow - Eigen::Vector2d(e.x, e.y)).norm(), 1.0) << k;
  }
  EXPECT_FALSE(run.problems.isEmpty());
}

TEST_F(Videos, GarbageAndMissingFilesAreErrorsWithAReason) {
  const PlayResult garbage = play({{"source", QString::fromStdString(dir->file("garbage.avi"))}});
  EXPECT_EQ(garbage.finalState, DeviceState::Error);
  EXPECT_TRUE(garbage.finalReason.contains("cannot read")) << garbage.finalReason.toStdString();
  EXPECT_TRUE(garbage.samples.empty());

  const PlayResult missing = play({{"source", QString::fromStdString(dir->file("nope.avi"))}});
  EXPECT_EQ(missing.finalState, DeviceState::Error);
  EXPECT_TRUE(missing.finalReason.contains("does not exist")) << missing.finalReason.toStdString();

  const PlayResult directory = play({{"source", QString::fromStdString(dir->path().string())}});
  EXPECT_EQ(directory.finalState, DeviceState::Error);

  // An empty file.
  std::ofstream(dir->file("empty.avi")).close();
  const PlayResult empty = play({{"source", QString::fromStdString(dir->file("empty.avi"))}});
  EXPECT_EQ(empty.finalState, DeviceState::Error);
  EXPECT_TRUE(empty.samples.empty());
}

TEST_F(Videos, BadOptionsAreRefusedWithTheReason) {
  DevicePlugin* plugin = test::loadPlugin(QStringLiteral("webcam"));
  ASSERT_TRUE(plugin);
  EXPECT_EQ(plugin->name(), QStringLiteral("webcam"));
  EXPECT_TRUE(plugin->optionsHelp().contains("markers=colour"));
  const auto refuse = [&](const QVariantMap& options, const char* needle) {
    QString error;
    EXPECT_FALSE(plugin->create(options, &error));
    EXPECT_TRUE(error.contains(QLatin1String(needle))) << error.toStdString();
  };
  refuse({{"markers", "laser"}}, "expected colour or aruco");
  refuse({{"colour", "red"}}, "unknown option 'colour'");
  refuse({{"wrist-hsv", "45-75"}}, "wrist-hsv=45-75");
  refuse({{"markers", "aruco"}, {"wrist-id", "2"}, {"elbow-id", "2"}}, "different ids");
  refuse({{"markers", "aruco"}, {"dictionary", "DICT_3X3_1"}}, "unknown ArUco dictionary");
  refuse({{"source", "0"}, {"loop", "on"}}, "video files only");
  refuse({{"camera", QString::fromStdString(dir->file("none.json"))}}, "no such file");
  std::ofstream(dir->file("bad.json")) << "{\"format\": \"armtrack-camera\", \"version\": 1";
  refuse({{"camera", QString::fromStdString(dir->file("bad.json"))}}, "not valid JSON");
}

TEST_F(Videos, CameraFileGivesTheStreamItsCameraModel) {
  devices::webcam::CameraFile f;
  f.intrinsics.imageSize = {640, 480};  // the colour video is 320x240: a warning, not an error
  f.intrinsics.fx = f.intrinsics.fy = 600;
  f.intrinsics.cx = 320;
  f.intrinsics.cy = 240;
  devices::webcam::Extrinsics e;
  e.t = {0, 0, 2};
  f.extrinsics = e;
  devices::webcam::writeCameraFile(dir->file("cam.json"), f);
  DevicePlugin* plugin = test::loadPlugin(QStringLiteral("webcam"));
  ASSERT_TRUE(plugin);
  QString error;
  auto device = plugin->create({{"source", QString::fromStdString(dir->file("colour.avi"))},
                                {"camera", QString::fromStdString(dir->file("cam.json"))}},
                               &error);
  ASSERT_TRUE(device) << error.toStdString();
  ASSERT_TRUE(device->streams()[0].camera);
  EXPECT_EQ(device->streams()[0].camera->fx, 600);
  EXPECT_EQ(device->streams()[0].camera->t.z(), 2);

  const PlayResult run = play({{"source", QString::fromStdString(dir->file("colour.avi"))},
                               {"camera", QString::fromStdString(dir->file("cam.json"))},
                               {"speed", "0"}});
  EXPECT_EQ(run.samples.size(), static_cast<std::size_t>(kFrames));
  ASSERT_FALSE(run.problems.isEmpty());
  EXPECT_TRUE(run.problems[0].contains("calibrated at 640x480")) << run.problems[0].toStdString();
}
