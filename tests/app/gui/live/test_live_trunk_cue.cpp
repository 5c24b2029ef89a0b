// The trunk in the live session screen (issue 26) under Xvfb, on estimates made here and shown
// through the screen's own drain path (showEstimates), 100 Hz in batches of four as the 40 Hz
// drain takes them: a simulated patient raises the arm six times and leans 25 deg forward in
// two of the reaches. With a 15 deg trunk limit the cue "Keep your back against the chair"
// appears during those leans only, and two repetitions are counted with compensation, also in
// the line the session's notes keep; leaning 10 deg, or not at all, never shows it; without a
// limit there is neither cue nor count, but the trunk's angles are shown, and the trunk-moved
// flag of an estimate shows its note. End to end, a virtual-arm session with a sternum sensor
// leaning 25 deg at each reach is cued and counted, one leaning 6 deg never. Screenshots at
// 1024x600, English and German.
#include <QElapsedTimer>
#include <QLabel>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <numbers>
#include <tuple>

#include "app/gui/live/LiveSessionScreen.h"
#include "app/i18n/Language.h"
#include "app/plugins/PluginRegistry.h"
#include "core/kinematics/ClinicalAngles.h"
#include "core/storage/ClinicalStore.h"
#include "core/storage/Database.h"
#include "tests/support/GuiTestMain.h"
#include "ui/AnglePlotPanel.h"

using namespace armtrack;
using namespace armtrack::app;
using namespace armtrack::app::gui;
using State = LiveSessionScreen::State;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kPeriodS = 4.0;  // one reach
constexpr int kReaches = 6;

gui::LiveSessionConfig config(std::optional<double> trunkLimitDeg) {
  gui::LiveSessionConfig c;
  c.devices = gui::demoDevices();  // never started here
  c.patientLabel = QStringLiteral("P01 Test Patient");
  c.primaryAngle = 0;
  c.targetDeg = std::make_pair(0.0, 90.0);
  c.targetRepetitions = kReaches;
  c.trunkLimitDeg = trunkLimitDeg;
  return c;
}

/// The reach: shoulder flexion 0 -> 90 -> 0 deg (raised cosine) in each 4 s period after a
/// second of rest; 0.5 s rest at the ends of each period.
double reachDeg(double t) {
  if (t < 1.0) return 0;
  const double u = std::fmod(t - 1.0, kPeriodS);
  if (u < 0.5 || u > kPeriodS - 0.5) return 0;
  return 45.0 * (1 - std::cos(2 * std::numbers::pi * (u - 0.5) / (kPeriodS - 1.0)));
}

int reachOf(double t) {
  return t < 1.0 ? -1 : static_cast<int>((t - 1.0) / kPeriodS);
}

/// The patient's trunk flexion: leanDeg at the top of the reaches in leaning (same shape as the
/// reach), upright otherwise; plus a little sway.
double trunkDeg(double t, double leanDeg, const std::vector<int>& leaning) {
  const int r = reachOf(t);
  const bool leans = std::find(leaning.begin(), leaning.end(), r) != leaning.end();
  return (leans ? leanDeg * reachDeg(t) / 90.0 : 0.0) + 0.3 * std::sin(2 * std::numbers::pi * t);
}

session::EstimateRow row(double t, std::optional<double> trunkFlexDeg, bool moved = false) {
  session::EstimateRow r;
  r.t = t;
  ClinicalAngles c;
  c.shoulderFlexion = reachDeg(t);
  c.elbowFlexion = 10;
  r.th = fromClinical(c);
  r.thStd = JointVector::Constant(0.5 * kDeg);
  if (trunkFlexDeg) {
    r.trunk = Eigen::Vector3d(*trunkFlexDeg * kDeg, 2 * kDeg, -3 * kDeg);
    r.trunkStd = Eigen::Vector3d::Constant(0.3 * kDeg);
  }
  r.trunkMoved = moved;
  return r;
}

struct Run {
  int batchesWithCue = 0;
  std::vector<int> reachesCued;  // reaches during which the cue was seen
};

