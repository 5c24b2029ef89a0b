// Calibration building blocks: the kinematics with a generic geometry, how a calibration undoes
// the simulator's misalignment and bias (both arms), the file format, and the protocol
// trajectory.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <random>
#include <unsupported/Eigen/AutoDiff>

#include "core/calibration/Calibration.h"
#include "core/calibration/Calibrator.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "tests/support/TempDirTest.h"

namespace fs = std::filesystem;

namespace armtrack {
namespace {

const Eigen::Matrix3d kD = Eigen::Vector3d(1, 1, -1).asDiagonal();

ArmGeometry oddGeometry() {
  ArmGeometry g;
  g.l3 = 0.25;
  g.l6 = 0.18;
  g.lu3 = 0.13;
  g.thu4 = 1.2;
  g.lu5 = 0.035;
  g.lf6 = 0.16;
  g.thf7 = 1.9;
  g.lf8 = 0.02;
  return g;
}

TEST(CalibrationModel, GenericGeometryKinematicsMatchTheDoubleVersion) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  const ArmGeometry g = oddGeometry();
  const Eigen::Vector3d gUp(-9.81, 0.3, 0.1);
  for (int k = 0; k < 20; ++k) {
    JointVector th, thd, thdd;
    for (int j = 0; j < kNumJoints; ++j) {
      th(j) = u(rng);
      thd(j) = 2 * u(rng);
      thdd(j) = 10 * u(rng);
    }
    const ArmKinematics<double> a = armKinematics<double>(g, th, thd, thdd, gUp);
    const ArmKinematics<double> b =
        armKinematics<double>(geometryAs<double>(g), th, thd, thdd, gUp);
    const double tol = 1e-12;
    EXPECT_LT((a.upperImu.omega - b.upperImu.omega).norm(), tol);
    EXPECT_LT((a.upperImu.accel + a.upperImu.up - b.upperImu.accel - b.upperImu.up).norm(), tol);
    EXPECT_LT((a.forearmImu.omega - b.forearmImu.omega).norm(), tol);
    EXPECT_LT((a.forearmImu.accel + a.forearmImu.up - b.forearmImu.accel - b.forearmImu.up).norm(),
              tol);
    EXPECT_LT((a.elbow - b.elbow).norm(), tol);
    EXPECT_LT((a.wrist - b.wrist).norm(), tol);
  }
}

// d(prediction)/d(geometry) by automatic differentiation equals central differences.
TEST(CalibrationModel, GeometryDerivativesMatchFiniteDifferences) {
  using Ad = Eigen::AutoDiffScalar<Eigen::Matrix<double, 8, 1>>;
  JointVector th, thd, thdd;
  th << 0.4, 0.3, -0.5, -1.1, 0.7;
  thd << 1.0, -0.8, 1.5, 2.0, -1.2;
  thdd << 5.0, 3.0, -4.0, 8.0, 2.0;
  const Eigen::Vector3d gUp(-9.81, 0.0, 0.0);
  const ArmGeometry g = oddGeometry();
  double ArmGeometry::*fields[8] = {&ArmGeometry::l3,   &ArmGeometry::l6,  &ArmGeometry::lu3,
                                    &ArmGeometry::thu4, &ArmGeometry::lu5, &ArmGeometry::lf6,
                                    &ArmGeometry::thf7, &ArmGeometry::lf8};
  auto stacked = [&](const auto& k) {
    using S = std::decay_t<decltype(k.elbow(0))>;
    Eigen::Matrix<S, 18, 1> v;
    v << k.upperImu.omega, k.upperImu.up + k.upperImu.accel, k.forearmImu.omega,
        k.forearmImu.up + k.forearmImu.accel, k.elbow, k.wrist;
    return v;
  };
  ArmGeometryT<Ad> ga = geometryAs<Ad>(g);
  Ad* ad[8] = {&ga.l3, &ga.l6, &ga.lu3, &ga.thu4, &ga.lu5, &ga.lf6, &ga.thf7, &ga.lf8};
  for (int i = 0; i < 8; ++i) ad[i]->derivatives() = Eigen::Matrix<double, 8, 1>::Unit(i);
  const Eigen::Matrix<Ad, 5, 1> tha = th.cast<Ad>(), thda = thd.cast<Ad>(), thdda = thdd.cast<Ad>();
  const auto va = stacked(armKinematics<Ad>(ga, tha, thda, thdda, gUp));
  for (int i = 0; i < 8; ++i) {
    const double h = 1e-6;
    ArmGeometry gp = g, gm = g;
    gp.*fields[i] += h;
    gm.*fields[i] -= h;
    const auto vp = stacked(armKinematics<double>(geometryAs<double>(gp), th, thd, thdd, gUp));
    const auto vm = stacked(armKinematics<double>(geometryAs<double>(gm), th, thd, thdd, gUp));
    const Eigen::Matrix<double, 18, 1> fd = (vp - vm) / (2 * h);
    for (int r = 0; r < 18; ++r)
      EXPECT_NEAR(va(r).derivatives()(i), fd(r), 1e-6 * (1.0 + std::abs(fd(r))))
          << "row " << r << " field " << i;
  }
}

// Noise-free recordings of one motion: perfectly mounted, and with a misalignment and bias.
struct Pair {
  Recording perfect, disturbed;
  ImuCalibration ua, fa;  // what undoes the disturbance, in the recording's sensor axes
};

Pair simulatedPair(Side side) {
  const MultiJointTrajectory motion(2);
  SimulationParams sim;
  sim.duration = 0.2;
  sim.side = side;
  sim.kinect.enabled = false;
  Pair p;
  p.perfect = simulateRecording(motion, sim);
  sim.upperArm.misalignment = randomMisalignment(10 * kDeg, 1);
  sim.forearm.misalignment = randomMisalignment(10 * kDeg, 2);
  sim.upperArm.gyroBias = Eigen::Vector3d(0.01, -0.02, 0.005);
  sim.forearm.gyroBias = Eigen::Vector3d(-0.01, 0.015, 0.02);
  p.disturbed = simulateRecording(motion, sim);
  // The simulator disturbs the right-arm twin; a left arm's real sensor sees the mirror image.
  p.ua = {sim.upperArm.misalignment, sim.upperArm.gyroBias};
  p.fa = {sim.forearm.misalignment, sim.forearm.gyroBias};
  if (side == Side::Left) {
    p.ua = mirrorImuCalibration(p.ua);
    p.fa = mirrorImuCalibration(p.fa);
  }
  return p;
}

void expectUndone(Side side) {
  Pair p = simulatedPair(side);
  Calibration c;
  c.side = side;
  c.upperArm = p.ua;
  c.forearm = p.fa;
  applyCalibration(c, p.disturbed);
  ASSERT_EQ(p.perfect.samples.size(), p.disturbed.samples.size());
  for (std::size_t i = 0; i < p.perfect.samples.size(); ++i) {
    const ArmSample& a = p.perfect.samples[i];
    const ArmSample& b = p.disturbed.samples[i];
    ASSERT_TRUE(a.upperArm && b.upperArm && a.forearm && b.forearm);
    EXPECT_LT((a.upperArm->gyr - b.upperArm->gyr).norm(), 1e-12);
    EXPECT_LT((a.upperArm->acc - b.upperArm->acc).norm(), 1e-12);
    EXPECT_LT((a.forearm->gyr - b.forearm->gyr).norm(), 1e-12);
    EXPECT_LT((a.forearm->acc - b.forearm->acc).norm(), 1e-12);
  }
}

TEST(CalibrationApply, UndoesTheSimulatorsMisalignmentAndBias) {
  expectUndone(Side::Right);
}

// A left arm's real sensor: its residual rotation is the mirror conjugate D R D of its twin's,
// and its bias -D b. Applying the twin's values unconjugated does not undo the disturbance.
TEST(CalibrationApply, LeftArmUsesTheMirrorConjugate) {
  expectUndone(Side::Left);
  Pair p = simulatedPair(Side::Left);
  const ImuCalibration twin = mirrorImuCalibration(p.ua);
  EXPECT_TRUE(mirrorImuCalibration(twin).rotation.isApprox(p.ua.rotation, 1e-15));  // involution
  EXPECT_TRUE(twin.rotation.isApprox(kD * p.ua.rotation * kD, 1e-15));
  Calibration wrong;
  wrong.side = Side::Left;
  wrong.upperArm = twin;
  applyCalibration(wrong, p.disturbed);
  EXPECT_GT((p.disturbed.samples[50].upperArm->acc - p.perfect.samples[50].upperArm->acc).norm(),
            0.05);
}

TEST(CalibrationApply, RejectsTheOtherArm) {
  Recording rec;
  rec.meta.side = Side::Left;
  Calibration c;  // right arm
  EXPECT_THROW(applyCalibration(c, rec), std::invalid_argument);
  EstimatorParams p;
  p.geometry.lu3 = 0.5;
  c.geometry.lu3 = 0.12;
  applyCalibration(c, p);
  EXPECT_EQ(p.geometry.lu3, 0.12);
}

class CalibrationFile : public armtrack::test::TempDirTest {
 protected:
  CalibrationFile() : TempDirTest("armtrack_calib_") {}
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(m_dir / name) << text;
    return m_dir / name;
  }
};

