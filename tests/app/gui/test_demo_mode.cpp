// armtrack --demo: fresh demo records made off the GUI thread with a progress bar, signed in as
// the demo therapist, the demo patient's page open within seconds; and the program itself, run
// unattended under Xvfb, saves its window and quits.
#include <QElapsedTimer>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <cmath>

#include "app/gui/AppController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/common/MessageScreen.h"
#include "app/gui/live/LiveSessionScreen.h"
#include "app/gui/patients/PatientScreen.h"
#include "app/gui/services/DemoData.h"
#include "tests/app/gui/support/GuiTestSupport.h"
#include "ui/RepetitionCounterWidget.h"

using namespace armtrack::gui;

namespace {

// The program run as a user would, with its exit and what it said on standard error.
struct GuiRun {
  bool finished = false;
  QProcess::ExitStatus status = QProcess::CrashExit;
  int code = -1;
  QString err;
};

GuiRun runGui(const QStringList& args, int timeoutMs) {
  QProcess p;
  p.start(QStringLiteral(ARMTRACK_GUI), args);
  GuiRun r;
  r.finished = p.waitForFinished(timeoutMs);
  r.status = p.exitStatus();
  r.code = p.exitCode();
  r.err = QString::fromLocal8Bit(p.readAllStandardError());
  return r;
}

}  // namespace

class TestDemoMode : public QObject {
  Q_OBJECT
  QTemporaryDir m_dir;

 private slots:
  void opensThePatientSignedInAsTheDemoTherapist() {
    AppOptions o;
    o.demo = true;
    o.database = m_dir.filePath(QStringLiteral("demo/armtrack-demo.db"));
    o.pluginFolders = {QStringLiteral(ARMTRACK_PLUGIN_DIR)};
    AppController app(o);
    QSignalSpy ready(&app, &AppController::demoReady);
    QElapsedTimer timer;
    timer.start();
    app.start();
    // While the records are made, the window shows progress and stays responsive.
    QVERIFY(qobject_cast<MessageScreen*>(app.window()->currentScreen()));
    QVERIFY(ready.wait(30000));
    qInfo("demo ready after %.2f s", timer.elapsed() / 1000.0);
    QVERIFY(app.records().signedIn());
    QCOMPARE(app.records().user().name, QString::fromLatin1(DemoAccounts::kTherapist));
    QCOMPARE(app.records().user().role, armtrack::storage::Role::Therapist);
    // The live session with the virtual arm: estimates flow within seconds.
    auto* live =
        qobject_cast<armtrack::app::gui::LiveSessionScreen*>(app.window()->currentScreen());
    QVERIFY(live);
    QTRY_VERIFY2_WITH_TIMEOUT(live->sessionTime() >= 2.0, qPrintable(live->bannerText()), 20000);
    qInfo("live estimates at %.1f s of session time, %.2f s after start", live->sessionTime(),
          timer.elapsed() / 1000.0);
    QVERIFY(live->estimatesDrained() > 100);
    QVERIFY(live->bannerText().isEmpty());
    // The virtual arm makes the demo protocol's exercise (shoulder flexion, target 90-150 deg):
    // one repetition every 5 s (4 s up and down, 1 s at rest), each a full one for the counter.
    const armtrack::RepetitionCounter& counter = live->repetitionCounter();
    QCOMPARE(counter.primaryAngle(), 0);
    QTRY_VERIFY2_WITH_TIMEOUT(
        counter.count() >= 3,
        qPrintable(
            QStringLiteral("%1 repetitions at %2 s").arg(counter.count()).arg(live->sessionTime())),
        30000);
    QCOMPARE(counter.partialCount(), std::size_t{0});
    const auto& reps = counter.repetitions();
    for (std::size_t i = 1; i < reps.size(); ++i)
      QVERIFY2(std::abs(reps[i].peakS - reps[i - 1].peakS - 5.0) < 0.3,
               qPrintable(QString::number(reps[i].peakS - reps[i - 1].peakS)));
    QVERIFY(counter.count() <= static_cast<std::size_t>(live->sessionTime() / 5.0) + 1);
    for (const armtrack::CountedRepetition& r : reps)  // 20 deg to 141 deg
      QVERIFY2(std::abs(r.excursionRad * 180 / M_PI - 121) < 8,
               qPrintable(QString::number(r.excursionRad * 180 / M_PI)));
    QVERIFY2(
        live->repetitions()->text().startsWith(QStringLiteral("%1 of 10").arg(counter.count())),
        qPrintable(live->repetitions()->text()));
    test::saveScreenshot(app.window(), QStringLiteral("demo-live"));
    live->stop();
    QTRY_VERIFY_WITH_TIMEOUT(qobject_cast<PatientScreen*>(app.window()->currentScreen()), 20000);
    // Nothing was recorded: still six sessions.
    auto* page = qobject_cast<PatientScreen*>(app.window()->currentScreen());
    QTRY_COMPARE(page->overview().sessions.size(), std::size_t{6});
  }

