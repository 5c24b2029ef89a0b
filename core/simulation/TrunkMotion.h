// A simulated patient's trunk: it leans and turns about a hip point as the arm reaches
// (compensation), with a small sway of its own. The angles are the patient-term trunk angles of
// core/kinematics/Trunk.h; the pose and its motion follow, with exact first and second
// derivatives, so the simulator can give a sternum IMU and the arm's moving base their readings.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>

#include "core/kinematics/ArmModel.h"
#include "core/kinematics/Side.h"
#include "core/kinematics/Trunk.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {

/// How the simulated trunk moves. Off by default: a still, upright trunk (the simulation is then
/// exactly what it was before the trunk existed).
///
/// The lean follows the arm's reaches as patients compensate: with shoulder flexion th0, the
/// reach's target r(t) = S((th0 - reachStartDeg) / (fullReachDeg - reachStartDeg)) S(t /
/// startSeconds), S the quintic smoothstep 10x^3 - 15x^4 + 6x^5 clamped to [0, 1] (flat at both
/// ends). The second factor brings the lean in over the first startSeconds, so the trunk is
/// upright at t = 0, where the world frame is registered, whatever the arm's first posture.
///
/// The trunk is heavier and slower than the arm, so it does not follow r at the arm's pace: its
/// reach w(t) is r averaged over the last followSeconds with a raised-cosine weight (kFollowTaps
/// samples; r before t = 0 is r(0)). Fast reaches then lean the trunk over about followSeconds,
/// and rates and accelerations stay continuous and exact (the average of r's derivatives). Each
/// angle is
///   flexion  = leanDeg w                          + (1 - w) sway_flexion(t)
///   lateral  = lateralSign  lateralRatio leanDeg w + (1 - w) sway_lateral(t)
///   rotation = rotationSign rotationRatio leanDeg w + (1 - w) sway_rotation(t)
/// so once the arm has held its fullest reach for followSeconds (after startSeconds) the trunk is
/// at exactly leanDeg forward, and no angle ever exceeds max(its lean part, swayDeg). The sway of
/// each angle is (swayDeg / 2) (sin(2 pi f t + p) - sin p) with f in [swayMinHz, swayMaxHz] and p
/// drawn from swaySeed: zero at t = 0, never beyond swayDeg.
struct TrunkSimParams {
  bool enabled = false;
  /// The hip pivot the trunk turns about, in the arm's frame 0 with the trunk upright (m, relative
  /// to the shoulder centre). Unset: 0.45 m below and 0.15 m medial to the shoulder, i.e.
  /// (0.45, 0, -0.15) for a right arm and (0.45, 0, 0.15) for a left one (z0 points to the
  /// patient's right for both).
  std::optional<Eigen::Vector3d> hip;
  double leanDeg = 15.0;        ///< forward lean at the fullest reach (deg)
  double lateralRatio = 0.5;    ///< lateral bending at the fullest reach, per degree of lean
  double rotationRatio = 0.5;   ///< axial rotation at the fullest reach, per degree of lean
  double lateralSign = 1.0;     ///< +1: leans towards the patient's right when reaching
  double rotationSign = 1.0;    ///< +1: the right shoulder comes forward when reaching
  double reachStartDeg = 20.0;  ///< shoulder flexion at which the lean starts (deg)
  double fullReachDeg = 90.0;   ///< shoulder flexion of the fullest reach (deg)
  double startSeconds = 2.0;    ///< the lean comes in over this time from t = 0 (s, >= 0)
  /// The trunk follows the reach averaged over this long (s, >= 0; 0: at the arm's own pace).
  /// Default 0.8 s: a fast reach (the arm at 400 deg/s) leans the trunk 20 deg at up to about
  /// 50 deg/s, where following at the arm's pace turned it at 225 deg/s.
  double followSeconds = 0.8;
  double swayDeg = 1.0;         ///< largest sway of each angle on its own (deg, >= 0)
  double swayMinHz = 0.1;       ///< sway frequencies are drawn from [swayMinHz, swayMaxHz]
  double swayMaxHz = 0.3;
  std::uint64_t swaySeed = 1;
};

/// The trunk's angles (patient terms, rad) and their first and second time derivatives.
struct TrunkMotionState {
  TrunkAngles angles = TrunkAngles::Zero();
  Eigen::Vector3d rates = Eigen::Vector3d::Zero();
  Eigen::Vector3d accels = Eigen::Vector3d::Zero();
};

/// The trunk's pose and motion in the world (frame 0 as it was upright), for one side's frame-0
/// axes: R = trunkRotation(angles, side), and the angular velocity and acceleration of the thorax
/// in world coordinates.
struct TrunkPose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();     ///< rad/s, world coordinates
  Eigen::Vector3d omegaDot = Eigen::Vector3d::Zero();  ///< rad/s^2, world coordinates
};

/// The default hip pivot for a side (see TrunkSimParams::hip).
Eigen::Vector3d defaultHip(Side side);

class TrunkMotion {
 public:
  /// Throws std::invalid_argument for non-finite values, a negative sway or start, sway
  /// frequencies outside (0, inf) or in the wrong order, a sign other than +-1, or fullReachDeg
  /// not above reachStartDeg.
  explicit TrunkMotion(const TrunkSimParams& params);
  /// The trunk's motion at t while the arm moves as given (its shoulder flexion over the last
  /// followSeconds drives the lean).
  TrunkMotionState at(double t, const Trajectory& arm) const;

  /// Samples of the reach's average (see TrunkSimParams).
  static constexpr int kFollowTaps = 48;

 private:
  struct Reach {
    double w = 0.0, wd = 0.0, wdd = 0.0;
  };
  /// The reach's target r and its derivatives at t with the arm's motion there.
  Reach target(double t, const JointMotion& arm) const;

  struct Sway {
    double amplitude, frequency, phase;  // rad, Hz, rad
  };
  TrunkSimParams m_params;
  std::array<Sway, 3> m_sway;
  std::array<double, kFollowTaps> m_weight{};  // the average's weights, summing to 1
};

/// R, its angular velocity and angular acceleration (world coordinates) from the angles' motion.
TrunkPose trunkPose(const TrunkMotionState& motion, Side side);

/// The motion of frame 0 as the arm's kinematics take it (armKinematics' base): the thorax's
/// angular velocity and acceleration, the shoulder centre's acceleration (the shoulder turning
/// about hip h) and gUpWorld, all in frame-0 coordinates.
FrameState<double> trunkBase(const TrunkPose& pose, const Eigen::Vector3d& hip,
                             const Eigen::Vector3d& gUpWorld);

/// Where a point fixed to the thorax at p (frame 0, upright) is in the world: h + R (p - h).
inline Eigen::Vector3d trunkPointInWorld(const TrunkPose& pose, const Eigen::Vector3d& hip,
                                         const Eigen::Vector3d& p) {
  return hip + pose.rotation * (p - hip);
}

}  // namespace armtrack