/// Shows the whole session in batches of four rows, processing events after each; notes in
/// which reaches the cue was visible.
template <class Flexion>
Run play(LiveSessionScreen& screen, Flexion flexion, double seconds = 1.0 + kReaches * kPeriodS,
         bool moved = false) {
  Run run;
  std::vector<session::EstimateRow> batch;
  const int n = static_cast<int>(seconds * 100);
  for (int i = 0; i <= n; ++i) {
    const double t = i / 100.0;
    batch.push_back(row(t, flexion(t), moved));
    if (batch.size() == 4 || i == n) {
      screen.showEstimates(batch);
      batch.clear();
      QCoreApplication::processEvents();
      if (screen.trunk().cueLabel()->isVisible()) {
        ++run.batchesWithCue;
        const int r = reachOf(t);
        if (run.reachesCued.empty() || run.reachesCued.back() != r) run.reachesCued.push_back(r);
      }
    }
  }
  return run;
}

}  // namespace

class TestLiveTrunkCue : public QObject {
  Q_OBJECT
  PluginRegistry m_registry;

  void showAt1024(LiveSessionScreen& s) {
    s.resize(1024, 600);
    s.show();
    QVERIFY(QTest::qWaitForWindowExposed(&s));
  }

 private slots:
  // English as the application starts it (its plural forms come from armtrack_en).
  void initTestCase() {
    QCOMPARE(i18n::setLanguage(QStringLiteral("en")), QStringLiteral("en"));
    m_registry.load({QStringLiteral(ARMTRACK_PLUGIN_DIR)});
    QVERIFY2(m_registry.plugin(QStringLiteral("virtual-arm")), "virtual-arm plugin not built");
  }

  void leaningPastTheLimitCuesAndCounts() {
    LiveSessionScreen screen(m_registry, config(15.0));
    showAt1024(screen);
    QVERIFY(!screen.trunk().cueLabel()->isVisible());
    QVERIFY(screen.trunk().countLabel()->isVisible());
    const std::vector<int> leaning{1, 4};
    // Stop at the top of reach 4, the patient leaning 25 deg: the cue is up; a picture of it.
    const double top = 1.0 + 4 * kPeriodS + 2.0;
    play(
        screen, [&](double t) { return trunkDeg(t, 25, leaning); }, top);
    QVERIFY(screen.trunk().cueLabel()->isVisible());
    QCOMPARE(screen.trunk().cueLabel()->text(), QStringLiteral("Keep your back against the chair"));
    QVERIFY2(screen.trunk().anglesLabel()->text().contains(QStringLiteral("flexion 25")),
             qPrintable(screen.trunk().anglesLabel()->text()));
    QVERIFY(screen.trunk().anglesLabel()->isVisible());
    screen.plots()->refresh();  // as the drain's timer would
    screen.armView()->updateIfChanged();
    test::saveScreenshot(test::grabFromScreen(&screen), QStringLiteral("live-trunk-cue"));
    // Its words fit: the label is as wide as the screen and shows them on its lines.
    const QLabel* cue = screen.trunk().cueLabel();
    QVERIFY(cue->height() >= cue->heightForWidth(cue->width()));
    QVERIFY(cue->fontMetrics().boundingRect(cue->text()).width() <= cue->width() ||
            cue->wordWrap());
  }

  void leaningPastTheLimitInTwoReachesCountsTwo() {
    LiveSessionScreen screen(m_registry, config(15.0));
    showAt1024(screen);
    const std::vector<int> leaning{1, 4};
    const Run run = play(screen, [&](double t) { return trunkDeg(t, 25, leaning); });
    QCOMPARE(run.reachesCued, leaning);                // only while leaning past it
    QVERIFY(!screen.trunk().cueLabel()->isVisible());  // upright again at the end
    QCOMPARE(screen.repetitionCounter().count(), std::size_t(kReaches));
    QCOMPARE(screen.trunk().compensated(), std::size_t(2));
    QCOMPARE(screen.trunk().countLabel()->text(),
             QStringLiteral("2 repetitions with compensation (trunk limit 15\u00b0)"));
    QCOMPARE(screen.trunk().notesLine(),
             QStringLiteral("Trunk limit 15\u00b0: 2 of 6 repetitions with compensation"));
    QCOMPARE(screen.trunk().cue()->cues(), std::size_t(2));
  }

