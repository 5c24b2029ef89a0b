// The "skeleton-udp" plugin against a fake tracker on loopback UDP. Datagrams are JSON text written
// here from the documented format; expected positions are computed here.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <QTemporaryDir>

#include <QTest>
#include <QThread>
#include <QUdpSocket>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "devices/api/Device.h"
#include "devices/vision/CameraFile.h"
#include "tests/support/DeviceHarness.h"
#include "tests/support/LoadPlugin.h"

using namespace armtrack;
using namespace armtrack::devices;

namespace {

// Joint positions of frame k (m, camera frame), exactly representable.
struct Joints {
  double shoulder[3], elbow[3], wrist[3];
};
Joints joints(int k) {
  const double d = 0.0625 * k;
  return {{0.25, 0.5, 2.0}, {0.25 + d, 0.25, 2.125}, {0.5, -0.125 + d, 1.875}};
}
std::string xyz(const double* p) {
  char s[96];
  std::snprintf(s, sizeof s, "[%.6f,%.6f,%.6f]", p[0], p[1], p[2]);
  return s;
}
double frameTime(int k) {
  return 100.0 + k / 32.0;
}
std::string frameJson(int k, bool shoulder = true, bool elbow = true, bool wrist = true) {
  const Joints j = joints(k);
  char head[96];
  std::snprintf(head, sizeof head, R"({"v":1,"t":%.6f,"frame":%d,"side":"right","joints":{)",
                frameTime(k), k);
  std::string s = head;
  std::string sep;
  if (shoulder) s += std::exchange(sep, ",") + "\"shoulder\":" + xyz(j.shoulder);
  if (elbow) s += std::exchange(sep, ",") + "\"elbow\":" + xyz(j.elbow);
  if (wrist) s += std::exchange(sep, ",") + "\"wrist\":" + xyz(j.wrist);
  return s + R"(},"confidence":{"elbow":0.9},"hand":[1,2,3]})";
}

void expectHas(const std::string& text, const std::string& needle) {
  EXPECT_NE(text.find(needle), std::string::npos) << "'" << needle << "' not in: " << text;
}

// A camera file for the tracker's camera (the intrinsics are not used by skeleton-udp).
std::string writeCamera(const QTemporaryDir& dir, const char* name,
                        std::optional<webcam::Extrinsics> pose) {
  webcam::CameraFile f;
  f.id = "tracker";
  f.intrinsics.imageSize = cv::Size(640, 480);
  f.intrinsics.fx = f.intrinsics.fy = 525.0;
  f.intrinsics.cx = 320.0;
  f.intrinsics.cy = 240.0;
  f.extrinsics = pose;
  const std::string path = dir.filePath(QString::fromLatin1(name)).toStdString();
  webcam::writeCameraFile(path, f);
  return path;
}

void expectFrame(const DeviceSample& s, int k, bool relative, bool elbow = true,
                 bool wrist = true) {
  SCOPED_TRACE("frame " + std::to_string(k));
  EXPECT_EQ(s.stream, 0);
  EXPECT_NEAR(s.deviceTime, frameTime(k), 1e-9);
  ASSERT_TRUE(std::holds_alternative<OpticalPositions>(s.payload));
  const OpticalPositions& p = std::get<OpticalPositions>(s.payload);
  const Joints j = joints(k);
  ASSERT_EQ(p.elbow.has_value(), elbow);
  ASSERT_EQ(p.wrist.has_value(), wrist);
  for (int i = 0; i < 3; ++i) {
    const double o = relative ? j.shoulder[i] : 0.0;
    if (elbow) {
      EXPECT_NEAR((*p.elbow)[i], j.elbow[i] - o, 1e-12);
    }
    if (wrist) {
      EXPECT_NEAR((*p.wrist)[i], j.wrist[i] - o, 1e-12);
    }
  }
}

using Harness = test::DeviceHarness;

class SkeletonDevice : public ::testing::Test {
 protected:
  void SetUp() override {
    m_plugin = test::loadPlugin(QStringLiteral("skeleton-udp"));
    ASSERT_NE(m_plugin, nullptr);
    QUdpSocket probe;  // a port that was free a moment ago
    ASSERT_TRUE(probe.bind(QHostAddress::LocalHost, 0));
    m_port = probe.localPort();
  }
  // Without a registration the tests say the tracker sends shoulder-frame axes.
  std::unique_ptr<Harness> start(QVariantMap options = {}) {
    options.insert(QStringLiteral("port"), m_port);
    if (!options.contains(QStringLiteral("camera")))
      options.insert(QStringLiteral("axes"), QStringLiteral("shoulder"));
    QString error;
    auto d = m_plugin->create(options, &error);
    EXPECT_TRUE(d) << error.toStdString();
    if (!d) return nullptr;
    auto h = std::make_unique<Harness>(std::move(d));
    EXPECT_TRUE(h->waitState(DeviceState::Connecting));
    return h;
  }
  void send(const std::string& d) {
    ASSERT_EQ(m_tx.writeDatagram(d.data(), static_cast<qint64>(d.size()), QHostAddress::LocalHost,
                                 m_port),
              static_cast<qint64>(d.size()));
  }

