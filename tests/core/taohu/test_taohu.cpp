// The Tao-Hu tracker (webcam markers + forearm IMU) against independent truth: simulated
// recordings with known joint angles, whose wrist and elbow positions come from the forward
// kinematics. The bounds were set from the printed measurements, with margin.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/taohu/TaoHuTracker.h"

namespace armtrack {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

void report(const std::string& what, double value) {
  std::printf("[ measured ] %s = %.4g\n", what.c_str(), value);
}

// Multi-joint motion, Table 5 IMU noise at 1 kHz, webcam 2 m in front at 30 Hz with 1 px noise.
Recording simulateWebcam(double duration, std::uint64_t seed = 1, Side side = Side::Right,
                         double outliers = 0.0) {
  SimulationParams sim = defaultSimulation();
  sim.webcam.enabled = true;
  sim.webcam.outlierProbability = outliers;
  sim.duration = duration;
  sim.seed = seed;
  sim.side = side;
  return simulateRecording(MultiJointTrajectory(seed), sim);
}

TaoHuErrors errorsOf(const Recording& rec, const TaoHuResult& r) {
  return taoHuErrors(r, rec.meta.geometry, rec.meta.side);
}

void reportErrors(const std::string& name, const TaoHuErrors& e) {
  report(name + " wrist RMSE (cm)", e.wristRmseCm);
  report(name + " wrist peak (cm)", e.wristPeakCm);
  report(name + " wrist largest coordinate error (cm)", e.wristAxisPeakCm);
  report(name + " elbow RMSE (cm)", e.elbowRmseCm);
  const char* names[kNumJoints] = {"th0", "th1", "th2", "th4", "th5"};
  for (int j = 0; j < kNumJoints; ++j) report(name + " " + names[j] + " RMSE (deg)", e.rmseDeg(j));
}

TEST(taohu, MultiJointSixtySecondsWithinThePapersFiveCentimetres) {
  const Recording rec = simulateWebcam(60.0);
  const auto t0 = std::chrono::steady_clock::now();
  const TaoHuResult r = runTaoHu(rec, taoHuParams(rec.meta));
  report("run time (s)",
         std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  const TaoHuErrors e = errorsOf(rec, r);
  reportErrors("60 s", e);
  // One estimate per camera frame after the 1 s warm-up.
  EXPECT_NEAR(static_cast<double>(r.frames.size()), 59.0 * 30.0, 5.0);
  EXPECT_GT(e.count, 1700u);
  EXPECT_LT(e.wristRmseCm, 0.8);  // measured 0.52
  EXPECT_LT(e.wristPeakCm, 5.0);  // measured 3.5; the paper reports +/-5 cm per coordinate
  EXPECT_LT(e.elbowRmseCm, 0.8);  // measured 0.52
  EXPECT_LT(e.rmseDeg(0), 2.5);   // measured 1.64
  EXPECT_LT(e.rmseDeg(1), 0.8);   // measured 0.46
  EXPECT_LT(e.rmseDeg(2), 1.8);   // measured 1.14
  EXPECT_LT(e.rmseDeg(3), 2.0);   // measured 1.25
  EXPECT_LT(e.rmseDeg(4), 1.7);   // measured 1.08
  const TaoHuCounters& c = r.counters;
  EXPECT_EQ(c.initialisations, 1u);
  EXPECT_EQ(c.restarts, 0u);
  EXPECT_EQ(c.rejectedNonFinite + c.rejectedTime, 0u);
  EXPECT_LE(c.wristGated + c.elbowGated, 3u);  // no outliers injected
  EXPECT_EQ(c.lmFailures, 0u);
  EXPECT_EQ(c.lmRuns + c.initialisations, r.frames.size());
}

TEST(taohu, LmKeepsElbowOnSphereAndForearmLength) {
  const Recording rec = simulateWebcam(20.0, 3);
  const TaoHuResult r = runTaoHu(rec, taoHuParams(rec.meta));
  double worstSphere = 0, worstForearm = 0;
  std::size_t refined = 0;
  for (const TaoHuFrame& f : r.frames) {
    if (!f.refined) continue;
    ++refined;
    worstSphere = std::max(worstSphere, std::abs(f.elbow.norm() - rec.meta.geometry.l3));
    worstForearm =
        std::max(worstForearm, std::abs((f.wrist - f.elbow).norm() - rec.meta.geometry.l6));
  }
  report("worst sphere residual (mm)", 1000 * worstSphere);
  EXPECT_EQ(refined, r.frames.size());
  EXPECT_LT(worstSphere, 0.001);  // measured 0.19 mm with sphereStdLm = 0.5 mm
  EXPECT_LT(worstForearm, 1e-9);  // rigid by construction
}

TEST(taohu, AnglesFromPointsInvertForwardKinematics) {
  const ArmGeometry geo;
  std::srand(7);
  double worst = 0;
  for (int k = 0; k < 500; ++k) {
    JointVector th = JointVector::Random() * 1.4;
    th(3) = -1.4 + 1.2 * JointVector::Random()(0);  // elbow flexed, in (-2.6, -0.2)
    const ArmPose pose = forwardKinematics(geo, th);
    const JointVector back = TaoHuTracker::anglesFromPoints(geo, pose.elbow, pose.wrist,
                                                            pose.forearmImu.topLeftCorner<3, 3>());
    for (int j = 0; j < kNumJoints; ++j)
      worst = std::max(worst, std::abs(wrapAngle(back(j) - th(j))));
  }
  EXPECT_LT(worst, 1e-9);
}

// The heading offset between the orientation filter's world and the shoulder frame is estimated:
// the forearm rotation the tracker uses must match the truth about every axis.
TEST(taohu, HeadingMakesForearmRotationMatchTruth) {
  const Recording rec = simulateWebcam(30.0, 2);
  TaoHuTracker tracker(taoHuParams(rec.meta));
  JointVector truth = JointVector::Zero();
  double worst = 0, sumSq = 0;
  std::size_t n = 0;
  for (const ArmSample& s : rec.samples) {
    if (s.trueAngles) truth = *s.trueAngles;
    if (tracker.update(s) != TaoHuStatus::Frame || s.t < 3.0) continue;
    const Eigen::Matrix3d Rt =
        forwardKinematics(rec.meta.geometry, truth).forearmImu.topLeftCorner<3, 3>();
    const double err = Eigen::AngleAxisd(Rt.transpose() * tracker.forearmRotation()).angle();
    worst = std::max(worst, err);
    sumSq += err * err;
    ++n;
  }
  ASSERT_GT(n, 800u);
  report("forearm rotation RMSE (deg)", std::sqrt(sumSq / n) * kRadToDeg);
  report("forearm rotation worst (deg)", worst * kRadToDeg);
  EXPECT_LT(std::sqrt(sumSq / n) * kRadToDeg, 1.0);  // measured 0.48
  EXPECT_LT(worst * kRadToDeg, 4.0);                 // measured 2.3
}

TEST(taohu, GatingCountsInjectedOutliers) {
  const Recording clean = simulateWebcam(30.0, 1);
  const Recording dirty = simulateWebcam(30.0, 1, Side::Right, 0.05);
  // The simulator draws the same noise either way, so the changed pixels are the outliers.
  ASSERT_EQ(clean.samples.size(), dirty.samples.size());
  std::size_t injected = 0;
  for (std::size_t i = 0; i < clean.samples.size(); ++i) {
    const ArmSample &a = clean.samples[i], &b = dirty.samples[i];
    if (a.camWrist && b.camWrist && (*a.camWrist - *b.camWrist).norm() > 1e-9) ++injected;
    if (a.camElbow && b.camElbow && (*a.camElbow - *b.camElbow).norm() > 1e-9) ++injected;
  }
  const TaoHuResult r = runTaoHu(dirty, taoHuParams(dirty.meta));
  const TaoHuErrors e = errorsOf(dirty, r);
  const TaoHuErrors ec = errorsOf(clean, runTaoHu(clean, taoHuParams(clean.meta)));
  const std::size_t gated = r.counters.wristGated + r.counters.elbowGated;
  report("injected outliers", injected);
  report("gated", gated);
  reportErrors("5 % outliers", e);
  ASSERT_GT(injected, 50u);
  // A uniform outlier can land within a few pixels of the truth and pass; almost none do.
  EXPECT_GE(gated, injected * 9 / 10);
  EXPECT_LE(gated, injected + 3);
  EXPECT_EQ(r.counters.restarts, 0u);
  EXPECT_LT(e.wristRmseCm, ec.wristRmseCm * 1.3 + 0.1);
  EXPECT_LT(e.wristPeakCm, 5.0);
}

TEST(taohu, BadInputIsCountedAndSkipped) {
  Recording rec = simulateWebcam(20.0, 1);
  const TaoHuErrors clean = errorsOf(rec, runTaoHu(rec, taoHuParams(rec.meta)));
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::vector<ArmSample> samples;
  std::size_t nonFinite = 0, backwards = 0;
  for (std::size_t i = 0; i < rec.samples.size(); ++i) {
    samples.push_back(rec.samples[i]);
    if (i % 997 == 500) {  // a NaN accelerometer reading
      ArmSample bad = rec.samples[i];
      bad.forearm = ImuReading{};
      bad.forearm->acc.x() = kNaN;
      samples.push_back(bad);
      ++nonFinite;
    }
    if (i % 1499 == 700) {  // a NaN pixel and a row from the past
      ArmSample bad;
      bad.t = rec.samples[i].t;
      bad.camWrist = Eigen::Vector2d(kNaN, 100.0);
      samples.push_back(bad);
      ++nonFinite;
      ArmSample old = rec.samples[i - 200];
      samples.push_back(old);
      ++backwards;
    }
  }
  ArmSample infTime = rec.samples[10];
  infTime.t = std::numeric_limits<double>::infinity();
  samples.insert(samples.begin() + 20, infTime);
  ++nonFinite;
  rec.samples = samples;
  const TaoHuResult r = runTaoHu(rec, taoHuParams(rec.meta));
  EXPECT_EQ(r.counters.rejectedNonFinite, nonFinite);
  EXPECT_EQ(r.counters.rejectedTime, backwards);
  EXPECT_EQ(r.counters.restarts, 0u);
  const TaoHuErrors e = errorsOf(rec, r);
  EXPECT_NEAR(e.wristRmseCm, clean.wristRmseCm, 0.05);
}

TEST(taohu, ImuGapRestartsAndRecovers) {
  Recording rec = simulateWebcam(20.0, 1);
  std::erase_if(rec.samples, [](const ArmSample& s) { return s.t > 10.0 && s.t < 11.0; });
  const TaoHuResult r = runTaoHu(rec, taoHuParams(rec.meta));
  EXPECT_EQ(r.counters.restarts, 1u);
  EXPECT_EQ(r.counters.initialisations, 2u);
  // After the restart (orientation warm-up 1 s, then the alignment) frames come again. A
  // re-alignment in the middle of motion can settle on the wrong depth branch (docs/tao-hu.md,
  // limitations), so the error is reported here, not bounded.
  double worstLate = 0;
  std::size_t late = 0;
  for (const TaoHuFrame& f : r.frames) {
    if (f.t < 13.0 || !f.trueAngles) continue;
    ++late;
    const ArmPose pose = forwardKinematics(rec.meta.geometry, *f.trueAngles);
    worstLate = std::max(worstLate, (f.wrist - pose.wrist).norm());
  }
  report("worst wrist error from 13 s (cm)", 100 * worstLate);
  EXPECT_GT(late, 200u);
  EXPECT_EQ(r.counters.rejectedTime + r.counters.rejectedNonFinite, 0u);
}

TEST(taohu, RejectsRecordingsWithoutCameraOrForearm) {
  SimulationParams sim = defaultSimulation();
  sim.duration = 2.0;
  const Recording noCamera = simulateRecording(MultiJointTrajectory(1), sim);
  EXPECT_THROW(taoHuParams(noCamera.meta), std::invalid_argument);
  Recording withCamera = simulateWebcam(2.0);
  const TaoHuParams p = taoHuParams(withCamera.meta);
  EXPECT_THROW(runTaoHu(noCamera, p), std::invalid_argument);
  for (ArmSample& s : withCamera.samples) s.forearm.reset();
  EXPECT_THROW(runTaoHu(withCamera, p), std::invalid_argument);
}

// A left arm is tracked as its mirrored right twin; the camera sees the real (left) arm.
TEST(taohu, LeftArmAsWellAsRight) {
  const Recording left = simulateWebcam(30.0, 5, Side::Left);
  const Recording right = simulateWebcam(30.0, 5, Side::Right);
  const TaoHuErrors el = errorsOf(left, runTaoHu(left, taoHuParams(left.meta)));
  const TaoHuErrors er = errorsOf(right, runTaoHu(right, taoHuParams(right.meta)));
  reportErrors("left", el);
  reportErrors("right", er);
  EXPECT_LT(el.wristRmseCm, 1.5);                                      // measured 0.96 (right 1.04)
  EXPECT_LT(el.wristPeakCm, 7.0);                                      // measured 5.1 (right 4.1)
  for (int j = 0; j < kNumJoints; ++j) EXPECT_LT(el.rmseDeg(j), 4.5);  // measured <= 3.3
  // Declaring the wrong side still tracks the points (the whole chain is mirrored consistently)
  // but reads abduction with the wrong sign.
  Recording wrong = left;
  wrong.meta.side = Side::Right;
  const TaoHuErrors ew = errorsOf(left, runTaoHu(wrong, taoHuParams(wrong.meta)));
  report("left declared right: th1 RMSE (deg)", ew.rmseDeg(1));
  EXPECT_GT(ew.rmseDeg(1), 10.0);
}

// The paper fuses the wrist marker only; without the elbow pixel the depth along the camera axis
// is left to the sphere and the double-integrated acceleration, and the track is far worse.
TEST(taohu, WristOnlyMeasurementIsReportedNotRelied) {
  const Recording rec = simulateWebcam(60.0);
  TaoHuParams p = taoHuParams(rec.meta);
  p.useElbowPixels = false;
  const TaoHuResult r = runTaoHu(rec, p);
  reportErrors("wrist marker only", errorsOf(rec, r));
  EXPECT_EQ(r.counters.elbowUpdates, 0u);
  EXPECT_GT(r.counters.wristUpdates, 1700u);
}

}  // namespace
}  // namespace armtrack
