// The trunk's pose and motion from a sternum IMU, and the shoulder's place in the world, for the
// joint-angle filter when the patient leans and turns (docs/estimator.md, "Trunk"). Private to
// the estimator; all vectors are in the (virtual right) arm's frame-0 axes, as the filter's.
//
// Orientation: the sternum gyroscope is integrated (frame 0 turns with the thorax) and the
// accelerometer corrects the inclination, a multiplicative Kalman filter whose error is a small
// rotation in world axes. The accelerometer reads gravity plus the sternum's own acceleration; the
// part a turn about the hip pivot explains is predicted, the rest is noise. Axial rotation (about
// the vertical) rests on the gyroscope alone: its variance grows with the gyroscope's noise.
//
// Motion of frame 0 for the arm's predicted readings: the angular velocity from the gyroscope,
// the angular acceleration from a small constant-acceleration Kalman filter on it, and the
// shoulder's specific force from the sternum's through the lever arm between them.
//
// The shoulder in the world: the trunk turns about a hip pivot h (world coordinates), so the
// shoulder centre is at s = h - R h. h starts at a typical place below and medial to the shoulder
// and is refined from the optical shoulder when one is seen (a linear least-squares fit), or else
// from the arm's own optical points (addHipObservation, fed by the arm filter). Without
// a trunk IMU, an optical shoulder still gives s directly (smoothed); the rotation is then unknown
// and taken as the start pose.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>

#include "core/ArmSample.h"
#include "core/io/Recording.h"
#include "core/kinematics/ArmModel.h"

namespace armtrack::detail {

/// The cross-product matrix: skew(v) w = v x w.
inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

struct TrunkTrackerParams {
  TrunkMount mount;                            ///< the sternum IMU, frame 0 at start
  Eigen::Vector3d gUp{-9.81, 0.0, 0.0};        ///< world, frame-0 axes (m/s^2)
  Eigen::Vector3d hipPrior{0.45, 0.0, -0.15};  ///< m: below and medial (right arm)
  double hipPriorStd = 0.10;                   ///< m, per axis
  /// The optical shoulder's constant offset from the model's shoulder centre (a skeleton's
  /// shoulder joint need not sit at the centre, only move with it): prior std, m per axis.
  double shoulderOffsetStd = 0.05;
  double gyroVariance = 0.1 * 3.0461741978670859e-4;  ///< (rad/s)^2: Table 5, 0.1 (deg/s)^2
  double accelVariance = 1e-2;                        ///< (m/s^2)^2, Table 5
  double shoulderVariance = 1e-4;                     ///< m^2 per axis, optical shoulder
  double jerkSpectralDensity = 20.0;                  ///< (rad/s^3)^2 s, the trunk's turns
  double maxGap = 0.1;                                ///< s: a longer step restarts the rates
  /// Side::Left when the vectors are a left arm's mirror image (the trunk's angles then come
  /// from trunkAngles(R, Side::Left), core/kinematics/Trunk.h).
  Side side = Side::Right;
};

/// The trunk at one instant: what the arm filter needs.
struct TrunkState {
  bool haveImu = false;                                    ///< the rotation is measured
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< frame 0 to world
  Eigen::Matrix3d rotationCov = Eigen::Matrix3d::Zero();   ///< rad^2, small rotation, world
  Eigen::Vector3d shoulder = Eigen::Vector3d::Zero();      ///< shoulder centre, world (m)
  double shoulderVariance = 0.0;                           ///< m^2 per axis
  Eigen::Vector3d hip = Eigen::Vector3d::Zero();           ///< the pivot, world (m)
  Eigen::Matrix3d hipCov = Eigen::Matrix3d::Zero();        ///< its covariance (m^2)
  FrameState<double> base;                                 ///< frame 0's motion, frame-0 axes
  double baseGyroVariance = 0.0;   ///< added to the arm gyroscopes' variance, (rad/s)^2
  double baseAccelVariance = 0.0;  ///< added to the arm accelerometers' at 1 m lever, (m/s^2)^2
};

class TrunkTracker {
 public:
  explicit TrunkTracker(const TrunkTrackerParams& p);
  /// A sternum IMU reading (IMU axes) at time t.
  void addImu(double t, const ImuReading& r);
  /// An optical shoulder position (world) at time t.
  void addShoulder(double t, const Eigen::Vector3d& s);
  /// A linear observation of the hip pivot from the arm's own optical points: what was seen minus
  /// what the arm and the trunk's pose predict, `residual ~ a (h_true - h)` with variance
  /// `variance` per row (rows: 3 for a point in the world, 2 for a pixel).
  void addHipObservation(const Eigen::Matrix<double, Eigen::Dynamic, 3>& a,
                         const Eigen::VectorXd& residual, double variance);
  const TrunkState& state() const { return m_state; }
  /// Flexion, lateral bending, axial rotation (rad, patient terms) and their standard deviations.
  Eigen::Vector3d angles() const;
  Eigen::Vector3d angleStd() const;
  bool seenImu() const { return m_haveImu; }
  bool seenShoulder() const { return m_haveShoulder; }

 private:
  void updateShoulder();

  TrunkTrackerParams m_p;
  TrunkState m_state;
  bool m_haveImu = false, m_haveShoulder = false;
  double m_t = 0.0;
  Eigen::Matrix3d m_P = Eigen::Matrix3d::Zero();  // rotation error covariance (world)
  // Per-axis [omega, alpha] filters of frame 0's angular velocity.
  Eigen::Matrix<double, 2, 3> m_rate = Eigen::Matrix<double, 2, 3>::Zero();
  std::array<Eigen::Matrix2d, 3> m_rateP{};
  // Hip pivot h and the optical shoulder's offset c: the information form of their joint
  // least-squares fit (each frame s = (I - R) h + c + noise), with priors on both.
  Eigen::Matrix<double, 6, 6> m_fitInfo = Eigen::Matrix<double, 6, 6>::Identity();
  Eigen::Matrix<double, 6, 1> m_fitVec = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Vector3d m_hip = Eigen::Vector3d::Zero();
  Eigen::Matrix3d m_hipCov = Eigen::Matrix3d::Zero();  // h's marginal covariance
  // Without a trunk IMU: the optical shoulder, low-passed.
  Eigen::Vector3d m_shoulderSmooth = Eigen::Vector3d::Zero();
  double m_shoulderT = 0.0;
  // Without a trunk IMU: the optical shoulder's start position (its mean over the first frames),
  // from which its displacement is taken.
  Eigen::Vector3d m_reference = Eigen::Vector3d::Zero();
  int m_referenceCount = 0;
};

}  // namespace armtrack::detail
