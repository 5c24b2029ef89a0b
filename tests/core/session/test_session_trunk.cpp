// The live session with a trunk (docs/session.md, docs/trunk.md): the virtual arm's patient leans
// as the arm reaches. With a sternum sensor the session estimates the trunk and records it; with
// only a Kinect's shoulder it says that the trunk moved, and flags the rows; a still trunk is
// never reported.
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <thread>

#include <Eigen/Geometry>

#include "core/io/Recording.h"
#include "core/kinematics/Trunk.h"
#include "core/session/Session.h"
#include "core/session/TrunkMessages.h"
#include "core/simulation/SensorSimulator.h"
#include "devices/api/Options.h"
#include "tests/support/LoadPlugin.h"

namespace armtrack::session {
namespace {

namespace fs = std::filesystem;
constexpr double kDeg = std::numbers::pi / 180.0;

struct TrunkRun {
  std::vector<std::string> events;
  std::vector<EstimateRow> results;
  Recording rec;
  RecordingColumns columns;  // as the reader finds them in the file
  RecordingMeta meta;
  fs::path csv;
};

std::size_t mentioning(const std::vector<std::string>& events, const std::string& text) {
  std::size_t n = 0;
  for (const std::string& e : events) n += e.find(text) != std::string::npos;
  return n;
}

std::string joined(const std::vector<std::string>& events) {
  std::string all;
  for (const std::string& e : events) all += "  " + e + "\n";
  return all;
}

// A session of one virtual arm (its option string) for `seconds`, recorded and read back.
TrunkRun runSession(const QTemporaryDir& dir, const QString& spec, double seconds) {
  TrunkRun r;
  devices::DevicePlugin* plugin = test::loadPlugin(QStringLiteral("virtual-arm"));
  if (!plugin) return r;
  SessionParams params;
  params.recordingPath = r.csv = fs::path(dir.path().toStdString()) / "trunk.csv";
  params.overwrite = true;
  Session session(params);
  QString why;
  auto device = plugin->create(devices::Options::parse(spec), &why);
  if (!device) {
    ADD_FAILURE() << why.toStdString();
    return r;
  }
  session.addDevice(test::hosted(std::move(device), QStringLiteral("arm")), QStringLiteral("arm"));
  why = session.start();
  EXPECT_TRUE(why.isEmpty()) << why.toStdString();
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    session.takeResults(r.results);
  }
  session.stop();
  session.takeResults(r.results);
  session.takeEvents(r.events);
  r.meta = session.meta();
  r.rec = readRecording(params.recordingPath);
  r.columns = RecordingReader(params.recordingPath).columns();
  return r;
}

// The patient of acceptance 2: raises the arm to the front again and again (shoulder flexion 10
// to 110 deg, 4 s each, 1 s at rest between), the IMUs at 200 Hz and a Kinect that sees the
// shoulder, the trunk leaning `lean` deg at the fullest reach (0: still); the same seed.
QString patient(double lean, const QString& extra = {}) {
  return QStringLiteral(
             "trajectory=exercise,exercise=shoulder_flexion,exercise-range=10:110,"
             "exercise-start=2,seed=5,imu-rate=200,trunk-lean=%1,kinect-shoulder=on%2")
      .arg(lean)
      .arg(extra);
}

double largestAngle(const Eigen::Vector3d& trunk) {
  return trunk.cwiseAbs().maxCoeff();
}

// The trunk's whole turn from its start pose (rad).
double wholeTurn(const Eigen::Vector3d& trunk) {
  return Eigen::AngleAxisd(trunkRotation(trunk, Side::Right)).angle();
}

class SessionTrunkTest : public ::testing::Test {
 protected:
  QTemporaryDir dir_;
};

// Acceptance 2, live: without a sternum sensor a leaning trunk is said (naming the trunk and the
// time) and flagged on the rows where it leans, judged against the simulated truth.
TEST_F(SessionTrunkTest, LeaningTrunkWithoutSternumSensorIsToldAndFlagged) {
  const TrunkRun r =
      runSession(dir_, patient(15, QStringLiteral(",sensors=upper+forearm+kinect")), 20.0);
  ASSERT_GT(r.results.size(), 3000u);
  std::size_t leaning = 0, flagged = 0, stillRows = 0, stillFlagged = 0, turned = 0,
              turnedFlagged = 0;
  for (const EstimateRow& e : r.results) {
    ASSERT_TRUE(e.trueTrunk.has_value());
    EXPECT_FALSE(e.trunk.has_value());  // nothing measures the trunk's angles
    if (wholeTurn(*e.trueTrunk) > 5.0 * kDeg) {
      ++turned;
      turnedFlagged += e.trunkMoved;
    }
    const double angle = largestAngle(*e.trueTrunk);
    if (angle > 5.0 * kDeg) {
      ++leaning;
      flagged += e.trunkMoved;
    } else if (angle < 1.0 * kDeg) {
      ++stillRows;
      stillFlagged += e.trunkMoved;
    }
  }
  std::printf(
      "[ figures  ] rows with an angle over 5 deg %zu, flagged %zu; turned over 5 deg %zu, "
      "flagged %zu; upright rows %zu, flagged %zu\n",
      leaning, flagged, turned, turnedFlagged, stillRows, stillFlagged);
  ASSERT_GT(leaning, 500u) << "the simulated patient hardly leaned";
  EXPECT_GE(flagged, 0.9 * static_cast<double>(leaning));
  EXPECT_GE(turnedFlagged, 0.9 * static_cast<double>(turned));
  EXPECT_GE(mentioning(r.events, "The trunk moved from its start pose at "), 1u)
      << joined(r.events);
  EXPECT_GE(mentioning(r.events, "Ask the patient to sit back, or add a sternum sensor"), 1u);
  // The recording has the Kinect's shoulder and the true trunk angles.
  EXPECT_TRUE(r.columns.shoulder);
  EXPECT_TRUE(r.columns.trueTrunk);
  EXPECT_FALSE(r.columns.trunk);
  EXPECT_FALSE(r.rec.meta.trunk.has_value());
}

// ... and never on a still trunk: the same patient sitting still, the same seed.
TEST_F(SessionTrunkTest, StillTrunkIsNeverReported) {
  const TrunkRun r =
      runSession(dir_, patient(0, QStringLiteral(",sensors=upper+forearm+kinect")), 20.0);
  ASSERT_GT(r.results.size(), 3000u);
  std::size_t shoulders = 0;
  for (const EstimateRow& e : r.results) {
    EXPECT_FALSE(e.trunkMoved) << "at " << e.t;
    shoulders += e.opticalShoulder.has_value();
  }
  EXPECT_GT(shoulders, 400u);  // the cue was there
  EXPECT_EQ(mentioning(r.events, "trunk"), 0u) << joined(r.events);
}

// With a sternum sensor the session estimates the trunk's angles (within 2 deg RMS of the truth)
// and records the sensor, its mounting, the shoulder and the true angles.
TEST_F(SessionTrunkTest, SternumSensorEstimatesAndRecordsTheTrunk) {
  const TrunkRun r =
      runSession(dir_, patient(15, QStringLiteral(",sensors=upper+forearm+kinect+trunk")), 20.0);
  ASSERT_GT(r.results.size(), 3000u);
  Eigen::Vector3d squared = Eigen::Vector3d::Zero();
  std::size_t n = 0, leaning = 0;
  for (const EstimateRow& e : r.results) {
    EXPECT_FALSE(e.trunkMoved);
    ASSERT_TRUE(e.trueTrunk.has_value());
    if (e.t < 2.0) continue;  // start-up
    ASSERT_TRUE(e.trunk.has_value()) << "at " << e.t;
    ASSERT_TRUE(e.trunkStd.has_value());
    EXPECT_TRUE(e.trunkStd->allFinite());
    squared += (*e.trunk - *e.trueTrunk).cwiseAbs2();
    leaning += largestAngle(*e.trueTrunk) > 5.0 * kDeg;
    ++n;
  }
  ASSERT_GT(n, 2000u);
  ASSERT_GT(leaning, 300u);
  const Eigen::Vector3d rmseDeg = (squared / static_cast<double>(n)).cwiseSqrt() / kDeg;
  std::printf("[ figures  ] trunk RMSE flexion %.2f, lateral %.2f, rotation %.2f deg\n", rmseDeg(0),
              rmseDeg(1), rmseDeg(2));
  for (int k = 0; k < 3; ++k) EXPECT_LT(rmseDeg(k), 2.0) << "trunk angle " << k;
  EXPECT_EQ(mentioning(r.events, "The trunk moved"), 0u) << joined(r.events);
  EXPECT_EQ(mentioning(r.events, "mounting is not known"), 0u) << joined(r.events);

  // The recording: tr_*, shoulder_* and true_trunk_* columns, and the sidecar's trunk block with
  // the simulated sensor's mounting.
  EXPECT_TRUE(r.columns.trunk);
  EXPECT_TRUE(r.columns.shoulder);
  EXPECT_TRUE(r.columns.trueTrunk);
  std::ifstream csv(r.csv);
  std::string line;
  std::getline(csv, line);
  std::getline(csv, line);
  for (const char* column : {"tr_gx", "tr_az", "shoulder_x", "true_trunk_flex", "true_trunk_rot"})
    EXPECT_NE(line.find(column), std::string::npos) << column << " not in " << line;
  const TrunkMount want = defaultSimulatedTrunkMount(Side::Right);
  ASSERT_TRUE(r.rec.meta.trunk.has_value());
  EXPECT_TRUE(r.rec.meta.trunk->imuPosition.isApprox(want.imuPosition));
  EXPECT_TRUE(r.rec.meta.trunk->imuRotation.isApprox(want.imuRotation));
  std::ifstream sidecar(sidecarPath(r.csv));
  std::stringstream text;
  text << sidecar.rdbuf();
  EXPECT_NE(text.str().find("\"trunk\""), std::string::npos) << text.str();
  std::size_t trunkRows = 0;
  for (const ArmSample& s : r.rec.samples) trunkRows += s.trunk.has_value();
  EXPECT_GT(trunkRows, 3000u);
}

// A trunk stream whose device does not know the sensor's mounting: the session assumes the
// sensor flat on the middle of the sternum and says so.
class TrunkOnlySource final : public SampleSource {
 public:
  TrunkOnlySource() {
    StreamInfo upper;
    upper.name = "upper";
    upper.role = StreamRole::UpperArmImu;
    StreamInfo trunk;
    trunk.name = "sternum";
    trunk.role = StreamRole::TrunkImu;
    m_streams = {upper, trunk};
  }
  const std::vector<StreamInfo>& streams() const override { return m_streams; }
  double timeScale() const override { return 1.0; }
  DeviceState state() const override { return DeviceState::Streaming; }
  DeviceHealth health() const override {
    DeviceHealth h;
    h.streams.resize(m_streams.size());
    return h;
  }
  void start(SampleInput&) override {}
  std::string stop() override { return {}; }

