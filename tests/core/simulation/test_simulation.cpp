// Tests of the trajectories and the sensor simulator against independent truth: finite
// differences, forward kinematics (DH products), closed-form rigid-body motion and sample
// statistics.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/kinematics/ArmModel.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// Central differences of th(t): first and second derivatives. Step h (s).
template <typename F>
void finiteDifferences(const F& th, double t, double h, JointVector& d1, JointVector& d2) {
  const JointVector p = th(t + h), m = th(t - h), c = th(t);
  d1 = (p - m) / (2.0 * h);
  d2 = (p - 2.0 * c + m) / (h * h);
}

// |a - b| <= abs + rel * |b|, element-wise, with a message naming the joint.
void expectClose(const JointVector& a, const JointVector& b, double abs, double rel,
                 const std::string& what) {
  for (int j = 0; j < kNumJoints; ++j)
    EXPECT_LE(std::abs(a(j) - b(j)), abs + rel * std::abs(b(j)))
        << what << " joint " << j << ": " << a(j) << " vs " << b(j);
}

// Checks at(t).thd and .thdd against finite differences of at(t).th at many instants.
// Tolerance 1e-6 absolute + 1e-6 relative (truncation ~h^2 f'''/6 ~ 1e-7 for these motions).
void checkDerivatives(const Trajectory& traj, double duration) {
  const auto th = [&](double t) { return traj.at(t).th; };
  for (double t = 0.013; t < duration; t += duration / 97.0) {
    JointVector d1, d2;
    finiteDifferences(th, t, 1e-4, d1, d2);
    const JointMotion m = traj.at(t);
    expectClose(m.thd, d1, 1e-6, 1e-6, "thd at t=" + std::to_string(t));
    expectClose(m.thdd, d2, 1e-6, 1e-6, "thdd at t=" + std::to_string(t));
  }
}

// A rigid spin of the whole arm about z0 at a constant rate (th0 = th0(0) + rate * t).
class ConstantRateTrajectory final : public Trajectory {
 public:
  ConstantRateTrajectory(const JointVector& start, double rate) : m_start(start), m_rate(rate) {}
  JointMotion at(double t) const override {
    JointMotion m;
    m.th = m_start;
    m.th(0) += m_rate * t;
    m.thd(0) = m_rate;
    return m;
  }

 private:
  JointVector m_start;
  double m_rate;
};

SinusoidTrajectory staticPose() {
  SinusoidTrajectory s;
  s.offset << 0.3, 0.2, 0.1, -0.5, 0.2;
  return s;  // zero amplitude: constant posture
}

SimulationParams noiseFree(double duration) {
  SimulationParams p;
  p.duration = duration;
  p.kinect.noiseStd = 0.0;
  return p;  // ImuSimParams default to zero noise and bias
}

// ---------------------------------------------------------------- trajectories

TEST(Trajectory, SinusoidValuesAndDerivatives) {
  SinusoidTrajectory s;
  s.offset << 0.1, 0.2, -0.1, -0.8, 0.0;
  s.amplitude << 1.5, 0.3, 0.4, 0.5, 0.6;
  s.frequency << 1.0, 0.3, 0.7, 2.0, 0.05;
  s.phase << 0.0, 1.0, -2.0, 0.5, 3.0;
  // Value: th0 = 0.1 + 1.5 sin(2 pi 0.25) = 1.6 at t = 0.25 s.
  EXPECT_NEAR(s.at(0.25).th(0), 1.6, 1e-15);
  checkDerivatives(s, 5.0);
}

TEST(Trajectory, MultiJointDerivatives) {
  for (std::uint64_t seed : {1u, 2u, 99u}) {
    SCOPED_TRACE(seed);
    checkDerivatives(MultiJointTrajectory(seed), 20.0);
  }
}

