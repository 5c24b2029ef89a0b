// The settings dialog: values checked in words before they are kept, saved in QSettings, the
// dark palette and the angle unit applied to the screens opened afterwards.
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardItemModel>

#include "app/gui/AppController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/SettingsDialog.h"
#include "app/gui/common/Forms.h"
#include "app/gui/patients/HomeDevicesBox.h"
#include "app/gui/patients/PatientScreen.h"
#include "app/gui/patients/ProgressChart.h"
#include "app/gui/services/DemoData.h"
#include "app/gui/signin/SignInScreen.h"
#include "tests/app/gui/support/GuiTestSupport.h"

using namespace armtrack::gui;
using armtrack::gui::test::findControl;
using armtrack::gui::test::typeInto;

class TestSettings : public QObject {
  Q_OBJECT
  QTemporaryDir m_dir;

  static void choose(QComboBox* box, const QString& data) {
    QVERIFY(box);
    const int i = box->findData(data);
    QVERIFY(i >= 0);
    box->setCurrentIndex(i);
  }

 private slots:
  void savedAppliedAndChecked() {
    const auto owner = test::demoApp(m_dir);
    QVERIFY(owner);
    AppController& app = *owner;

    app.showSettings();
    SettingsDialog* d = nullptr;
    QTRY_VERIFY((d = app.window()->findChild<SettingsDialog*>()) != nullptr);
    choose(findControl<QComboBox>(d, QStringLiteral("Angle units")), QStringLiteral("rad"));
    choose(findControl<QComboBox>(d, QStringLiteral("Default filter")), QStringLiteral("ukf"));
    choose(findControl<QComboBox>(d, QStringLiteral("Default method")), QStringLiteral("C"));
    choose(findControl<QComboBox>(d, QStringLiteral("Appearance")), QStringLiteral("dark"));
    auto* ok = d->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    // A relative data folder and a malformed database are refused in words.
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Data folder")), QStringLiteral("data"));
    QTest::mouseClick(ok, Qt::LeftButton);
    QVERIFY(d->isVisible());
    QVERIFY(d->findChild<MessageLine*>()->text().contains(QStringLiteral("full path")));
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Data folder")), m_dir.path());
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Database")),
             QStringLiteral("mysql://somewhere/db"));
    QTest::mouseClick(ok, Qt::LeftButton);
    QVERIFY(d->isVisible());
    QVERIFY2(d->findChild<MessageLine*>()->text().contains(QStringLiteral("not one ArmTrack")),
             qPrintable(d->findChild<MessageLine*>()->text()));
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Database")), QString());
    // The sync server address: optional, but when given an https address with a host.
    auto* server = findControl<QLineEdit>(d, QStringLiteral("Sync server address"));
    QVERIFY(server);
    for (const QString& bad : {QStringLiteral("http://sync.clinic.example:8443"),
                               QStringLiteral("sync clinic"), QStringLiteral("https://")}) {
      typeInto(server, bad);
      QTest::mouseClick(ok, Qt::LeftButton);
      QVERIFY2(d->isVisible(), qPrintable(bad));
      QVERIFY2(d->findChild<MessageLine*>()->text().contains(QStringLiteral("https://NAME:PORT")),
               qPrintable(d->findChild<MessageLine*>()->text()));
    }
    typeInto(server, QStringLiteral(" https://sync.clinic.example:8443 "));
    test::saveScreenshot(d, QStringLiteral("settings"));
    QSignalSpy applied(&app, &AppController::settingsApplied);
    QTest::mouseClick(ok, Qt::LeftButton);
    QVERIFY(applied.count() == 1 || applied.wait(5000));

    QSettings s;
    QCOMPARE(s.value("display/units").toString(), QStringLiteral("rad"));
    QCOMPARE(s.value("analysis/filter").toString(), QStringLiteral("ukf"));
    QCOMPARE(s.value("analysis/method").toString(), QStringLiteral("C"));
    QCOMPARE(s.value("display/theme").toString(), QStringLiteral("dark"));
    QCOMPARE(s.value("data/folder").toString(), m_dir.path());
    QCOMPARE(s.value("sync/serverAddress").toString(),
             QStringLiteral("https://sync.clinic.example:8443"));
    QCOMPARE(app.settings().filter, QStringLiteral("ukf"));
    QVERIFY(QApplication::palette().color(QPalette::Window).lightness() < 100);

    // The patient page now shows ranges of motion in radians.
    app.showPatient(QStringLiteral("P001"));
    auto* page = qobject_cast<PatientScreen*>(app.window()->currentScreen());
    QVERIFY(page);
    QTRY_COMPARE(page->progressChart()->points(), 6);
    const QStandardItemModel* t = page->progressChart()->table();
    QCOMPARE(t->horizontalHeaderItem(1)->text(), QStringLiteral("Largest (rad)"));
    const double rad = t->item(5, 1)->text().toDouble();  // week 5: 125 deg simulated
    QVERIFY2(std::abs(rad - 125.0 * M_PI / 180) < 0.01, qPrintable(t->item(5, 1)->text()));
    test::saveScreenshot(app.window(), QStringLiteral("patient-dark"));
    // An enrolment code made there names the server the patient types.
    QVERIFY(page->homeDevices());
    QTRY_VERIFY(!page->homeDevices()->account().isEmpty());
    page->homeDevices()->makeCode();
    QTRY_VERIFY(!page->homeDevices()->shownCode().isEmpty());
    bool named = false;
    for (auto* l : page->homeDevices()->findChildren<QLabel*>())
      named |=
          l->isVisible() && l->text().contains(QStringLiteral("https://sync.clinic.example:8443"));
    QVERIFY(named);
    applyTheme(Theme::Light);
  }
};

ARMTRACK_APP_TEST_MAIN(TestSettings)
#include "test_settings.moc"
