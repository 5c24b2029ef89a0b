// The trunk limit in the home window's exercise screen (issue 26) under Xvfb, signed in as the
// demo's home account: a simulated patient bends the elbow four times (one set) while the screen
// takes estimates made here (its estimate source) instead of the virtual arm's. With a 15 deg
// trunk limit and a 25 deg lean in the second and fourth repetitions, "Keep your back against
// the chair" shows (big, with the hint sound) during those leans only, and the result stored with
// the session counts two repetitions leaning too far; leaning 10 deg, or sitting still, never
// shows it and counts none. End to end, the virtual arm leaning 25 deg at each reach of a
// shoulder exercise is cued and counted. Screenshots at 1024x600, English and German.
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <cmath>
#include <numbers>

#include "app/gui/AppController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/home/ExerciseScreen.h"
#include "app/gui/home/FeedbackSound.h"
#include "app/gui/home/HomeSummaryScreen.h"
#include "app/gui/services/DemoData.h"
#include "app/gui/services/HomeRecords.h"
#include "app/i18n/Language.h"
#include "core/kinematics/ClinicalAngles.h"
#include "tests/app/gui/support/GuiTestSupport.h"

using namespace armtrack;
using namespace armtrack::gui;
using namespace armtrack::gui::home;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kPeriodS = 4.0;
constexpr int kReps = 4;
constexpr int kBatch = 30;

/// Elbow flexion 0 -> 90 -> 0 deg (raised cosine) in each 4 s period after a second of rest,
/// 0.5 s rest at the ends of each period.
double elbowDeg(double t) {
  if (t < 1.0) return 0;
  const double u = std::fmod(t - 1.0, kPeriodS);
  if (t >= 1.0 + kReps * kPeriodS || u < 0.5 || u > kPeriodS - 0.5) return 0;
  return 45.0 * (1 - std::cos(2 * std::numbers::pi * (u - 0.5) / (kPeriodS - 1.0)));
}

int repOf(double t) {
  return t < 1.0 ? -1 : static_cast<int>((t - 1.0) / kPeriodS);
}

HomeExercise elbowExercise(std::optional<double> trunkLimitDeg) {
  HomeExercise e;
  e.protocol.name = QStringLiteral("Elbow flexion");
  e.protocol.angleKey = QStringLiteral("elbow_flexion");
  e.angle = 3;
  e.item.protocolName = e.protocol.name;
  e.item.position = 1;
  e.item.sets = 1;
  e.item.restS = 0;
  e.repetitions = kReps;
  e.targetMinDeg = 0;
  e.targetMaxDeg = 85;
  e.trunkLimitDeg = trunkLimitDeg;
  return e;
}

/// The patient's estimates at 100 Hz, handed out kBatch at a time (one batch per tick of the
/// screen's 33 ms timer) from the moment the set starts; the lean (deg) in the repetitions listed,
/// none in the others. The screen's cue, counts and set go by the estimates' times, not the wall
/// clock, so 0.3 s of movement a tick (about 9 times real time; it was 0.1 s) runs the same
/// exercise in a third of the time, and the cue (on for about 1.5 s of movement in a leaning
/// repetition) is still seen at five ticks or more.
struct Patient {
  double leanDeg = 0;
  std::vector<int> leaning;
  bool trunkSensor = true;
  double t = 0;
  const ExerciseScreen* screen = nullptr;
  std::vector<int> repsCued;

  bool operator()(std::vector<session::EstimateRow>& rows, std::vector<std::string>& events) {
    rows.clear();
    events.clear();
    if (screen->phase() != ExerciseScreen::Phase::Set) return true;
    if (screen->trunkCueShown() && (repsCued.empty() || repsCued.back() != repOf(t)))
      repsCued.push_back(repOf(t));
    for (int i = 0; i < kBatch && t < 1.0 + kReps * kPeriodS + 3.0; ++i, t += 0.01) {
      session::EstimateRow r;
      r.t = t;
      ClinicalAngles c;
      c.elbowFlexion = elbowDeg(t);
      r.th = fromClinical(c);
      r.thStd = JointVector::Constant(0.5 * kDeg);
      const bool leans = std::find(leaning.begin(), leaning.end(), repOf(t)) != leaning.end();
      if (trunkSensor)
        r.trunk = Eigen::Vector3d((leans ? leanDeg * elbowDeg(t) / 90.0 : 0.0) * kDeg, 0, 0);
      rows.push_back(r);
    }
    return true;
  }
};

}  // namespace

