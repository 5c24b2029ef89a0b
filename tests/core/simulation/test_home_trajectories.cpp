// The movements the virtual arm plays for a home session: the sensor check (only the elbow
// moves, after a still start) and an exercise repeated, with its rates consistent with its angles
// and its faults where they were put.
#include <gtest/gtest.h>

#include <cmath>

#include "core/kinematics/ClinicalAngles.h"
#include "core/simulation/Trajectory.h"

using namespace armtrack;

namespace {

std::array<double, 5> clinical(const JointVector& th) {
  return asArray(toClinical(th));
}

// Central differences of th(t), to hold the analytic rates to.
void expectRatesMatchAngles(const Trajectory& traj, double from, double to) {
  const double h = 1e-5;
  for (double t = from; t < to; t += 0.0371) {
    const JointMotion m = traj.at(t);
    const JointVector d = (traj.at(t + h).th - traj.at(t - h).th) / (2 * h);
    const JointVector dd = (traj.at(t + h).thd - traj.at(t - h).thd) / (2 * h);
    EXPECT_LT((m.thd - d).cwiseAbs().maxCoeff(), 1e-6) << "t = " << t;
    EXPECT_LT((m.thdd - dd).cwiseAbs().maxCoeff(), 1e-4) << "t = " << t;
  }
}

}  // namespace

TEST(SensorCheckTrajectory, StillThenOnlyTheElbowBends) {
  const SensorCheckTrajectory check;
  EXPECT_EQ(check.duration(), 13.0);
  for (double t = 0; t <= SensorCheckTrajectory::restSeconds(); t += 0.1) {
    EXPECT_EQ(check.at(t).th, JointVector::Zero()) << t;
    EXPECT_EQ(check.at(t).thd, JointVector::Zero()) << t;
  }
  double peak = 0;
  int tops = 0;
  for (int i = 0; i < SensorCheckTrajectory::bends(); ++i) {
    const double top =
        SensorCheckTrajectory::restSeconds() + (i + 0.5) * SensorCheckTrajectory::bendSeconds();
    const std::array<double, 5> c = clinical(check.at(top).th);
    EXPECT_NEAR(c[3], SensorCheckTrajectory::bendDeg(), 1e-9);
    tops += std::abs(c[3] - 100.0) < 1e-6;
  }
  EXPECT_EQ(tops, 3);
  for (double t = 0; t < check.duration() + 1; t += 0.05) {
    const JointMotion m = check.at(t);
    // The shoulder and the forearm's rotation never move.
    for (int j : {0, 1, 2, 4}) {
      EXPECT_EQ(m.th(j), 0.0);
      EXPECT_EQ(m.thd(j), 0.0);
    }
    peak = std::max(peak, clinical(m.th)[3]);
  }
  EXPECT_NEAR(peak, 100.0, 1e-6);
  EXPECT_EQ(check.at(check.duration() + 5).th, JointVector::Zero());
  expectRatesMatchAngles(check, 0.01, check.duration());
}

TEST(ExerciseTrajectory, RepeatsBetweenItsEndsWithPauses) {
  ExerciseMotion m;
  m.angle = 0;  // shoulder flexion
  m.fromDeg = 10;
  m.toDeg = 110;
  m.periodSeconds = 4;
  m.pauseSeconds = 1;
  m.startSeconds = 2;
  const ExerciseTrajectory ex(m);
  // Still at rest before the first repetition.
  for (double t = 0; t <= 2.0; t += 0.25) {
    const std::array<double, 5> c = clinical(ex.at(t).th);
    EXPECT_NEAR(c[0], 10, 1e-9);
    EXPECT_NEAR(c[3], 5, 1e-9);  // the elbow almost straight
  }
  // Each repetition tops out at toDeg half a period in, and the cycle repeats every 5 s.
  for (int rep = 0; rep < 4; ++rep) {
    const double top = 2.0 + rep * 5.0 + 2.0;
    EXPECT_NEAR(clinical(ex.at(top).th)[0], 110, 1e-9) << rep;
    EXPECT_NEAR(clinical(ex.at(top + 2.5).th)[0], 10, 1e-9) << rep;  // in the pause
  }
  // Nothing else moves.
  for (double t = 0; t < 30; t += 0.1) {
    const std::array<double, 5> c = clinical(ex.at(t).th);
    EXPECT_NEAR(c[1], 0, 1e-12);
    EXPECT_NEAR(c[3], 5, 1e-9);
    EXPECT_GE(c[0], 10 - 1e-9);
    EXPECT_LE(c[0], 110 + 1e-9);
  }
  expectRatesMatchAngles(ex, 0.01, 25);
}

TEST(ExerciseTrajectory, CompensationMovesTheOtherAngle) {
  ExerciseMotion m;
  m.angle = 0;
  m.fromDeg = 0;
  m.toDeg = 90;
  m.compensationDeg = 40;
  const ExerciseTrajectory shoulder(m);
  EXPECT_EQ(ExerciseTrajectory::compensatingAngle(0), 3);
  const double top = m.startSeconds + 0.5 * m.periodSeconds;
  EXPECT_NEAR(clinical(shoulder.at(top).th)[3], 45, 1e-9);  // the elbow bends 5 -> 45 deg
  m.angle = 3;  // elbow flexion: the shoulder lifts instead
  m.fromDeg = 20;
  m.toDeg = 120;
  const ExerciseTrajectory elbow(m);
  EXPECT_EQ(ExerciseTrajectory::compensatingAngle(3), 0);
  EXPECT_NEAR(clinical(elbow.at(top).th)[0], 40, 1e-9);
  EXPECT_NEAR(clinical(elbow.at(top).th)[3], 120, 1e-9);
  // Forearm rotation is done with the elbow at a right angle.
  m.angle = 4;
  m.fromDeg = -40;
  m.toDeg = 60;
  m.compensationDeg = 0;
  const ExerciseTrajectory pronation(m);
  EXPECT_NEAR(clinical(pronation.at(0).th)[3], 90, 1e-9);
  EXPECT_NEAR(clinical(pronation.at(top).th)[4], 60, 1e-9);
}

TEST(ExerciseTrajectory, RefusesNonsense) {
  const auto refused = [](ExerciseMotion m) {
    EXPECT_THROW(ExerciseTrajectory{m}, std::invalid_argument);
  };
  ExerciseMotion m;
  m.angle = 5;
  refused(m);
  m = {};
  m.angle = -1;
  refused(m);
  m = {};
  m.periodSeconds = 0;
  refused(m);
  m = {};
  m.pauseSeconds = -1;
  refused(m);
  m = {};
  m.toDeg = std::nan("");
  refused(m);
  m = {};
  m.startSeconds = INFINITY;
  refused(m);
  TrajectoryOptions o;
  o.exercise.angle = 9;
  EXPECT_THROW(makeTrajectory("exercise", o), std::invalid_argument);
}
