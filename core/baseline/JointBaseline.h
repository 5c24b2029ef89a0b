// A plain complementary joint-angle estimator (docs/baseline.md): the yardstick the DH filter of
// core/estimation must beat. The elbow's two angles (flexion th4 and pronation th5) come from the
// relative gyroscope rate about the elbow's axes, corrected towards the angles at which the two
// IMUs agree on the elbow's specific force (each IMU's accelerometer carried to the elbow by its
// lever arm); the shoulder's inclination (the humerus' elevation from the downward vertical) from
// the upper-arm IMU's gyroscope, corrected towards gravity as the accelerometer sees it at the
// shoulder's centre. One time constant (1 s by default) sets how much the accelerometers are
// trusted. Plain C++20 and Eigen; deterministic.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <optional>

#include "core/ArmSample.h"
#include "core/kinematics/ArmModel.h"

namespace armtrack {

/// The constant parts of the arm model the baseline needs, from the sidecar's geometry:
/// R_uf(th4, th5) = A Rz(th4) Rx(pi/2) Rz(th5) B is the forearm IMU's frame in the upper-arm
/// IMU's; the lever arms are in each IMU's own axes.
struct ElbowModel {
  Eigen::Matrix3d A;               ///< frame 4 (before the elbow's rotation) in upper-IMU axes
  Eigen::Matrix3d B;               ///< forearm IMU axes in frame 6 (after pronation)
  Eigen::Vector3d elbowFromUpper;  ///< elbow centre relative to the upper IMU, upper axes (m)
  Eigen::Vector3d elbowFromFore;   ///< elbow centre relative to the forearm IMU, forearm axes (m)
  Eigen::Vector3d shoulderFromUpper;  ///< shoulder centre relative to the upper IMU (m)
  Eigen::Vector3d humerus;            ///< unit vector shoulder -> elbow, upper-IMU axes