TEST(Trajectory, MultiJointAllJointsMoveWithinRanges) {
  const double centre[kNumJoints] = {40, 30, 0, -60, 0};         // deg
  const double maxAmplitude[kNumJoints] = {40, 25, 35, 45, 50};  // deg
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(seed);
    const MultiJointTrajectory traj(seed);
    JointVector lo = JointVector::Constant(1e9), hi = JointVector::Constant(-1e9);
    for (double t = 0.0; t <= 20.0; t += 0.01) {
      const JointVector th = traj.at(t).th / kDeg;
      lo = lo.cwiseMin(th);
      hi = hi.cwiseMax(th);
    }
    for (int j = 0; j < kNumJoints; ++j) {
      EXPECT_GT(hi(j) - lo(j), 10.0) << "joint " << j << " barely moves";
      EXPECT_GE(lo(j), centre[j] - maxAmplitude[j] - 1e-9) << "joint " << j;
      EXPECT_LE(hi(j), centre[j] + maxAmplitude[j] + 1e-9) << "joint " << j;
    }
    EXPECT_LE(hi(3), 0.0);  // never hyperextended
  }
}

TEST(Trajectory, MultiJointLargeScaleStaysAnatomical) {
  const MultiJointTrajectory traj(5, 0.8, 10.0);
  for (double t = 0.0; t <= 30.0; t += 0.01) {
    const JointVector th = traj.at(t).th;
    EXPECT_LT(std::abs(th(1)), 85 * kDeg);  // away from the gimbal singularity
    EXPECT_LE(th(3), 1e-12);
    EXPECT_GE(th(3), -145 * kDeg);
  }
}

TEST(Trajectory, MultiJointFrequencyBound) {
  // Every component is slower than maxFrequencyHz, so |thdd| <= (2 pi fmax)^2 * sum of amplitudes.
  const double fmax = 0.3;
  const MultiJointTrajectory traj(3, fmax);
  const double bound = std::pow(2 * kPi * fmax, 2) * 50 * kDeg;  // 50 deg: largest sum
  for (double t = 0.0; t <= 30.0; t += 0.01)
    EXPECT_LE(traj.at(t).thdd.cwiseAbs().maxCoeff(), bound + 1e-12);
}

TEST(Trajectory, MultiJointDeterministicPerSeed) {
  const MultiJointTrajectory a(42), b(42), c(43);
  bool differs = false;
  for (double t = 0.0; t < 10.0; t += 0.37) {
    const JointMotion ma = a.at(t), mb = b.at(t), mc = c.at(t);
    EXPECT_EQ(ma.th, mb.th);
    EXPECT_EQ(ma.thd, mb.thd);
    EXPECT_EQ(ma.thdd, mb.thdd);
    differs = differs || (ma.th - mc.th).norm() > 1e-3;
  }
  EXPECT_TRUE(differs);
}

TEST(Trajectory, MultiJointRejectsBadArguments) {
  EXPECT_THROW(MultiJointTrajectory(1, 0.05), std::invalid_argument);
  EXPECT_THROW(MultiJointTrajectory(1, 0.8, -1.0), std::invalid_argument);
}

TEST(Trajectory, PlanarArmConventionMatchesForwardKinematics) {
  // With th1 = th2 = th5 = 0: elbow = l3 (cos th0, sin th0, 0) and the forearm points at angle
  // th0 - th4 in the (x0, y0) plane. The wheel's inverse kinematics relies on this.
  const ArmGeometry geo;
  for (double th0 = -1.0; th0 <= 2.5; th0 += 0.35) {
    for (double th4 = -2.5; th4 <= 0.0; th4 += 0.3) {
      JointVector th;
      th << th0, 0, 0, th4, 0;
      const ArmPose pose = forwardKinematics(geo, th);
      const Eigen::Vector3d elbow(geo.l3 * std::cos(th0), geo.l3 * std::sin(th0), 0.0);
      const Eigen::Vector3d fore(std::cos(th0 - th4), std::sin(th0 - th4), 0.0);
      EXPECT_LT((pose.elbow - elbow).norm(), 1e-12);
      EXPECT_LT((pose.wrist - elbow - geo.l6 * fore).norm(), 1e-12);
    }
  }
}

TEST(Trajectory, WheelHandleOnCircle) {
  ArmGeometry geo;
  geo.l3 = 0.25;
  geo.l6 = 0.22;
  const double w = 0.25, h = 0.05, r = 0.15, s = 0.04;
  for (const ArmGeometry& g : {ArmGeometry{}, geo}) {
    const ShoulderWheelTrajectory wheel(g, 4.0, w, h, r, s);
    for (double phi = -7.0; phi <= 7.0; phi += 0.05) {
      const JointVector th = wheel.anglesAt(phi);
      EXPECT_EQ(th(1), 0.0);
      EXPECT_EQ(th(2), 0.0);
      EXPECT_EQ(th(4), 0.0);
      EXPECT_LE(th(3), 0.0);
      const ArmPose pose = forwardKinematics(g, th);
      const Eigen::Vector3d fore = (pose.wrist - pose.elbow).normalized();
      const Eigen::Vector3d hand = pose.wrist + s * fore;
      const Eigen::Vector3d expected(h + r * std::cos(phi), w + r * std::sin(phi), 0.0);
      EXPECT_LT((hand - expected).norm(), 1e-9) << "phi " << phi;
    }
  }
}

