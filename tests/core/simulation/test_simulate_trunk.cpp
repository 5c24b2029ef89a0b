// The simulator's moving trunk and sternum IMU against independent truth: every IMU reading is
// the finite difference of the sensor's world pose (the DH forward kinematics carried by the
// trunk's rotation about the hip), the optical points are the still-trunk points carried the same
// way, and the trunk's angles are what the patient's words say.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/camera/PinholeCamera.h"
#include "core/kinematics/ArmModel.h"
#include "core/kinematics/Trunk.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/simulation/TrunkMotion.h"

namespace armtrack {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
const Eigen::Matrix3d kS = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();  // the mirror S = D

struct Pose {
  Eigen::Matrix3d r;  // columns: the sensor's axes in the world
  Eigen::Vector3d p;  // position in the world (m)
};

Eigen::Vector3d vee(const Eigen::Matrix3d& m) {
  return {0.5 * (m(2, 1) - m(1, 2)), 0.5 * (m(0, 2) - m(2, 0)), 0.5 * (m(1, 0) - m(0, 1))};
}

// A trunk that leans well within the motion of MultiJointTrajectory (th0 between 0 and 80 deg).
SimulationParams movingTrunk(Side side) {
  SimulationParams p;  // no noise, no bias
  p.side = side;
  p.up = Eigen::Vector3d(-1.0, 0.0, 0.0);
  p.duration = 4.0;
  p.upperArm.rateHz = p.forearm.rateHz = 100.0;
  p.kinect.noiseStd = 0.0;
  p.kinect.rateHz = 25.0;
  p.trunk.enabled = true;
  p.trunk.leanDeg = 18.0;
  p.trunk.reachStartDeg = 10.0;
  p.trunk.fullReachDeg = 70.0;
  p.trunk.lateralSign = -1.0;
  p.trunk.swayDeg = 1.5;
  p.trunk.swaySeed = 7;
  p.trunkImu.enabled = true;
  p.trunkImu.rateHz = 50.0;
  return p;
}

// The world poses of every sensor at time t, built from the definitions alone: the arm's DH
// forward kinematics in frame 0 (mirrored for a left arm, F -> S F D, p -> S p), the trunk's
// rotation R about the hip h (a left arm's frame 0 has the same axes as a right arm's, so the
// patient's words give the same world rotation, the mirror of trunkRotation(a, Left)), and
// world = h + R (p - h).
struct WorldPoses {
  Pose upper, forearm, sternum;
  Eigen::Vector3d elbow, wrist, shoulder;
};

WorldPoses worldPoses(const Trajectory& traj, const SimulationParams& params, double t) {
  const JointMotion m = traj.at(t);
  const TrunkAngles a = TrunkMotion(params.trunk).at(t, traj).angles;
  const bool left = params.side == Side::Left;
  const Eigen::Matrix3d r = left ? Eigen::Matrix3d(kS * trunkRotation(a, Side::Left) * kS)
                                 : trunkRotation(a, Side::Right);
  const Eigen::Vector3d h = params.trunk.hip.value_or(defaultHip(params.side));
  const auto place = [&](const Eigen::Matrix4d& f) {
    Eigen::Matrix3d rf = f.topLeftCorner<3, 3>();
    Eigen::Vector3d pf = f.topRightCorner<3, 1>();
    if (left) {
      rf = kS * rf * kS;
      pf = kS * pf;
    }
    return Pose{r * rf, h + r * (pf - h)};
  };
  const ArmPose arm = forwardKinematics(params.geometry, m.th);
  WorldPoses w;
  w.upper = place(arm.upperImu);
  w.forearm = place(arm.forearmImu);
  const Eigen::Vector3d elbow = left ? Eigen::Vector3d(kS * arm.elbow) : arm.elbow;
  const Eigen::Vector3d wrist = left ? Eigen::Vector3d(kS * arm.wrist) : arm.wrist;
  w.elbow = h + r * (elbow - h);
  w.wrist = h + r * (wrist - h);
  w.shoulder = h - r * h;
  const TrunkMount mount = params.trunkMount.value_or(defaultSimulatedTrunkMount(params.side));
  w.sternum = {r * mount.imuRotation, h + r * (mount.imuPosition - h)};
  return w;
}

// What an ideal IMU moving along pose(t) reads: the body angular velocity and the specific force
// in its own axes, by central differences (step dt).
template <typename F>
ImuReading differentiate(const F& pose, double t, double g, const Eigen::Vector3d& up) {
  const double dt = 2e-4;
  const Pose m = pose(t - dt), c = pose(t), p = pose(t + dt);
  ImuReading r;
  r.gyr = vee(c.r.transpose() * (p.r - m.r) / (2.0 * dt));
  const Eigen::Vector3d acc = (p.p - 2.0 * c.p + m.p) / (dt * dt);
  r.acc = c.r.transpose() * (acc + g * up);
  return r;
}

void expectReading(const ImuReading& got, const ImuReading& want, const std::string& what) {
  EXPECT_LT((got.gyr - want.gyr).norm(), 1e-5)
      << what << " gyro " << got.gyr.transpose() << " vs " << want.gyr.transpose();
  EXPECT_LT((got.acc - want.acc).norm(), 2e-4)
      << what << " acc " << got.acc.transpose() << " vs " << want.acc.transpose();
}

TEST(SimulateTrunk, EveryImuReadingIsTheDerivativeOfTheWorldPoses) {
  for (Side side : {Side::Right, Side::Left}) {
    SCOPED_TRACE(sideName(side));
    const MultiJointTrajectory traj(3);
    const SimulationParams params = movingTrunk(side);
    const Recording rec = simulateRecording(traj, params);
    int upper = 0, forearm = 0, sternum = 0;
    double largestRate = 0.0;
    for (const ArmSample& s : rec.samples) {
      if (s.t < 0.01) continue;  // central differences need t - dt >= 0
      const auto at = [&](double t) { return worldPoses(traj, params, t); };
      const std::string when = "t=" + std::to_string(s.t);
      if (s.upperArm) {
        expectReading(
            *s.upperArm,
            differentiate([&](double t) { return at(t).upper; }, s.t, params.g, params.up),
            "upper arm " + when);
        ++upper;
      }
      if (s.forearm) {
        expectReading(
            *s.forearm,
            differentiate([&](double t) { return at(t).forearm; }, s.t, params.g, params.up),
            "forearm " + when);
        ++forearm;
      }
      if (s.trunk) {
        const ImuReading want =
            differentiate([&](double t) { return at(t).sternum; }, s.t, params.g, params.up);
        expectReading(*s.trunk, want, "sternum " + when);
        largestRate = std::max(largestRate, want.gyr.norm());
        ++sternum;
      }
    }
    EXPECT_EQ(upper, 400);
    EXPECT_EQ(forearm, 400);
    EXPECT_EQ(sternum, 200);
    // The trunk really moved: its rate is not lost in the tolerance.
    EXPECT_GT(largestRate, 0.05);
  }
}

TEST(SimulateTrunk, OpticalPointsAreTheStillTrunksPointsCarriedIntoTheWorld) {
  for (Side side : {Side::Right, Side::Left}) {
    SCOPED_TRACE(sideName(side));
    const MultiJointTrajectory traj(5);
    SimulationParams params = movingTrunk(side);
    params.webcam.enabled = true;
    params.webcam.noiseStdPx = 0.0;
    params.webcam.camera = frontCamera(2.0);
    params.webcam.rateHz = 25.0;
    SimulationParams still = params;
    still.trunk.enabled = false;
    still.trunkImu.enabled = false;
    const Recording moving = simulateRecording(traj, params);
    const Recording upright = simulateRecording(traj, still);
    ASSERT_EQ(moving.samples.size(), upright.samples.size());
    const PinholeCamera camera(params.webcam.camera);
    const Eigen::Vector3d h = defaultHip(side);
    int rows = 0, pixels = 0;
    double largestShift = 0.0;
    for (std::size_t i = 0; i < moving.samples.size(); ++i) {
      const ArmSample& m = moving.samples[i];
      const ArmSample& u = upright.samples[i];
      ASSERT_EQ(m.t, u.t);
      ASSERT_EQ(m.elbow.has_value(), u.elbow.has_value());
      EXPECT_FALSE(u.shoulder.has_value());  // a still trunk's Kinect reports no shoulder
      if (!m.elbow) continue;
      ASSERT_TRUE(m.shoulder.has_value());  // a moving trunk's does
      const WorldPoses w = worldPoses(traj, params, m.t);
      const TrunkAngles a = TrunkMotion(params.trunk).at(m.t, traj).angles;
      const Eigen::Matrix3d r = side == Side::Left
                                    ? Eigen::Matrix3d(kS * trunkRotation(a, Side::Left) * kS)
                                    : trunkRotation(a);
      EXPECT_LT((*m.elbow - (h + r * (*u.elbow - h))).norm(), 1e-12);
      EXPECT_LT((*m.wrist - (h + r * (*u.wrist - h))).norm(), 1e-12);
      EXPECT_LT((*m.elbow - w.elbow).norm(), 1e-12);
      EXPECT_LT((*m.wrist - w.wrist).norm(), 1e-12);
      EXPECT_LT((*m.shoulder - w.shoulder).norm(), 1e-12);
      largestShift = std::max(largestShift, m.shoulder->norm());
      // The camera stays put in the world and sees the world points.
      Eigen::Vector2d px;
      if (m.camWrist) {
        ASSERT_TRUE(camera.project(w.wrist, px));
        EXPECT_LT((*m.camWrist - px).norm(), 1e-9);
        ++pixels;
      }
      if (m.camElbow) {
        ASSERT_TRUE(camera.project(w.elbow, px));
        EXPECT_LT((*m.camElbow - px).norm(), 1e-9);
        ++pixels;
      }
      ++rows;
    }
    EXPECT_EQ(rows, 101);
    EXPECT_GT(pixels, 150);
    EXPECT_GT(largestShift, 0.05);  // the shoulder moved several centimetres
  }
}

TEST(SimulateTrunk, LeaningAndTurningFollowThePatientsWords) {
  // Each angle on its own, held: the optical shoulder moves where the words say, for both arms
  // (z0 points to the patient's right in both frames).
  for (Side side : {Side::Right, Side::Left}) {
    SCOPED_TRACE(sideName(side));
    SinusoidTrajectory reach;  // the arm held at the fullest reach
    reach.offset << 100 * kDeg, 0, 0, -20 * kDeg, 0;
    const auto shoulderAt = [&](double lateralRatio, double rotationRatio, double lean) {
      SimulationParams p = movingTrunk(side);
      p.duration = 0.0;
      p.trunk.swayDeg = 0.0;
      p.trunk.startSeconds = 0.0;  // leaning from the first instant
      p.trunk.leanDeg = lean;
      p.trunk.lateralSign = p.trunk.rotationSign = 1.0;
      p.trunk.lateralRatio = lateralRatio;
      p.trunk.rotationRatio = rotationRatio;
      const Recording rec = simulateRecording(reach, p);
      EXPECT_TRUE(rec.samples.front().trueTrunk.has_value());
      EXPECT_NEAR(rec.samples.front().trueTrunk->x(), lean * kDeg, 1e-12);
      return *rec.samples.front().shoulder;
    };
    const Eigen::Vector3d forward = shoulderAt(0.0, 0.0, 10.0);
    EXPECT_GT(forward.y(), 0.07);  // 0.45 m above the hip, 10 deg forward: ~7.8 cm
    EXPECT_NEAR(forward.z(), 0.0, 1e-12);
    // Lateral bending comes with the lean; compared with the lean alone, bending to the right
    // moves the shoulder to the patient's right.
    const Eigen::Vector3d bent = shoulderAt(1.0, 0.0, 10.0);
    EXPECT_GT(bent.z() - forward.z(), 0.05);
    // Axial rotation brings the right shoulder forward: a right shoulder (to the right of the
    // hip) comes forward, a left one (to the left of the hip) goes back.
    const Eigen::Vector3d turned = shoulderAt(0.0, 1.0, 10.0);
    if (side == Side::Right)
      EXPECT_GT(turned.y() - forward.y(), 0.01);
    else
      EXPECT_LT(turned.y() - forward.y(), -0.01);
  }
}

TEST(SimulateTrunk, AnglesAreSmoothAndStayInRangeFollowingTheReaches) {
  TrunkSimParams p;
  p.enabled = true;
  p.leanDeg = 19.0;  // plus at most 1 deg of sway: the acceptance's 20 deg
  p.swayDeg = 1.0;
  const TrunkMotion trunk(p);
  const ReachingTrajectory traj(11, 200 * kDeg, 1500 * kDeg, 60.0);
  Eigen::Vector3d largest = Eigen::Vector3d::Zero();
  int atFullReach = 0;
  // Whether shoulder flexion stayed at or above x (resp. at or below) over [t - window, t].
  const auto heldAbove = [&](double t, double x, double window, bool above) {
    for (double u = std::max(0.0, t - window); u <= t + 1e-12; u += 0.005) {
      const double th0 = traj.at(u).th(0);
      if (above ? th0 < x : th0 > x) return false;
    }
    return true;
  };
  double fastestDegS = 0.0;
  for (double t = 0.0; t < 60.0; t += 0.005) {
    const TrunkMotionState s = trunk.at(t, traj);
    largest = largest.cwiseMax(s.angles.cwiseAbs());
    if (t > p.startSeconds) fastestDegS = std::max(fastestDegS, s.rates.norm() / kDeg);
    // Once the arm has held its fullest reach for the trunk's following time the lean is
    // exactly the configured one; while the arm stays below the lean's start only the sway
    // moves the trunk.
    if (t >= p.startSeconds + p.followSeconds &&
        heldAbove(t, p.fullReachDeg * kDeg, p.followSeconds, true)) {
      EXPECT_NEAR(s.angles(0), 19.0 * kDeg, 1e-12);
      EXPECT_NEAR(s.angles(1), 9.5 * kDeg, 1e-12);
      EXPECT_NEAR(s.angles(2), 9.5 * kDeg, 1e-12);
      ++atFullReach;
    }
    if (heldAbove(t, p.reachStartDeg * kDeg, p.followSeconds, false)) {
      EXPECT_LE(s.angles.cwiseAbs().maxCoeff(), 1.0 * kDeg);
    }
  }
  EXPECT_GT(atFullReach, 100);
  // The arm reaches at up to 200 deg/s; the heavier trunk follows far more slowly (at the arm's
  // pace it turned at over 100 deg/s here).
  EXPECT_LT(fastestDegS, 60.0);
  EXPECT_GT(fastestDegS, 5.0);
  // An arm that starts at the fullest reach: the trunk is upright at t = 0 (where the world
  // frame is registered) and has leaned fully once the start and the following time are over.
  SinusoidTrajectory held;
  held.offset << 100 * kDeg, 0, 0, -20 * kDeg, 0;
  EXPECT_TRUE(trunk.at(0.0, held).angles.isZero(0.0));
  EXPECT_LT(trunk.at(0.2, held).angles(0), 1.0 * kDeg);
  EXPECT_NEAR(trunk.at(p.startSeconds + p.followSeconds, held).angles(0), 19.0 * kDeg, 1e-12);
  EXPECT_LE(largest(0), 20.0 * kDeg);
  EXPECT_LE(largest(1), 10.0 * kDeg);
  EXPECT_LE(largest(2), 10.0 * kDeg);
  EXPECT_GT(largest(0), 18.9 * kDeg);
  // C2: rates and accelerations are the derivatives of the angles (central differences, also
  // across the ends of the lean's ramp).
  for (double t = 0.003; t < 60.0; t += 0.0517) {
    const double dt = 1e-4;
    const auto angles = [&](double u) { return trunk.at(u, traj).angles; };
    const TrunkMotionState s = trunk.at(t, traj);
    const Eigen::Vector3d d1 = (angles(t + dt) - angles(t - dt)) / (2 * dt);
    const Eigen::Vector3d d2 = (angles(t + dt) - 2 * angles(t) + angles(t - dt)) / (dt * dt);
    EXPECT_LT((s.rates - d1).norm(), 1e-6) << t;
    EXPECT_LT((s.accels - d2).norm(), 1e-3 + 1e-4 * d2.norm()) << t;
  }
}

TEST(SimulateTrunk, StillTrunkSternumReadsGravityThroughItsMounting) {
  for (Side side : {Side::Right, Side::Left}) {
    SCOPED_TRACE(sideName(side));
    SinusoidTrajectory arm;
    arm.amplitude = JointVector::Constant(0.4);
    arm.frequency = JointVector::Constant(0.5);
    SimulationParams p;
    p.side = side;
    p.duration = 1.0;
    p.trunkImu.enabled = true;
    p.trunkImu.rateHz = 100.0;
    const Recording rec = simulateRecording(arm, p);
    ASSERT_TRUE(rec.meta.trunk.has_value());
    // The default mounting: x up, y to the patient's right, z forward; at rest the accelerometer
    // reads +g along its x axis, and the gyroscope nothing.
    EXPECT_TRUE(rec.meta.trunk->imuRotation.isApprox(defaultSimulatedTrunkMount(side).imuRotation));
    EXPECT_NEAR(rec.meta.trunk->imuPosition.z(), side == Side::Left ? 0.18 : -0.18, 1e-15);
    int rows = 0;
    for (const ArmSample& s : rec.samples) {
      if (!s.trunk) continue;
      EXPECT_LT((s.trunk->acc - Eigen::Vector3d(9.81, 0, 0)).norm(), 1e-12);
      EXPECT_LT(s.trunk->gyr.norm(), 1e-12);
      ASSERT_TRUE(s.trueTrunk.has_value());
      EXPECT_TRUE(s.trueTrunk->isZero(0.0));
      EXPECT_FALSE(s.shoulder.has_value());
      ++rows;
    }
    EXPECT_EQ(rows, 101);
    // The sensor turned 90 deg about its own z axis: its y axis now points down, so gravity's
    // reaction reads along -y.
    SimulationParams tilted = p;
    TrunkMount mount = defaultSimulatedTrunkMount(side);
    mount.imuRotation = mount.imuRotation *
                        Eigen::AngleAxisd(90 * kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    tilted.trunkMount = mount;
    const Recording t = simulateRecording(arm, tilted);
    for (const ArmSample& s : t.samples)
      if (s.trunk) {
        EXPECT_LT((s.trunk->acc - Eigen::Vector3d(0, -9.81, 0)).norm(), 1e-12);
      }
  }
}

// Every number of a recording, for exact comparison.
std::vector<double> flatten(const Recording& rec) {
  std::vector<double> v;
  const auto add = [&](const auto& opt) {
    v.push_back(opt.has_value() ? 1.0 : 0.0);
    if (opt) v.insert(v.end(), opt->data(), opt->data() + opt->size());
  };
  for (const ArmSample& s : rec.samples) {
    v.push_back(s.t);
    for (const auto* imu : {&s.upperArm, &s.forearm, &s.trunk}) {
      v.push_back(imu->has_value() ? 1.0 : 0.0);
      if (*imu) {
        v.insert(v.end(), (*imu)->gyr.data(), (*imu)->gyr.data() + 3);
        v.insert(v.end(), (*imu)->acc.data(), (*imu)->acc.data() + 3);
      }
    }
    add(s.elbow);
    add(s.wrist);
    add(s.shoulder);
    add(s.camWrist);
    add(s.camElbow);
    add(s.trueAngles);
    add(s.trueTrunk);
  }
  return v;
}

TEST(SimulateTrunk, TrunkOffLeavesEverythingAsItWas) {
  // With the trunk off, whatever its other settings, every number is the same as the plain
  // simulation's (bit for bit), for both sides and with every optical sensor on.
  for (Side side : {Side::Right, Side::Left}) {
    SCOPED_TRACE(sideName(side));
    const MultiJointTrajectory traj(2);
    SimulationParams plain = defaultSimulation();
    plain.side = side;
    plain.duration = 2.0;
    plain.webcam.enabled = true;
    SimulationParams off = plain;
    off.trunk.leanDeg = 20.0;
    off.trunk.swayDeg = 3.0;
    off.trunk.hip = Eigen::Vector3d(0.5, 0.1, -0.2);
    off.trunkMount = defaultSimulatedTrunkMount(side);
    const Recording a = simulateRecording(traj, plain);
    const Recording b = simulateRecording(traj, off);
    EXPECT_EQ(flatten(a), flatten(b));
    EXPECT_FALSE(b.meta.trunk.has_value());
    for (const ArmSample& s : b.samples) {
      EXPECT_FALSE(s.trunk || s.shoulder || s.trueTrunk);
    }
    // Switching the sternum IMU on adds its readings and truth, and changes nothing else.
    SimulationParams imu = plain;
    imu.trunkImu.enabled = true;
    Recording c = simulateRecording(traj, imu);
    for (ArmSample& s : c.samples) {
      EXPECT_EQ(s.trunk.has_value(), s.upperArm.has_value());  // 1 kHz, like the arm
      s.trunk.reset();
      s.trueTrunk.reset();
    }
    EXPECT_EQ(flatten(a), flatten(c));
  }
}

TEST(SimulateTrunk, RejectsBadTrunkSettings) {
  const MultiJointTrajectory traj(1);
  const auto bad = [&](auto change) {
    SimulationParams p = movingTrunk(Side::Right);
    change(p);
    EXPECT_THROW(simulateRecording(traj, p), std::invalid_argument);
  };
  bad([](SimulationParams& p) { p.trunk.leanDeg = std::nan(""); });
  bad([](SimulationParams& p) { p.trunk.swayDeg = -1.0; });
  bad([](SimulationParams& p) { p.trunk.lateralSign = 0.5; });
  bad([](SimulationParams& p) { p.trunk.fullReachDeg = p.trunk.reachStartDeg; });
  bad([](SimulationParams& p) { p.trunk.swayMinHz = 0.0; });
  bad([](SimulationParams& p) { p.trunk.startSeconds = -1.0; });
  bad([](SimulationParams& p) { p.trunk.hip = Eigen::Vector3d(INFINITY, 0, 0); });
  bad([](SimulationParams& p) { p.trunkImu.rateHz = 0.0; });
  bad([](SimulationParams& p) {
    TrunkMount m;
    m.imuRotation = 2.0 * Eigen::Matrix3d::Identity();
    p.trunkMount = m;
  });
}

TEST(SimulateTrunk, StreamEqualsRecordingAndSkipsTheSternumToo) {
  const MultiJointTrajectory traj(4);
  SimulationParams p = movingTrunk(Side::Left);
  p.trunkImu.gyroNoiseStd = 0.01;
  const Recording rec = simulateRecording(traj, p);
  SensorStream stream(traj, p);
  ASSERT_TRUE(stream.meta().trunk.has_value());
  std::vector<ArmSample> rows;
  while (auto s = stream.next()) rows.push_back(*s);
  Recording again;
  again.samples = rows;
  EXPECT_EQ(flatten(rec), flatten(again));
  SensorStream late(traj, p);
  late.skipTo(2.0);
  EXPECT_EQ(late.nextTime(), 2.0);
  const auto first = late.next();
  ASSERT_TRUE(first && first->trunk);
}

}  // namespace
}  // namespace armtrack
