// The home window tells the patient about the straps only when it matters (docs/user-guide.md,
// "Straps checked from the movement"): while an exercise runs, a fit from the movement that
// found a strap turned 25 deg brings one plain sentence, once; straps turned a few degrees, or
// as fitted, bring none. The finding is made here (the screen's straps source); the exercise
// runs on the virtual arm, signed in as the demo's home account.
#include <QPushButton>

#include "app/gui/AppController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/home/ExerciseScreen.h"
#include "app/gui/home/FeedbackSound.h"
#include "app/gui/services/DemoData.h"
#include "app/gui/services/StrapsText.h"
#include "tests/app/gui/support/GuiTestSupport.h"

using namespace armtrack;
using namespace armtrack::gui;
using namespace armtrack::gui::home;

namespace {

HomeExercise elbowExercise() {
  HomeExercise e;
  e.protocol.name = QStringLiteral("Elbow flexion");
  e.protocol.angleKey = QStringLiteral("elbow_flexion");
  e.angle = 3;
  e.item.protocolName = e.protocol.name;
  e.item.position = 1;
  e.item.sets = 1;
  e.item.restS = 0;
  e.repetitions = 4;
  e.targetMinDeg = 0;
  e.targetMaxDeg = 85;
  return e;
}

/// A fit in use that found the upper-arm sensor turned upperDeg (or none: as fitted).
session::LiveCalibrationStatus finding(std::optional<double> upperDeg) {
  session::LiveCalibrationStatus s;
  s.fits = 1;
  if (!upperDeg) {
    s.state = session::LiveCalibrationStatus::State::AsFitted;
    return s;
  }
  s.state = session::LiveCalibrationStatus::State::Applied;
  s.applied = 1;
  s.calibration = Calibration{};
  MountingSummary m;
  m.upperTurnDeg = *upperDeg;
  m.forearmTurnDeg = 3.0;
  m.forearmFromWristCm = 4.0;
  s.summary = m;
  return s;
}

}  // namespace

class TestHomeStraps : public QObject {
  Q_OBJECT

  QTemporaryDir m_dir;
  std::unique_ptr<AppController> m_app;

  /// The feedback shown over the first seconds of an exercise whose straps source gives status.
  QStringList feedbackWith(const session::LiveCalibrationStatus& status) {
    app::gui::LiveSessionConfig config;
    config.devices = QStringList{QStringLiteral("virtual-arm:sensors=upper+forearm")};
    FeedbackSound sound;
    ExerciseScreen screen(m_app->plugins(), m_app->records(), elbowExercise(), 1, 1,
                          QString::fromLatin1(DemoAccounts::kLivePatient), config, false, &sound);
    int asked = 0;
    screen.setStrapsSource([&] {
      ++asked;
      return status;
    });
    screen.resize(1024, 600);
    screen.show();
    [&] { QVERIFY(QTest::qWaitForWindowExposed(&screen)); }();
    // Looked at about once a second; then two seconds more, in which nothing is told again.
    [&] { QTRY_VERIFY_WITH_TIMEOUT(asked >= 1, 10000); }();
    QTest::qWait(2500);
    const QStringList shown = screen.feedbackShown();
    screen.cutShort();
    return shown;
  }

  static QString turnedWords() { return app::gui::strapsPatientLine(finding(25.0)); }

 private slots:
  void initTestCase() {
    AppOptions o;
    o.pluginFolders = {QStringLiteral(ARMTRACK_PLUGIN_DIR)};
    m_app = armtrack::gui::test::demoApp(m_dir, o);
    QVERIFY(m_app);
    m_app->signOut();
    QVERIFY(armtrack::gui::test::signInAs(*m_app, DemoAccounts::kHome));
  }

  void aTurnedStrapIsToldOnceInPlainWords() {
    QVERIFY(!turnedWords().isEmpty());
    // No numbers, no sensor frames: the patient's words.
    QVERIFY2(!turnedWords().contains(QRegularExpression(QStringLiteral("\\d"))),
             qPrintable(turnedWords()));
    const QStringList shown = feedbackWith(finding(25.0));
    QCOMPARE(shown.count(turnedWords()), 1);
  }

  void strapsThatSitWellAreNotMentioned() {
    for (const auto& f : {finding(5.0), finding(std::nullopt)}) {
      QVERIFY(app::gui::strapsPatientLine(f).isEmpty());
      const QStringList shown = feedbackWith(f);
      QCOMPARE(shown.count(turnedWords()), 0);
    }
  }
};

ARMTRACK_APP_TEST_MAIN(TestHomeStraps)
#include "test_home_straps.moc"
