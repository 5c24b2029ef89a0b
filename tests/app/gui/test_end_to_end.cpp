// The therapist's whole path through the real application under Xvfb: the first-run assistant,
// signing in, a new patient, a 20 s virtual-arm session (new-session steps, live screen with a
// Kinect that drops out for 3 s: health turns red and the session goes on, recording), its
// analysis and review with a re-estimation, and the session report (pdftotext finds the
// patient's name). Every main screen is grabbed from the X server into the screenshot folder:
// docs/user-guide.md embeds them (ARMTRACK_SCREENSHOT_DIR=docs/images, see the guide).
#include <QDate>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTableView>
#include <QWizard>

#include "app/gui/AppController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/common/SensorCalibrationPage.h"
#include "app/gui/live/LiveSessionScreen.h"
#include "app/gui/newsession/DevicesPage.h"
#include "app/gui/newsession/NewSessionScreen.h"
#include "app/gui/patients/PatientDialog.h"
#include "app/gui/patients/PatientListScreen.h"
#include "app/gui/patients/PatientScreen.h"
#include "app/gui/patients/ProgressChart.h"
#include "app/gui/review/ReviewScreen.h"
#include "app/gui/signin/FirstRunScreen.h"
#include "app/gui/signin/SignInScreen.h"
#include "tests/app/gui/support/GuiTestSupport.h"
#include "ui/DeviceHealthPanel.h"

using namespace armtrack::gui;
using armtrack::app::gui::LiveSessionScreen;
using armtrack::gui::test::findControl;
using armtrack::gui::test::typeInto;

class TestEndToEnd : public QObject {
  Q_OBJECT

  QTemporaryDir m_dir;
  std::unique_ptr<AppController> m_app;

  QWidget* screen() const { return m_app->window()->currentScreen(); }
  template <class T>
  T* current() const {
    return qobject_cast<T*>(screen());
  }
  void activate(QWidget* w) { QVERIFY(test::activate(w)); }
  void shot(const char* name) { test::saveScreenshot(m_app->window(), QString::fromLatin1(name)); }

 private slots:
  void initTestCase() {
    // The session's devices: the virtual arm, whose Kinect is silent from 8 s to 11 s.
    QSettings().setValue(
        QStringLiteral("devices/default"),
        QStringList{
            QStringLiteral("virtual-arm:sensors=upper+forearm+kinect+webcam,dropout=kinect@8+3")});
    AppOptions o;
    o.pluginFolders = {QStringLiteral(ARMTRACK_PLUGIN_DIR)};
    m_app = std::make_unique<AppController>(o);
    m_app->start();
    activate(m_app->window());
  }

  void firstRunCreatesTheRecords() {
    QTRY_VERIFY(current<FirstRunScreen>());
    typeInto(findControl<QLineEdit>(screen(), QStringLiteral("Data folder")),
             m_dir.filePath(QStringLiteral("clinic")));
    typeInto(findControl<QLineEdit>(screen(), QStringLiteral("Administrator name")),
             QStringLiteral("admin"));
    typeInto(findControl<QLineEdit>(screen(), QStringLiteral("Password")),
             QStringLiteral("clinic-pass-1"));
    typeInto(findControl<QLineEdit>(screen(), QStringLiteral("Password again")),
             QStringLiteral("clinic-pass-1"));
    shot("first-run");
    QTest::keyClick(findControl<QLineEdit>(screen(), QStringLiteral("Password again")),
                    Qt::Key_Return);
    QTRY_VERIFY(current<PatientListScreen>());
  }

  void signsIn() {
    m_app->signOut();
    QTRY_VERIFY(current<SignInScreen>());
    auto* password = findControl<QLineEdit>(screen(), QStringLiteral("Password"));
    QCOMPARE(findControl<QLineEdit>(screen(), QStringLiteral("Account name"))->text(),
             QStringLiteral("admin"));
    typeInto(password, QStringLiteral("clinic-pass-1"));
    shot("sign-in");
    QTest::keyClick(password, Qt::Key_Return);
    QTRY_VERIFY(current<PatientListScreen>());
    QCOMPARE(m_app->records().user().name, QStringLiteral("admin"));
  }