TEST(Trajectory, WheelTimeMapping) {
  const ArmGeometry geo;
  const ShoulderWheelTrajectory wheel(geo, 5.0);
  // phi = 2 pi t / period.
  EXPECT_EQ(wheel.at(1.25).th, wheel.anglesAt(kPi / 2));
  EXPECT_LT((wheel.at(5.0).th - wheel.at(0.0).th).norm(), 1e-12);
}

TEST(Trajectory, WheelDerivatives) {
  const ArmGeometry geo;
  for (double period : {4.0, 1.5}) {
    SCOPED_TRACE(period);
    const ShoulderWheelTrajectory wheel(geo, period);
    // Finite differences of the inverse kinematics itself, independent of at()'s Jacobian.
    const auto th = [&](double t) { return wheel.anglesAt(2 * kPi * t / period); };
    for (double t = 0.01; t < period; t += period / 53.0) {
      JointVector d1, d2;
      finiteDifferences(th, t, 1e-4, d1, d2);
      const JointMotion m = wheel.at(t);
      expectClose(m.thd, d1, 1e-6, 1e-6, "thd");
      expectClose(m.thdd, d2, 1e-5, 1e-5, "thdd");
    }
  }
}

TEST(Trajectory, WheelRejectsUnreachable) {
  const ArmGeometry geo;
  EXPECT_THROW(ShoulderWheelTrajectory(geo, 4.0, 0.45, 0.1, 0.15), std::invalid_argument);
  EXPECT_THROW(ShoulderWheelTrajectory(geo, 0.0), std::invalid_argument);
}

TEST(Trajectory, Factory) {
  const std::vector<std::string> names = trajectoryNames();
  ASSERT_EQ(names,
            (std::vector<std::string>{"sinusoid", "multi-joint", "shoulder-wheel", "calibration",
                                      "reaching", "session", "sensor-check", "exercise"}));
  TrajectoryOptions opts;
  for (const std::string& n : names) EXPECT_NE(makeTrajectory(n, opts), nullptr);

  opts.amplitude << 1.0, 0, 0, 0, 0;
  opts.frequency << 0.25, 0, 0, 0, 0;
  EXPECT_NEAR(makeTrajectory("sinusoid", opts)->at(1.0).th(0), 1.0, 1e-15);

  opts.seed = 7;
  EXPECT_EQ(makeTrajectory("multi-joint", opts)->at(3.0).th, MultiJointTrajectory(7).at(3.0).th);
  EXPECT_EQ(makeTrajectory("shoulder-wheel", opts)->at(1.0).th,
            ShoulderWheelTrajectory(ArmGeometry{}, 4.0).at(1.0).th);

  try {
    makeTrajectory("spiral", opts);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    for (const std::string& n : names) EXPECT_NE(msg.find(n), std::string::npos) << msg;
  }
}

// ---------------------------------------------------------------- simulator

TEST(Simulator, Table5AndDefaults) {
  EXPECT_NEAR(Table5::gyroStd(), 0.316227766016838 * kPi / 180.0, 1e-15);
  EXPECT_NEAR(Table5::accelStd(), 0.1, 1e-15);
  EXPECT_NEAR(Table5::posStd(), 0.01, 1e-15);
  const SimulationParams p = defaultSimulation();
  EXPECT_EQ(p.duration, 10.0);
  for (const ImuSimParams& imu : {p.upperArm, p.forearm}) {
    EXPECT_TRUE(imu.enabled);
    EXPECT_EQ(imu.rateHz, 1000.0);
    EXPECT_EQ(imu.gyroNoiseStd, Table5::gyroStd());
    EXPECT_EQ(imu.accelNoiseStd, Table5::accelStd());
  }
  EXPECT_TRUE(p.kinect.enabled);
  EXPECT_EQ(p.kinect.rateHz, 30.0);
  EXPECT_EQ(p.kinect.noiseStd, 0.01);
}

