// The virtual arm worn wrongly, as the home window's sensor check must find it: the two IMUs'
// readings exchanged (swap-imus), a sensor strapped end over end (upside-down), and the movements
// of a home session (trajectory=sensor-check, trajectory=exercise); the plugin's options for
// them, with the plugin's own words for bad values.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <map>
#include <numbers>

#include "core/calibration/SensorCheck.h"
#include "core/estimation/ArmFilter.h"
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

// The source's samples for the whole run (p.sim.duration), put back into rows by stream role as
// the session's assembler would.
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
    ArmSample& row = rows.back();
    if (role == StreamRole::UpperArmImu) row.upperArm = std::get<ImuReading>(s.payload);
    if (role == StreamRole::ForearmImu) row.forearm = std::get<ImuReading>(s.payload);
    if (role == StreamRole::Truth) row.trueAngles = std::get<TruthAngles>(s.payload).th;
    if (const auto* o = std::get_if<OpticalPositions>(&s.payload)) {
      row.elbow = o->elbow;
      row.wrist = o->wrist;
    }
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
  for (const char* good : {"resolution=full", "resolution=shimmer3", "resolution=16.4:2048"})
    EXPECT_NE(make(QString::fromLatin1(good), &why), nullptr) << good << ": " << why.toStdString();
  const std::pair<const char*, const char*> badResolution[] = {
      {"resolution=fine", "resolution=fine: use full, shimmer3 or GYRO:ACC"},
      {"resolution=0:83", "counts per unit must be above 0"},
      {"resolution=65.5:x", "'x' is not a number"},
      {"resolution=nan:83", "counts per unit must be above 0"},
  };
  for (const auto& [options, says] : badResolution) {
    why.clear();
    EXPECT_EQ(make(QString::fromLatin1(options), &why), nullptr) << options;
    EXPECT_TRUE(why.contains(QString::fromLatin1(says))) << options << ": " << why.toStdString();
  }
  for (const auto& [options, says] : bad) {
    why.clear();
    EXPECT_EQ(make(QString::fromLatin1(options), &why), nullptr) << options;
    EXPECT_TRUE(why.contains(QString::fromLatin1(says))) << options << ": " << why.toStdString();
  }
}

namespace {

// The multi-joint movement at 1 kHz with the Kinect and the true angles, as rows.
std::vector<ArmSample> playMultiJoint(const ImuResolution& resolution, std::uint64_t seed,
                                      double seconds) {
  VirtualArmParams p;
  p.sim = defaultSimulation();
  p.sim.seed = seed;
  p.trajectoryOptions.seed = static_cast<int>(seed);
  p.sim.duration = seconds;
  p.resolution = resolution;
  return play(p);
}

// RMS error (deg) of the default filter's angles against the truth, after 2 s of settling.
double rmsErrorDeg(const std::vector<ArmSample>& rows, const RecordingMeta& meta) {
  std::map<double, JointVector> truth;
  for (const ArmSample& s : rows)
    if (s.trueAngles) truth[s.t] = *s.trueAngles;
  const BatchResult r = estimateSamples(rows, recordingParams(meta));
  double sum = 0.0;
  std::size_t n = 0;
  for (const JointEstimate& e : r.estimates) {
    const auto it = truth.find(e.t);
    if (e.t < 2.0 || it == truth.end()) continue;
    for (int j = 0; j < 5; ++j) {
      const double d = std::remainder(e.th[j] - it->second[j], 2.0 * std::numbers::pi);
      sum += d * d;
      ++n;
    }
  }
  return n ? std::sqrt(sum / static_cast<double>(n)) * 180.0 / std::numbers::pi : INFINITY;
}

}  // namespace

// resolution=shimmer3 puts every IMU value on a Shimmer3's lattice (a whole count times the step,
// within half a step of the full-precision reading; full scale clamps), and the estimator is as
// accurate on it as on full precision: the quantisation (0.0044 deg/s and 0.0035 m/s^2 rms) is
// far below Table 5's noise (0.32 deg/s, 0.1 m/s^2).
TEST(VirtualArmResolution, Shimmer3LatticeAndUnchangedAccuracy) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  const ImuResolution shimmer = ImuResolution::shimmer3();
  const auto full = playMultiJoint({}, 1, 20.0), quantised = playMultiJoint(shimmer, 1, 20.0);
  ASSERT_EQ(full.size(), quantised.size());
  std::size_t values = 0;
  for (std::size_t i = 0; i < full.size(); ++i) {
    for (const auto& [f, q] : {std::pair{&full[i].upperArm, &quantised[i].upperArm},
                               {&full[i].forearm, &quantised[i].forearm}}) {
      ASSERT_EQ(f->has_value(), q->has_value());
      if (!*f) continue;
      for (int k = 0; k < 3; ++k) {
        const double gc = (**q).gyr[k] / kDeg * 65.5, ac = (**q).acc[k] * 83.0;
        ASSERT_NEAR(gc, std::round(gc), 1e-6) << "row " << i;
        ASSERT_NEAR(ac, std::round(ac), 1e-6) << "row " << i;
        ASSERT_LE(std::fabs((**q).gyr[k] - (**f).gyr[k]), 0.5 / 65.5 * kDeg * (1 + 1e-9));
        ASSERT_LE(std::fabs((**q).acc[k] - (**f).acc[k]), 0.5 / 83.0 * (1 + 1e-9));
        values += 2;
      }
    }
  }
  EXPECT_GT(values, 200000u);
  ImuReading hot{Eigen::Vector3d::Constant(kGyroFullScale),
                 Eigen::Vector3d(kAccelFullScale, -kAccelFullScale, NAN)};
  shimmer.apply(hot);
  EXPECT_DOUBLE_EQ(hot.gyr.x(), 32767.0 / 65.5 * kDeg);  // +-500 deg/s full scale
  EXPECT_DOUBLE_EQ(hot.acc.x(), 2047.0 / 83.0);
  EXPECT_DOUBLE_EQ(hot.acc.y(), -2048.0 / 83.0);
  EXPECT_TRUE(std::isnan(hot.acc.z()));

  const RecordingMeta meta = VirtualArmSource([] {
                               VirtualArmParams p;
                               p.sim = defaultSimulation();
                               return p;
                             }())
                                 .meta();
  const double eFull = rmsErrorDeg(full, meta), eQuantised = rmsErrorDeg(quantised, meta);
  const double eOtherSeed = rmsErrorDeg(playMultiJoint({}, 2, 20.0), meta);
  std::printf(
      "[ figures  ] RMS angle error, 20 s multi-joint: full %.4f deg, shimmer3 %.4f deg; "
      "another noise seed (full) %.4f deg\n",
      eFull, eQuantised, eOtherSeed);
  ASSERT_TRUE(std::isfinite(eFull) && std::isfinite(eQuantised));
  // Within what another draw of the noise changes, and within 5 % either way.
  EXPECT_LT(std::fabs(eQuantised - eFull), std::max(std::fabs(eOtherSeed - eFull), 0.05 * eFull));
}