  DevicePlugin* m_plugin = nullptr;
  std::uint16_t m_port = 0;
  QUdpSocket m_tx;
};

}  // namespace

TEST_F(SkeletonDevice, OptionsSayWhatToChange) {
  EXPECT_EQ(m_plugin->name(), QStringLiteral("skeleton-udp"));
  const QString axes = QStringLiteral("axes"), shoulder = QStringLiteral("shoulder");
  const auto errorOf = [&](const QVariantMap& options) {
    QString error;
    EXPECT_FALSE(m_plugin->create(options, &error));
    return error.toStdString();
  };
  expectHas(errorOf({{QStringLiteral("origin"), QStringLiteral("hip")}, {axes, shoulder}}),
            "shoulder, start or camera, not 'hip'");
  expectHas(errorOf({{QStringLiteral("role"), QStringLiteral("upper")}, {axes, shoulder}}),
            "unknown option 'role'");
  // Positions must reach the filter in the shoulder frame: a registration is required.
  expectHas(errorOf({}), "give camera=FILE");
  expectHas(errorOf({{axes, QStringLiteral("camera")}}), "'axes' can only be 'shoulder'");
  expectHas(errorOf({{axes, shoulder}, {QStringLiteral("camera"), QStringLiteral("c.json")}}),
            "not both");
  expectHas(errorOf({{QStringLiteral("camera"), QStringLiteral("/nonexistent/cam.json")}}),
            "/nonexistent/cam.json");
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const std::string unregistered = writeCamera(dir, "intrinsics-only.json", std::nullopt);
  expectHas(errorOf({{QStringLiteral("camera"), QString::fromStdString(unregistered)}}),
            "run armtrack-cli camera-register");
  QString error;
  auto d = m_plugin->create({{axes, shoulder}}, &error);
  ASSERT_TRUE(d) << error.toStdString();
  ASSERT_EQ(d->streams().size(), 1u);
  EXPECT_EQ(d->streams()[0].role, StreamRole::Optical);
  // The default is the world frame, shoulder included; relative to the moving shoulder there is
  // no shoulder to publish.
  EXPECT_EQ(d->streams()[0].name, "tracker elbow, wrist and shoulder");
  d = m_plugin->create({{axes, shoulder}, {QStringLiteral("origin"), shoulder}}, &error);
  ASSERT_TRUE(d) << error.toStdString();
  EXPECT_EQ(d->streams()[0].name, "tracker elbow and wrist");
}

