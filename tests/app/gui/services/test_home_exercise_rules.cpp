// The home window's exercise rules without a display (app/gui/services/HomeExerciseRules): when a
// shoulder angle stops being shown, the clinical angles in radians, and the set tallies on a
// known movement (the elbow bent from 0 to 90 deg and back, three times per set).
#include <QTest>
#include <cmath>
#include <numbers>

#include "app/gui/services/HomeExerciseRules.h"
#include "core/kinematics/ClinicalAngles.h"

using namespace armtrack;
using armtrack::gui::HeadingTrust;

namespace {

constexpr double kOneDeg = std::numbers::pi / 180.0;

session::EstimateRow row(double t, bool startPoseOnly, double stdDeg = 1.0) {
  session::EstimateRow r;
  r.t = t;
  r.headingFromStartPoseOnly = startPoseOnly;
  r.thStd = JointVector::Constant(stdDeg * kOneDeg);
  return r;
}

// Elbow flexion (clinical angle 3) going 0 -> peakOneDeg -> 0 `count` times, 2 s each, at 100 Hz,
// with a second of rest before and after; every other angle stays at 0.
void bendElbow(ExerciseFeedback& f, int count, double peakOneDeg, double t0 = 0) {
  const double period = 2.0;
  const double end = 1.0 + count * period + 1.0;
  for (double t = 0; t <= end + 1e-9; t += 0.01) {
    double a = 0;
    if (t > 1.0 && t < 1.0 + count * period)
      a = peakOneDeg * kOneDeg * 0.5 * (1 - std::cos(2 * std::numbers::pi * (t - 1.0) / period));
    f.add(t0 + t, {0, 0, 0, a, 0});
  }
}

ExerciseFeedback elbowSet(double targetMaxDeg = 80) {
  ExerciseSpec spec;
  spec.primaryAngle = 3;
  spec.target = {0, targetMaxDeg * kOneDeg};
  return ExerciseFeedback(spec);
}

gui::HomeExercise elbowExercise() {
  gui::HomeExercise e;
  e.protocol.name = QStringLiteral("Elbow bends");
  e.angle = 3;
  e.item.position = 2;
  e.item.sets = 2;
  e.repetitions = 3;
  e.targetMinDeg = 0;
  e.targetMaxDeg = 80;
  return e;
}

}  // namespace

class TestHomeExerciseRules : public QObject {
  Q_OBJECT
 private slots:
  void elbowNeverBlind() {
    HeadingTrust trust(3);
    for (double t = 0; t < 10; t += 0.5) trust.add(row(t, true));
    QVERIFY(!trust.blind(10));
    QVERIFY(trust.shown(row(10, true)));
  }

  void shoulderBlindAfterThreeSeconds() {
    HeadingTrust trust(0);
    trust.add(row(0.0, false));
    for (double t = 1.0; t <= 3.9; t += 0.1) trust.add(row(t, true));
    QVERIFY(!trust.blind(3.9));  // resting on the start pose since 1.0: 2.9 s
    QVERIFY(!trust.blind(4.0));  // exactly the limit is still trusted
    QVERIFY(trust.blind(4.05));  // past it
    QVERIFY(!trust.shown(row(4.05, true)));
    // One optical fix trusts it again at once.
    trust.add(row(4.1, false));
    QVERIFY(!trust.blind(4.1));
    QVERIFY(trust.shown(row(4.1, false)));
    // A new blind stretch counts from its own start.
    trust.add(row(5.0, true));
    QVERIFY(!trust.blind(7.9));
    QVERIFY(trust.blind(8.1));
  }

  void uncertainAngleNotShown() {
    HeadingTrust trust(3);
    QVERIFY(trust.shown(row(1, false, 2.0)));    // 2 sigma = 4 deg
    QVERIFY(!trust.shown(row(1, false, 20.0)));  // 2 sigma = 40 deg
    QVERIFY(!trust.shown(row(1, false, std::nan(""))));
  }

  void customLimit() {
    HeadingTrust trust(1, 0.5);
    trust.add(row(0, true));
    QVERIFY(!trust.blind(0.4));
    QVERIFY(trust.blind(0.6));
  }

