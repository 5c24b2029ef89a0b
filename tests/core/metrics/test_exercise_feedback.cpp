// Live feedback on an exercise against simulated motions with known faults: done well, too fast,
// too small, with the elbow bending during a shoulder exercise (the simulator's compensation), on
// the true angles with estimator-like noise and on the angles the EKF estimates from simulated
// IMUs and a Kinect; and which angles can be trusted without optical data.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/estimation/RecordingEstimator.h"
#include "core/kinematics/ClinicalAngles.h"
#include "core/metrics/ExerciseFeedback.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

constexpr double kDeg = kDegToRad;

ExerciseSpec spec(int angle, double loDeg, double hiDeg) {
  ExerciseSpec s;
  s.primaryAngle = angle;
  s.target = {loDeg * kDeg, hiDeg * kDeg};
  return s;
}

struct Feedback {
  std::vector<FeedbackEvent> events;
  std::size_t count(FeedbackKind k) const {
    return static_cast<std::size_t>(std::count_if(
        events.begin(), events.end(), [k](const FeedbackEvent& e) { return e.kind == k; }));
  }
};

/// Feeds the true clinical angles of motion at 100 Hz for seconds, with Gaussian noise (deg),
/// taking the events every 25 ms as a GUI timer would.
Feedback feed(ExerciseFeedback& f, const ExerciseMotion& motion, double seconds,
              double noiseDeg = 0.3, unsigned seed = 5) {
  const ExerciseTrajectory trajectory(motion);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, noiseDeg * kDeg);
  Feedback run;
  for (int k = 0; k <= static_cast<int>(seconds * 100); ++k) {
    const double t = k / 100.0;
    std::array<double, 5> c = asArray(toClinical(trajectory.at(t).th));
    for (double& a : c) a = a * kDeg + noise(rng);
    f.add(t, c);
    if (k % 3 == 0)
      for (const FeedbackEvent& e : f.takeEvents()) run.events.push_back(e);
  }
  for (const FeedbackEvent& e : f.takeEvents()) run.events.push_back(e);
  return run;
}

ExerciseMotion elbowMotion(double toDeg, double period) {
  ExerciseMotion m;
  m.angle = 3;
  m.fromDeg = 30;
  m.toDeg = toDeg;
  m.periodSeconds = period;
  m.pauseSeconds = 1.0;
  m.startSeconds = 1.0;
  return m;
}

TEST(ExerciseFeedback, WellDoneRepetitionsAreCountedAndReachTheTarget) {
  ExerciseFeedback f(spec(3, 30, 120));
  // Five repetitions of 4 s with 1 s pauses after a 1 s start: 26 s.
  const Feedback run = feed(f, elbowMotion(120, 4.0), 26.5);
  EXPECT_EQ(f.repetitions(), 5u);
  EXPECT_EQ(run.count(FeedbackKind::RepetitionCounted), 5u);
  EXPECT_EQ(run.count(FeedbackKind::TargetReached), 5u);
  EXPECT_EQ(f.targetReached(), 5u);
  EXPECT_EQ(run.count(FeedbackKind::RangeNotReached), 0u);
  EXPECT_EQ(run.count(FeedbackKind::TooFast), 0u);
  EXPECT_EQ(run.count(FeedbackKind::Compensation), 0u);
  EXPECT_EQ(f.partial(), 0u);
  EXPECT_NEAR(f.rangeMaxRad() / kDeg, 120, 1.5);
  EXPECT_NEAR(f.rangeMinRad() / kDeg, 30, 1.5);
  // The target is told live, at the top of each repetition (2 s into it), before it is counted.
  for (int rep = 0; rep < 5; ++rep) {
    const auto reached =
        std::find_if(run.events.begin(), run.events.end(), [rep](const FeedbackEvent& e) {
          return e.kind == FeedbackKind::TargetReached && e.repetition == rep + 1;
        });
    const auto counted =
        std::find_if(run.events.begin(), run.events.end(), [rep](const FeedbackEvent& e) {
          return e.kind == FeedbackKind::RepetitionCounted && e.repetition == rep + 1;
        });
    ASSERT_NE(reached, run.events.end());
    ASSERT_NE(counted, run.events.end());
    EXPECT_LT(reached - run.events.begin(), counted - run.events.begin());
    const double top = 1.0 + rep * 5.0 + 2.0;
    EXPECT_NEAR(reached->t, top, 0.6) << rep;
    EXPECT_GT(counted->t, top + 0.5);
  }
}