TEST_F(SkeletonDevice, RegisteredTrackerAxesBecomeShoulderFrameAxes) {
  // The tracker camera stands in front of the patient, turned and tilted: p_cam = R p_sh + t.
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(2.6, Eigen::Vector3d(0.2, -1.0, 0.3).normalized()) *
                             Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const Eigen::Vector3d t(0.1, -0.3, 2.2);
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  webcam::Extrinsics e;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) e.R(r, c) = R(r, c);
    e.t[r] = t[r];
  }
  const QString path = QString::fromStdString(writeCamera(dir, "tracker.json", e));
  const auto expectShoulderFrame = [&](const DeviceSample& s, int k, bool relative) {
    SCOPED_TRACE("frame " + std::to_string(k));
    const Joints j = joints(k);
    const Eigen::Vector3d sh(j.shoulder), el(j.elbow), wr(j.wrist);
    const Eigen::Vector3d origin = relative ? sh : t;
    // Independent of the device's formula: solve R x = p - origin.
    const Eigen::Vector3d elbow = R.colPivHouseholderQr().solve(el - origin);
    const Eigen::Vector3d wrist = R.colPivHouseholderQr().solve(wr - origin);
    const OpticalPositions& p = std::get<OpticalPositions>(s.payload);
    ASSERT_TRUE(p.elbow && p.wrist);
    EXPECT_LT((*p.elbow - elbow).norm(), 1e-6);  // the camera file keeps about 9 digits
    EXPECT_LT((*p.wrist - wrist).norm(), 1e-6);
    // The arm's segment lengths do not depend on the axes.
    EXPECT_NEAR((*p.wrist - *p.elbow).norm(), (wr - el).norm(), 1e-9);
  };
  {
    auto h = start(
        {{QStringLiteral("camera"), path}, {QStringLiteral("origin"), QStringLiteral("shoulder")}});
    ASSERT_TRUE(h);
    for (int k = 0; k < 3; ++k) send(frameJson(k));
    ASSERT_TRUE(h->waitSamples(3));
    for (int k = 0; k < 3; ++k) expectShoulderFrame(h->samples[k], k, /*relative=*/true);
    EXPECT_TRUE(h->problems.isEmpty()) << h->problems.join(u'\n').toStdString();
  }
  {
    auto h = start(
        {{QStringLiteral("camera"), path}, {QStringLiteral("origin"), QStringLiteral("camera")}});
    ASSERT_TRUE(h);
    send(frameJson(0, /*shoulder=*/false));
    ASSERT_TRUE(h->waitSamples(1));
    expectShoulderFrame(h->samples[0], 0, /*relative=*/false);
  }
}

TEST_F(SkeletonDevice, FramesBecomeShoulderRelativePositions) {
  auto h = start({{QStringLiteral("origin"), QStringLiteral("shoulder")}});
  ASSERT_TRUE(h);
  const double before = hostNow();
  for (int k = 0; k < 10; ++k) send(frameJson(k));
  send(frameJson(10, true, false, true));  // elbow not tracked
  ASSERT_TRUE(h->waitSamples(11));
  ASSERT_EQ(h->samples.size(), 11u);
  for (int k = 0; k < 10; ++k) {
    expectFrame(h->samples[k], k, /*relative=*/true);
    EXPECT_GE(h->samples[k].arrivalTime, before);
    EXPECT_LE(h->samples[k].arrivalTime, hostNow());
  }
  expectFrame(h->samples[10], 10, true, /*elbow=*/false, /*wrist=*/true);
  EXPECT_EQ(h->state(), DeviceState::Streaming);
  EXPECT_TRUE(h->problems.isEmpty()) << h->problems.join(u'\n').toStdString();
}

TEST_F(SkeletonDevice, CameraOriginPassesPositionsThroughAndNeedsNoShoulder) {
  auto h = start({{QStringLiteral("origin"), QStringLiteral("camera")}});
  ASSERT_TRUE(h);
  send(frameJson(0));
  send(frameJson(1, /*shoulder=*/false));
  ASSERT_TRUE(h->waitSamples(2));
  expectFrame(h->samples[0], 0, /*relative=*/false);
  expectFrame(h->samples[1], 1, false);
}

