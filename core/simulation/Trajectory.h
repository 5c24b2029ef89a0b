// Seeded, deterministic joint-angle trajectories with exact first and second derivatives.
#pragma once

#include <cstdint>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/kinematics/ArmModel.h"

namespace armtrack {

/// Joint angles (rad), rates (rad/s) and accelerations (rad/s^2) at one instant.
struct JointMotion {
  JointVector th = JointVector::Zero();
  JointVector thd = JointVector::Zero();
  JointVector thdd = JointVector::Zero();
};

class Trajectory {
 public:
  virtual ~Trajectory() = default;
  /// Motion at time t (s). Deterministic: the same t always gives the same result.
  virtual JointMotion at(double t) const = 0;
};

/// th_j(t) = offset_j + amplitude_j * sin(2 pi frequency_j t + phase_j), per joint.
class SinusoidTrajectory final : public Trajectory {
 public:
  JointVector offset = JointVector::Zero();     ///< rad
  JointVector amplitude = JointVector::Zero();  ///< rad
  JointVector frequency = JointVector::Zero();  ///< Hz
  JointVector phase = JointVector::Zero();      ///< rad
  JointMotion at(double t) const override;
};

/// Smooth multi-joint motion: every joint moves as a sum of a few sinusoids whose amplitudes,
/// frequencies (0.1-maxFrequency Hz) and phases are drawn from a seeded generator, around a
/// mid-range posture, staying inside anatomical ranges (docs/arm-model.md).
/// Centre [40 30 0 -60 0] deg; per joint 2-3 components whose amplitudes sum to
/// [40 25 35 45 50] deg * amplitudeScale, capped at [80 50 60 60 80] deg (so th1 stays within
/// [-20, 80] deg and th4 within [-120, 0] deg). Throws std::invalid_argument if
/// maxFrequencyHz < 0.1 or amplitudeScale < 0.
class MultiJointTrajectory final : public Trajectory {
 public:
  explicit MultiJointTrajectory(std::uint64_t seed, double maxFrequencyHz = 0.8,
                                double amplitudeScale = 1.0);
  JointMotion at(double t) const override;

 private:
  struct Component {
    int joint;
    double amplitude, frequency, phase;  // rad, Hz, rad
  };
  JointVector m_centre;
  std::vector<Component> m_components;
};

/// The shoulder-wheel task of the paper's section 4: the hand grips a handle at radius r on a
/// wheel in the sagittal plane, centre w forward of and h below the shoulder, turning at a
/// constant rate; th1 = th2 = th5 = 0 and (th0, th4) follow from planar inverse kinematics with
/// the hand s beyond the wrist. Lengths in m. The handle is at (x0, y0) = (h, w) +
/// r (cos phi, sin phi), phi = 2 pi t / period; the IK takes the branch th4 <= 0. Throws
/// std::invalid_argument unless every handle position is strictly reachable and the circle does
/// not enclose the shoulder.
class ShoulderWheelTrajectory final : public Trajectory {
 public:
  ShoulderWheelTrajectory(const ArmGeometry& geometry, double periodSeconds = 4.0, double w = 0.25,
                          double h = 0.05, double r = 0.15, double s = 0.04);
  JointMotion at(double t) const override;
  /// Joint angles only (the inverse kinematics), for wheel angle phi (rad).
  JointVector anglesAt(double phi) const;

 private:
  ArmGeometry m_geometry;
  double m_period, m_w, m_h, m_r, m_s;
};

/// Postures joined by minimum-jerk moves, s(u) = 10u^3 - 15u^4 + 6u^5: rates and accelerations
/// are continuous and zero at every key. Before the first key and after the last the arm holds.
class MinimumJerkPath {
 public:
  /// Appends a key: the arm reaches th (rad) at time t (s), t not before the previous key's.
  void add(double t, const JointVector& th);
  /// Holds the last posture for s seconds (a second key at the same posture).
  void hold(double seconds);
  JointMotion at(double t) const;
  double endTime() const;
  const JointVector& lastPosture() const;

