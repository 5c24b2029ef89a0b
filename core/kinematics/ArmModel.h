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
#include <type_traits>

namespace armtrack {

/// Joint vector [th0 th1 th2 th4 th5] (rad): shoulder flexion/extension, abduction/adduction,
/// internal/external rotation; elbow flexion/extension, pronation/supination (paper's eq. 2).
using JointVector = Eigen::Matrix<double, 5, 1>;
inline constexpr int kNumJoints = 5;

/// Segment lengths and IMU mounting parameters (paper's Table 7 defaults).
struct ArmGeometry {
  double l3 = 0.22;                    ///< upper arm length, shoulder to elbow (m)
  double l6 = 0.20;                    ///< forearm length, elbow to wrist (m)
  double lu3 = 0.11;                   ///< upper-arm strap distance from the shoulder (m)
  double thu4 = std::numbers::pi / 2;  ///< upper-arm strap angle about the arm axis (rad)
  double lu5 = 0.02;                   ///< upper-arm strap effective radius (m)
  double lf6 = 0.20;                   ///< forearm strap distance from the elbow (m)
  double thf7 = std::numbers::pi / 2;  ///< forearm strap angle about the forearm axis (rad)
  double lf8 = 0.01;                   ///< forearm strap effective radius (m)
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

/// Motion of one DH frame, propagated by the recursion of eqs. 12-15. All vectors are in the
/// frame's own coordinates.
template <typename T>
struct FrameState {
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  Vec3 omega = Vec3::Zero();     ///< angular velocity (rad/s)
  Vec3 omegaDot = Vec3::Zero();  ///< angular acceleration (rad/s^2)
  Vec3 accel = Vec3::Zero();     ///< acceleration of the frame's origin (m/s^2)
  Vec3 up = Vec3::Zero();        ///< g * up, the gravity reaction (m/s^2)
};

namespace detail {
inline constexpr double kHalfPi = std::numbers::pi / 2;

/// (i-1)_R_i^T v = Rx(-beta) Rz(-gamma) v, with gamma given by its cosine and sine. The rotation
/// is applied as two plane rotations: with automatic differentiation this costs far less than a
/// matrix product, and beta = 0 or +-pi/2 (every row of Tables 1-4) is exact.
template <typename T, typename C>
Eigen::Matrix<T, 3, 1> toChild(const Eigen::Matrix<T, 3, 1>& v, const C& c, const C& s,
                               double beta) {
  const T x = c * v(0) + s * v(1);
  const T y = c * v(1) - s * v(0);
  if (beta == 0.0) return {x, y, v(2)};
  if (beta == kHalfPi) return {x, v(2), -y};
  if (beta == -kHalfPi) return {x, -v(2), y};
  const double cb = std::cos(beta), sb = std::sin(beta);
  return {x, cb * y + sb * v(2), cb * v(2) - sb * y};
}

/// (i-1)_R_i v = Rz(gamma) Rx(beta) v.
template <typename T, typename C>
Eigen::Matrix<T, 3, 1> toParent(const Eigen::Matrix<T, 3, 1>& v, const C& c, const C& s,
                                double beta) {
  T y = v(1), z = v(2);
  if (beta == kHalfPi) {
    y = -v(2);
    z = v(1);
  } else if (beta == -kHalfPi) {
    y = v(2);
    z = -v(1);
  } else if (beta != 0.0) {
    const double cb = std::cos(beta), sb = std::sin(beta);
    y = cb * v(1) - sb * v(2);
    z = sb * v(1) + cb * v(2);
  }
  return {c * v(0) - s * y, s * v(0) + c * y, z};
}
}  // namespace detail

/// Advances the recursion by one DH row H = Rz(gamma) Tz(lambda) Rx(beta) Tx(delta); c, s are
/// cos and sin of gamma, gammaDot and gammaDDot its rates (zero for a constant row).
/// Eqs. 12-15 in frame i-1 coordinates, then expressed in frame i:
///   w  = w' + gammaDot k,   w. = w.' + w' x gammaDot k + gammaDDot k,
///   a  = a' + w.' x lambda k + w' x (w' x lambda k)  [+ w. x d + w x (w x d) when delta != 0,
///        where d = delta Rz(gamma) x is the part of the offset that turns with frame i].
/// The paper's eq. 15 prints R g; coordinates change by the transpose, R^T g, as for the rest.
/// lambda may be a number (skipped when zero) or an unknown of type L = T (a calibration
/// parameter, always applied: a zero value may still carry a derivative).
template <typename T, typename C, typename L = double>
FrameState<T> propagate(const FrameState<T>& prev, const C& c, const C& s, const T& gammaDot,
                        const T& gammaDDot, const L& lambda, double beta, double delta) {
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  const Vec3& w0 = prev.omega;
  const Vec3& wd0 = prev.omegaDot;
  const Vec3 w(w0(0), w0(1), w0(2) + gammaDot);
  const Vec3 wd(wd0(0) + w0(1) * gammaDot, wd0(1) - w0(0) * gammaDot, wd0(2) + gammaDDot);
  Vec3 a = prev.accel;
  if (!std::is_arithmetic_v<L> || lambda != L(0)) {
    a(0) += lambda * (wd0(1) + w0(0) * w0(2));
    a(1) += lambda * (w0(1) * w0(2) - wd0(0));
    a(2) -= lambda * (w0(0) * w0(0) + w0(1) * w0(1));
  }
  if (delta != 0.0) {
    const Vec3 d(delta * c, delta * s, T(0));
    a += wd.cross(d) + w.cross(w.cross(d));
  }
  FrameState<T> next;
  next.omega = detail::toChild(w, c, s, beta);
  next.omegaDot = detail::toChild(wd, c, s, beta);
  next.accel = detail::toChild(a, c, s, beta);
  next.up = detail::toChild(prev.up, c, s, beta);
  return next;
}

/// A row whose rotation is a joint angle: gamma = angle + offset.
template <typename T>
FrameState<T> propagateJoint(const FrameState<T>& prev, const T& angle, double offset,
                             const T& rate, const T& accel, double lambda, double beta,
                             double delta = 0.0) {
  using std::cos;
  using std::sin;
  const T gamma = offset == 0.0 ? angle : T(angle + offset);
  return propagate<T, T>(prev, cos(gamma), sin(gamma), rate, accel, lambda, beta, delta);
}

/// A row with a constant rotation gamma (strap angles, fixed offsets).
template <typename T>
FrameState<T> propagateFixed(const FrameState<T>& prev, double gamma, double lambda, double beta,
                             double delta = 0.0) {
  const T zero(0);
  return propagate<T, double>(prev, std::cos(gamma), std::sin(gamma), zero, zero, lambda, beta,
                              delta);
}

/// What the arm model predicts at one instant, for every sensor.
template <typename T>
struct ArmKinematics {
  FrameState<T> upperImu;        ///< upper-arm IMU frame (Table 1, frame 6)
  FrameState<T> forearmImu;      ///< forearm IMU frame (Table 3, frame 9)
  Eigen::Matrix<T, 3, 1> elbow;  ///< elbow position in frame 0 (Table 2, frame 5), m
  Eigen::Matrix<T, 3, 1> wrist;  ///< wrist position in frame 0 (Table 4, frame 7), m
};

/// Runs the recursion for the whole arm. th, thd, thdd: joint angles (rad), rates (rad/s),
/// accelerations (rad/s^2). gUp: g times the unit vector pointing up, in frame 0 (m/s^2); the
/// accelerometer reading predicted by eqs. 17-18 is then frame.up + frame.accel.
/// With a moving trunk, frame 0 moves with the thorax: base holds frame 0's angular velocity,
/// angular acceleration, the shoulder centre's acceleration and g * up, all in frame-0
/// coordinates (core/kinematics/Trunk.h); the recursion carries them to every sensor, Coriolis
/// and centripetal terms included. A still trunk is base = {0, 0, 0, gUp}. Positions stay in
/// frame 0.
template <typename T>
ArmKinematics<T> armKinematics(const ArmGeometry& geo, const Eigen::Matrix<T, 5, 1>& th,
                               const Eigen::Matrix<T, 5, 1>& thd,
                               const Eigen::Matrix<T, 5, 1>& thdd, const FrameState<double>& base) {
  using std::cos;
  using std::sin;
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  constexpr double kHalfPi = detail::kHalfPi;
  FrameState<T> f0;
  f0.omega = base.omega.cast<T>();
  f0.omegaDot = base.omegaDot.cast<T>();
  f0.accel = base.accel.cast<T>();
  f0.up = base.up.cast<T>();
  // Shoulder, rows 1-3 (shared by Tables 1-4). Rows 1 and 2 rotate by th0 and th1 + pi/2.
  const T c1 = cos(th(0)), s1 = sin(th(0));
  const T c2 = -sin(th(1)), s2 = cos(th(1));  // cos and sin of th1 + pi/2
  const T c3 = cos(th(2)), s3 = sin(th(2));
  const FrameState<T> f1 = propagate<T, T>(f0, c1, s1, thd(0), thdd(0), 0.0, kHalfPi, 0.0);
  const FrameState<T> f2 = propagate<T, T>(f1, c2, s2, thd(1), thdd(1), 0.0, kHalfPi, 0.0);
  const FrameState<T> f3 = propagate<T, T>(f2, c3, s3, thd(2), thdd(2), 0.0, 0.0, 0.0);

  ArmKinematics<T> out;
  // Upper-arm IMU, Table 1 rows 4-6.
  {
    const FrameState<T> u4 = propagateFixed<T>(f3, 0.0, geo.lu3, 0.0);
    const FrameState<T> u5 = propagateFixed<T>(u4, geo.thu4, 0.0, kHalfPi);
    out.upperImu = propagateFixed<T>(u5, 0.0, geo.lu5, 0.0);
  }
  // Elbow, Table 2 rows 4-5; forearm, Table 3 rows 6-9.
  const T c5 = cos(th(3)), s5 = sin(th(3));
  const T c6 = cos(th(4)), s6 = sin(th(4));
  {
    const FrameState<T> e4 = propagateFixed<T>(f3, kHalfPi, geo.l3, -kHalfPi);
    const FrameState<T> e5 = propagate<T, T>(e4, c5, s5, thd(3), thdd(3), 0.0, kHalfPi, 0.0);
    const FrameState<T> e6 = propagate<T, T>(e5, c6, s6, thd(4), thdd(4), 0.0, 0.0, 0.0);
    const FrameState<T> f7 = propagateFixed<T>(e6, 0.0, geo.lf6, 0.0);
    const FrameState<T> f8 = propagateFixed<T>(f7, geo.thf7 + kHalfPi, 0.0, kHalfPi);
    out.forearmImu = propagateFixed<T>(f8, 0.0, geo.lf8, 0.0);
  }
  // Positions (eq. 11): the elbow is l3 along z3, the wrist l6 further along z6 (Table 4 row 7).
  // Vectors are carried back to frame 0 row by row, the innermost row first.
  const double c4 = 0.0, s4 = 1.0;            // row 4: gamma = pi/2
  Vec3 v(T(0), T(0), T(geo.l6));              // wrist offset in frame 6
  v = detail::toParent(v, c6, s6, 0.0);       // row 6 (no translation)
  v = detail::toParent(v, c5, s5, kHalfPi);   // row 5
  v = detail::toParent(v, c4, s4, -kHalfPi);  // row 4 rotation ...
  v(2) += T(geo.l3);                          // ... and its translation l3 along z3
  // v is now wrist - shoulder in frame 3; rotate both it and the elbow (l3 z3) to frame 0.
  Vec3 e(T(0), T(0), T(geo.l3));
  v = detail::toParent(v, c3, s3, 0.0);
  e = detail::toParent(e, c3, s3, 0.0);
  v = detail::toParent(v, c2, s2, kHalfPi);
  e = detail::toParent(e, c2, s2, kHalfPi);
  out.wrist = detail::toParent(v, c1, s1, kHalfPi);
  out.elbow = detail::toParent(e, c1, s1, kHalfPi);
  return out;
}

/// A still trunk: frame 0 fixed in the world.
template <typename T>
ArmKinematics<T> armKinematics(const ArmGeometry& geo, const Eigen::Matrix<T, 5, 1>& th,
                               const Eigen::Matrix<T, 5, 1>& thd,
                               const Eigen::Matrix<T, 5, 1>& thdd, const Eigen::Vector3d& gUp) {
  FrameState<double> base;
  base.up = gUp;
  return armKinematics<T>(geo, th, thd, thdd, base);
}

/// ArmGeometry with a generic scalar (a ceres::Jet or Eigen::AutoDiffScalar), so that predicted
/// readings can be differentiated with respect to the segment lengths and the IMU mounting
/// (sensor-to-segment calibration, core/calibration/). Same fields, units and meaning as
/// ArmGeometry.
template <typename T>
struct ArmGeometryT {
  T l3, l6, lu3, thu4, lu5, lf6, thf7, lf8;
};

/// geo's values as an ArmGeometryT<T> (constants for automatic differentiation).
template <typename T>
ArmGeometryT<T> geometryAs(const ArmGeometry& geo) {
  return {T(geo.l3),  T(geo.l6),  T(geo.lu3),  T(geo.thu4),
          T(geo.lu5), T(geo.lf6), T(geo.thf7), T(geo.lf8)};
}

/// One DH row whose lambda or gamma is a calibration unknown (no Tx offset).
template <typename T>
FrameState<T> propagateGeneric(const FrameState<T>& prev, const T& c, const T& s, const T& gammaDot,
                               const T& gammaDDot, const T& lambda, double beta) {
  return propagate<T, T, T>(prev, c, s, gammaDot, gammaDDot, lambda, beta, 0.0);
}

/// Frame 3 (the upper arm after the three shoulder rows), shared by every sensor.
template <typename T>
FrameState<T> shoulderKinematics(const Eigen::Matrix<T, 5, 1>& th,
                                 const Eigen::Matrix<T, 5, 1>& thd,
                                 const Eigen::Matrix<T, 5, 1>& thdd, const Eigen::Vector3d& gUp) {
  using std::cos;
  using std::sin;
  constexpr double kHalfPi = detail::kHalfPi;
  FrameState<T> f0;
  f0.up = gUp.cast<T>();
  const T c1 = cos(th(0)), s1 = sin(th(0));
  const T c2 = -sin(th(1)), s2 = cos(th(1));  // cos and sin of th1 + pi/2
  const T c3 = cos(th(2)), s3 = sin(th(2));
  const FrameState<T> f1 = propagate<T, T>(f0, c1, s1, thd(0), thdd(0), 0.0, kHalfPi, 0.0);
  const FrameState<T> f2 = propagate<T, T>(f1, c2, s2, thd(1), thdd(1), 0.0, kHalfPi, 0.0);
  return propagate<T, T>(f2, c3, s3, thd(2), thdd(2), 0.0, 0.0, 0.0);
}

/// The upper-arm IMU frame (Table 1 rows 4-6) from frame 3, with a generic geometry.
template <typename T>
FrameState<T> upperImuKinematics(const FrameState<T>& f3, const ArmGeometryT<T>& geo) {
  using std::cos;
  using std::sin;
  const T zero(0), one(1);
  const FrameState<T> u4 = propagateGeneric<T>(f3, one, zero, zero, zero, geo.lu3, 0.0);
  const FrameState<T> u5 =
      propagateGeneric<T>(u4, cos(geo.thu4), sin(geo.thu4), zero, zero, zero, detail::kHalfPi);
  return propagateGeneric<T>(u5, one, zero, zero, zero, geo.lu5, 0.0);
}

/// The forearm IMU frame (Table 3 rows 4-9) from frame 3, with a generic geometry.
template <typename T>
FrameState<T> forearmImuKinematics(const FrameState<T>& f3, const Eigen::Matrix<T, 5, 1>& th,
                                   const Eigen::Matrix<T, 5, 1>& thd,
                                   const Eigen::Matrix<T, 5, 1>& thdd, const ArmGeometryT<T>& geo) {
  using std::cos;
  using std::sin;
  constexpr double kHalfPi = detail::kHalfPi;
  const T zero(0), one(1);
  const FrameState<T> e4 = propagateGeneric<T>(f3, zero, one, zero, zero, geo.l3, -kHalfPi);
  const FrameState<T> e5 =
      propagate<T, T>(e4, cos(th(3)), sin(th(3)), thd(3), thdd(3), 0.0, kHalfPi, 0.0);
  const FrameState<T> e6 =
      propagate<T, T>(e5, cos(th(4)), sin(th(4)), thd(4), thdd(4), 0.0, 0.0, 0.0);
  const FrameState<T> f7 = propagateGeneric<T>(e6, one, zero, zero, zero, geo.lf6, 0.0);
  const T g8 = geo.thf7 + kHalfPi;
  const FrameState<T> f8 = propagateGeneric<T>(f7, cos(g8), sin(g8), zero, zero, zero, kHalfPi);
  return propagateGeneric<T>(f8, one, zero, zero, zero, geo.lf8, 0.0);
}

/// Elbow and wrist positions in frame 0 (m), with a generic geometry (eq. 11).
template <typename T>
void armPositions(const Eigen::Matrix<T, 5, 1>& th, const ArmGeometryT<T>& geo,
                  Eigen::Matrix<T, 3, 1>& elbow, Eigen::Matrix<T, 3, 1>& wrist) {
  using std::cos;
  using std::sin;
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  constexpr double kHalfPi = detail::kHalfPi;
  const T c1 = cos(th(0)), s1 = sin(th(0));
  const T c2 = -sin(th(1)), s2 = cos(th(1));
  const T c3 = cos(th(2)), s3 = sin(th(2));
  const T c5 = cos(th(3)), s5 = sin(th(3));
  const T c6 = cos(th(4)), s6 = sin(th(4));
  const double c4 = 0.0, s4 = 1.0;
  Vec3 v(T(0), T(0), geo.l6);
  v = detail::toParent(v, c6, s6, 0.0);
  v = detail::toParent(v, c5, s5, kHalfPi);
  v = detail::toParent(v, c4, s4, -kHalfPi);
  v(2) += geo.l3;
  Vec3 e(T(0), T(0), geo.l3);
  v = detail::toParent(v, c3, s3, 0.0);
  e = detail::toParent(e, c3, s3, 0.0);
  v = detail::toParent(v, c2, s2, kHalfPi);
  e = detail::toParent(e, c2, s2, kHalfPi);
  wrist = detail::toParent(v, c1, s1, kHalfPi);
  elbow = detail::toParent(e, c1, s1, kHalfPi);
}

/// armKinematics with a generic geometry: the same predictions, differentiable with respect to
/// the geometry as well as the joint motion.
template <typename T>
ArmKinematics<T> armKinematics(const ArmGeometryT<T>& geo, const Eigen::Matrix<T, 5, 1>& th,
                               const Eigen::Matrix<T, 5, 1>& thd,
                               const Eigen::Matrix<T, 5, 1>& thdd, const Eigen::Vector3d& gUp) {
  const FrameState<T> f3 = shoulderKinematics<T>(th, thd, thdd, gUp);
  ArmKinematics<T> out;
  out.upperImu = upperImuKinematics<T>(f3, geo);
  out.forearmImu = forearmImuKinematics<T>(f3, th, thd, thdd, geo);
  armPositions<T>(th, geo, out.elbow, out.wrist);
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

/// Wraps an angle to (-pi, pi]. An angle already there is returned as it is (the filter wraps
/// every angle twice a step, nearly always in range: shifting by pi and back would round it).
inline double wrapAngle(double a) {
  if (a > -std::numbers::pi && a <= std::numbers::pi) return a;
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  a = std::fmod(a + std::numbers::pi, kTwoPi);
  if (a <= 0) a += kTwoPi;
  return a - std::numbers::pi;
}

}  // namespace armtrack