TEST_F(SkeletonDevice, MalformedDatagramsAreReportedAndLaterFramesKept) {
  auto h = start();
  ASSERT_TRUE(h);
  std::vector<int> good;
  auto sendGood = [&](int k) {
    good.push_back(k);
    send(frameJson(k));
  };
  sendGood(0);
  send("\x01\x02\xff\xfe binary");  // 1: not JSON
  const std::string whole = frameJson(1);
  send(whole.substr(0, whole.size() / 2));  // 2: truncated
  sendGood(2);
  std::string v2 = frameJson(3);
  v2.replace(v2.find("\"v\":1"), 5, "\"v\":2");
  send(v2);  // 3: wrong version
  std::string far = frameJson(4);
  far.replace(far.find("2.125000"), 8, "99.00000");
  send(far);                                          // 4: elbow 99 m away
  send(R"({"v":1,"t":1,"frame":5,"side":"right"})");  // 5: no joints
  send("{" + std::string(9000, ' ') + "}");           // 6: too long
  sendGood(6);                                        // frames 1, 3-5 missing: 4 dropped
  sendGood(7);
  ASSERT_TRUE(h->waitSamples(good.size()));
  QTest::qWait(50);
  ASSERT_EQ(h->samples.size(), good.size());
  for (std::size_t i = 0; i < good.size(); ++i) expectFrame(h->samples[i], good[i], true);
  const DeviceHealth health = h->device->health();
  EXPECT_EQ(health.streams[0].corrupt, 6u);
  EXPECT_EQ(health.streams[0].dropped, 4u);
  ASSERT_FALSE(h->problems.isEmpty());
  EXPECT_TRUE(h->problems.front().contains(QStringLiteral("datagram")))
      << h->problems.front().toStdString();
  EXPECT_LE(h->problems.size(), 2);
  EXPECT_EQ(h->state(), DeviceState::Streaming);
}

TEST_F(SkeletonDevice, FrameWithoutShoulderIsReportedNotPublished) {
  auto h = start({{QStringLiteral("origin"), QStringLiteral("shoulder")}});
  ASSERT_TRUE(h);
  send(frameJson(0, /*shoulder=*/false));
  send(frameJson(1));
  ASSERT_TRUE(h->waitSamples(1));
  QTest::qWait(50);
  ASSERT_EQ(h->samples.size(), 1u);
  expectFrame(h->samples[0], 1, true);
  ASSERT_EQ(h->problems.size(), 1);
  EXPECT_TRUE(h->problems[0].contains(QStringLiteral("origin=camera")))
      << h->problems[0].toStdString();
  EXPECT_EQ(h->device->health().streams[0].corrupt, 0u);
}

TEST_F(SkeletonDevice, SilenceGoesConnectingAndTheTrackerComesBack) {
  auto h = start({{QStringLiteral("timeout"), QStringLiteral("0.3")}});
  ASSERT_TRUE(h);
  send(frameJson(0));
  ASSERT_TRUE(h->waitState(DeviceState::Streaming));
  ASSERT_TRUE(h->waitState(DeviceState::Connecting, 1500));
  EXPECT_TRUE(h->reason().contains(QStringLiteral("no tracker frame")))
      << h->reason().toStdString();
  send("garbage");
  send(frameJson(1));
  ASSERT_TRUE(h->waitState(DeviceState::Streaming));
  ASSERT_TRUE(h->waitSamples(2));
  expectFrame(h->samples[1], 1, true);
  EXPECT_EQ(h->device->health().reconnects, 1u);
  EXPECT_EQ(h->device->health().streams[0].corrupt, 1u);
}

TEST_F(SkeletonDevice, PortInUseIsAnError) {
  QUdpSocket other;
  ASSERT_TRUE(other.bind(QHostAddress::Any, m_port));
  QString error;
  auto device = m_plugin->create(
      {{QStringLiteral("port"), m_port}, {QStringLiteral("axes"), QStringLiteral("shoulder")}},
      &error);
  ASSERT_TRUE(device) << error.toStdString();
  Harness h(std::move(device));
  ASSERT_TRUE(h.waitState(DeviceState::Error));
  EXPECT_TRUE(h.reason().contains(QStringLiteral("already in use"))) << h.reason().toStdString();
}