TEST(ExerciseFeedback, TooFastIsToldForEachFastRepetition) {
  ExerciseFeedback f(spec(3, 30, 120));
  // 90 deg up and down in 0.9 s: minimum jerk peaks at 1.875 * 90 / 0.45 = 375 deg/s.
  const Feedback run = feed(f, elbowMotion(120, 0.9), 10.0);
  ASSERT_GE(f.repetitions(), 5u);
  EXPECT_EQ(run.count(FeedbackKind::TooFast), f.repetitions());
  for (const FeedbackEvent& e : run.events)
    if (e.kind == FeedbackKind::TooFast) {
      EXPECT_GT(e.value / kDeg, 250);
    }
  // The same exercise at 3 s a repetition (125 deg/s) is not too fast.
  ExerciseFeedback slow(spec(3, 30, 120));
  feed(slow, elbowMotion(120, 3.0), 20.0);
  EXPECT_GE(slow.repetitions(), 4u);
  EXPECT_EQ(slow.tooFast(), 0u);
}

TEST(ExerciseFeedback, TooSmallRepetitionsFallShortAndTinyOnesAreAttempts) {
  ExerciseFeedback f(spec(3, 30, 120));
  // 30 -> 80 deg: counted (past the counter's entry level, 61.5 deg) but short of 115.
  const Feedback run = feed(f, elbowMotion(80, 4.0), 26.5);
  EXPECT_EQ(f.repetitions(), 5u);
  EXPECT_EQ(run.count(FeedbackKind::TargetReached), 0u);
  EXPECT_EQ(run.count(FeedbackKind::RangeNotReached), 5u);
  EXPECT_EQ(f.partial(), 5u);
  for (const FeedbackEvent& e : run.events)
    if (e.kind == FeedbackKind::RangeNotReached) {
      EXPECT_GT(e.repetition, 0);
      EXPECT_NEAR(e.value / kDeg, 80, 2);  // how far it got
    }
  // 30 -> 55 deg: not a repetition at all, but each attempt is told.
  ExerciseFeedback tiny(spec(3, 30, 120));
  const Feedback small = feed(tiny, elbowMotion(55, 4.0), 26.5);
  EXPECT_EQ(tiny.repetitions(), 0u);
  EXPECT_EQ(small.count(FeedbackKind::RangeNotReached), 5u);
  for (const FeedbackEvent& e : small.events) EXPECT_EQ(e.repetition, 0);
}

TEST(ExerciseFeedback, TheElbowBendingDuringAShoulderExerciseIsCompensation) {
  ExerciseMotion m;
  m.angle = 0;  // shoulder flexion 10 -> 110
  m.fromDeg = 10;
  m.toDeg = 110;
  m.compensationDeg = 40;  // the elbow bends 40 deg with each lift
  ExerciseFeedback f(spec(0, 10, 110));
  Feedback run = feed(f, m, 26.5);
  EXPECT_EQ(f.repetitions(), 5u);
  EXPECT_EQ(run.count(FeedbackKind::Compensation), 5u);
  EXPECT_EQ(f.compensations(), 5u);
  for (const FeedbackEvent& e : run.events)
    if (e.kind == FeedbackKind::Compensation) {
      EXPECT_EQ(e.angle, 3);
      // Measured while the shoulder is away from rest (past the exit level, 15 % of the
      // target's range): most of the elbow's 40 deg.
      EXPECT_GT(e.value / kDeg, 30);
      EXPECT_LT(e.value / kDeg, 41);
    }
  // A little elbow movement (8 deg) is no compensation.
  m.compensationDeg = 8;
  ExerciseFeedback g(spec(0, 10, 110));
  run = feed(g, m, 26.5);
  EXPECT_EQ(g.repetitions(), 5u);
  EXPECT_EQ(run.count(FeedbackKind::Compensation), 0u);
  // Not watched when asked not to (the angle cannot be trusted).
  m.compensationDeg = 40;
  ExerciseSpec unwatched = spec(0, 10, 110);
  unwatched.stillAngles = std::vector<int>{};
  ExerciseFeedback h(unwatched);
  run = feed(h, m, 26.5);
  EXPECT_EQ(run.count(FeedbackKind::Compensation), 0u);
  // An elbow exercise done by lifting the shoulder.
  ExerciseMotion lift = elbowMotion(120, 4.0);
  lift.compensationDeg = 35;
  ExerciseFeedback e(spec(3, 30, 120));
  run = feed(e, lift, 26.5);
  EXPECT_EQ(run.count(FeedbackKind::Compensation), 5u);
  for (const FeedbackEvent& ev : run.events)
    if (ev.kind == FeedbackKind::Compensation) {
      EXPECT_EQ(ev.angle, 0);
    }
}

