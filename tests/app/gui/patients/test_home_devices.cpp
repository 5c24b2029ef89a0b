// The patient page's home devices (issue 28): the therapist makes an enrolment code for the
// patient's home account with the validity chosen by keyboard; the code the page shows is one
// the store accepts (a device enrols with it through ClinicalStore, as armtrack-server does, and
// the code's stored expiry is the chosen one); the device then appears in the page's list;
// revoking it asks first (Cancel changes nothing) and then the store refuses its token. The
// device's own label, markup included, is shown as typed, never rendered. A home
// account gets a message instead of the controls' results; a patient without a home account is
// told how to get one. Screenshots at 1024x600 in English and German.
#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSignalSpy>
#include <QSqlQuery>
#include <QTableView>

#include "app/gui/AppController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/patients/DeviceTableModel.h"
#include "app/gui/patients/HomeDevicesBox.h"
#include "app/gui/patients/PatientListScreen.h"
#include "app/gui/patients/PatientScreen.h"
#include "app/gui/services/AppSettings.h"
#include "app/gui/services/DemoData.h"
#include "app/gui/services/RecordsService.h"
#include "app/i18n/Language.h"
#include "core/storage/Database.h"
#include "tests/app/gui/support/GuiTestSupport.h"

using namespace armtrack;
using namespace armtrack::gui;
using armtrack::gui::test::findControl;

namespace {
/// What a device calls itself, with markup a label must not render.
const QString kLabel = QStringLiteral("kitchen <b>tablet</b> & co");
}  // namespace

class TestHomeDevices : public QObject {
  Q_OBJECT

  QTemporaryDir m_dir;
  std::unique_ptr<AppController> m_app;
  QString m_patient;  ///< the demo home account's patient

  storage::DatabaseUrl url() const {
    storage::DatabaseUrl u;
    u.path = m_dir.filePath(QStringLiteral("demo.db"));
    return u;
  }
  PatientScreen* openPatient(const QString& code) {
    m_app->showPatient(code);
    auto* page = qobject_cast<PatientScreen*>(m_app->window()->currentScreen());
    if (!page || !QTest::qWaitFor([&] { return page->overview().patient.code == code; }))
      return nullptr;
    return page;
  }
  /// The open message box (the revocation's question), or nullptr.
  static QMessageBox* question() {
    for (QWidget* w : QApplication::topLevelWidgets())
      if (auto* b = qobject_cast<QMessageBox*>(w); b && b->isVisible()) return b;
    return nullptr;
  }

 private slots:
  void initTestCase() {
    i18n::setLanguage(QStringLiteral("en"));
    m_app = gui::test::demoApp(m_dir);
    QVERIFY(m_app);
    storage::Database db(url(), {});
    storage::ClinicalStore home(db);
    home.signIn(QString::fromLatin1(DemoAccounts::kHome), DemoAccounts::kPassword);
    m_patient = home.listPatients().at(0).code;
  }