  void runsUnattendedAndSavesItsWindow() {
    const QString shot = m_dir.filePath(QStringLiteral("window.png"));
    const GuiRun r =
        runGui({QStringLiteral("--demo"), QStringLiteral("--db"),
                m_dir.filePath(QStringLiteral("unattended.db")), QStringLiteral("--quit-after"),
                QStringLiteral("8"), QStringLiteral("--screenshot"), shot},
               60000);
    QVERIFY(r.finished);
    QCOMPARE(r.status, QProcess::NormalExit);
    QVERIFY2(r.code == 0, qPrintable(r.err));
    const QImage image(shot);
    QVERIFY(!image.isNull());
    QVERIFY(image.width() >= 900 && image.height() >= 600);
    // Not a blank picture: many distinct colours.
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 7)
      for (int x = 0; x < image.width(); x += 7) colours.insert(image.pixel(x, y));
    QVERIFY2(colours.size() > 20, qPrintable(QString::number(colours.size())));
  }

  // The home window ignores a plain close until it has ended its exercise and saved: an
  // unattended home run used to save its picture and then never end.
  void homeRunsUnattendedAndQuits() {
    const QString shot = m_dir.filePath(QStringLiteral("home.png"));
    const GuiRun r =
        runGui({QStringLiteral("--home"), QStringLiteral("--demo"), QStringLiteral("--db"),
                m_dir.filePath(QStringLiteral("home.db")), QStringLiteral("--quit-after"),
                QStringLiteral("8"), QStringLiteral("--screenshot"), shot},
               60000);
    QVERIFY2(r.finished, "still running 60 s after --quit-after 8");
    QCOMPARE(r.status, QProcess::NormalExit);
    QVERIFY2(r.code == 0, qPrintable(r.err));
    const QImage image(shot);
    QVERIFY(!image.isNull());
    QVERIFY(image.width() >= 900 && image.height() >= 600);
  }

  // --quit-when-live: how the package's install test knows the installed program reached the
  // live screen (tests/packaging): it quits on the condition, not after a guessed time.
  void quitsOnceTheLiveSessionShowsEstimates() {
    const QString shot = m_dir.filePath(QStringLiteral("live.png"));
    const GuiRun r = runGui({QStringLiteral("--demo"), QStringLiteral("--db"),
                             m_dir.filePath(QStringLiteral("live.db")),
                             QStringLiteral("--quit-when-live"), QStringLiteral("--quit-after"),
                             QStringLiteral("120"), QStringLiteral("--screenshot"), shot},
                            150000);
    const QString& err = r.err;
    QVERIFY(r.finished);
    QCOMPARE(r.status, QProcess::NormalExit);
    QVERIFY2(r.code == 0, qPrintable(err));
    const QRegularExpression running(
        QStringLiteral("the live session is running: (\\d+) "
                       "estimates in ([0-9.]+) s"));
    const QRegularExpressionMatch m = running.match(err);
    QVERIFY2(m.hasMatch(), qPrintable(err));
    QVERIFY2(m.captured(1).toLongLong() > 100, qPrintable(err));
    QVERIFY2(m.captured(2).toDouble() >= 2.0, qPrintable(err));
    QVERIFY(!QImage(shot).isNull());
  }

  void saysSoWhenNoLiveSessionCame() {
    // Without --demo the records open at the sign-in (here the first run): no live session.
    const GuiRun r = runGui(
        {QStringLiteral("--db"), m_dir.filePath(QStringLiteral("none.db")),
         QStringLiteral("--quit-when-live"), QStringLiteral("--quit-after"), QStringLiteral("1.5")},
        60000);
    QVERIFY(r.finished);
    QCOMPARE(r.status, QProcess::NormalExit);
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(QStringLiteral("no live session showed estimates within 1.5 s")),
             qPrintable(r.err));
  }
};

ARMTRACK_APP_TEST_MAIN(TestDemoMode)
#include "test_demo_mode.moc"
