// The paper's simulation studies (section 3), reproduced: Table 6 (body-acceleration
// compensation, Methods A/B/C), Fig. 5 (error against motion frequency per measurement model),
// Fig. 7 (position-measurement accuracy against IMU perturbations) and Fig. 8 (perturbation error
// against motion frequency, with and without positions); and one of our own, the sensor study
// (the same five-joint motions from every sensor combination).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "core/estimation/ArmFilter.h"

namespace armtrack {

/// Called after each finished run with (done, total), for progress display. May be empty.
using StudyProgress = std::function<void(int done, int total)>;

/// Mean and standard deviation over runs (deg).
struct Stat {
  double mean = 0.0;
  double std = 0.0;
};

struct Table6Row {
  MeasurementModel method;
  Stat rmse;                                                ///< deg
  Stat peak;                                                ///< deg
  double paperRmse, paperRmseStd, paperPeak, paperPeakStd;  ///< the paper's Table 6 (deg)
};

struct StudySetup {
  int runs = 10;
  double duration = 10.0;      ///< s per run; errors count after the first second
  double amplitudeDeg = 90.0;  ///< th0 sinusoid amplitude
  FilterKind filter = FilterKind::Ekf;
};

/// One segment (shoulder and upper arm, one IMU near the elbow), th0 = 90 deg sin(2 pi 1 Hz t),
/// Table 5 noise, seeds 1..runs.
std::vector<Table6Row> runTable6(const StudySetup& setup, const StudyProgress& progress = {});
std::string formatTable6(const std::vector<Table6Row>& rows, const StudySetup& setup);

struct Fig5Point {
  double frequencyHz;
  MeasurementModel model;  ///< Inclinometer, InclinometerGyro or AccelGyro
  FilterKind filter;
  Stat rmse;  ///< deg
};

/// The IMU at the shoulder's centre of rotation (no body acceleration), th0 sinusoid of 90 deg
/// at 0 to 2.5 Hz in steps of 0.25 Hz, three measurement models, EKF and UKF.
std::vector<Fig5Point> runFig5(const StudySetup& setup, const StudyProgress& progress = {});
std::string formatFig5(const std::vector<Fig5Point>& points, const StudySetup& setup);

/// What is wrong with the upper-arm IMU in Figs. 7 and 8 (section 3.2). The paper's "unit
/// perturbations" are a 1 m/s^2 accelerometer error and a 1 deg/s gyroscope error; we put each
/// along the axis where it does the most harm to th0 (the accelerometer's tangential axis at the
/// zero pose, the gyroscope's flexion axis). The third case is a real mounting error: the sensor
/// turned 5 deg about the flexion axis.
enum class Perturbation { None, Accel, Gyro, Misalignment };
std::string perturbationName(Perturbation p);

struct Fig7Point {
  double positionStd;  ///< m; 0 = no position measurements
  Perturbation perturbation;
  Stat error;  ///< deg, steady-state th0 RMSE (second half of each run)
};

/// Static arm (th0 = 0), one segment with the IMU 20 cm down the upper arm, Table 5 IMU noise,
/// elbow positions at 30 Hz with noise std 1 mm ... 1 m (the filter told the same variance), and
/// without positions.
std::vector<Fig7Point> runFig7(const StudySetup& setup, const StudyProgress& progress = {});
std::string formatFig7(const std::vector<Fig7Point>& points, const StudySetup& setup);

struct Fig8Point {
  double frequencyHz;
  Perturbation perturbation;  ///< None, Accel or Gyro
  bool positions;             ///< Kinect elbow positions (1 cm) fused
  Stat rmse;                  ///< deg, th0 after the first second
};

/// th0 = 90 deg sin(2 pi f t), f = 0 ... 3 Hz, the same segment and perturbations as Fig. 7, with
/// and without Kinect elbow positions (sigma_p^2 = 1e-4 m^2).
std::vector<Fig8Point> runFig8(const StudySetup& setup, const StudyProgress& progress = {});
std::string formatFig8(const std::vector<Fig8Point>& points, const StudySetup& setup);

/// The sensor study: which sensors are worth having. Five joints moving (MultiJointTrajectory,
/// seeds 1..runs), Table 5 IMU noise, a 30 Hz Kinect with 1 cm noise, a 30 Hz webcam 2 m in front
/// with 1 px noise, all in one recording per run; each configuration sees its own subset.
enum class SensorSet { ImuOnly, ImuKinect, ImuWebcam, ImuKinectWebcam, TaoHu };
std::string sensorSetName(SensorSet s);

struct SensorRow {
  SensorSet sensors;
  std::array<Stat, kNumJoints> rmse;  ///< deg per joint, after the first second
  Stat wristRmse;                     ///< cm, wrist position (forward kinematics of the angles)
  double wristPeak = 0.0;             ///< cm, largest wrist position error over all runs
  bool available = true;              ///< false when the method could not run (message in note)
  std::string note;
};

/// The joint-acceleration noise the five-joint studies use, (10 deg/s^2)^2 per 1 ms step
/// (docs/estimator.md, "Tuning for five-joint motion").
double fiveJointAccelVariance();

/// Runs the four filter configurations (EKF, five-joint tuning) and the Tao-Hu tracker on the
/// same recordings.
std::vector<SensorRow> runSensors(const StudySetup& setup, const StudyProgress& progress = {});
std::string formatSensors(const std::vector<SensorRow>& rows, const StudySetup& setup);

}  // namespace armtrack