TEST(Simulator, StaticPoseReadsGravityOnly) {
  const SinusoidTrajectory pose = staticPose();
  SimulationParams p = noiseFree(0.1);
  p.g = 9.81;
  p.kinect.enabled = false;
  const Recording rec = simulateRecording(pose, p);
  EXPECT_EQ(rec.meta.g, 9.81);
  EXPECT_EQ(rec.meta.up, p.up);
  EXPECT_EQ(rec.meta.geometry.l3, p.geometry.l3);
  // Gravity reaction expressed in each IMU frame from the DH product (not the recursion).
  const ArmPose fk = forwardKinematics(p.geometry, pose.offset);
  const Eigen::Vector3d upperAcc = fk.upperImu.topLeftCorner<3, 3>().transpose() * (9.81 * p.up);
  const Eigen::Vector3d foreAcc = fk.forearmImu.topLeftCorner<3, 3>().transpose() * (9.81 * p.up);
  ASSERT_EQ(rec.samples.size(), 101u);
  for (const ArmSample& s : rec.samples) {
    ASSERT_TRUE(s.upperArm && s.forearm);
    EXPECT_NEAR(s.upperArm->acc.norm(), 9.81, 1e-12);
    EXPECT_NEAR(s.forearm->acc.norm(), 9.81, 1e-12);
    EXPECT_LT(s.upperArm->gyr.norm(), 1e-15);
    EXPECT_LT(s.forearm->gyr.norm(), 1e-15);
    EXPECT_LT((s.upperArm->acc - upperAcc).norm(), 1e-12);
    EXPECT_LT((s.forearm->acc - foreAcc).norm(), 1e-12);
  }
}

TEST(Simulator, ConstantRateSpinMatchesModelAndRigidBodyMotion) {
  JointVector start;
  start << 0.2, 0.4, -0.3, -1.1, 0.5;
  const double rate = 2.0;  // rad/s about z0
  const ConstantRateTrajectory traj(start, rate);
  SimulationParams p = noiseFree(1.0);
  p.upperArm.rateHz = p.forearm.rateHz = 100.0;
  const Recording rec = simulateRecording(traj, p);
  const Eigen::Vector3d gUp = p.g * p.up, z0 = Eigen::Vector3d::UnitZ();
  for (const ArmSample& s : rec.samples) {
    if (!s.upperArm) continue;
    const JointMotion m = traj.at(s.t);
    // Exactly what the model predicts when noise is off.
    const ArmPrediction pred = predictSensors(p.geometry, m.th, m.thd, m.thdd, gUp);
    EXPECT_EQ(s.upperArm->gyr, pred.upper.gyr);
    EXPECT_EQ(s.upperArm->acc, pred.upper.acc);
    EXPECT_EQ(s.forearm->gyr, pred.forearm.gyr);
    EXPECT_EQ(s.forearm->acc, pred.forearm.acc);
    // Rigid rotation about z0: omega = rate z0, a = -rate^2 * (p minus its z0 component).
    const ArmPose fk = forwardKinematics(p.geometry, m.th);
    for (const auto& [reading, pose] :
         {std::pair{*s.upperArm, fk.upperImu}, std::pair{*s.forearm, fk.forearmImu}}) {
      const Eigen::Matrix3d r = pose.topLeftCorner<3, 3>();
      const Eigen::Vector3d pos = pose.topRightCorner<3, 1>();
      const Eigen::Vector3d accel = -rate * rate * (pos - pos.dot(z0) * z0);
      EXPECT_LT((reading.gyr - r.transpose() * (rate * z0)).norm(), 1e-12);
      EXPECT_LT((reading.acc - r.transpose() * (gUp + accel)).norm(), 1e-11);
    }
  }
}

