// The new session's device check with a third sensor: the virtual arm's sternum IMU is listed as
// the trunk (sternum) sensor with its rate and health like the arm sensors, named in the language
// switched to while the check's result is shown; screenshots at 1024 x 600 in English and German.
// The sensor calibration's words count the sensors strapped on: two, or three with the sternum's.
#include <QLineEdit>
#include <QListWidget>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "app/gui/common/SensorCalibrationPage.h"
#include "app/gui/newsession/DevicesPage.h"
#include "app/i18n/Language.h"
#include "app/plugins/PluginRegistry.h"
#include "tests/support/GuiTestMain.h"
#include "ui/DeviceHealthPanel.h"
#include "ui/DeviceOptionsForm.h"

using namespace armtrack;

class TestTrunkDeviceCheck : public QObject {
  Q_OBJECT

  app::PluginRegistry m_registry;

 private slots:
  void initTestCase() {
    m_registry.load({QStringLiteral(ARMTRACK_PLUGIN_DIR)});
    QVERIFY2(m_registry.plugin(QStringLiteral("virtual-arm")), "virtual-arm plugin not built");
  }

  void sternumSensorIsListedWithItsRateAndHealth() {
    app::gui::DevicesPage page(m_registry, app::gui::LiveSessionConfig{});
    page.resize(1024, 600);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    const auto items =
        page.pluginList()->findItems(QStringLiteral("virtual-arm"), Qt::MatchExactly);
    QCOMPARE(items.size(), 1);
    page.pluginList()->setCurrentItem(items.front());
    items.front()->setCheckState(Qt::Checked);
    QLineEdit* sensors = page.optionsForm()->edit(QStringLiteral("sensors"));
    QVERIFY(sensors);
    sensors->setText(QStringLiteral("upper+forearm+kinect+trunk"));
    QSignalSpy finished(&page, &app::gui::DevicesPage::checkFinished);
    page.checkButton()->click();
    QVERIFY(finished.wait(20000));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
    const ui::DeviceHealthModel* health = page.health()->model();
    int trunkRow = -1;
    for (int row = 0; row < health->rowCount(); ++row)
      if (health->data(health->index(row, ui::DeviceHealthModel::Stream)).toString() ==
          QStringLiteral("Trunk (sternum) sensor"))
        trunkRow = row;
    QVERIFY2(trunkRow >= 0, "no trunk (sternum) sensor row");
    QCOMPARE(health->rowCount(), 5);  // upper, forearm, trunk, Kinect, truth
    QTRY_VERIFY_WITH_TIMEOUT(page.health()->tracker().allOk(), 5000);
    // Its rate is the arm IMUs' (1 kHz), in the summary too.
    QVERIFY2(page.statusText().contains(QStringLiteral("Trunk (sternum) sensor")),
             qPrintable(page.statusText()));
    test::saveScreenshot(test::grabFromScreen(&page), QStringLiteral("new_session_devices_trunk"));
    // The language switched while the check's result is shown: the result names the sensor in
    // German at once, as the health table does.
    i18n::setLanguage(QStringLiteral("de"));
    QCoreApplication::processEvents();
    const QString german = QStringLiteral("Rumpfsensor (Brustbein)");
    QVERIFY2(page.statusText().contains(german), qPrintable(page.statusText()));
    QVERIFY2(!page.statusText().contains(QStringLiteral("Trunk (sternum) sensor")),
             qPrintable(page.statusText()));
    QCOMPARE(health->data(health->index(trunkRow, ui::DeviceHealthModel::Stream)).toString(),
             german);
    QTest::qWait(1200);  // the health table's next refresh, in German
    test::saveScreenshot(test::grabFromScreen(&page),
                         QStringLiteral("new_session_devices_trunk_de"));
    i18n::setLanguage(QStringLiteral("en"));
    QCoreApplication::processEvents();
    QVERIFY2(page.statusText().contains(QStringLiteral("Trunk (sternum) sensor")),
             qPrintable(page.statusText()));
    page.stopCheck();
  }

  void calibrationNamesTheSensorsStrappedOn() {
    i18n::setLanguage(QStringLiteral("en"));  // whatever a test before left
    QTemporaryDir dir;
    app::gui::LiveSessionConfig c;
    c.devices = {QStringLiteral("virtual-arm:sensors=upper+forearm+kinect")};
    {
      app::gui::SensorCalibrationPage two(m_registry, c, dir.path().toStdString());
      QVERIFY2(two.instructionText().contains(QStringLiteral("both sensors strapped on")),
               qPrintable(two.instructionText()));
    }
    c.devices = {QStringLiteral("virtual-arm:sensors=upper+forearm+kinect+trunk")};
    app::gui::SensorCalibrationPage three(m_registry, c, dir.path().toStdString());
    three.resize(1024, 600);
    three.show();
    QVERIFY(QTest::qWaitForWindowExposed(&three));
    QVERIFY2(!three.instructionText().contains(QStringLiteral("both")),
             qPrintable(three.instructionText()));
    QVERIFY2(three.instructionText().contains(QStringLiteral("all three sensors")),
             qPrintable(three.instructionText()));
    test::saveScreenshot(test::grabFromScreen(&three),
                         QStringLiteral("new_session_calibration_trunk_intro"));
    // A fit that did not settle asks to check every sensor calibrated.
    CalibrationResult r;
    r.converged = false;
    QString why;
    app::gui::judgeCalibration(r, &why);
    QVERIFY2(why.contains(QStringLiteral("both sensors")), qPrintable(why));
    r.calibration.trunk.emplace();
    app::gui::judgeCalibration(r, &why);
    QVERIFY2(why.contains(QStringLiteral("all three sensors")), qPrintable(why));
  }
};

ARMTRACK_GUI_TEST_MAIN(TestTrunkDeviceCheck)
#include "test_trunk_device_check.moc"