  void leaningLessThanTheLimitNeverCues() {
    for (const double lean : {0.0, 10.0}) {
      LiveSessionScreen screen(m_registry, config(15.0));
      showAt1024(screen);
      const Run run = play(screen, [&](double t) { return trunkDeg(t, lean, {0, 1, 2, 3, 4, 5}); });
      QCOMPARE(run.batchesWithCue, 0);
      QCOMPARE(screen.repetitionCounter().count(), std::size_t(kReaches));
      QCOMPARE(screen.trunk().compensated(), std::size_t(0));
      QCOMPARE(screen.trunk().countLabel()->text(),
               QStringLiteral("0 repetitions with compensation (trunk limit 15\u00b0)"));
    }
  }

  void withoutATrunkSensorNothingIsCued() {
    // A limit, a lean that would pass it, but no trunk angles in the estimates.
    LiveSessionScreen screen(m_registry, config(15.0));
    showAt1024(screen);
    const Run run = play(screen, [](double) { return std::optional<double>(); });
    QCOMPARE(run.batchesWithCue, 0);
    QVERIFY(!screen.trunk().anglesLabel()->isVisible());
    QCOMPARE(screen.trunk().compensated(), std::size_t(0));
  }

  void withoutALimitTheAnglesAreShownButNothingCued() {
    LiveSessionScreen screen(m_registry, config(std::nullopt));
    showAt1024(screen);
    const Run run = play(
        screen,
        [](double t) {
          return trunkDeg(t, 30, {0, 1, 2, 3, 4, 5});
        },
        3.0);
    QCOMPARE(run.batchesWithCue, 0);
    QVERIFY(!screen.trunk().countLabel()->isVisible());
    QVERIFY(screen.trunk().anglesLabel()->isVisible());
    QVERIFY(screen.trunk().anglesLabel()->text().startsWith(QStringLiteral("Trunk: flexion ")));
    QVERIFY(screen.trunk().notesLine().isEmpty());
  }

  void theTrunkMovedNoteFollowsTheFlag() {
    LiveSessionScreen screen(m_registry, config(std::nullopt));
    showAt1024(screen);
    play(
        screen, [](double) { return std::optional<double>(); }, 2.0, true);
    QVERIFY(screen.trunk().anglesLabel()->isVisible());
    QCOMPARE(screen.trunk().anglesLabel()->text(),
             QStringLiteral("The trunk moved: shoulder angles include the lean."));
    test::saveScreenshot(test::grabFromScreen(&screen), QStringLiteral("live-trunk-moved"));
    // A second later without the flag, it goes.
    std::vector<session::EstimateRow> later;
    for (int i = 0; i < 150; ++i) later.push_back(row(2.01 + i / 100.0, std::nullopt));
    screen.showEstimates(later);
    QVERIFY(!screen.trunk().anglesLabel()->isVisible());
  }