TEST_F(CalibrationFile, RoundTrip) {
  Calibration c;
  c.side = Side::Left;
  c.geometry = oddGeometry();
  c.upperArm = {randomMisalignment(7 * kDeg, 4), Eigen::Vector3d(0.01, 0.02, -0.03)};
  c.forearm = {randomMisalignment(3 * kDeg, 5), Eigen::Vector3d(-0.01, 0.0, 0.004)};
  c.opticalUsed = false;
  c.headingFromStartPoseOnly = true;
  c.estimated = {"lu3", "thu4"};
  c.fromStartPose = {"thf7", "heading"};
  c.heldFixed = {"l3", "l6"};
  const fs::path p = m_dir / "c.json";
  writeCalibration(p, c);
  const Calibration r = readCalibration(p);
  EXPECT_EQ(r.side, Side::Left);
  EXPECT_EQ(r.geometry.thf7, c.geometry.thf7);
  EXPECT_EQ(r.geometry.lf8, c.geometry.lf8);
  EXPECT_TRUE(r.upperArm.rotation.isApprox(c.upperArm.rotation, 1e-14));
  EXPECT_TRUE(r.forearm.rotation.isApprox(c.forearm.rotation, 1e-14));
  EXPECT_EQ(r.upperArm.gyroBias, c.upperArm.gyroBias);
  EXPECT_TRUE(r.headingFromStartPoseOnly);
  EXPECT_EQ(r.fromStartPose, c.fromStartPose);
  EXPECT_EQ(r.heldFixed, c.heldFixed);
}