  void aCodeMadeHereEnrolsADeviceThatCanBeRevoked() {
    m_app->window()->resize(1024, 600);
    auto* page = openPatient(m_patient);
    QVERIFY(page);
    HomeDevicesBox* box = page->homeDevices();
    QVERIFY2(box, "the therapist sees the home devices");
    QTRY_COMPARE(box->account(), QString::fromLatin1(DemoAccounts::kHome));
    QCOMPARE(box->devices()->rowCount(), 0);
    QCOMPARE(box->validity(), qint64{7 * 24 * 3600});  // the default

    // One day, chosen by keyboard; the code made by keyboard too.
    auto* validity = findControl<QComboBox>(page, QStringLiteral("Code valid for"));
    QVERIFY(validity);
    validity->setFocus();
    QTest::keyClick(validity, Qt::Key_Up);
    QCOMPARE(box->validity(), qint64{24 * 3600});
    auto* make = findControl<QPushButton>(page, QStringLiteral("Make enrolment code"));
    QVERIFY(make);
    make->setFocus();
    QTest::keyClick(make, Qt::Key_Space);
    QTRY_VERIFY(!box->shownCode().isEmpty());
    const QString code = box->shownCode();
    QVERIFY2(
        QRegularExpression(QStringLiteral("^[0-9A-HJKMNP-TV-Z]{4}(-[0-9A-HJKMNP-TV-Z]{4}){2}$"))
            .match(code)
            .hasMatch(),
        qPrintable(code));
    auto* shown = findControl<QLabel>(page, QStringLiteral("Enrolment code"));
    QVERIFY(shown && shown->isVisible());
    QCOMPARE(shown->text(), code);
    QVERIFY(QTest::qWaitFor([&] { return shown->visibleRegion().boundingRect().width() > 0; }));
    QVERIFY2(shown->sizeHint().width() <= shown->width(), "the code is not cut");
    auto* copy = findControl<QPushButton>(page, QStringLiteral("Copy code"));
    QVERIFY(copy);
    copy->click();
    QCOMPARE(QApplication::clipboard()->text(), code);
    gui::test::saveScreenshot(page, QStringLiteral("patient_home_devices_code"));

    // Independent truth: the store holds one code for the account, valid for a day, and a
    // device enrols with it (as armtrack-server's POST /api/v1/enrol does), typed loosely.
    QString token;
    {
      storage::Database db(url(), {});
      QSqlQuery q =
          db.exec(QStringLiteral(
                      "SELECT c.expires_at FROM enrolment_codes c JOIN users u ON u.id = c.user_id "
                      "WHERE u.name = ? AND c.used_at IS NULL"),
                  {QString::fromLatin1(DemoAccounts::kHome)});
      QVERIFY(q.next());
      const qint64 left = QDateTime::currentDateTimeUtc().secsTo(
          QDateTime::fromString(q.value(0).toString(), Qt::ISODateWithMs));
      QVERIFY2(left > 24 * 3600 - 120 && left <= 24 * 3600, qPrintable(QString::number(left)));
      QVERIFY(!q.next());
      storage::ClinicalStore device(db);
      const storage::DeviceEnrolment e = device.enrolDevice(code.toLower().remove(u'-'), kLabel);
      QVERIFY(e.deviceId > 0);
      QCOMPARE(e.patientCode, m_patient);
      token = e.token;
      storage::ClinicalStore again(db);  // used once only
      QVERIFY_THROWS_EXCEPTION(storage::StorageError,
                               again.enrolDevice(code, QStringLiteral("second")));
    }

    // The device in the page's list once read again.
    findControl<QPushButton>(page, QStringLiteral("Refresh"))->click();
    QTRY_COMPARE(box->devices()->rowCount(), 1);
    DeviceTableModel* devices = box->devices();
    QCOMPARE(devices->data(devices->index(0, DeviceTableModel::Label)).toString(), kLabel);
    QCOMPARE(devices->data(devices->index(0, DeviceTableModel::Status)).toString(),
             QStringLiteral("enrolled"));
    QVERIFY(devices->data(devices->index(0, DeviceTableModel::LastSync)).toString() !=
            QStringLiteral("never"));

    // Revoke: the question first; Cancel (the default, Enter) keeps the device.
    auto* table = findControl<QTableView>(page, QStringLiteral("Enrolled devices"));
    QVERIFY(table);
    table->setFocus();
    table->selectRow(0);
    auto* revoke = findControl<QPushButton>(page, QStringLiteral("Revoke device..."));
    QVERIFY(revoke && revoke->isEnabled());
    revoke->click();
    QTRY_VERIFY(question());
    QVERIFY(question()->text().contains(kLabel));
    gui::test::saveScreenshot(question(), QStringLiteral("patient_home_devices_revoke"));
    QCOMPARE(question()->textFormat(), Qt::PlainText);
    QTest::keyClick(question(), Qt::Key_Return);
    QTRY_VERIFY(!question());
    QTest::qWait(200);
    {
      storage::Database db(url(), {});
      storage::ClinicalStore device(db);
      device.signInWithDeviceToken(token);  // still enrolled
    }
    revoke->click();
    QTRY_VERIFY(question());
    QAbstractButton* yes = nullptr;
    for (QAbstractButton* b : question()->buttons())
      if (question()->buttonRole(b) == QMessageBox::DestructiveRole) yes = b;
    QVERIFY(yes);
    yes->click();
    QTRY_VERIFY(devices->data(devices->index(0, DeviceTableModel::Status))
                    .toString()
                    .startsWith(QStringLiteral("revoked")));
    QVERIFY(!revoke->isEnabled());  // a revoked device cannot be revoked again
    MessageLine* said = nullptr;
    for (auto* m : box->findChildren<MessageLine*>())
      if (m->isVisible()) said = m;
    QVERIFY(said && said->text().contains(kLabel));
    for (auto* l : said->findChildren<QLabel*>()) QCOMPARE(l->textFormat(), Qt::PlainText);
    {
      storage::Database db(url(), {});
      storage::ClinicalStore device(db);
      try {
        device.signInWithDeviceToken(token);
        QFAIL("the revoked device's token was accepted");
      } catch (const storage::StorageError& e) {
        QCOMPARE(e.kind(), storage::StorageError::Kind::Authentication);
      }
    }
  }