 private:
  std::vector<StreamInfo> m_streams;
};

TEST_F(SessionTrunkTest, UnknownMountingIsAssumedAndSaid) {
  SessionParams params;
  params.meta.side = Side::Left;
  params.recordingPath = fs::path(dir_.path().toStdString()) / "mount.csv";
  Session session(params);
  session.addDevice(std::make_unique<TrunkOnlySource>(), QStringLiteral("imus"));
  const QString why = session.start();
  ASSERT_TRUE(why.isEmpty()) << why.toStdString();
  session.stop();
  std::vector<std::string> events;
  session.takeEvents(events);
  ASSERT_TRUE(session.meta().trunk.has_value());
  EXPECT_EQ(session.meta().trunk->imuPosition, defaultTrunkMount(Side::Left).imuPosition);
  EXPECT_EQ(mentioning(events, "imus sternum: the sternum sensor's mounting is not known"), 1u)
      << joined(events);
  // The sidecar carries it.
  EXPECT_TRUE(readRecording(params.recordingPath).meta.trunk.has_value());
}

// The messages alone: told at once, back when it is back, departures within the quiet time
// counted into the next message, never anything while the trunk is still.
TEST(TrunkMessagesTest, ToldBackAndRateLimited) {
  TrunkMessages m(10.0);
  std::vector<std::string> out;
  auto feed = [&](double from, double to, bool moving, double cm) {
    for (double t = from; t < to; t += 0.1)
      m.update({moving, cm / 100.0, TrunkCue::Shoulder}, t, out);
  };
  feed(0.0, 12.0, false, 0.0);
  EXPECT_TRUE(out.empty());
  feed(12.3, 14.0, true, 8.0);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0],
            "The trunk moved from its start pose at 12.3 s (shoulder 8 cm away): the shoulder "
            "angles include the patient's lean. Ask the patient to sit back, or add a sternum "
            "sensor.");
  feed(14.0, 15.0, false, 0.0);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[1],
            "The trunk is back at its start pose at 14.0 s (it was away 1.7 s, the "
            "shoulder up to 8 cm away).");
  // Two more leans within 10 s of the first message: counted, not told.
  feed(16.0, 17.0, true, 5.0);
  feed(17.0, 18.0, false, 0.0);
  feed(19.0, 20.0, true, 12.0);
  feed(20.0, 23.0, false, 0.0);
  EXPECT_EQ(out.size(), 2u);
  feed(23.0, 24.0, true, 4.0);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_NE(out[2].find("at 23.0 s (shoulder 4 cm away; it also moved 2 times between 16.0 s "
                        "and 19.9 s, the shoulder up to 12 cm away)"),
            std::string::npos)
      << out[2];
  feed(24.0, 25.0, false, 0.0);
  feed(26.0, 27.0, true, 6.0);  // within 10 s of 23: left for the end
  m.finish(out);
  ASSERT_EQ(out.size(), 5u);
  EXPECT_NE(out[4].find("moved from its start pose 1 more time between 26.0 s and 26.9 s"),
            std::string::npos)
      << out[4];
}

}  // namespace
}  // namespace armtrack::session