TEST_F(CalibrationFile, SternumMountRoundTripsAndAnImpossibleOneIsRefused) {
  Calibration c;
  TrunkMount m;
  m.imuPosition = Eigen::Vector3d(0.1, 0.07, -0.18);
  m.imuRotation = randomMisalignment(20 * kDeg, 9);
  c.trunk = m;
  const fs::path p = m_dir / "trunk.json";
  writeCalibration(p, c);
  const Calibration r = readCalibration(p);
  ASSERT_TRUE(r.trunk);
  EXPECT_TRUE(r.trunk->imuRotation.isApprox(m.imuRotation, 1e-14));
  EXPECT_EQ(r.trunk->imuPosition, m.imuPosition);
  // Without one, none comes back (and older files have none).
  writeCalibration(p, Calibration{});
  EXPECT_FALSE(readCalibration(p).trunk);
  // Not a rotation: refused on writing and on reading.
  c.trunk->imuRotation(0, 0) = 3.0;
  EXPECT_THROW(writeCalibration(m_dir / "bad.json", c), CalibrationError);
  const std::string file =
      "{\"format\": \"armtrack-calibration\", \"version\": 1, \"geometry\": {\"l3\": 0.22, "
      "\"l6\": 0.2, \"lu3\": 0.11, \"thu4\": 1.57, \"lu5\": 0.02, \"lf6\": 0.2, \"thf7\": "
      "1.57, \"lf8\": 0.01}, \"trunk\": {\"imu_position\": [0, 0, 0], \"imu_rotation\": ";
  for (const std::string& rot : {std::string("[2, 0, 0, 0, 1, 0, 0, 0, 1]"),
                                 std::string("[1, 0, 0]"), std::string("\"x\"")}) {
    const fs::path bad = write("bad_trunk.json", file + rot + "}}");
    try {
      readCalibration(bad);
      ADD_FAILURE() << "no exception for " << rot;
    } catch (const CalibrationError& e) {
      EXPECT_NE(std::string(e.what()).find("trunk"), std::string::npos) << e.what();
    }
  }
}

