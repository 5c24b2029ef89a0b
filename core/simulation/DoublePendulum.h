// A planar two-segment chain with a fixed pivot swinging under gravity (a double pendulum of two
// uniform rods with viscous damping in both joints), integrated from its real equations of
// motion, and the recording its two IMUs would give, read in the arm model's terms
// (docs/baseline.md, "The double pendulum"): the pivot is the shoulder, the swing is shoulder
// flexion th0, the hinge is elbow flexion th4; the other joints stay at zero.
#pragma once

#include <cstdint>
#include <numbers>
#include <vector>

#include "core/io/Recording.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {

struct PendulumParams {
  double upperLength = 0.22;   ///< m, pivot to hinge (the model's l3)
  double lowerLength = 0.20;   ///< m, hinge to the free end (the model's l6)
  double upperMass = 1.0;      ///< kg, uniform rod
  double lowerMass = 0.7;      ///< kg, uniform rod
  double pivotDamping = 2e-3;  ///< N m s, torque -b * swing rate at the pivot
  double hingeDamping = 1e-3;  ///< N m s, torque -b * hinge rate between the rods
  double g = 9.81;             ///< m/s^2
  /// Release pose (rad): the upper rod from the downward vertical (forward positive) and the
  /// lower rod relative to the upper (positive turns it further forward), both at rest.
  double swing0 = 80.0 * std::numbers::pi / 180.0;
  double hinge0 = 70.0 * std::numbers::pi / 180.0;
  double holdSeconds = 1.0;  ///< s held still at the release pose before it is let go
  double step = 1e-4;        ///< s, the Runge-Kutta step
};

/// The pendulum's motion, integrated once (classical fourth-order Runge-Kutta) over a duration and
/// looked up at any time in it. Deterministic.
class DoublePendulum {
 public:
  struct State {
    double swing = 0, hinge = 0;            ///< rad: upper rod from down; lower relative to upper
    double swingRate = 0, hingeRate = 0;    ///< rad/s
    double swingAccel = 0, hingeAccel = 0;  ///< rad/s^2
  };
  /// Throws std::invalid_argument for non-positive lengths, masses, step or g, negative damping
  /// or hold, or a non-finite duration.
  DoublePendulum(const PendulumParams& params, double duration);
  /// The motion at time t (s; clamped to [0, duration]).
  State at(double t) const;
  /// Kinetic plus potential energy (J, zero potential at the pivot's height) at time t.
  double energy(double t) const;
  const PendulumParams& params() const { return m_p; }

 private:
  struct Abs {
    double p1, p2, w1, w2;  // absolute angles of the rods from down, and their rates
  };
  void accelerations(const Abs& s, double& a1, double& a2) const;
  Abs rk4(const Abs& s, double h) const;
  Abs absAt(double t) const;

  PendulumParams m_p;
  double m_duration;
  double m_gridStep;        // s between stored states (a whole number of steps)
  std::vector<Abs> m_grid;  // states after the hold, every m_gridStep
};

/// The pendulum's motion as a Trajectory of the arm model (th0 = swing, th4 = -(hinge + zero)).
class PendulumTrajectory final : public Trajectory {
 public:
  PendulumTrajectory(const DoublePendulum& pendulum, double zeroOffset);
  JointMotion at(double t) const override;

 private:
  const DoublePendulum& m_pendulum;
  double m_zero;
};

struct PendulumSimParams {
  PendulumParams pendulum;
  double duration = 60.0;       ///< s
  double outputRateHz = 100.0;  ///< the logger's clock: one row per tick
  /// The sensors' own rates (Hz); 0 = a new reading every row. Below the output rate the logger
  /// repeats the last reading until a new one comes (sample and hold).
  double gyroRateHz = 0.0;
  double accelRateHz = 0.0;
  double gyroNoiseStd = 0.0;   ///< rad/s, white, per new reading
  double accelNoiseStd = 0.0;  ///< m/s^2, white, per new reading
  std::uint64_t seed = 1;
  /// Where the model's straight elbow is put relative to the pendulum's straight hinge (rad): the
  /// model's elbow flexion when the rods are in line. The forearm IMU's readings are turned into
  /// the model's forearm IMU frame, as a mounting tool would; the sensor itself stays on the rod,
  /// so with a zero other than 0 its real lever arm is off the model's forearm axis.
  double zeroOffset = 0.0;
  /// The sidecar's forearm mounting (lf6, lf8, thf7) put where the sensor really sits on the rod,
  /// and its readings turned into that frame: what a mounting tool that measured the sensor's
  /// lever arm writes (pendulumMountingOnRod). Both estimators are then told the real lever arm
  /// and the zero only relabels the hinge. False: the model's mounting, whose lever arm the zero
  /// turns off the rod.
  bool mountingOnRod = false;
  /// Strap wobble on both IMUs (core/simulation/ImuErrors.h: a spring-damper between the sensor
  /// and the rod, driven by the rod's acceleration at the sensor): the static tilt per m/s^2 of
  /// acceleration (rad; 0: none, and the readings are as without it), the translational gain, the
  /// natural frequency and damping ratio. The realistic preset draws the tilt from 0.03-0.08 deg
  /// per m/s^2, the gain from 0.1-0.4, 8-20 Hz, 0.2-0.5.
  double wobbleTiltPerAccel = 0.0;
  double wobbleTranslationGain = 0.0;
  double wobbleFrequencyHz = 12.0;
  double wobbleDamping = 0.3;
};

/// The recording: both IMUs on every row (the arm model's mounting with lu3 = l3 / 2 and
/// lf6 = l6, so the sensors sit where the sidecar says), the true joint angles, no optics.
/// Throws std::invalid_argument on bad parameters.
Recording simulatePendulum(const PendulumSimParams& params);

/// The sidecar geometry simulatePendulum uses for a pendulum.
ArmGeometry pendulumGeometry(const PendulumParams& pendulum);

/// geometry with its forearm IMU moved to where it sits on the rod when the model's straight
/// elbow is put zeroOffset (rad) from the rod's straight hinge: the same point relative to the
/// elbow, in the cylinder coordinates of the forearm's axis (lf6 along it, lf8 out at thf7).
ArmGeometry pendulumMountingOnRod(const ArmGeometry& geometry, double zeroOffset);

}  // namespace armtrack