 private:
  struct Key {
    double t;        // s, time the arm reaches the pose
    JointVector th;  // rad
  };
  std::vector<Key> m_keys;
};

/// The sensor-to-segment calibration protocol of docs/calibration.md, as a therapist would guide
/// it (about 57 s): the start pose held 4 s (upper arm hanging, elbow flexed 90 deg, forearm
/// pointing forward, thumb up: th = [0 0 0 -90 0] deg), four static poses (2 s move, 2 s hold),
/// then functional movements (elbow flexion with pronation/supination, shoulder rotation with the
/// elbow at 90 deg, reach-to-mouth, abduction/adduction), and back to the start pose held 3 s.
/// Moves between consecutive key poses follow a minimum-jerk (quintic) profile, so rates and
/// accelerations are continuous and zero at every key pose. Before 0 and after duration() the arm
/// stays in the start pose.
class CalibrationProtocolTrajectory final : public Trajectory {
 public:
  CalibrationProtocolTrajectory();
  JointMotion at(double t) const override;
  /// Length of the protocol (s).
  double duration() const;
  /// The start pose [0 0 0 -90 0] deg, in rad.
  static JointVector startPose();

 private:
  MinimumJerkPath m_path;
};

/// Fast, smooth reaching: the arm moves from one posture to the next, all five joints at once,
/// each move a minimum-jerk profile, with a short pause (0.1-0.4 s) between moves. Target postures
/// are drawn from a seeded generator inside anatomical ranges (th0 [-40, 120], th1 [-20, 80],
/// th2 [-60, 60], th4 [-120, 0], th5 [-80, 80] deg), each at least 60 deg from the last in the
/// joint that moves most. A move lasts long enough that no joint exceeds peakRate (rad/s) or
/// peakAccel (rad/s^2); the joint that moves most reaches one of the two. Minimum jerk gives
/// peak rate 1.875 A / T and peak acceleration 5.77 A / T^2 for a move of A over T seconds.
/// Moves are planned for durationSeconds; after that the arm holds its last posture.
class ReachingTrajectory final : public Trajectory {
 public:
  /// Throws std::invalid_argument unless peakRate and peakAccel are finite and positive.
  ReachingTrajectory(std::uint64_t seed, double peakRate, double peakAccel,
                     double durationSeconds = 600.0);
  JointMotion at(double t) const override;

 private:
  MinimumJerkPath m_path;
};

/// A patient's session of reaches: the arm rests in the start pose the patient is told to take
/// (restPose(): upper arm hanging, elbow at a right angle, forearm forward, thumb up) still for
/// startSeconds, then reaches to a posture drawn as ReachingTrajectory draws them, holds it
/// 0.3-0.8 s and comes back to rest, and rests 1-3 s before the next reach. Each rest posture,
/// the first too, is the rest pose moved by up to restScatter() per joint (a patient's scatter).
/// Moves are limited by peakRate and peakAccel as in ReachingTrajectory; the rests are what
/// real sessions have and what a gyroscope's bias at rest is taken from.
/// Where a SessionTrajectory rests and how closely the patient keeps to it.
struct SessionRest {
  JointVector pose;          ///< rad
  double scatter = 0.0;      ///< rad: each rest within this of pose, per joint
  bool scatterFirst = true;  ///< the first rest too (from a generator of its own)
  /// The start pose the patient is told to rest in (the default).
  static SessionRest startPose();
  /// The rest of the sessions simulated before the start pose was asked for (hand on the lap:
  /// shoulder flexed 15 deg, abducted 10, elbow flexed 80, up to 5 deg per joint, the first rest
  /// exact): for tests whose figures were measured on those sessions.
  static SessionRest handOnLap();
};

class SessionTrajectory final : public Trajectory {
 public:
  /// Throws std::invalid_argument unless peakRate and peakAccel are finite and positive and
  /// the durations are finite and >= 0.
  SessionTrajectory(std::uint64_t seed, double peakRate, double peakAccel,
                    double durationSeconds = 600.0, double startSeconds = 3.0,
                    const SessionRest& rest = SessionRest::startPose());
  JointMotion at(double t) const override;
  static JointVector restPose();
  static constexpr double restScatter() { return 3.0 * std::numbers::pi / 180.0; }  ///< rad