  // End to end: the virtual arm raises the arm (shoulder flexion 20 to 120 deg) wearing a
  // sternum sensor, its trunk leaning at each reach; the session estimates the trunk and the
  // screen drains it. Leaning 25 deg past a 15 deg limit cues and counts; leaning 6 deg never.
  void aVirtualPatientLeaningPastTheLimitIsCued() {
    // The leaning session is recorded into the records: its notes keep the count.
    QTemporaryDir dir;
    const auto url = storage::DatabaseUrl::parse(dir.filePath(QStringLiteral("clinic.db")));
    storage::Database db(url, {.create = true, .migrate = false});
    storage::ClinicalStore store(db);
    store.initialise(QStringLiteral("boss"), "a long enough password");
    store.signIn(QStringLiteral("boss"), "a long enough password");
    storage::Patient p;
    p.code = QStringLiteral("P01");
    p.name = QStringLiteral("Ada Example");
    store.addPatient(p);
    std::shared_ptr<DatabaseRecordingTarget> target;
    const auto session = [&](double leanDeg, double seconds) {
      gui::LiveSessionConfig c = config(15.0);
      c.recordFromStart = target != nullptr;
      c.targetDeg = std::make_pair(20.0, 120.0);
      c.devices = QStringList{
          QStringLiteral("virtual-arm:sensors=upper+forearm+kinect+trunk,trajectory=exercise,"
                         "exercise=shoulder_flexion,exercise-range=20:120,trunk-lean=%1")
              .arg(leanDeg)};
      auto screen = std::make_unique<LiveSessionScreen>(m_registry, c, target);
      showAt1024(*screen);
      QSignalSpy started(screen.get(), &LiveSessionScreen::sessionStarted);
      screen->start();
      [&] { QVERIFY(started.wait(15000)); }();
      bool cueSeen = false, anglesSeen = false;
      QElapsedTimer wall;
      wall.start();
      while (screen->sessionTime() < seconds && wall.elapsed() < 120000) {
        QTest::qWait(25);
        cueSeen = cueSeen || screen->trunk().cueLabel()->isVisible();
        anglesSeen = anglesSeen || screen->trunk().anglesLabel()->isVisible();
        if (cueSeen && leanDeg > 15 && screen->trunk().compensated() > 0) break;
      }
      if (cueSeen && leanDeg > 15)
        test::saveScreenshot(test::grabFromScreen(screen.get()),
                             QStringLiteral("live-trunk-cue-virtual-arm"));
      [&] { QTRY_VERIFY_WITH_TIMEOUT(!target || screen->state() == State::Recording, 10000); }();
      screen->stop();
      [&] { QTRY_COMPARE_WITH_TIMEOUT(screen->state(), State::Stopped, 15000); }();
      return std::make_tuple(cueSeen, anglesSeen, screen->trunk().compensated(),
                             screen->repetitionCounter().count(), screen->sessionTime());
    };
    target = std::make_shared<DatabaseRecordingTarget>(store, url, QStringLiteral("P01"));
    const auto [cued, angles, compensated, reps, t] = session(25.0, 40.0);
    QVERIFY2(angles, "no trunk angles reached the screen");
    QVERIFY2(cued, qPrintable(QStringLiteral("no cue in %1 s").arg(t)));
    QVERIFY2(compensated >= 1 && compensated <= reps,
             qPrintable(QStringLiteral("%1 of %2").arg(compensated).arg(reps)));
    QVERIFY(target->sessionId() > 0);
    const QString notes = store.session(target->sessionId()).notes;
    QVERIFY2(notes.contains(
                 QStringLiteral("Trunk limit 15\u00b0: %1 of %2 repetitions with compensation")
                     .arg(compensated)
                     .arg(reps)),
             qPrintable(notes));
    target.reset();
    // Three reaches (tops at 3, 8 and 13 s of the virtual arm's 1 s start, 4 s reach and 1 s
    // pause), all leaning 6 deg as alike as the session's noise lets them: 16 s show them where
    // 25 s showed the same reaches five times over.
    const auto [cuedLess, anglesLess, compensatedLess, repsLess, tLess] = session(6.0, 16.0);
    QVERIFY(anglesLess);
    QVERIFY2(repsLess >= 2, qPrintable(QString::number(repsLess)));
    QVERIFY2(!cuedLess, qPrintable(QStringLiteral("cued in %1 s").arg(tLess)));
    QCOMPARE(compensatedLess, std::size_t(0));
  }

  void theCueInGerman() {
    QCOMPARE(i18n::setLanguage(QStringLiteral("de")), QStringLiteral("de"));
    {
      LiveSessionScreen screen(m_registry, config(15.0));
      showAt1024(screen);
      const double top = 1.0 + 1 * kPeriodS + 2.0;
      play(
          screen, [&](double t) { return trunkDeg(t, 25, {1}); }, top);
      QVERIFY(screen.trunk().cueLabel()->isVisible());
      QVERIFY(screen.trunk().cueLabel()->text() !=
              QStringLiteral("Keep your back against the chair"));
      test::saveScreenshot(test::grabFromScreen(&screen), QStringLiteral("live-trunk-cue-de"));
    }
    i18n::setLanguage(QStringLiteral("en"));
  }
};

ARMTRACK_GUI_TEST_MAIN(TestLiveTrunkCue)
#include "test_live_trunk_cue.moc"