TEST(Simulator, NoiseStatisticsAndBias) {
  const SinusoidTrajectory pose = staticPose();
  SimulationParams p = defaultSimulation();
  p.duration = 60.0;
  p.seed = 11;
  p.upperArm.gyroBias = Eigen::Vector3d(0.01, -0.02, 0.005);
  p.forearm.gyroNoiseStd = 0.02;
  p.forearm.accelNoiseStd = 0.3;
  const ArmPrediction ideal =
      predictSensors(p.geometry, pose.offset, JointVector::Zero(), JointVector::Zero(), p.g * p.up);

  // Per-axis sums of the errors (reading - ideal) and of their squares.
  struct Stats {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sumSq = Eigen::Vector3d::Zero();
    int n = 0;
    void add(const Eigen::Vector3d& e) {
      sum += e;
      sumSq += e.cwiseAbs2();
      ++n;
    }
    Eigen::Vector3d mean() const { return sum / n; }
    Eigen::Vector3d stdDev() const { return ((sumSq - sum.cwiseAbs2() / n) / (n - 1)).cwiseSqrt(); }
  };
  Stats ug, ua, fg, fa, pos;
  const Recording rec = simulateRecording(pose, p);
  for (const ArmSample& s : rec.samples) {
    if (s.upperArm) {
      ug.add(s.upperArm->gyr - ideal.upper.gyr);
      ua.add(s.upperArm->acc - ideal.upper.acc);
    }
    if (s.forearm) {
      fg.add(s.forearm->gyr - ideal.forearm.gyr);
      fa.add(s.forearm->acc - ideal.forearm.acc);
    }
    if (s.elbow) pos.add(*s.elbow - ideal.elbow);
    if (s.wrist) pos.add(*s.wrist - ideal.wrist);
  }
  ASSERT_EQ(ug.n, 60001);
  ASSERT_EQ(pos.n, 2 * 1801);
  const auto checkStd = [](const Stats& st, double expected, const char* what) {
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(st.stdDev()(i), expected, 0.05 * expected) << what << " axis " << i;
  };
  checkStd(ug, Table5::gyroStd(), "upper gyro");
  checkStd(ua, Table5::accelStd(), "upper accel");
  checkStd(fg, 0.02, "forearm gyro");
  checkStd(fa, 0.3, "forearm accel");
  checkStd(pos, 0.01, "kinect");
  // Means: the bias on the upper gyro, zero elsewhere (5 standard errors).
  const auto checkMean = [](const Stats& st, const Eigen::Vector3d& expected, double std,
                            const char* what) {
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(st.mean()(i), expected(i), 5 * std / std::sqrt(st.n)) << what << " axis " << i;
  };
  checkMean(ug, p.upperArm.gyroBias, Table5::gyroStd(), "upper gyro");
  checkMean(ua, Eigen::Vector3d::Zero(), Table5::accelStd(), "upper accel");
  checkMean(fg, Eigen::Vector3d::Zero(), 0.02, "forearm gyro");
  checkMean(pos, Eigen::Vector3d::Zero(), 0.01, "kinect");
}

TEST(Simulator, MisalignmentRotatesReadings) {
  const MultiJointTrajectory traj(3);
  SimulationParams ideal = noiseFree(2.0);
  SimulationParams rotated = ideal;
  const Eigen::Matrix3d mu = randomMisalignment(0.2, 7), mf = randomMisalignment(0.1, 8);
  rotated.upperArm.misalignment = mu;
  rotated.forearm.misalignment = mf;
  const Recording a = simulateRecording(traj, ideal), b = simulateRecording(traj, rotated);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    const ArmSample &sa = a.samples[i], &sb = b.samples[i];
    ASSERT_EQ(sa.t, sb.t);
    if (!sa.upperArm) continue;
    EXPECT_LT((sb.upperArm->gyr - mu.transpose() * sa.upperArm->gyr).norm(), 1e-12);
    EXPECT_LT((sb.upperArm->acc - mu.transpose() * sa.upperArm->acc).norm(), 1e-12);
    EXPECT_LT((sb.forearm->gyr - mf.transpose() * sa.forearm->gyr).norm(), 1e-12);
    EXPECT_LT((sb.forearm->acc - mf.transpose() * sa.forearm->acc).norm(), 1e-12);
  }
}

TEST(Simulator, RandomMisalignmentIsARotationByTheAngle) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const double angle = 0.01 + 0.1 * static_cast<double>(seed);
    const Eigen::Matrix3d m = randomMisalignment(angle, seed);
    EXPECT_LT((m.transpose() * m - Eigen::Matrix3d::Identity()).norm(), 1e-14);
    EXPECT_NEAR(m.determinant(), 1.0, 1e-14);
    // Rotation angle from the trace: cos(angle) = (tr - 1) / 2.
    EXPECT_NEAR(std::acos(std::clamp((m.trace() - 1.0) / 2.0, -1.0, 1.0)), angle, 1e-7);
    EXPECT_EQ(m, randomMisalignment(angle, seed));
  }
  const Eigen::Vector3d a1 = Eigen::AngleAxisd(randomMisalignment(0.3, 1)).axis();
  const Eigen::Vector3d a2 = Eigen::AngleAxisd(randomMisalignment(0.3, 2)).axis();
  EXPECT_GT((a1 - a2).norm(), 1e-3);
}

