// The home window syncing with armtrack-server's code on loopback (issue 28, acceptance 2 on the
// home side): a home account with no programme yet connects to the clinic from the start
// screen's "Clinic" with the address and a code typed on the keyboard; the programme arrives and
// shows; a session stored at home is sent ("Everything is sent", "Sent today") and found at the
// clinic; a programme changed by the therapist shows at the next sync; with the server gone, a
// new session waits ("Not connected: sessions are kept and sent later", "1 session waiting").
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTest>
#include <tuple>

#include "app/gui/home/HomeConnectScreen.h"
#include "app/gui/home/HomeController.h"
#include "app/gui/home/HomeStartScreen.h"
#include "app/gui/home/HomeWindow.h"
#include "app/gui/services/RecordsService.h"
#include "app/i18n/Language.h"
#include "app/plugins/PluginRegistry.h"
#include "app/server/HttpsServer.h"
#include "app/server/SyncApi.h"
#include "app/server/Tls.h"
#include "app/sync/HomeSyncService.h"
#include "tests/app/server/TestCertificate.h"
#include "tests/core/storage/StorageTestSupport.h"
#include "tests/support/GuiTestMain.h"

using namespace armtrack;
using namespace armtrack::gui;
using namespace armtrack::gui::home;
using namespace armtrack::storage;
using namespace armtrack::storage::test;

namespace {
constexpr const char* kHomePassword = "home password 123";
}

class TestHomeSyncWindow : public QObject {
  Q_OBJECT

  std::unique_ptr<Fixture> m_clinic, m_home;
  QTemporaryDir m_dir;
  QString m_cert, m_key;
  std::unique_ptr<server::SyncApi> m_api;
  std::unique_ptr<server::HttpsServer> m_server;
  quint16 m_port = 0;
  std::unique_ptr<RecordsService> m_records;
  app::PluginRegistry m_plugins;
  std::unique_ptr<HomeController> m_controller;

  bool startServer() {
    m_api = std::make_unique<server::SyncApi>(*m_clinic->db, server::SyncApi::Options{});
    m_server = std::make_unique<server::HttpsServer>(
        server::serverTls(m_cert, m_key), server::HttpsServer::Limits{},
        [this](const server::HttpRequest& r) { return m_api->handle(r); });
    return m_server->listen(QHostAddress::LocalHost, m_port);
  }
  HomeWindow* window() const { return m_controller->window(); }
  QString syncLine() const { return window()->syncText(); }
  void recordAtHome(const char* name) {
    const std::filesystem::path csv = m_home->file(name);
    simulateTo(csv, 5.0, 100.0);
    ClinicalStore patient(*m_home->db);
    patient.signIn("home1", kHomePassword);
    const qint64 id = patient.importRecording(csv, "P1", "reach");
    patient.saveHomeOutcome(id, 1, "fine", "{}");
    m_controller->syncService()->sessionStored();
  }
  QStringList startLines() const {
    auto* start = qobject_cast<HomeStartScreen*>(window()->currentScreen());
    return start ? start->exerciseLines() : QStringList{};
  }

 private slots:
  void initTestCase() {
    i18n::setLanguage("en");
    std::tie(m_cert, m_key) = armtrack::test::makeCertificate(m_dir);
    QVERIFY(!m_cert.isEmpty());
    m_clinic = std::make_unique<Fixture>();
    m_home = std::make_unique<Fixture>();
    for (Fixture* f : {m_clinic.get(), m_home.get()}) {
      f->store->addPatient(makePatient("P1"));
      f->store->addUser("home1", Role::Home, kHomePassword, "P1");
      f->store->addProtocol(makeProtocol("reach", "elbow_flexion", 10, 110, 8));
    }
    ProgrammeItem item;
    item.protocolName = "reach";
    item.sets = 3;
    m_clinic->store->setProgrammeExercise("P1", item);
    QTcpServer probe;
    QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
    m_port = probe.serverPort();
    probe.close();
    QVERIFY(startServer());

    m_records = std::make_unique<RecordsService>();
    bool signedIn = false;
    m_records->signIn(
        DatabaseUrl::parse(m_home->path), "home1", kHomePassword, this,
        [&](const User&) { signedIn = true; },
        [](const RecordsFailure& f) { qWarning() << f.message; });
    QTRY_VERIFY_WITH_TIMEOUT(signedIn, 20000);
    HomeSetup setup;
    setup.devices = {QStringLiteral("virtual-arm:sensors=upper+forearm")};
    setup.workFolder = m_dir.filePath("work");
    setup.syncFolder = m_dir.filePath("home-sync");
    m_controller = std::make_unique<HomeController>(*m_records, m_plugins, setup, QString());
    QSignalSpy loaded(m_controller.get(), &HomeController::planLoaded);
    m_controller->start();
    QVERIFY(loaded.wait(20000));
    QVERIFY(QTest::qWaitForWindowExposed(window()));
  }
  void cleanupTestCase() {
    if (m_controller) window()->allowClose();
    m_controller.reset();
    m_records.reset();
    m_server.reset();
    m_api.reset();
  }

