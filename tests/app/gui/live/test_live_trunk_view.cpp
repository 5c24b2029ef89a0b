// The live screen with a leaning virtual patient and a sternum sensor under Xvfb: the 3D view's
// trunk follows the session's trunk estimate and the trunk plot appears; screenshots at the
// smallest supported screen (1024 x 600), in English and in German.
#include <QLineSeries>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTest>
#include <cmath>
#include <numbers>

#include "app/gui/live/LiveSessionScreen.h"
#include "app/i18n/Language.h"
#include "app/plugins/PluginRegistry.h"
#include "tests/support/GuiTestMain.h"
#include "ui/AnglePlotPanel.h"
#include "ui/ArmView.h"

using namespace armtrack;
using armtrack::app::gui::LiveSessionScreen;

class TestLiveTrunkView : public QObject {
  Q_OBJECT

  app::PluginRegistry m_registry;

 private slots:
  void initTestCase() {
    m_registry.load({QStringLiteral(ARMTRACK_PLUGIN_DIR)});
    QVERIFY2(m_registry.plugin(QStringLiteral("virtual-arm")), "virtual-arm plugin not built");
  }

  void leaningPatientLeansTheTrunkInTheView() {
    app::gui::LiveSessionConfig c;
    c.devices = {QStringLiteral(
        "virtual-arm:sensors=upper+forearm+kinect+trunk,trajectory=reaching,trunk-lean=20")};
    c.patientLabel = QStringLiteral("P07 Leaning Patient");
    LiveSessionScreen screen(m_registry, c);
    screen.resize(1024, 600);
    screen.show();
    QVERIFY(QTest::qWaitForWindowExposed(&screen));
    QSignalSpy started(&screen, &LiveSessionScreen::sessionStarted);
    screen.start();
    QVERIFY(started.wait(10000));
    ui::ArmView* view = screen.armView();
    // The sternum sensor is drawn on the chest, where it is put by default (no calibration).
    QVERIFY(view->sternumImu().has_value());
    QVERIFY(view->sternumImu()->imuPosition.isApprox(defaultTrunkMount(Side::Right).imuPosition));
    // The session estimates the trunk from the sternum sensor; the view takes each estimate.
    QTRY_VERIFY_WITH_TIMEOUT(view->trunk().has_value(), 10000);
    // The reaches lean the trunk forward, up to 20 deg: the view leans with them.
    double most = 0;
    QVERIFY(QTest::qWaitFor(
        [&] {
          if (view->trunk()) most = std::max(most, (*view->trunk())(0));
          return most > 12.0 * std::numbers::pi / 180.0;
        },
        30000));
    QVERIFY(screen.plots()->trunkChart()->isVisible());
    QVERIFY(!screen.plots()->trunkTrace().empty());
    // The trunk plot draws the same lean (degrees).
    screen.plots()->refresh();
    double plotted = 0;
    for (const QPointF& p : screen.plots()->trunkChart()->series(0)->points())
      plotted = std::max(plotted, p.y());
    QVERIFY2(plotted > 12.0, qPrintable(QString::number(plotted)));
    // Freeze a clearly leaning moment, some seconds in, for the pictures.
    QVERIFY(QTest::qWaitFor(
        [&] {
          return screen.sessionTime() > 8.0 && view->trunk() &&
                 (*view->trunk())(0) > 12.0 * std::numbers::pi / 180.0;
        },
        60000));
    QSignalSpy stopped(&screen, &LiveSessionScreen::sessionStopped);
    screen.stop();
    QVERIFY(stopped.wait(15000));
    // The plots scrolled down to the trunk's.
    auto* scroll = screen.plots()->findChild<QScrollArea*>();
    QVERIFY(scroll);
    scroll->verticalScrollBar()->setValue(scroll->verticalScrollBar()->maximum());
    screen.plots()->refresh();
    view->scheduleFrame();
    QTest::qWait(300);
    test::saveScreenshot(test::grabFromScreen(&screen), QStringLiteral("live_trunk_lean"));
    i18n::setLanguage(QStringLiteral("de"));
    QCoreApplication::processEvents();
    screen.plots()->refresh();
    view->scheduleFrame();
    QTest::qWait(300);
    test::saveScreenshot(test::grabFromScreen(&screen), QStringLiteral("live_trunk_lean_de"));
    i18n::setLanguage(QStringLiteral("en"));
  }
};

ARMTRACK_GUI_TEST_MAIN(TestLiveTrunkView)
#include "test_live_trunk_view.moc"