TEST(Simulator, KinectRowsAndMergedTimeline) {
  const MultiJointTrajectory traj(4);
  SimulationParams p = noiseFree(2.0);
  const Recording rec = simulateRecording(traj, p);
  // IMU times k/1000 (k = 0..2000) and Kinect times m/30 (m = 0..60) coincide when 1000 m / 30
  // is an integer.
  int coincident = 0;
  for (int m = 0; m <= 60; ++m) coincident += (1000 * m) % 30 == 0;
  ASSERT_EQ(rec.samples.size(), static_cast<std::size_t>(2001 + 61 - coincident));

  int kinectRows = 0, imuRows = 0;
  for (std::size_t i = 0; i < rec.samples.size(); ++i) {
    const ArmSample& s = rec.samples[i];
    if (i > 0) {
      EXPECT_LT(rec.samples[i - 1].t, s.t) << "row " << i;
    }
    EXPECT_EQ(s.upperArm.has_value(), s.forearm.has_value());  // shared IMU clock
    EXPECT_EQ(s.elbow.has_value(), s.wrist.has_value());
    EXPECT_EQ(s.trueAngles.has_value(), s.hasImu());
    EXPECT_FALSE(s.camWrist || s.camElbow);
    if (s.hasImu()) {
      ++imuRows;
      EXPECT_NEAR(s.t * 1000.0, std::round(s.t * 1000.0), 1e-6);
    }
    if (s.elbow) {
      EXPECT_NEAR(s.t * 30.0, std::round(s.t * 30.0), 1e-6);
      EXPECT_EQ(s.t, static_cast<double>(kinectRows) / 30.0);
      ++kinectRows;
      const ArmPose fk = forwardKinematics(p.geometry, traj.at(s.t).th);
      EXPECT_LT((*s.elbow - fk.elbow).norm(), 1e-12);
      EXPECT_LT((*s.wrist - fk.wrist).norm(), 1e-12);
    }
  }
  EXPECT_EQ(kinectRows, 61);
  EXPECT_EQ(imuRows, 2001);
  EXPECT_EQ(rec.samples.front().t, 0.0);
  EXPECT_EQ(rec.samples.back().t, 2.0);
}

TEST(Simulator, ImusAtDifferentRates) {
  const MultiJointTrajectory traj(4);
  SimulationParams p = noiseFree(1.0);
  p.kinect.enabled = false;
  p.upperArm.rateHz = 100.0;
  p.forearm.rateHz = 40.0;
  const Recording rec = simulateRecording(traj, p);
  // j/40 = k/100 when j is even: 21 shared instants.
  ASSERT_EQ(rec.samples.size(), 101u + 41u - 21u);
  int upper = 0, fore = 0;
  for (std::size_t i = 0; i < rec.samples.size(); ++i) {
    const ArmSample& s = rec.samples[i];
    if (i > 0) {
      EXPECT_LT(rec.samples[i - 1].t, s.t);
    }
    EXPECT_FALSE(s.elbow || s.wrist);
    EXPECT_TRUE(s.hasImu());
    if (s.upperArm) {
      EXPECT_EQ(s.t, static_cast<double>(upper) / 100.0);
      ++upper;
    }
    if (s.forearm) {
      EXPECT_EQ(s.t, static_cast<double>(fore) / 40.0);
      ++fore;
    }
  }
  EXPECT_EQ(upper, 101);
  EXPECT_EQ(fore, 41);

  p.forearm.enabled = false;
  p.includeTruth = false;
  const Recording only = simulateRecording(traj, p);
  ASSERT_EQ(only.samples.size(), 101u);
  for (const ArmSample& s : only.samples) EXPECT_FALSE(s.forearm || s.trueAngles);
}