  void germanAt1024x600() {
    m_app->window()->resize(1024, 600);
    auto* page = openPatient(m_patient);
    QVERIFY(page && page->homeDevices());
    HomeDevicesBox* box = page->homeDevices();
    QTRY_COMPARE(box->devices()->rowCount(), 1);
    box->makeCode();
    QTRY_VERIFY(!box->shownCode().isEmpty());
    QCOMPARE(i18n::setLanguage(QStringLiteral("de")), QStringLiteral("de"));
    QCoreApplication::processEvents();
    QCOMPARE(box->title(), QStringLiteral("Heimger\u00e4te"));
    QCOMPARE(box->devices()->headerData(DeviceTableModel::LastSync, Qt::Horizontal).toString(),
             QStringLiteral("Letzte Synchronisierung"));
    // The side pane scrolled to the box, as Tab would.
    for (auto* area : page->findChildren<QScrollArea*>())
      if (area->isAncestorOf(box)) area->ensureWidgetVisible(box);
    gui::test::saveScreenshot(page, QStringLiteral("patient_home_devices_de"));
    i18n::setLanguage(QStringLiteral("en"));
    QCoreApplication::processEvents();
    QCOMPARE(box->title(), QStringLiteral("Home devices"));
  }

  void everyControlIsReachedByTab() {
    auto* page = openPatient(m_patient);
    QVERIFY(page && page->homeDevices());
    HomeDevicesBox* box = page->homeDevices();
    QTRY_COMPARE(box->devices()->rowCount(), 1);
    box->makeCode();
    QTRY_VERIFY(!box->shownCode().isEmpty());
    QVERIFY(gui::test::activate(m_app->window()));
    auto* account = findControl<QComboBox>(page, QStringLiteral("Home account"));
    QVERIFY(account && account->isEnabled());
    account->setFocus();
    QTRY_COMPARE(QApplication::focusWidget(), account);
    QList<QWidget*> reached;
    for (int i = 0; i < 12 && QApplication::focusWidget(); ++i) {
      reached << QApplication::focusWidget();
      QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
    }
    for (const QString& name :
         {QStringLiteral("Code valid for"), QStringLiteral("Enrolled devices")})
      QVERIFY2(reached.contains(findControl<QWidget>(page, name)), qPrintable(name));
    for (const QString& name : {QStringLiteral("Make enrolment code"), QStringLiteral("Copy code"),
                                QStringLiteral("Refresh")})
      QVERIFY2(reached.contains(findControl<QPushButton>(page, name)), qPrintable(name));
  }

  void aPatientWithoutAHomeAccountIsToldHowToGetOne() {
    auto* page = openPatient(QStringLiteral("P002"));
    QVERIFY(page);
    HomeDevicesBox* box = page->homeDevices();
    QVERIFY(box);
    const auto told = [box] {
      for (auto* l : box->findChildren<QLabel*>())
        if (l->isVisible() && l->text().contains(QStringLiteral("no home account"))) return true;
      return false;
    };
    QTRY_VERIFY(told());
    QCOMPARE(box->account(), QString());
    auto* make = findControl<QPushButton>(page, QStringLiteral("Make enrolment code"));
    QVERIFY(make && !make->isEnabled());
  }

  void aHomeAccountIsRefusedWithAMessage() {
    RecordsService records;
    bool in = false;
    records.signIn(
        url(), QString::fromLatin1(DemoAccounts::kHome),
        QString::fromLatin1(DemoAccounts::kPassword), this,
        [&](const storage::User&) { in = true; }, [](const RecordsFailure&) {});
    QTRY_VERIFY(in);
    AppSettings settings;
    HomeDevicesBox box(records, settings, m_patient);
    QSignalSpy failed(&box, &HomeDevicesBox::failed);
    box.show();
    box.reload();
    QTRY_COMPARE(failed.count(), 1);
    QVERIFY2(gui::test::visibleMessage(&box).contains(QStringLiteral("Only therapists and "
                                                                     "administrators")),
             qPrintable(gui::test::visibleMessage(&box)));
    box.makeCode();  // nothing to make it for: no crash, no code
    QTest::qWait(200);
    QVERIFY(box.shownCode().isEmpty());
  }

  void cleanupTestCase() { m_app.reset(); }
};

ARMTRACK_APP_TEST_MAIN(TestHomeDevices)
#include "test_home_devices.moc"
