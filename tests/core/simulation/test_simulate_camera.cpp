// The simulated webcam: marker pixels are the camera's projection of the true markers plus the
// stated noise, at the camera's own rate; markers outside the image are absent.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/camera/PinholeCamera.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

SimulationParams webcamOnly(double duration) {
  SimulationParams sp = defaultSimulation();
  sp.duration = duration;
  sp.webcam.enabled = true;
  return sp;
}

// Pixel residuals against the projection of the true markers (forward kinematics of the true
// angles, held by the IMU row at the same instant).
TEST(SimulatedWebcam, PixelsAreProjectionsOfTheTrueMarkersPlusNoise) {
  for (const Side side : {Side::Right, Side::Left}) {
    SimulationParams sp = webcamOnly(20.0);
    sp.side = side;
    const MultiJointTrajectory traj(3);
    const Recording rec = simulateRecording(traj, sp);
    ASSERT_TRUE(rec.meta.camera.has_value());
    const PinholeCamera camera(*rec.meta.camera);
    double sum = 0, sumSq = 0;
    int n = 0, frames = 0;
    for (const ArmSample& s : rec.samples) {
      if (!s.camWrist && !s.camElbow) continue;
      ++frames;
      const JointMotion m = traj.at(s.t);
      const ArmPose pose = forwardKinematics(sp.geometry, m.th);
      auto check = [&](const std::optional<Eigen::Vector2d>& px, Eigen::Vector3d p) {
        if (!px) return;
        if (side == Side::Left) p = mirrorPoint(p);  // the left arm in its own shoulder frame
        Eigen::Vector2d expected;
        ASSERT_TRUE(camera.project(p, expected));
        const Eigen::Vector2d d = *px - expected;
        sum += d.sum();
        sumSq += d.squaredNorm();
        n += 2;
      };
      check(s.camWrist, pose.wrist);
      check(s.camElbow, pose.elbow);
    }
    EXPECT_EQ(frames, 20 * 30 + 1);  // 30 Hz from t = 0 to t = 20 s inclusive
    const double mean = sum / n, std = std::sqrt(sumSq / n - mean * mean);
    EXPECT_NEAR(std, 1.0, 0.05);  // the default 1 px
    EXPECT_NEAR(mean, 0.0, 0.05);
  }
}

TEST(SimulatedWebcam, MarkersOutsideTheImageAreAbsent) {
  SimulationParams sp = webcamOnly(10.0);
  sp.webcam.camera = frontCamera(0.6);  // so close that the arm leaves the 640x480 image
  sp.webcam.noiseStdPx = 0.0;
  const Recording rec = simulateRecording(MultiJointTrajectory(4), sp);
  int present = 0, absent = 0;
  for (const ArmSample& s : rec.samples) {
    if (std::abs(std::round(s.t * 30) - s.t * 30) > 1e-6) continue;  // camera instants only
    for (const auto& px : {s.camWrist, s.camElbow}) {
      if (!px) {
        ++absent;
        continue;
      }
      ++present;
      EXPECT_GE(px->x(), 0.0);
      EXPECT_LE(px->x(), sp.webcam.width);
      EXPECT_GE(px->y(), 0.0);
      EXPECT_LE(px->y(), sp.webcam.height);
    }
  }
  EXPECT_GT(present, 50);
  EXPECT_GT(absent, 50);
}

TEST(SimulatedWebcam, OffByDefaultAndDoesNotChangeOtherSensorsNoise) {
  const MultiJointTrajectory traj(5);
  SimulationParams sp = defaultSimulation();
  sp.duration = 2.0;
  const Recording without = simulateRecording(traj, sp);
  EXPECT_FALSE(without.meta.camera.has_value());
  for (const ArmSample& s : without.samples) ASSERT_FALSE(s.camWrist || s.camElbow);
  sp.webcam.enabled = true;
  const Recording with = simulateRecording(traj, sp);
  // Every IMU and Kinect reading is the same with the webcam on.
  std::size_t j = 0;
  for (const ArmSample& s : with.samples) {
    if (!s.hasImu() && !s.elbow) continue;
    ASSERT_LT(j, without.samples.size());
    const ArmSample& r = without.samples[j++];
    ASSERT_EQ(s.t, r.t);
    if (s.upperArm) {
      EXPECT_EQ(s.upperArm->gyr, r.upperArm->gyr);
    }
    if (s.elbow) {
      EXPECT_EQ(*s.elbow, *r.elbow);
    }
  }
  EXPECT_EQ(j, without.samples.size());
}

TEST(SimulatedWebcam, RejectsBadParameters) {
  const MultiJointTrajectory traj(5);
  SimulationParams sp = webcamOnly(1.0);
  sp.webcam.rateHz = 0.0;
  EXPECT_THROW(simulateRecording(traj, sp), std::invalid_argument);
  sp = webcamOnly(1.0);
  sp.webcam.outlierProbability = 1.5;
  EXPECT_THROW(simulateRecording(traj, sp), std::invalid_argument);
  sp = webcamOnly(1.0);
  sp.webcam.camera.fx = 0.0;
  EXPECT_THROW(simulateRecording(traj, sp), std::invalid_argument);
  sp = webcamOnly(1.0);
  sp.webcam.width = 0;
  EXPECT_THROW(simulateRecording(traj, sp), std::invalid_argument);
}

}  // namespace
}  // namespace armtrack