class TestHomeTrunkCue : public QObject {
  Q_OBJECT

  QTemporaryDir m_dir;
  std::unique_ptr<AppController> m_app;

  /// Runs one exercise to its end with the patient (nullptr: the virtual arm's own session,
  /// with devices and the exercise given); returns its result.
  HomeExerciseResult exercise(
      std::optional<double> limit, Patient* patient, const QString& shot = {},
      const QString& devices = QStringLiteral("virtual-arm:sensors=upper+forearm"),
      std::optional<HomeExercise> given = std::nullopt) {
    app::gui::LiveSessionConfig config;
    config.devices = QStringList{devices};
    FeedbackSound sound;
    ExerciseScreen screen(m_app->plugins(), m_app->records(), given.value_or(elbowExercise(limit)),
                          1, 1, QString::fromLatin1(DemoAccounts::kLivePatient), config, !patient,
                          &sound);
    if (patient) {
      patient->screen = &screen;
      screen.setEstimateSource(std::ref(*patient));
    }
    screen.resize(1024, 600);
    screen.show();
    [&] { QVERIFY(QTest::qWaitForWindowExposed(&screen)); }();
    std::optional<HomeExerciseResult> result;
    connect(&screen, &ExerciseScreen::finished, this,
            [&](const HomeExerciseResult& r, bool) { result = r; });
    auto* start = static_cast<QPushButton*>(screen.defaultChoice());
    [&] { QTRY_VERIFY_WITH_TIMEOUT(start && start->isEnabled(), 20000); }();
    start->click();
    [&] { QCOMPARE(screen.phase(), ExerciseScreen::Phase::Set); }();
    if (!shot.isEmpty()) {
      // At the top of the second repetition the patient leans: the cue is up.
      [&] { QTRY_VERIFY_WITH_TIMEOUT(screen.trunkCueShown(), 20000); }();
      auto* cue = armtrack::gui::test::findControl<QLabel>(
          &screen, QCoreApplication::translate("armtrack::gui::home::ExerciseScreen", "Trunk cue"));
      [&] { QVERIFY(cue && cue->isVisible()); }();
      armtrack::gui::test::saveScreenshot(&screen, shot);
    }
    [&] { QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), 90000); }();
    const int hints = static_cast<int>(sound.asked(FeedbackSound::Cue::Hint));
    const int cues = static_cast<int>(screen.feedbackShown().count(QCoreApplication::translate(
        "armtrack::gui::home::ExerciseScreen", "Keep your back against the chair")));
    [&] { QVERIFY(hints >= cues); }();  // each cue was sounded
    m_cues = cues;
    return result.value_or(HomeExerciseResult{});
  }
  int m_cues = 0;

 private slots:
  void initTestCase() {
    AppOptions o;
    o.pluginFolders = {QStringLiteral(ARMTRACK_PLUGIN_DIR)};
    m_app = armtrack::gui::test::demoApp(m_dir, o);
    QVERIFY(m_app);
    m_app->signOut();
    QVERIFY(armtrack::gui::test::signInAs(*m_app, DemoAccounts::kHome));
  }

  void leaningPastTheLimitCuesAndCounts() {
    Patient patient;
    patient.leanDeg = 25;
    patient.leaning = {1, 3};
    const HomeExerciseResult r = exercise(15.0, &patient, QStringLiteral("home-trunk-cue"));
    QCOMPARE(patient.repsCued, patient.leaning);
    QCOMPARE(m_cues, 2);
    QCOMPARE(r.repetitions, kReps);
    QCOMPARE(r.trunkLimitDeg, std::optional(15.0));
    QCOMPARE(r.trunkCompensation, 2);
    // What the records keep with the session, and read back.
    const QJsonObject stored = r.toJson();
    QCOMPARE(stored.value("trunk_compensation").toInt(), 2);
    QCOMPARE(stored.value("trunk_limit_deg").toDouble(), 15.0);
    QCOMPARE(HomeExerciseResult::fromJson(stored)->trunkCompensation, 2);
    // The summary's line tells the patient too.
    QVERIFY2(
        HomeSummaryScreen::line(r, {}).contains(QStringLiteral("2 repetitions leaning too far")),
        qPrintable(HomeSummaryScreen::line(r, {})));
  }

  void leaningLessOrSittingStillNeverCues() {
    for (const double lean : {0.0, 10.0}) {
      Patient patient;
      patient.leanDeg = lean;
      patient.leaning = {0, 1, 2, 3};
      const HomeExerciseResult r = exercise(15.0, &patient);
      QVERIFY(patient.repsCued.empty());
      QCOMPARE(m_cues, 0);
      QCOMPARE(r.repetitions, kReps);
      QCOMPARE(r.trunkCompensation, 0);
    }
  }

  void withoutALimitOrATrunkSensorNothingIsCued() {
    Patient leaning;
    leaning.leanDeg = 30;
    leaning.leaning = {0, 1, 2, 3};
    HomeExerciseResult r = exercise(std::nullopt, &leaning);
    QVERIFY(leaning.repsCued.empty());
    QCOMPARE(r.trunkCompensation, 0);
    QVERIFY(!r.trunkLimitDeg);
    QVERIFY(!r.toJson().value("trunk_limit_deg").isDouble());
    Patient unmeasured;
    unmeasured.leanDeg = 30;
    unmeasured.leaning = {0, 1, 2, 3};
    unmeasured.trunkSensor = false;
    r = exercise(15.0, &unmeasured);
    QVERIFY(unmeasured.repsCued.empty());
    QCOMPARE(r.trunkCompensation, 0);
  }

  // End to end: the virtual arm raises the arm forward (shoulder flexion, a Kinect and a sternum
  // sensor) three times, leaning 25 deg at each reach: cued, and counted in the result.
  void aVirtualPatientLeaningPastTheLimitIsCued() {
    HomeExercise e = elbowExercise(15.0);
    e.protocol.name = QStringLiteral("Shoulder flexion");
    e.protocol.angleKey = QStringLiteral("shoulder_flexion");
    e.item.protocolName = e.protocol.name;
    e.angle = 0;
    e.repetitions = 3;
    e.targetMinDeg = 20;
    e.targetMaxDeg = 110;
    const HomeExerciseResult r = exercise(
        15.0, nullptr, QStringLiteral("home-trunk-cue-virtual-arm"),
        QStringLiteral("virtual-arm:sensors=upper+forearm+kinect+trunk,trajectory=exercise,"
                       "exercise=shoulder_flexion,exercise-range=20:120,trunk-lean=25"),
        e);
    QVERIFY(m_cues >= 1);
    QVERIFY2(r.repetitions >= 3, qPrintable(QString::number(r.repetitions)));
    QVERIFY2(r.trunkCompensation >= 1 && r.trunkCompensation <= r.repetitions,
             qPrintable(QString::number(r.trunkCompensation)));
  }

  void theCueInGerman() {
    QCOMPARE(i18n::setLanguage(QStringLiteral("de")), QStringLiteral("de"));
    Patient patient;
    patient.leanDeg = 25;
    patient.leaning = {1};
    const HomeExerciseResult r = exercise(15.0, &patient, QStringLiteral("home-trunk-cue-de"));
    QCOMPARE(r.trunkCompensation, 1);
    i18n::resetLanguage();
  }

  void cleanupTestCase() { m_app.reset(); }
};

ARMTRACK_APP_TEST_MAIN(TestHomeTrunkCue)
#include "test_home_trunk_cue.moc"