TEST(CalibrationApply, SternumMountOnlyForARecordingWithASternumSensor) {
  Calibration c;
  TrunkMount m;
  m.imuRotation = randomMisalignment(10 * kDeg, 3);
  c.trunk = m;
  RecordingMeta without;
  applyCalibration(c, without);
  EXPECT_FALSE(without.trunk);  // no sternum sensor: the estimator stays without a trunk
  RecordingMeta with;
  with.trunk = defaultTrunkMount(Side::Right);
  applyCalibration(c, with);
  ASSERT_TRUE(with.trunk);
  EXPECT_TRUE(with.trunk->imuRotation.isApprox(m.imuRotation));
}

TEST_F(CalibrationFile, ErrorsNameTheFileAndTheProblem) {
  auto expectError = [&](const fs::path& p, const std::string& what) {
    try {
      readCalibration(p);
      ADD_FAILURE() << "no exception for " << what;
    } catch (const CalibrationError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(p.string() + ": ", 0), 0u) << msg;
      EXPECT_NE(msg.find(what), std::string::npos) << msg;
    }
  };
  expectError(m_dir / "none.json", "no such file");
  expectError(write("a.json", "{\"format\": "), "bad JSON at byte");
  expectError(write("b.json", "{\"format\": \"armtrack-recording\", \"version\": 1}"),
              "\"format\" must be \"armtrack-calibration\"");
  expectError(write("c.json", "{\"format\": \"armtrack-calibration\", \"version\": 2}"),
              "unsupported \"version\" 2");
  const std::string head = "{\"format\": \"armtrack-calibration\", \"version\": 1, ";
  const std::string geo =
      "\"geometry\": {\"l3\": 0.22, \"l6\": 0.2, \"lu3\": 0.11, \"thu4\": 1.57, \"lu5\": 0.02, "
      "\"lf6\": 0.2, \"thf7\": 1.57";
  expectError(write("d.json", head + geo + "}}"), "missing \"geometry.lf8\"");
  expectError(write("e.json", head + geo + ", \"lf8\": \"x\"}}"),
              "\"geometry.lf8\" must be a number");
  expectError(write("f.json", head + geo +
                                  ", \"lf8\": 0.01}, \"upperArm\": {\"rotationVector\": "
                                  "[1, 2]}}"),
              "\"upperArm.rotationVector\" must be an array of 3 numbers");
  expectError(write("g.json", head + geo + ", \"lf8\": 0.01}, \"side\": \"up\"}"), "unknown side");
  // A minimal valid file: identity rotations and zero biases.
  const Calibration ok = readCalibration(write("h.json", head + geo + ", \"lf8\": 0.01}}"));
  EXPECT_TRUE(ok.upperArm.rotation.isIdentity());
  EXPECT_EQ(ok.side, Side::Right);
}