  void createsAPatient() {
    activate(m_app->window());
    QTest::keySequence(screen(), QKeySequence::New);
    PatientDialog* d = nullptr;
    QTRY_VERIFY((d = screen()->findChild<PatientDialog*>()) != nullptr);
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Patient code")), QStringLiteral("P100"));
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Patient name")), QStringLiteral("Eva Ende"));
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Birth date")), QStringLiteral("1948-06-03"));
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Diagnosis")),
             QStringLiteral("Stroke, left hemisphere"));
    findControl<QDoubleSpinBox>(d, QStringLiteral("Upper arm length"))->setValue(22);
    findControl<QDoubleSpinBox>(d, QStringLiteral("Forearm length"))->setValue(20);
    test::saveScreenshot(d, QStringLiteral("patient-dialog"));
    QTest::mouseClick(findControl<QPushButton>(d, QStringLiteral("Save")), Qt::LeftButton);
    QTRY_VERIFY(!screen()->findChild<PatientDialog*>());
    QTRY_COMPARE(current<PatientListScreen>()->selectedCode(), QStringLiteral("P100"));
    shot("patients");
    activate(m_app->window());
    QTest::keyClick(findControl<QTableView>(screen(), QStringLiteral("Patient list")),
                    Qt::Key_Return);
    QTRY_VERIFY(current<PatientScreen>());
    QTRY_COMPARE(current<PatientScreen>()->overview().patient.name, QStringLiteral("Eva Ende"));
    QCOMPARE(current<PatientScreen>()->overview().patient.birthDate, QStringLiteral("1948-06-03"));
  }

  void recordsA20SecondSession() {
    activate(m_app->window());
    QTest::keySequence(screen(), QKeySequence(QStringLiteral("Ctrl+R")));
    QTRY_VERIFY(current<NewSessionScreen>());
    QWizard* wizard = current<NewSessionScreen>()->wizard();
    QTRY_VERIFY(current<NewSessionScreen>()->setupPage()->isComplete());
    shot("new-session");
    QTest::mouseClick(wizard->button(QWizard::NextButton), Qt::LeftButton);

    // Devices: the virtual arm from the settings; the connection check sees every stream.
    NewSessionScreen* ns = current<NewSessionScreen>();
    QTRY_COMPARE(wizard->currentPage(), static_cast<QWizardPage*>(ns->devicesStep()));
    auto* devices = qobject_cast<armtrack::app::gui::DevicesPage*>(ns->devicesStep()->page());
    QVERIFY(devices);
    QCOMPARE(devices->devices().size(), 1);
    QVERIFY(devices->devices().first().startsWith(QStringLiteral("virtual-arm")));
    devices->startCheck();
    QTRY_VERIFY_WITH_TIMEOUT(devices->checkPassed(), 30000);
    shot("devices");
    QTest::mouseClick(wizard->button(QWizard::NextButton), Qt::LeftButton);

    // The guided sensor calibration: the virtual arm plays the protocol; a verdict follows.
    QTRY_COMPARE(wizard->currentPage(), static_cast<QWizardPage*>(ns->calibrationStep()));
    auto* calibration =
        qobject_cast<armtrack::app::gui::SensorCalibrationPage*>(ns->calibrationStep()->page());
    QVERIFY(calibration);
    QVERIFY(!wizard->button(QWizard::NextButton)->isEnabled());  // not before a verdict
    QTest::mouseClick(calibration->startButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(
        calibration->state() == armtrack::app::gui::SensorCalibrationPage::State::Recording, 20000);
    const QString firstStep = calibration->instructionTitle();
    QTRY_VERIFY_WITH_TIMEOUT(calibration->instructionTitle() != firstStep, 30000);
    shot("calibration");  // the guide at its second step
    QTRY_VERIFY2_WITH_TIMEOUT(
        calibration->state() == armtrack::app::gui::SensorCalibrationPage::State::Done ||
            calibration->state() == armtrack::app::gui::SensorCalibrationPage::State::Failed,
        qPrintable(calibration->verdictText()), 300000);
    QVERIFY2(calibration->isComplete(), qPrintable(calibration->verdictText()));
    shot("calibration-verdict");
    QTest::mouseClick(wizard->button(QWizard::NextButton), Qt::LeftButton);

    // The virtual arm's webcam is simulated (its camera model known): the camera step names it
    // and has nothing to do; Finish starts the live session.
    QTRY_COMPARE(wizard->currentPage(), static_cast<QWizardPage*>(ns->cameraStep()));
    auto* cameraText = ns->cameraStep()->findChild<QLabel*>(QStringLiteral("cameraStepText"));
    QVERIFY(cameraText);
    QVERIFY2(cameraText->text().contains(QStringLiteral("virtual-arm")),
             qPrintable(cameraText->text()));
    QTRY_VERIFY(wizard->button(QWizard::FinishButton)->isEnabled());
    QVERIFY(ns->choices().calibration.has_value());
    QVERIFY(QFileInfo::exists(ns->choices().calibrationFile));
    QTest::mouseClick(wizard->button(QWizard::FinishButton), Qt::LeftButton);
    QTRY_VERIFY(current<LiveSessionScreen>());
    LiveSessionScreen* live = current<LiveSessionScreen>();
    QTRY_VERIFY2_WITH_TIMEOUT(live->state() == LiveSessionScreen::State::Live,
                              qPrintable(live->bannerText()), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(live->sessionTime() >= 1.0, 20000);
    QTest::mouseClick(live->recordButton(), Qt::LeftButton);
    QTRY_COMPARE(live->state(), LiveSessionScreen::State::Recording);
    const double from = live->sessionTime();

    // The Kinect drops out: its row turns red while the estimates go on.
    const auto kinectDown = [&] {
      for (const auto& r : live->health()->tracker().rows())
        if (r.stream.contains(QStringLiteral("kinect")) &&
            r.level == armtrack::ui::HealthLevel::Down)
          return true;
      return false;
    };
    QTRY_VERIFY_WITH_TIMEOUT(kinectDown(), 20000);
    const double downAt = live->sessionTime();
    QTRY_VERIFY_WITH_TIMEOUT(live->sessionTime() > downAt + 1.0, 10000);  // the session goes on
    QVERIFY(live->state() == LiveSessionScreen::State::Recording);
    QTRY_VERIFY_WITH_TIMEOUT(!kinectDown(), 20000);  // and green again
    QTRY_VERIFY_WITH_TIMEOUT(live->sessionTime() >= from + 15.0, 30000);
    shot("live");
    QTRY_VERIFY_WITH_TIMEOUT(live->sessionTime() >= from + 20.2, 30000);
    QTest::mouseClick(live->stopButton(), Qt::LeftButton);
    // Stopped, analysed (with the session's calibration), reviewed.
    QTRY_VERIFY_WITH_TIMEOUT(current<ReviewScreen>(), 60000);
    QSignalSpy loaded(current<ReviewScreen>(), &ReviewScreen::loaded);
    QTRY_VERIFY_WITH_TIMEOUT(current<ReviewScreen>()->data().analysis.has_value(), 30000);
    const auto& info = current<ReviewScreen>()->data().info;
    QVERIFY2(info.durationS > 19.5 && info.durationS < 23,
             qPrintable(QString::number(info.durationS)));
    QCOMPARE(info.status, QStringLiteral("complete"));
    QCOMPARE(info.patientCode, QStringLiteral("P100"));
    const QJsonObject made =
        QJsonDocument::fromJson(current<ReviewScreen>()->data().analysis->paramsJson.toUtf8())
            .object();
    QVERIFY(made["calibration"].toBool());
  }

  void reviewsWithAReestimation() {
    ReviewScreen* r = current<ReviewScreen>();
    QVERIFY(r);
    r->setCursor(r->data().analysis->t.front() + 6.0);
    QSignalSpy done(r, &ReviewScreen::reestimated);
    ReestimateChoice c;
    c.filter = armtrack::FilterKind::Ukf;
    r->reestimate(c);
    QVERIFY(done.wait(120000));
    QCOMPARE(done.at(0).at(0).toInt(), 2);
    const QJsonObject p = QJsonDocument::fromJson(r->data().analysis->paramsJson.toUtf8()).object();
    QCOMPARE(p["filter"].toString(), QStringLiteral("ukf"));
    shot("review");
  }

  void writesTheSessionReport() {
    ReviewScreen* r = current<ReviewScreen>();
    QSignalSpy written(r, &ReviewScreen::outputWritten);
    const QString pdf = m_dir.filePath(QStringLiteral("report.pdf"));
    r->writeReport(pdf);
    QVERIFY(written.wait(60000));
    QCOMPARE(written.at(0).at(1).toString(), QString());
    const QString text = test::pdfText(pdf);
    QVERIFY2(text.contains(QStringLiteral("Eva Ende")), qPrintable(text.left(300)));
    QVERIFY(text.contains(QStringLiteral("P100")));
  }

  void thePatientPageListsTheSession() {
    QTest::mouseClick(findControl<QPushButton>(screen(), QStringLiteral("Back to the patient")),
                      Qt::LeftButton);
    QTRY_VERIFY(current<PatientScreen>());
    QTRY_COMPARE(current<PatientScreen>()->overview().sessions.size(), std::size_t{1});
    QCOMPARE(current<PatientScreen>()->progressChart()->points(), 1);
    shot("patient");
  }

  void cleanupTestCase() { m_app.reset(); }
};

ARMTRACK_APP_TEST_MAIN(TestEndToEnd)
#include "test_end_to_end.moc"