  explicit ElbowModel(const ArmGeometry& geometry);
  /// The forearm IMU's axes in the upper-arm IMU's (columns), at elbow angles th4, th5 (rad).
  Eigen::Matrix3d relative(double th4, double th5) const;
  /// The flexion axis (z4) and the pronation axis (z5) in upper-IMU axes, at flexion th4.
  Eigen::Vector3d flexionAxis() const;
  Eigen::Vector3d pronationAxis(double th4) const;
};

/// What the two IMUs' accelerometers say about the elbow: the elbow's specific force as the
/// upper-arm IMU sees it (upper axes) and as the forearm IMU sees it (forearm axes).
/// f_elbow = f + w. x r + w x (w x r), r the elbow relative to the sensor.
Eigen::Vector3d leverArmShift(const Eigen::Vector3d& specificForce, const Eigen::Vector3d& omega,
                              const Eigen::Vector3d& omegaDot, const Eigen::Vector3d& r);

/// One damped Gauss-Newton step on (th4, th5) towards R_uf(th) fFore || fUpper (unit vectors):
/// the accelerometers' view of the elbow angles. Directions in which the two vectors do not
/// constrain the angles (the specific force along an elbow axis) are damped by mu, so they keep
/// what the gyroscopes say. Also returns the residual's Jacobian for tests.
struct ElbowAccelStep {
  Eigen::Vector2d step;                  ///< rad, (dth4, dth5)
  Eigen::Vector3d residual;              ///< unit(fUpper) - R_uf unit(fFore)
  Eigen::Matrix<double, 3, 2> jacobian;  ///< d(R_uf unit(fFore)) / d(th4, th5)
};
ElbowAccelStep elbowAccelStep(const ElbowModel& model, double th4, double th5,
                              const Eigen::Vector3d& fUpper, const Eigen::Vector3d& fFore,
                              double mu);

/// The humerus' elevation from the downward vertical (rad, 0 hanging, pi straight up) for joint
/// angles th in a shoulder frame whose unit up vector is up: the "swing" or "inclination" a
/// baseline can measure without heading. Used for the truth and for the DH filter's angles.
double humerusElevation(const JointVector& th, const Eigen::Vector3d& up);

struct BaselineParams {
  ArmGeometry geometry;                  ///< the sidecar's
  Eigen::Vector3d gUp{-9.81, 0.0, 0.0};  ///< g times up, shoulder frame (m/s^2)
  /// Which arm. A left arm's readings are in its own frames, the mirror image of a right arm's
  /// (core/kinematics/Side.h): they and gUp are mirrored back, as the DH filter does.
  Side side = Side::Right;
  double timeConstant = 1.0;  ///< s: the accelerometers' correction
  double maxGap = 0.1;        ///< s: a longer step restarts
  /// s: low-pass of the differenced gyroscope (the angular acceleration of the lever-arm terms);
  /// 0 takes the plain difference of consecutive readings.
  double omegaDotTau = 0.0;
  double damping = 0.01;  ///< Levenberg damping of elbowAccelStep
  /// Largest relative disagreement of the two IMUs' elbow specific-force magnitudes (or of the
  /// shoulder's from g) for which the accelerometers correct the angles.
  double accelTolerance = 0.3;
  /// The elbow centre relative to the forearm IMU (forearm axes, m) when it is known better than
  /// the sidecar's mounting says (e.g. from a joint-position calibration); empty: the sidecar's.
  std::optional<Eigen::Vector3d> elbowFromForearm;
  /// Take a reading bit-identical to the sensor's previous one as the logger repeating it (a
  /// gyroscope or accelerometer slower than the rows, held): it is not differenced for the
  /// angular acceleration, and a repeated accelerometer does not correct the angles again (the
  /// next new one corrects for the whole time since the last). Real sensors' noise makes an exact
  /// repeat of a three-axis reading practically impossible otherwise.
  bool repeatsAreStale = true;
};

/// One output row. Angles the recording cannot give are NaN.
struct BaselineRow {
  static constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  double t = 0.0;
  double flexion = kNan;    ///< th4 (rad), the model's sign: negative is flexion
  double pronation = kNan;  ///< th5 (rad)
  double elevation = kNan;  ///< humerus from the downward vertical (rad)
  bool restarted = false;   ///< first row after the start or a gap
};

struct BaselineCounters {
  std::size_t rows = 0;            ///< samples offered
  std::size_t estimates = 0;       ///< rows output
  std::size_t rejectedTime = 0;    ///< times not after the previous row's, or not finite
  std::size_t nonFinite = 0;       ///< IMU readings with a NaN or infinite value, skipped
  std::size_t restarts = 0;        ///< gaps longer than maxGap
  std::size_t withoutForearm = 0;  ///< rows with an upper-arm reading and no forearm yet
  std::size_t withoutUpper = 0;    ///< rows with a forearm reading and no upper-arm yet
  std::size_t accelSkipped = 0;    ///< elbow corrections left out (accelerometers disagree)
  std::size_t repeatedGyro = 0;    ///< gyroscope readings equal to the previous (held)
  std::size_t repeatedAccel = 0;   ///< accelerometer readings equal to the previous (held)
};

/// The baseline, fed one sample at a time in time order. Not thread-safe.
class JointBaseline {
 public:
  /// Throws std::invalid_argument for a non-positive time constant or gap, or a zero gUp.
  explicit JointBaseline(const BaselineParams& params);
  /// True when the sample yields a row (it carried IMU data and something could be estimated).
  bool push(const ArmSample& sample, BaselineRow& row);
  const BaselineCounters& counters() const { return m_counters; }

 private:
  struct Imu {
    bool seen = false;
    double tGyr = 0.0;    // when the gyroscope last read something new
    bool newAcc = false;  // this row brought a new accelerometer reading
    Eigen::Vector3d gyr = Eigen::Vector3d::Zero(), acc = Eigen::Vector3d::Zero();
    Eigen::Vector3d gyrDot = Eigen::Vector3d::Zero();
  };
  void restart();
  void take(Imu& imu, const ImuReading& r, double t);
  void stepShoulder(double dt);
  void stepElbow(double dt);
  void initElbow();

  BaselineParams m_p;
  ElbowModel m_model;
  BaselineCounters m_counters;
  double m_lastT = -std::numeric_limits<double>::infinity();
  Imu m_upper, m_fore;
  std::optional<Eigen::Vector3d> m_up;     // unit up vector in upper-IMU axes
  std::optional<Eigen::Vector2d> m_elbow;  // th4, th5
  bool m_restarted = true;
  double m_shoulderWait = 0.0;  // s since the shoulder's last accelerometer correction
  double m_elbowWait = 0.0;     // s since the elbow's
};

}  // namespace armtrack
