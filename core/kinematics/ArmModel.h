// The Denavit-Hartenberg arm model of Alizadegan & Behzadipour (2016), Tables 1-4, and the
// recursive rigid-body kinematics (eqs. 11-18) that predict what each IMU reads.
//
// Conventions (docs/arm-model.md): frame 0 is fixed to the trunk at the shoulder's centre of
// rotation. For the right arm, x0 points down (along the hanging arm), y0 forward and z0 to the
// right (lateral). At theta = 0 the arm hangs straight down with the elbow extended.
// Everything here is SI: metres, radians, seconds.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>

namespace armtrack {

/// Joint vector [th0 th1 th2 th4 th5] (rad): shoulder flexion/extension, abduction/adduction,
/// internal/external rotation; elbow flexion/extension, pronation/supination (paper's eq. 2).
using JointVector = Eigen::Matrix<double, 5, 1>;
inline constexpr int kNumJoints = 5;

/// Segment lengths and IMU mounting parameters (paper's Table 7 defaults).
struct ArmGeometry {
  double l3 = 0.22;                      ///< upper arm length, shoulder to elbow (m)
  double l6 = 0.20;                      ///< forearm length, elbow to wrist (m)
  double lu3 = 0.11;                     ///< upper-arm strap distance from the shoulder (m)
  double thu4 = std::numbers::pi / 2;    ///< upper-arm strap angle about the arm axis (rad)
  double lu5 = 0.02;                     ///< upper-arm strap effective radius (m)
  double lf6 = 0.20;                     ///< forearm strap distance from the elbow (m)
  double thf7 = std::numbers::pi / 2;    ///< forearm strap angle about the forearm axis (rad)
  double lf8 = 0.01;                     ///< forearm strap effective radius (m)
};

/// One DH row, H = Rz(gamma) Tz(lambda) Rx(beta) Tx(delta); gamma = theta[joint] + gammaOffset
/// when joint >= 0, else the constant gammaOffset.
struct DhRow {
  int joint;           ///< index into JointVector, or -1 for a constant row
  double gammaOffset;  ///< rad
  double lambda;       ///< m
  double beta;         ///< rad
  double delta;        ///< m
};

/// Homogeneous transform of one DH row (eq. 10).
template <typename T>
Eigen::Matrix<T, 4, 4> dhTransform(const T& gamma, double lambda, double beta, double delta) {
  using std::cos;
  using std::sin;
  const T cg = cos(gamma), sg = sin(gamma);
  const double cb = std::cos(beta), sb = std::sin(beta);
  Eigen::Matrix<T, 4, 4> h;
  h << cg, -sg * cb, sg * sb, T(delta) * cg,  //
      sg, cg * cb, -cg * sb, T(delta) * sg,   //
      T(0), T(sb), T(cb), T(lambda),          //
      T(0), T(0), T(0), T(1);
  return h;
}

/// Kinematic state of one DH frame, propagated by the recursion of eqs. 11-15.
template <typename T>
struct FrameState {
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  using Mat3 = Eigen::Matrix<T, 3, 3>;
  Mat3 rotation = Mat3::Identity();  ///< frame axes expressed in frame 0 (0_R_i)
  Vec3 position = Vec3::Zero();      ///< origin in frame 0 (m)
  Vec3 omega = Vec3::Zero();         ///< angular velocity, frame i coordinates (rad/s)
  Vec3 omegaDot = Vec3::Zero();      ///< angular acceleration, frame i coordinates (rad/s^2)
  Vec3 accel = Vec3::Zero();         ///< origin's acceleration, frame i coordinates (m/s^2)
  Vec3 up = Vec3::Zero();            ///< g * up (the gravity reaction), frame i coordinates
};

/// Advances the recursion by one DH row. gamma, gammaDot, gammaDDot are the row's rotation about
/// z(i-1) and its time derivatives. The paper's eq. 14 assumes delta = 0 (all of Tables 1-4); the
/// extra terms here keep it exact for delta != 0, where the origin moves within frame i-1.
template <typename T>
FrameState<T> propagate(const FrameState<T>& prev, const T& gamma, const T& gammaDot,
                        const T& gammaDDot, double lambda, double beta, double delta) {
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  using Mat3 = Eigen::Matrix<T, 3, 3>;
  const Eigen::Matrix<T, 4, 4> h = dhTransform<T>(gamma, lambda, beta, delta);
  const Mat3 r = h.template topLeftCorner<3, 3>();  // (i-1)_R_i
  const Vec3 k(T(0), T(0), T(1));
  const Vec3 lam(T(0), T(0), T(lambda));             // part fixed in frame i-1
  const Vec3 d = h.template topRightCorner<3, 1>() - lam;  // part that turns with frame i

  // Angular velocity and acceleration of frame i, in frame i-1 coordinates (eqs. 12, 13).
  const Vec3 w = prev.omega + gammaDot * k;
  const Vec3 wd = prev.omegaDot + prev.omega.cross(gammaDot * k) + gammaDDot * k;
  // Acceleration of origin i (eq. 14, plus the delta terms).
  Vec3 a = prev.accel + prev.omegaDot.cross(lam) + prev.omega.cross(prev.omega.cross(lam));
  if (delta != 0.0) a += wd.cross(d) + w.cross(w.cross(d));

  FrameState<T> next;
  const Mat3 rt = r.transpose();
  next.rotation = prev.rotation * r;
  next.position = prev.position + prev.rotation * h.template topRightCorner<3, 1>();  // eq. 11
  next.omega = rt * w;
  next.omegaDot = rt * wd;
  next.accel = rt * a;
  next.up = rt * prev.up;  // eq. 15: coordinates change by the transpose
  return next;
}

/// What the arm model predicts at one instant, for every sensor.
template <typename T>
struct ArmKinematics {
  FrameState<T> upperImu;  ///< upper-arm IMU frame (Table 1, frame 6)
  FrameState<T> forearmImu;  ///< forearm IMU frame (Table 3, frame 9)
  Eigen::Matrix<T, 3, 1> elbow;  ///< elbow position in frame 0 (Table 2, frame 5), m
  Eigen::Matrix<T, 3, 1> wrist;  ///< wrist position in frame 0 (Table 4, frame 7), m
  Eigen::Matrix<T, 3, 3> upperArmRotation;  ///< frame 3 (upper arm, z along the arm) in frame 0
  Eigen::Matrix<T, 3, 3> forearmRotation;   ///< frame 6 (forearm, z along the forearm) in frame 0
};

/// Runs the recursion for the whole arm. th, thd, thdd: joint angles (rad), rates (rad/s),
/// accelerations (rad/s^2). gUp: g times the unit vector pointing up, in frame 0 (m/s^2); the
/// accelerometer reading predicted by eqs. 17-18 is then frame.up + frame.accel.
template <typename T>
ArmKinematics<T> armKinematics(const ArmGeometry& geo, const Eigen::Matrix<T, 5, 1>& th,
                               const Eigen::Matrix<T, 5, 1>& thd,
                               const Eigen::Matrix<T, 5, 1>& thdd, const Eigen::Vector3d& gUp) {
  constexpr double kHalfPi = std::numbers::pi / 2;
  const T zero(0);
  const T c90(kHalfPi);
  FrameState<T> f0;
  f0.up = gUp.cast<T>();
  // Shoulder, rows 1-3 (shared by Tables 1-4).
  const FrameState<T> f1 = propagate<T>(f0, th(0), thd(0), thdd(0), 0.0, kHalfPi, 0.0);
  const FrameState<T> f2 = propagate<T>(f1, th(1) + c90, thd(1), thdd(1), 0.0, kHalfPi, 0.0);
  const FrameState<T> f3 = propagate<T>(f2, th(2), thd(2), thdd(2), 0.0, 0.0, 0.0);

  ArmKinematics<T> out;
  out.upperArmRotation = f3.rotation;
  // Upper-arm IMU, Table 1 rows 4-6.
  {
    const FrameState<T> u4 = propagate<T>(f3, zero, zero, zero, geo.lu3, 0.0, 0.0);
    const FrameState<T> u5 = propagate<T>(u4, T(geo.thu4), zero, zero, 0.0, kHalfPi, 0.0);
    out.upperImu = propagate<T>(u5, zero, zero, zero, geo.lu5, 0.0, 0.0);
  }
  // Elbow, Table 2 rows 4-5.
  const FrameState<T> e4 = propagate<T>(f3, c90, zero, zero, geo.l3, -kHalfPi, 0.0);
  const FrameState<T> e5 = propagate<T>(e4, th(3), thd(3), thdd(3), 0.0, kHalfPi, 0.0);
  out.elbow = e5.position;
  // Forearm, Table 3 row 6 (pronation/supination) shared with Table 4.
  const FrameState<T> e6 = propagate<T>(e5, th(4), thd(4), thdd(4), 0.0, 0.0, 0.0);
  out.forearmRotation = e6.rotation;
  {
    const FrameState<T> f7 = propagate<T>(e6, zero, zero, zero, geo.lf6, 0.0, 0.0);
    const FrameState<T> f8 = propagate<T>(f7, T(geo.thf7 + kHalfPi), zero, zero, 0.0, kHalfPi, 0.0);
    out.forearmImu = propagate<T>(f8, zero, zero, zero, geo.lf8, 0.0, 0.0);
  }
  // Wrist, Table 4 row 7: only the position is needed.
  out.wrist = e6.position + e6.rotation.col(2) * T(geo.l6);
  return out;
}

/// The DH tables as data, for the forward-kinematics reference and the docs. Table 1 (upper-arm
/// IMU), 2 (elbow), 3 (forearm IMU), 4 (wrist).
std::array<DhRow, 6> upperImuTable(const ArmGeometry& geo);
std::array<DhRow, 5> elbowTable(const ArmGeometry& geo);
std::array<DhRow, 9> forearmImuTable(const ArmGeometry& geo);
std::array<DhRow, 7> wristTable(const ArmGeometry& geo);

/// Product of the rows' homogeneous transforms for joint angles th: the frame's pose in frame 0.
template <std::size_t N>
Eigen::Matrix4d chainTransform(const std::array<DhRow, N>& rows, const JointVector& th) {
  Eigen::Matrix4d h = Eigen::Matrix4d::Identity();
  for (const DhRow& row : rows) {
    const double gamma = row.joint >= 0 ? th(row.joint) + row.gammaOffset : row.gammaOffset;
    h = h * dhTransform<double>(gamma, row.lambda, row.beta, row.delta);
  }
  return h;
}

/// Forward kinematics of the four frames of interest (poses in frame 0).
struct ArmPose {
  Eigen::Matrix4d upperImu;
  Eigen::Matrix4d forearmImu;
  Eigen::Vector3d elbow;
  Eigen::Vector3d wrist;
};
ArmPose forwardKinematics(const ArmGeometry& geo, const JointVector& th);

/// Predicted IMU readings: gyroscope (rad/s) and accelerometer specific force (m/s^2), both in
/// the IMU's DH frame.
struct ImuPrediction {
  Eigen::Vector3d gyr;
  Eigen::Vector3d acc;
};
struct ArmPrediction {
  ImuPrediction upper;
  ImuPrediction forearm;
  Eigen::Vector3d elbow;
  Eigen::Vector3d wrist;
};
ArmPrediction predictSensors(const ArmGeometry& geo, const JointVector& th, const JointVector& thd,
                             const JointVector& thdd, const Eigen::Vector3d& gUp);

/// Wraps an angle to (-pi, pi].
inline double wrapAngle(double a) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  a = std::fmod(a + std::numbers::pi, kTwoPi);
  if (a <= 0) a += kTwoPi;
  return a - std::numbers::pi;
}

}  // namespace armtrack