  void clinicalRadiansWithoutDegrees() {
    JointVector th;
    th << 0.3, 0.2, 0.1, -1.0, 0.5;
    const std::array<double, 5> r = clinicalRadians(th);
    // The signs of docs/arm-model.md, exactly: no trip through degrees.
    QCOMPARE(r[0], 0.3);
    QCOMPARE(r[1], 0.2);
    QCOMPARE(r[2], -0.1);
    QCOMPARE(r[3], 1.0);
    QCOMPARE(r[4], -0.5);
    // Agrees with the degrees the screens show.
    const std::array<double, 5> deg = asArray(toClinical(th));
    for (std::size_t i = 0; i < 5; ++i) QVERIFY(std::abs(deg[i] * kOneDeg - r[i]) < 1e-12);
    // Wrapped into (-pi, pi].
    th << 2 * std::numbers::pi + 0.25, 0, 0, 0, 0;
    QVERIFY(std::abs(clinicalRadians(th)[0] - 0.25) < 1e-12);
  }

  void plannedResultFromExercise() {
    const gui::HomeExerciseResult r = gui::plannedResult(elbowExercise(), true);
    QCOMPARE(r.exercise, QStringLiteral("Elbow bends"));
    QCOMPARE(r.angle, 3);
    QCOMPARE(r.position, 2);
    QCOMPARE(r.setsPlanned, 2);
    QCOMPARE(r.repetitionsPlanned, 6);
    QCOMPARE(r.targetMaxDeg, 80.0);
    QCOMPARE(r.setsDone, 0);
    QCOMPARE(r.repetitions, 0);
    QVERIFY(r.measured);
    QVERIFY(!r.rangeMaxDeg);
    QVERIFY(!gui::plannedResult(elbowExercise(), false).measured);
  }

  void setsAddUp() {
    gui::HomeExerciseResult r = gui::plannedResult(elbowExercise(), true);
    ExerciseFeedback first = elbowSet();
    bendElbow(first, 3, 90);
    gui::addSet(r, first, true);
    QCOMPARE(r.setsDone, 1);
    QCOMPARE(r.repetitions, 3);
    QCOMPARE(r.targetReached, 3);
    QVERIFY(r.rangeMaxDeg && r.rangeMinDeg);
    QVERIFY2(std::abs(*r.rangeMaxDeg - 90) < 3, qPrintable(QString::number(*r.rangeMaxDeg)));
    QVERIFY2(std::abs(*r.rangeMinDeg) < 3, qPrintable(QString::number(*r.rangeMinDeg)));
    // A second set that goes only to 60 deg: counted, the target (80) not reached; the range
    // reached stays the widest of both sets.
    ExerciseFeedback second = elbowSet();
    bendElbow(second, 3, 60);
    gui::addSet(r, second, true);
    QCOMPARE(r.setsDone, 2);
    QCOMPARE(r.targetReached, 3);
    QVERIFY(r.repetitions + r.partial >= 6);
    QVERIFY(std::abs(*r.rangeMaxDeg - 90) < 3);
  }

  void unmeasuredSetHasNoRange() {
    gui::HomeExerciseResult r = gui::plannedResult(elbowExercise(), false);
    ExerciseFeedback set = elbowSet();
    bendElbow(set, 2, 90);
    gui::addSet(r, set, false);
    QCOMPARE(r.setsDone, 1);
    QVERIFY(!r.rangeMinDeg && !r.rangeMaxDeg);
  }

  void emptySetCountsAsDoneOnly() {
    gui::HomeExerciseResult r = gui::plannedResult(elbowExercise(), true);
    ExerciseFeedback set = elbowSet();
    gui::addSet(r, set, true);
    QCOMPARE(r.setsDone, 1);
    QCOMPARE(r.repetitions, 0);
    QVERIFY(!r.rangeMaxDeg);
  }
};

QTEST_GUILESS_MAIN(TestHomeExerciseRules)
#include "test_home_exercise_rules.moc"