namespace {

// A frame from given camera-frame positions (m), any of them absent.
std::string jointsJson(int k, double t, const std::optional<Eigen::Vector3d>& shoulder,
                       const std::optional<Eigen::Vector3d>& elbow,
                       const std::optional<Eigen::Vector3d>& wrist) {
  char head[96];
  std::snprintf(head, sizeof head, R"({"v":1,"t":%.6f,"frame":%d,"side":"right","joints":{)", t, k);
  std::string s = head, sep;
  const auto add = [&](const char* name, const std::optional<Eigen::Vector3d>& p) {
    if (!p) return;
    char v[128];
    std::snprintf(v, sizeof v, "\"%s\":[%.12f,%.12f,%.12f]", name, p->x(), p->y(), p->z());
    s += std::exchange(sep, ",") + v;
  };
  add("shoulder", shoulder);
  add("elbow", elbow);
  add("wrist", wrist);
  return s + "}}";
}

// A seated patient in the world frame (frame 0 with the trunk upright at the start: x down,
// y forward, z to the right, the shoulder centre at the origin), seen by a registered tracker
// camera: p_cam = Rc p_world + tc. The trunk leans about a hip point h, so the shoulder centre
// moves to h - R h and the arm (fixed to the trunk here) goes with it.
struct Scene {
  Eigen::Matrix3d Rc = (Eigen::AngleAxisd(2.6, Eigen::Vector3d(0.2, -1.0, 0.3).normalized()) *
                        Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()))
                           .toRotationMatrix();
  Eigen::Vector3d tc{0.1, -0.3, 2.2};
  Eigen::Vector3d hip{0.45, 0.0, -0.15};
  Eigen::Vector3d elbowT{0.28, 0.05, 0.02}, wristT{0.30, 0.30, 0.05};  // trunk frame, m

  // Forward lean by `lean` rad (about the lateral axis z0).
  Eigen::Matrix3d trunk(double lean) const {
    return Eigen::AngleAxisd(-lean, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  }
  Eigen::Vector3d shoulderW(double lean) const { return hip - trunk(lean) * hip; }
  Eigen::Vector3d elbowW(double lean) const { return shoulderW(lean) + trunk(lean) * elbowT; }
  Eigen::Vector3d wristW(double lean) const { return shoulderW(lean) + trunk(lean) * wristT; }
  Eigen::Vector3d cam(const Eigen::Vector3d& w) const { return Rc * w + tc; }
  std::string frame(int k, double t, double lean, bool shoulder = true) const {
    return jointsJson(k, t, shoulder ? std::optional(cam(shoulderW(lean))) : std::nullopt,
                      cam(elbowW(lean)), cam(wristW(lean)));
  }
};

QString writeSceneCamera(const QTemporaryDir& dir, const Scene& sc) {
  webcam::Extrinsics e;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) e.R(r, c) = sc.Rc(r, c);
    e.t[r] = sc.tc[r];
  }
  return QString::fromStdString(writeCamera(dir, "tracker.json", e));
}

}  // namespace

// origin=start on a still trunk: the same elbow and wrist as origin=shoulder, and the shoulder,
// now published, at the world origin. The old mode publishes no shoulder.
TEST_F(SkeletonDevice, StartOriginOnAStillTrunkMatchesTheShoulderOrigin) {
  const Scene sc;
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString path = writeSceneCamera(dir, sc);
  std::vector<DeviceSample> bySample[2];
  for (int mode = 0; mode < 2; ++mode) {
    auto h = start(
        {{QStringLiteral("camera"), path},
         {QStringLiteral("origin"), mode ? QStringLiteral("start") : QStringLiteral("shoulder")}});
    ASSERT_TRUE(h);
    for (int k = 0; k < 60; ++k) send(sc.frame(k, 10.0 + k / 30.0, 0.0));
    ASSERT_TRUE(h->waitSamples(60));
    bySample[mode] = h->samples;
    EXPECT_TRUE(h->problems.isEmpty()) << h->problems.join(u'\n').toStdString();
  }
  for (int k = 0; k < 60; ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    const auto& old = std::get<OpticalPositions>(bySample[0][k].payload);
    const auto& now = std::get<OpticalPositions>(bySample[1][k].payload);
    ASSERT_TRUE(old.elbow && old.wrist && now.elbow && now.wrist && now.shoulder);
    EXPECT_FALSE(old.shoulder.has_value());
    EXPECT_LT((*now.elbow - *old.elbow).norm(), 1e-9);
    EXPECT_LT((*now.wrist - *old.wrist).norm(), 1e-9);
    EXPECT_LT(now.shoulder->norm(), 1e-9);
    // And both are the truth: the trunk frame is the world frame while the trunk is upright.
    EXPECT_LT((*now.elbow - sc.elbowT).norm(), 1e-6);  // the camera file keeps about 9 digits
    EXPECT_LT((*now.wrist - sc.wristT).norm(), 1e-6);
  }
}