 private:
  MinimumJerkPath m_path;
};

/// The sensor check before a home session (core/calibration/SensorCheck.h): the arm hangs still,
/// elbow straight, for restSeconds(), then the elbow bends to 100 deg and straightens
/// bends() times, each bend bendSeconds() long (minimum jerk), then the arm hangs still again
/// until duration(). Only the elbow moves, so the forearm's gyroscope sees it and the upper
/// arm's does not.
class SensorCheckTrajectory final : public Trajectory {
 public:
  SensorCheckTrajectory();
  JointMotion at(double t) const override;
  static constexpr double restSeconds() { return 3.0; }
  static constexpr double bendSeconds() { return 3.0; }
  static constexpr int bends() { return 3; }
  static constexpr double bendDeg() { return 100.0; }
  static constexpr double duration() { return restSeconds() + bends() * bendSeconds() + 1.0; }

 private:
  MinimumJerkPath m_path;
};

/// One exercise repeated as a patient at home would do it: one clinical angle goes from fromDeg
/// to toDeg and back (minimum jerk, periodSeconds per repetition), with a pause at rest between
/// repetitions, the other angles held in a posture that suits the exercise (the elbow at 90 deg
/// for forearm rotation, almost straight otherwise). Faults a home window must notice can be
/// put in: compensationDeg makes another angle move with each repetition (the elbow for a
/// shoulder exercise, shoulder flexion for an elbow or forearm one).
struct ExerciseMotion {
  int angle = 3;               ///< clinical angle index (clinicalAngleInfo() order): elbow flexion
  double fromDeg = 20;         ///< rest (clinical degrees)
  double toDeg = 120;          ///< top of each repetition
  double periodSeconds = 4.0;  ///< up and down, s (> 0)
  double pauseSeconds = 1.0;   ///< at rest between repetitions, s (>= 0)
  double startSeconds = 1.0;   ///< still at rest before the first repetition, s (>= 0)
  double compensationDeg = 0;  ///< another angle's excursion with each repetition (deg)
};

class ExerciseTrajectory final : public Trajectory {
 public:
  /// Throws std::invalid_argument for an angle outside 0-4, a non-finite value, a period <= 0 or
  /// a negative pause or start.
  explicit ExerciseTrajectory(const ExerciseMotion& motion);
  JointMotion at(double t) const override;
  /// The clinical angle (index) that compensationDeg moves for this exercise.
  static int compensatingAngle(int exerciseAngle);

 private:
  ExerciseMotion m_motion;
  MinimumJerkPath m_cycle;  // one repetition and its pause, from time 0
  double m_cycleSeconds;
};

struct TrajectoryOptions {
  std::uint64_t seed = 1;
  JointVector amplitude = JointVector::Constant(0.5);    ///< sinusoid: rad
  JointVector frequency = JointVector::Constant(0.5);    ///< sinusoid: Hz
  JointVector offset = JointVector::Zero();              ///< sinusoid: rad
  double maxFrequencyHz = 0.8;                           ///< multi-joint
  double amplitudeScale = 1.0;                           ///< multi-joint
  double wheelPeriod = 4.0;                              ///< shoulder wheel: s per turn
  double peakRate = 420.0 * std::numbers::pi / 180.0;    ///< reaching: rad/s
  double peakAccel = 4000.0 * std::numbers::pi / 180.0;  ///< reaching: rad/s^2
  double duration = 600.0;                               ///< reaching: s of planned moves
  ArmGeometry geometry;                                  ///< shoulder wheel
  ExerciseMotion exercise;                               ///< exercise
};

/// Names: "sinusoid", "multi-joint", "shoulder-wheel", "calibration" (the calibration protocol),
/// "reaching", "session" (SessionTrajectory: reaches from a rest and back, with rests),
/// "sensor-check" (SensorCheckTrajectory), "exercise" (ExerciseTrajectory).
/// Throws std::invalid_argument otherwise.
std::unique_ptr<Trajectory> makeTrajectory(const std::string& name, const TrajectoryOptions& opts);
std::vector<std::string> trajectoryNames();

}  // namespace armtrack