// The angles a live session gives: the EKF on simulated IMUs and a Kinect with the paper's noise.
TEST(ExerciseFeedback, WorksOnEstimatedAngles) {
  for (const double compensation : {0.0, 40.0}) {
    ExerciseMotion m;
    m.angle = 0;
    m.fromDeg = 10;
    m.toDeg = 110;
    m.compensationDeg = compensation;
    const ExerciseTrajectory trajectory(m);
    SimulationParams sim = defaultSimulation();
    sim.duration = 26.5;
    sim.upperArm.rateHz = sim.forearm.rateHz = 200;
    const Recording rec = simulateRecording(trajectory, sim);
    ExerciseFeedback f(spec(0, 10, 110));
    std::size_t compensated = 0;
    EstimateCallbacks callbacks;
    callbacks.row = [&](const EstimateRow& row) {
      std::array<double, 5> c = asArray(toClinical(row.th));
      for (double& a : c) a *= kDeg;
      f.add(row.t, c);
      for (const FeedbackEvent& e : f.takeEvents())
        compensated += e.kind == FeedbackKind::Compensation;
    };
    estimateRecording(rec, estimatorParamsFor(rec.meta, {}), callbacks);
    SCOPED_TRACE(compensation);
    EXPECT_EQ(f.repetitions(), 5u);
    EXPECT_EQ(f.tooFast(), 0u);
    EXPECT_GE(f.targetReached(), 4u);  // the first may start while the filter settles
    EXPECT_EQ(compensated, compensation > 0 ? 5u : 0u);
  }
}

TEST(ExerciseFeedback, GarbageIsIgnoredAndCounted) {
  ExerciseFeedback f(spec(3, 30, 120));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  f.add(0.0, {0, 0, 0, 0.5, 0});
  f.add(0.01, {0, 0, 0, 0.5, 0});
  f.add(0.011, {0, 0, 0, nan, 0});
  f.add(nan, {0, 0, 0, 0.5, 0});
  f.add(0.005, {0, 0, 0, 0.5, 0});  // back in time
  f.add(0.01, {0, 0, 0, 0.5, 0});   // the same time
  EXPECT_EQ(f.ignored(), 4u);
  f.add(0.02, {nan, 1e300, -1e300, 0.5, 0});  // other angles absurd: the primary still counts
  EXPECT_EQ(f.ignored(), 4u);
  EXPECT_TRUE(f.takeEvents().empty());
  const auto refused = [](ExerciseSpec s) {
    EXPECT_THROW(ExerciseFeedback{s}, std::invalid_argument);
  };
  refused(spec(5, 30, 120));
  refused(spec(3, 120, 30));
  refused(spec(3, nan, 30));
  ExerciseSpec s = spec(3, 30, 120);
  s.stillAngles = std::vector<int>{3};
  refused(s);
  s = spec(3, 30, 120);
  s.maxSpeedRadPerS = 0;
  refused(s);
}

TEST(ExerciseFeedback, ShoulderAnglesNeedOpticsToBeTrusted) {
  for (int a = 0; a < 5; ++a) {
    EXPECT_EQ(angleNeedsOptics(a), a <= 2);
    EXPECT_EQ(angleTrustworthy(a, 1 * kDeg, true), a > 2) << a;
    EXPECT_TRUE(angleTrustworthy(a, 1 * kDeg, false)) << a;
    EXPECT_FALSE(angleTrustworthy(a, 6 * kDeg, false)) << a;  // 2 sigma = 12 deg
    EXPECT_FALSE(angleTrustworthy(a, std::numeric_limits<double>::quiet_NaN(), false));
  }
  EXPECT_EQ(ExerciseFeedback::defaultStillAngles(0), std::vector<int>{3});
  EXPECT_EQ(ExerciseFeedback::defaultStillAngles(3), (std::vector<int>{0, 1}));
}

}  // namespace
}  // namespace armtrack