TEST(Simulator, TruthIsWrapped) {
  SinusoidTrajectory s;
  s.offset << 3.5, 0.1, -4.0, -0.5, 7.0;
  const Recording rec = simulateRecording(s, noiseFree(0.01));
  ASSERT_FALSE(rec.samples.empty());
  const JointVector truth = *rec.samples.front().trueAngles;
  const JointVector expected =
      (JointVector() << 3.5 - 2 * kPi, 0.1, -4.0 + 2 * kPi, -0.5, 7.0 - 2 * kPi).finished();
  EXPECT_LT((truth - expected).norm(), 1e-12);
}

TEST(Simulator, DeterministicGivenSeed) {
  const MultiJointTrajectory traj(9);
  SimulationParams p = defaultSimulation();
  p.duration = 1.0;
  const Recording a = simulateRecording(traj, p), b = simulateRecording(traj, p);
  p.seed = 2;
  const Recording c = simulateRecording(traj, p);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  ASSERT_EQ(a.samples.size(), c.samples.size());
  int differ = 0;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    const ArmSample &sa = a.samples[i], &sb = b.samples[i], &sc = c.samples[i];
    EXPECT_EQ(sa.t, sb.t);
    if (sa.upperArm) {
      EXPECT_EQ(sa.upperArm->gyr, sb.upperArm->gyr);
      EXPECT_EQ(sa.upperArm->acc, sb.upperArm->acc);
      EXPECT_EQ(sa.forearm->gyr, sb.forearm->gyr);
      EXPECT_EQ(sa.forearm->acc, sb.forearm->acc);
      differ += sa.upperArm->gyr != sc.upperArm->gyr;
    }
    if (sa.elbow) {
      EXPECT_EQ(*sa.elbow, *sb.elbow);
      EXPECT_EQ(*sa.wrist, *sb.wrist);
    }
  }
  EXPECT_GT(differ, 900);
}

TEST(Simulator, KinectDoesNotChangeImuNoise) {
  const MultiJointTrajectory traj(9);
  SimulationParams p = defaultSimulation();
  p.duration = 0.5;
  const Recording with = simulateRecording(traj, p);
  p.kinect.enabled = false;
  const Recording without = simulateRecording(traj, p);
  std::size_t j = 0;
  for (const ArmSample& s : with.samples) {
    if (!s.upperArm) continue;
    ASSERT_LT(j, without.samples.size());
    EXPECT_EQ(s.upperArm->gyr, without.samples[j].upperArm->gyr);
    EXPECT_EQ(s.forearm->acc, without.samples[j].forearm->acc);
    ++j;
  }
  EXPECT_EQ(j, without.samples.size());
}

TEST(Simulator, RejectsBadParameters) {
  const SinusoidTrajectory pose = staticPose();
  SimulationParams p = noiseFree(1.0);
  p.upperArm.rateHz = 0.0;
  EXPECT_THROW(simulateRecording(pose, p), std::invalid_argument);
  p = noiseFree(-1.0);
  EXPECT_THROW(simulateRecording(pose, p), std::invalid_argument);
  p = noiseFree(1.0);
  p.forearm.accelNoiseStd = -0.1;
  EXPECT_THROW(simulateRecording(pose, p), std::invalid_argument);
  p = noiseFree(1.0);
  p.up = Eigen::Vector3d(-2.0, 0.0, 0.0);
  EXPECT_THROW(simulateRecording(pose, p), std::invalid_argument);
  p = noiseFree(1.0);
  p.upperArm.misalignment = 2.0 * Eigen::Matrix3d::Identity();
  EXPECT_THROW(simulateRecording(pose, p), std::invalid_argument);
}

TEST(Simulator, TenMinutesAtOneKilohertz) {
  const MultiJointTrajectory traj(1);
  SimulationParams p = defaultSimulation();
  p.duration = 600.0;
  const auto start = std::chrono::steady_clock::now();
  const Recording rec = simulateRecording(traj, p);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("600 s at 1 kHz: %zu rows in %.3f s\n", rec.samples.size(), seconds);
  EXPECT_EQ(rec.samples.size(), 600001u + 18001u - 6001u);
#ifdef NDEBUG
  EXPECT_LT(seconds, 5.0);  // generous: the machine may be shared
#endif
}