// A geometry no real arm has (MetaLimits, core/io/Recording.h) is never written, and a file that
// holds one is refused, naming the file, the value and what to do (issue 9 item 2).
TEST_F(CalibrationFile, RefusesAGeometryOutsidePhysicalLimits) {
  auto expectRefused = [](const auto& action, const fs::path& p, const std::string& key) {
    try {
      action();
      ADD_FAILURE() << "no exception for " << key;
    } catch (const CalibrationError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(p.string() + ": ", 0), 0u) << msg;
      EXPECT_NE(msg.find("\"" + key + "\""), std::string::npos) << msg;
      EXPECT_NE(msg.find("redo the calibration protocol"), std::string::npos) << msg;
    }
  };
  Calibration c;
  c.geometry.l3 = c.geometry.l6 = 0.05;  // what calibrate wrote after one spike row (issue 9)
  c.geometry.lf6 = 0.0;
  const fs::path p = m_dir / "impossible.json";
  expectRefused([&] { writeCalibration(p, c); }, p, "geometry.l3");
  EXPECT_FALSE(fs::exists(p));

  const std::string head = "{\"format\": \"armtrack-calibration\", \"version\": 1, ";
  const fs::path shortArm =
      write("short.json", head +
                              "\"geometry\": {\"l3\": 0.05, \"l6\": 0.05, "
                              "\"lu3\": 0.11, \"thu4\": 1.57, \"lu5\": 0.02, "
                              "\"lf6\": 0.0, \"thf7\": 1.57, \"lf8\": 0.01}}");
  expectRefused([&] { readCalibration(shortArm); }, shortArm, "geometry.l3");
  // The upper-arm IMU 0.2 m beyond the elbow.
  const fs::path offArm = write("off.json", head +
                                                "\"geometry\": {\"l3\": 0.3, \"l6\": 0.25, "
                                                "\"lu3\": 0.6, \"thu4\": 1.57, \"lu5\": 0.02, "
                                                "\"lf6\": 0.2, \"thf7\": 1.57, \"lf8\": 0.01}}");
  expectRefused([&] { readCalibration(offArm); }, offArm, "geometry.lu3");
}

TEST(CalibrationProtocol, StartsAndEndsInTheStartPoseWithConsistentDerivatives) {
  const CalibrationProtocolTrajectory traj;
  EXPECT_EQ(CalibrationProtocolTrajectory::startPose(), protocolStartPose());
  EXPECT_GT(traj.duration(), 50.0);
  EXPECT_LT(traj.duration(), 65.0);
  for (double t : {0.0, 2.0, 4.0, traj.duration() - 1.0, traj.duration() + 5.0}) {
    const JointMotion m = traj.at(t);
    EXPECT_LT((m.th - protocolStartPose()).norm(), 1e-12) << t;
    EXPECT_LT(m.thd.norm(), 1e-12) << t;
  }
  const double h = 1e-5;
  for (double t = 4.1; t < traj.duration(); t += 0.73) {
    const JointMotion m = traj.at(t), p = traj.at(t + h), q = traj.at(t - h);
    EXPECT_LT((m.thd - (p.th - q.th) / (2 * h)).norm(), 1e-6) << t;
    EXPECT_LT((m.thdd - (p.thd - q.thd) / (2 * h)).norm(), 1e-4) << t;
    EXPECT_LT(std::abs(m.th(1)), 80 * kDeg);  // away from the shoulder's gimbal lock
  }
  TrajectoryOptions opts;
  EXPECT_EQ(makeTrajectory("calibration", opts)->at(10.0).th, traj.at(10.0).th);
}

TEST(CalibrationInput, RejectsUnusableRecordings) {
  const MultiJointTrajectory motion(1);
  SimulationParams sim = defaultSimulation();
  sim.duration = 5.0;
  EXPECT_THROW(calibrate(simulateRecording(motion, sim)), std::invalid_argument);  // too short
  sim.duration = 12.0;
  sim.forearm.enabled = false;
  EXPECT_THROW(calibrate(simulateRecording(motion, sim)), std::invalid_argument);  // one IMU
}

TEST(CalibrationModel, MountingRotationTurnsAboutTheSegmentAxis) {
  const Eigen::Matrix3d r = mountingRotation(1.0, 0.75, Eigen::Matrix3d::Identity());
  EXPECT_TRUE(r.isApprox(Eigen::AngleAxisd(0.25, Eigen::Vector3d::UnitY()).toRotationMatrix()));
}

}  // namespace
}  // namespace armtrack