  void connectsFromTheStartScreenWithTheKeyboardAndGetsTheProgramme() {
    QVERIFY(startLines().isEmpty());  // no programme on this computer yet
    QTRY_VERIFY2_WITH_TIMEOUT(syncLine().contains("Not connected to a clinic"),
                              qPrintable(syncLine()), 20000);
    auto* start = qobject_cast<HomeStartScreen*>(window()->currentScreen());
    QVERIFY(start && start->clinicButton()->isVisible());
    start->clinicButton()->setFocus();
    QTest::keyClick(start->clinicButton(), Qt::Key_Space);
    auto* connect = qobject_cast<HomeConnectScreen*>(window()->currentScreen());
    QVERIFY(connect);
    QCOMPARE(QApplication::focusWidget(), connect->serverField());
    const QString code = m_clinic->store->createEnrolmentCode("home1", 600).code;
    QTest::keyClicks(connect->serverField(), "https://localhost:" + QString::number(m_port));
    QTest::keyClick(connect->serverField(), Qt::Key_Return);
    QTest::keyClicks(connect->codeField(), code);
    QTest::keyClick(connect->codeField(), Qt::Key_Return);
    QTRY_VERIFY2_WITH_TIMEOUT(connect->resultText().contains("Connected to the clinic"),
                              qPrintable(connect->resultText()), 30000);
    QTRY_VERIFY2_WITH_TIMEOUT(syncLine().contains("Everything is sent"), qPrintable(syncLine()),
                              30000);
    // Back: the programme fetched from the clinic is today's. Under load the first plan loaded
    // after Back was once empty (seen in a run of 62 tests at once; why the programme was not
    // there yet is not known). A changed programme reloads the start screen's plan, so the test
    // waits for the line rather than for the first load.
    QSignalSpy loaded(m_controller.get(), &HomeController::planLoaded);
    QTest::keyClick(connect->choices().last(), Qt::Key_Space);
    QVERIFY(loaded.wait(20000));
    QTRY_COMPARE_WITH_TIMEOUT(startLines().size(), 1, 30000);
    QVERIFY2(startLines()[0].contains("reach: 3 sets of 8"), qPrintable(startLines()[0]));
  }

  void aSessionStoredAtHomeIsSentAndTheChangedProgrammeShows() {
    recordAtHome("one.csv");
    QTRY_VERIFY2_WITH_TIMEOUT(syncLine().contains("Sent today"), qPrintable(syncLine()), 30000);
    QVERIFY2(syncLine().contains("Everything is sent"), qPrintable(syncLine()));
    QCOMPARE(m_clinic->store->listSessions("P1").size(), 1u);
    QCOMPARE(m_clinic->store->listSessions("P1")[0].setting, QString(kSettingHome));
    // The therapist changes the programme; the next sync brings it to the start screen.
    ProgrammeItem item;
    item.protocolName = "reach";
    item.sets = 5;
    item.position = 1;
    m_clinic->store->setProgrammeExercise("P1", item);
    m_controller->syncService()->syncNow();
    QTRY_VERIFY_WITH_TIMEOUT(!startLines().isEmpty() && startLines()[0].contains("5 sets"), 30000);
  }

  void withTheServerGoneANewSessionWaits() {
    m_server.reset();
    recordAtHome("two.csv");
    QTRY_VERIFY2_WITH_TIMEOUT(
        syncLine().contains("Not connected: sessions are kept and sent later") &&
            syncLine().contains("1 session waiting to be sent"),
        qPrintable(syncLine()), 30000);
    QCOMPARE(m_clinic->store->listSessions("P1").size(), 1u);
    QVERIFY(startServer());
    m_controller->syncService()->syncNow();
    QTRY_VERIFY2_WITH_TIMEOUT(syncLine().contains("Everything is sent"), qPrintable(syncLine()),
                              30000);
    QCOMPARE(m_clinic->store->listSessions("P1").size(), 2u);
  }
};

ARMTRACK_GUI_TEST_MAIN(TestHomeSyncWindow)
#include "test_home_sync_window.moc"