TEST(SensorStream, EndlessStreamStartsLikeAFiniteRecording) {
  // A live source runs without an end: its rows must be those of a finite recording with the same
  // seed, sensors and rates (all four sensors, rates that do not divide each other).
  const MultiJointTrajectory traj(3);
  SimulationParams p = defaultSimulation();
  p.duration = 2.0;
  p.forearm.rateHz = 400.0;
  p.webcam.enabled = true;
  const Recording rec = simulateRecording(traj, p);
  p.duration = std::numeric_limits<double>::infinity();
  SensorStream stream(traj, p);
  for (const ArmSample& want : rec.samples) {
    ASSERT_EQ(stream.nextTime(), want.t);
    const std::optional<ArmSample> got = stream.next();
    ASSERT_TRUE(got.has_value());
    EXPECT_EQ(got->t, want.t);
    ASSERT_EQ(got->upperArm.has_value(), want.upperArm.has_value());
    if (want.upperArm) {
      EXPECT_EQ(got->upperArm->acc, want.upperArm->acc);
    }
    ASSERT_EQ(got->forearm.has_value(), want.forearm.has_value());
    if (want.forearm) {
      EXPECT_EQ(got->forearm->gyr, want.forearm->gyr);
    }
    ASSERT_EQ(got->wrist.has_value(), want.wrist.has_value());
    if (want.wrist) {
      EXPECT_EQ(*got->wrist, *want.wrist);
    }
    ASSERT_EQ(got->camWrist.has_value(), want.camWrist.has_value());
    if (want.camWrist) {
      EXPECT_EQ(*got->camWrist, *want.camWrist);
    }
  }
  // And it goes on past the finite recording's end.
  EXPECT_GT(stream.nextTime(), 2.0);
  EXPECT_TRUE(std::isfinite(stream.nextTime()));
  EXPECT_EQ(stream.meta().camera.has_value(), true);
}

TEST(SensorStream, FiniteStreamEndsAndRecordingRefusesInfinity) {
  const MultiJointTrajectory traj(1);
  SimulationParams p = defaultSimulation();
  p.duration = 0.01;
  SensorStream stream(traj, p);
  int rows = 0;
  while (stream.next()) ++rows;
  EXPECT_EQ(rows, 11);  // IMU rows at 0, 1, ..., 10 ms; the Kinect's first frame shares t = 0
  EXPECT_FALSE(std::isfinite(stream.nextTime()));
  EXPECT_FALSE(stream.next().has_value());
  p.duration = std::numeric_limits<double>::infinity();
  EXPECT_THROW(simulateRecording(traj, p), std::invalid_argument);
  p.duration = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(SensorStream(traj, p), std::invalid_argument);
}

// The reaching trajectory keeps to its peak rate and acceleration, reaches one of them on its
// fastest joint, and its rates and accelerations are the derivatives of its angles.
TEST(Trajectory, ReachingKeepsToItsPeaksAndIsSmooth) {
  const double peakRate = 420 * kDeg, peakAccel = 4000 * kDeg;
  const ReachingTrajectory traj(5, peakRate, peakAccel, 20.0);
  double maxRate = 0.0, maxAccel = 0.0;
  const double h = 1e-5;
  for (double t = 0.0; t < 20.0; t += 1e-3) {
    const JointMotion m = traj.at(t);
    maxRate = std::max(maxRate, m.thd.cwiseAbs().maxCoeff());
    maxAccel = std::max(maxAccel, m.thdd.cwiseAbs().maxCoeff());
    const JointVector fdRate = (traj.at(t + h).th - traj.at(t - h).th) / (2 * h);
    const JointVector fdAccel = (traj.at(t + h).thd - traj.at(t - h).thd) / (2 * h);
    ASSERT_LT((fdRate - m.thd).cwiseAbs().maxCoeff(), 1e-4) << "t = " << t;
    ASSERT_LT((fdAccel - m.thdd).cwiseAbs().maxCoeff(), 2e-3) << "t = " << t;
  }
  EXPECT_LE(maxRate, peakRate * 1.0001);
  EXPECT_LE(maxAccel, peakAccel * 1.0001);
  EXPECT_TRUE(maxRate > 0.99 * peakRate || maxAccel > 0.99 * peakAccel)
      << maxRate / kDeg << " deg/s, " << maxAccel / kDeg << " deg/s^2";
  EXPECT_THROW(ReachingTrajectory(1, 0.0, peakAccel), std::invalid_argument);
  EXPECT_THROW(ReachingTrajectory(1, peakRate, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace armtrack