// origin=start on a leaning trunk: the first second sets the origin; then a 10 deg forward lean
// about the hip moves the published shoulder by |h - R h| = 2 * 0.45 m * sin(5 deg) = 7.84 cm,
// and elbow and wrist are where the leaning trunk carries them in the world, not relative to the
// moving shoulder.
TEST_F(SkeletonDevice, StartOriginFollowsALeaningTrunkInTheWorldFrame) {
  const Scene sc;
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  auto h = start({{QStringLiteral("camera"), writeSceneCamera(dir, sc)},
                  {QStringLiteral("origin"), QStringLiteral("start")}});
  ASSERT_TRUE(h);
  constexpr double kLean = 10.0 * 3.14159265358979323846 / 180.0;
  std::vector<double> lean;
  for (int k = 0; k < 90; ++k) {
    // Upright for the first 1.2 s, then leaning over 0.5 s, then held.
    const double t = k / 30.0;
    lean.push_back(kLean * std::clamp((t - 1.2) / 0.5, 0.0, 1.0));
    send(sc.frame(k, 50.0 + t, lean.back(), /*shoulder=*/k % 7 != 3));  // some frames lose it
    if (k % 10 == 0) QTest::qWait(2);
  }
  ASSERT_TRUE(h->waitSamples(90));
  for (int k = 0; k < 90; ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    const auto& p = std::get<OpticalPositions>(h->samples[k].payload);
    ASSERT_TRUE(p.elbow && p.wrist);
    ASSERT_EQ(p.shoulder.has_value(), k % 7 != 3);
    if (p.shoulder) {
      EXPECT_LT((*p.shoulder - sc.shoulderW(lean[k])).norm(), 1e-6);
    }
    EXPECT_LT((*p.elbow - sc.elbowW(lean[k])).norm(), 1e-6);
    EXPECT_LT((*p.wrist - sc.wristW(lean[k])).norm(), 1e-6);
  }
  const auto& last = std::get<OpticalPositions>(h->samples.back().payload);
  ASSERT_TRUE(last.shoulder);
  EXPECT_NEAR(last.shoulder->norm(), 2.0 * 0.45 * std::sin(kLean / 2.0), 1e-6);
  EXPECT_NEAR(last.shoulder->norm(), 0.0784, 5e-4);
}

// origin=start before any shoulder: nothing can be placed, which is said; the first shoulder
// sets the origin, and later frames without one are placed.
TEST_F(SkeletonDevice, StartOriginWaitsForAShoulderAndSaysSo) {
  auto h = start({{QStringLiteral("origin"), QStringLiteral("start")}});
  ASSERT_TRUE(h);
  send(frameJson(0, /*shoulder=*/false));
  QTest::qWait(20);
  send(frameJson(1));
  QTest::qWait(20);
  send(frameJson(2, /*shoulder=*/false));
  ASSERT_TRUE(h->waitSamples(2));
  QTest::qWait(50);
  ASSERT_EQ(h->samples.size(), 2u);
  expectFrame(h->samples[0], 1, /*relative=*/true);  // the shoulder of frame 1 is the origin
  expectFrame(h->samples[1], 2, true);               // joints(k) keeps the shoulder still
  ASSERT_FALSE(h->problems.isEmpty());
  EXPECT_TRUE(h->problems[0].contains(QStringLiteral("no shoulder seen yet")))
      << h->problems[0].toStdString();
}
