// Issue 28, acceptance 2, through both windows under Xvfb: the therapist's application on the
// clinic's records (a SQLite file) and a home install's application on its own records (another
// SQLite file), with armtrack-server's code (SyncApi over HttpsServer) on loopback with a
// certificate the test makes, started and stopped in this process.
// - The therapist makes an enrolment code in the patient page's Home devices box (keyboard).
// - The home install connects to the clinic with it from the home window's start screen
//   ("Clinic", address and code typed); the programme arrives and shows.
// - The server goes down; the home window records a session with the virtual arm (sensor check,
//   exercise, summary with pain score and comment); it waits ("1 session waiting to be sent").
// - The server comes up; the next sync sends it. At the clinic it is stored once, a home session
//   with the patient's outcome, analysed on arrival (the analysis state and the metrics rows
//   read from the clinic's file), with the SHA-256 of the CSV the home records export; the
//   therapist opens the patient again from the list and the page lists it as a home session,
//   analysed, in the progress chart.
// - An administrator changes the home programme on the administrator's Programmes page (the
//   only place it is edited in the GUI); the home window shows it after its next sync.
// The home install's timer (every 5 minutes) is stood in for by HomeSyncService::syncNow().
#include <QComboBox>
#include <QCryptographicHash>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QSqlQuery>
#include <QTableView>
#include <QTableWidget>
#include <QTcpServer>
#include <tuple>

#include "app/gui/admin/AdminDialogs.h"
#include "app/gui/admin/AdminScreen.h"
#include "app/gui/common/SessionTableModel.h"
#include "app/gui/home/ExerciseScreen.h"
#include "app/gui/home/HomeCalibrationScreen.h"
#include "app/gui/home/HomeConnectScreen.h"
#include "app/gui/home/HomeController.h"
#include "app/gui/home/HomeStartScreen.h"
#include "app/gui/home/HomeSummaryScreen.h"
#include "app/gui/home/HomeWindow.h"
#include "app/gui/home/SensorCheckScreen.h"
#include "app/gui/patients/DeviceTableModel.h"
#include "app/gui/patients/HomeDevicesBox.h"
#include "app/gui/patients/PatientListScreen.h"
#include "app/gui/patients/PatientScreen.h"
#include "app/i18n/Language.h"
#include "app/server/HttpsServer.h"
#include "app/server/SyncApi.h"
#include "app/server/Tls.h"
#include "app/sync/HomeSyncService.h"
#include "app/sync/SyncState.h"
#include "core/storage/Database.h"
#include "tests/app/gui/support/GuiTestSupport.h"
#include "tests/app/server/TestCertificate.h"

using namespace armtrack;
using namespace armtrack::gui;
using namespace armtrack::gui::home;
using armtrack::gui::test::findControl;
using armtrack::gui::test::typeInto;

namespace {
constexpr int kSlowMs = 60000;
const QString kPatient = QString::fromLatin1(DemoAccounts::kLivePatient);
const QString kHomeAccount = QString::fromLatin1(DemoAccounts::kHome);
const std::string kPassword = DemoAccounts::kPassword;
const QString kHomeAdmin = QStringLiteral("home-admin");
const QString kExercise = QStringLiteral("Elbow flexion");
const QString kComment = QStringLiteral("A little stiff");

using armtrack::test::fileSha256;
}  // namespace

class TestHomeToClinic : public QObject {
  Q_OBJECT

  QTemporaryDir m_dir;
  QTemporaryDir m_homeDir;
  QString m_cert, m_key;
  quint16 m_port = 0;
  std::unique_ptr<AppController> m_clinic;  ///< the therapist's application
  std::unique_ptr<AppController> m_home;    ///< the home install's application
  std::unique_ptr<storage::Database> m_serverDb;
  std::unique_ptr<server::SyncApi> m_api;
  std::unique_ptr<server::HttpsServer> m_server;
  QString m_code;
  qint64 m_homeSession = 0;  ///< in the home records

  storage::DatabaseUrl clinicUrl() const {
    storage::DatabaseUrl u;
    u.path = m_dir.filePath(QStringLiteral("demo.db"));
    return u;
  }
  storage::DatabaseUrl homeUrl() const {
    storage::DatabaseUrl u;
    u.path = m_homeDir.filePath(QStringLiteral("home.db"));
    return u;
  }
  /// Reads a records file apart from both applications, signed in as its administrator.
  template <class Fn>
  static auto read(const storage::DatabaseUrl& url, const QString& admin, Fn fn) {
    storage::Database db(url, {});
    storage::ClinicalStore store(db);
    store.signIn(admin, kPassword);
    return fn(db, store);
  }
  bool startServer() {
    m_serverDb = std::make_unique<storage::Database>(clinicUrl(), storage::Database::Options{});
    m_api = std::make_unique<server::SyncApi>(*m_serverDb, server::SyncApi::Options{});
    m_server = std::make_unique<server::HttpsServer>(
        server::serverTls(m_cert, m_key), server::HttpsServer::Limits{},
        [this](const server::HttpRequest& r) { return m_api->handle(r); });
    return m_server->listen(QHostAddress::LocalHost, m_port);
  }
  void stopServer() {
    m_server.reset();
    m_api.reset();
    m_serverDb.reset();
  }

  HomeController* homeController() const { return m_home ? m_home->home() : nullptr; }
  HomeWindow* homeWindow() const { return homeController() ? homeController()->window() : nullptr; }
  template <class T>
  T* homeScreen() const {
    return homeWindow() ? qobject_cast<T*>(homeWindow()->currentScreen()) : nullptr;
  }
  QString syncLine() const { return homeWindow() ? homeWindow()->syncText() : QString(); }
  QStringList startLines() const {
    auto* start = homeScreen<HomeStartScreen>();
    return start ? start->exerciseLines() : QStringList{};
  }
  /// Space to the home window's focused choice (the keyboard, the default way).
  void press() {
    QTest::keyClick(QApplication::focusWidget() ? QApplication::focusWidget() : homeWindow(),
                    Qt::Key_Space);
  }
  QWidget* clinicScreen() const { return m_clinic->window()->currentScreen(); }
  /// The window of w as the screen shows it: raised first, the two applications' windows
  /// overlap (Xvfb has no window manager to stack them).
  void shot(QWidget* w, const char* name) {
    w->window()->raise();
    QTest::qWait(100);
    armtrack::gui::test::saveScreenshot(w, QString::fromLatin1(name));
  }

  static void signIn(AppController& app, const QString& name) {
    SignInScreen* s = nullptr;
    QTRY_VERIFY_WITH_TIMEOUT((s = qobject_cast<SignInScreen*>(app.window()->currentScreen())),
                             20000);
    typeInto(findControl<QLineEdit>(s, QStringLiteral("Account name")), name);
    auto* password = findControl<QLineEdit>(s, QStringLiteral("Password"));
    typeInto(password, QString::fromStdString(kPassword));
    QTest::keyClick(password, Qt::Key_Return);
    QTRY_VERIFY_WITH_TIMEOUT(app.records().signedIn(), 20000);
  }

  /// The home sessions of the patient at the clinic.
  std::vector<storage::SessionInfo> clinicHomeSessions() {
    return read(clinicUrl(), QString::fromLatin1(DemoAccounts::kAdmin),
                [](storage::Database&, storage::ClinicalStore& s) {
                  std::vector<storage::SessionInfo> out;
                  for (const storage::SessionInfo& i : s.listSessions(kPatient))
                    if (i.setting == QLatin1String(storage::kSettingHome)) out.push_back(i);
                  return out;
                });
  }

 private slots:
  void initTestCase() {
    i18n::setLanguage(QStringLiteral("en"));
    // The certificate the clinic's server shows (the home install pins it at enrolment).
    std::tie(m_cert, m_key) = armtrack::test::makeCertificate(m_dir);
    QVERIFY(!m_cert.isEmpty());
    QTcpServer probe;
    QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
    m_port = probe.serverPort();
    probe.close();

    // The clinic: the demo records, the therapist signed in.
    AppOptions o;
    o.pluginFolders = {QStringLiteral(ARMTRACK_PLUGIN_DIR)};
    m_clinic = armtrack::gui::test::demoApp(m_dir, o);
    QVERIFY(m_clinic);
    // Ada's home programme, short enough for a test: one set of three elbow bends (the IMUs
    // measure the elbow well). The administrator changes it later through the GUI.
    read(clinicUrl(), QString::fromLatin1(DemoAccounts::kAdmin),
         [](storage::Database&, storage::ClinicalStore& s) {
           for (const storage::ProgrammeItem& old : s.programme(kPatient))
             s.unassignProtocol(kPatient, old.protocolName);
           storage::ProgrammeItem elbow;
           elbow.protocolName = kExercise;
           elbow.sets = 1;
           elbow.repetitions = 3;
           elbow.targetMinDeg = 30;
           elbow.targetMaxDeg = 110;
           elbow.restS = 3;
           s.setProgrammeExercise(kPatient, elbow);
           return 0;
         });
    QCOMPARE(clinicHomeSessions().size(), std::size_t{0});

    // The home install: records of its own with the patient and the home account, no
    // protocols and no programme; the home window's devices are the virtual arm.
    {
      storage::Database db(homeUrl(), {.create = true, .migrate = false});
      storage::ClinicalStore store(db);
      store.initialise(kHomeAdmin, kPassword);
      store.signIn(kHomeAdmin, kPassword);
      storage::Patient ada;
      ada.code = kPatient;
      ada.name = QStringLiteral("Ada Example");
      ada.affectedSide = QStringLiteral("right");
      store.addPatient(ada);
      store.addUser(kHomeAccount, storage::Role::Home, kPassword, kPatient);
    }
    QSettings().setValue(QStringLiteral("devices/default"),
                         QStringList{QStringLiteral("virtual-arm:sensors=upper+forearm+webcam")});
    AppOptions h;
    h.database = homeUrl().path;
    h.pluginFolders = {QStringLiteral(ARMTRACK_PLUGIN_DIR)};
    m_home = std::make_unique<AppController>(h);
    m_home->start();
    signIn(*m_home, kHomeAccount);
    QTRY_VERIFY_WITH_TIMEOUT(homeWindow() && homeWindow()->isVisible(), 20000);
    QVERIFY2(homeController()->syncService(), "the home install syncs");
    QVERIFY(armtrack::gui::test::activate(homeWindow()));
    QTRY_VERIFY_WITH_TIMEOUT(homeScreen<HomeStartScreen>(), 20000);
  }

  void theTherapistMakesAnEnrolmentCode() {
    QVERIFY(armtrack::gui::test::activate(m_clinic->window()));
    m_clinic->window()->resize(1024, 700);
    m_clinic->showPatient(kPatient);
    PatientScreen* page = nullptr;
    QTRY_VERIFY((page = qobject_cast<PatientScreen*>(clinicScreen())) &&
                page->overview().patient.code == kPatient);
    HomeDevicesBox* box = page->homeDevices();
    QVERIFY(box);
    QTRY_COMPARE(box->account(), kHomeAccount);
    auto* make = findControl<QPushButton>(page, QStringLiteral("Make enrolment code"));
    QVERIFY(make);
    make->setFocus();
    QTest::keyClick(make, Qt::Key_Space);
    QTRY_VERIFY(!box->shownCode().isEmpty());
    m_code = box->shownCode();
    shot(page, "home_to_clinic_code");
  }

  void theHomeInstallConnectsWithTheCodeByKeyboard() {
    QVERIFY(startServer());
    QVERIFY(startLines().isEmpty());  // no programme on this computer yet
    QTRY_VERIFY2_WITH_TIMEOUT(syncLine().contains(QStringLiteral("Not connected to a clinic")),
                              qPrintable(syncLine()), 20000);
    QVERIFY(armtrack::gui::test::activate(homeWindow()));
    auto* start = homeScreen<HomeStartScreen>();
    start->clinicButton()->setFocus();
    QTest::keyClick(start->clinicButton(), Qt::Key_Space);
    auto* connect = homeScreen<HomeConnectScreen>();
    QVERIFY(connect);
    QCOMPARE(QApplication::focusWidget(), connect->serverField());
    QTest::keyClicks(connect->serverField(), "https://localhost:" + QString::number(m_port));
    QTest::keyClick(connect->serverField(), Qt::Key_Return);
    QTest::keyClicks(connect->codeField(), m_code);
    QTest::keyClick(connect->codeField(), Qt::Key_Return);
    QTRY_VERIFY2_WITH_TIMEOUT(connect->resultText().contains(QStringLiteral("Connected")),
                              qPrintable(connect->resultText()), 30000);
    QTRY_VERIFY2_WITH_TIMEOUT(syncLine().contains(QStringLiteral("Everything is sent")),
                              qPrintable(syncLine()), 30000);
    shot(homeWindow(), "home_to_clinic_connected");
    QSignalSpy loaded(homeController(), &HomeController::planLoaded);
    QTest::keyClick(connect->choices().last(), Qt::Key_Space);  // Back
    QVERIFY(loaded.wait(20000));
    QCOMPARE(startLines().size(), 1);
    QVERIFY2(startLines()[0].contains(kExercise + QStringLiteral(": 1 set of 3 repetitions")),
             qPrintable(startLines()[0]));

    // The clinic's records: the code used, one device of the home account; the therapist's
    // page lists it once read again.
    const int devices =
        read(clinicUrl(), QString::fromLatin1(DemoAccounts::kAdmin),
             [](storage::Database& db, storage::ClinicalStore&) {
               QSqlQuery q = db.exec(
                   QStringLiteral("SELECT count(*) FROM devices d JOIN users u ON u.id = "
                                  "d.user_id WHERE u.name = 'demo-home' AND d.revoked_at IS NULL"));
               return q.next() ? q.value(0).toInt() : -1;
             });
    QCOMPARE(devices, 1);
    auto* page = qobject_cast<PatientScreen*>(clinicScreen());
    QVERIFY(page);
    findControl<QPushButton>(page, QStringLiteral("Refresh"))->click();
    QTRY_COMPARE(page->homeDevices()->devices()->rowCount(), 1);
  }

  void aSessionRecordedWithTheServerDownWaits() {
    stopServer();
    QVERIFY(armtrack::gui::test::activate(homeWindow()));
    QVERIFY(homeScreen<HomeStartScreen>());
    press();  // Start
    QTRY_VERIFY(homeScreen<SensorCheckScreen>());
    press();  // Start the check
    auto* check = homeScreen<SensorCheckScreen>();
    QTRY_COMPARE_WITH_TIMEOUT(check->state(), SensorCheckScreen::State::Passed, kSlowMs);
    press();  // Go on
    QTRY_VERIFY(homeScreen<HomeCalibrationScreen>());
    auto* calibration = homeScreen<HomeCalibrationScreen>();
    findControl<QPushButton>(calibration, QStringLiteral("Skip the calibration"))->click();
    QMessageBox* skip = nullptr;
    QTRY_VERIFY((skip = calibration->skipQuestion()) && skip->isVisible());
    for (QAbstractButton* b : skip->buttons())
      if (b->text().remove(u'&') == QStringLiteral("Skip it")) b->click();
    QTRY_VERIFY(homeScreen<ExerciseScreen>());
    auto* exercise = homeScreen<ExerciseScreen>();
    QSignalSpy finished(exercise, &ExerciseScreen::finished);
    press();  // Start set 1
    QTRY_COMPARE(exercise->phase(), ExerciseScreen::Phase::Set);
    QVERIFY(finished.wait(kSlowMs));
    const auto result = finished.first().first().value<HomeExerciseResult>();
    QCOMPARE(result.repetitions, 3);
    QVERIFY(result.sessionId != 0);
    m_homeSession = result.sessionId;
    QTRY_VERIFY(homeScreen<HomeSummaryScreen>());
    auto* summary = homeScreen<HomeSummaryScreen>();
    for (int i = 0; i < 2; ++i)
      findControl<QPushButton>(summary, QStringLiteral("More pain"))->click();
    QCOMPARE(summary->painScore(), std::optional<int>(2));  // "no answer", 1, 2
    auto* comment = findControl<QPlainTextEdit>(summary, QStringLiteral("Your comment"));
    comment->setFocus();
    QTest::keyClicks(comment, kComment);
    findControl<QPushButton>(summary, QStringLiteral("Save and finish"))->setFocus();
    press();
    QTRY_VERIFY_WITH_TIMEOUT(summary->status().startsWith(QStringLiteral("Saved")), 20000);
    QTRY_VERIFY2_WITH_TIMEOUT(
        syncLine().contains(QStringLiteral("Not connected: sessions are kept and sent later")) &&
            syncLine().contains(QStringLiteral("1 session waiting to be sent")),
        qPrintable(syncLine()), 30000);
    shot(homeWindow(), "home_to_clinic_waiting");
    QCOMPARE(clinicHomeSessions().size(), std::size_t{0});
  }

  void theServerComesUpAndTheSessionArrivesAnalysed() {
    QVERIFY(startServer());
    homeController()->syncService()->syncNow();  // the home install's timer
    QTRY_VERIFY2_WITH_TIMEOUT(syncLine().contains(QStringLiteral("Everything is sent")) &&
                                  syncLine().contains(QStringLiteral("Sent today")),
                              qPrintable(syncLine()), 60000);

    // Independent truth, from the files: one session at home, the same one once at the clinic,
    // a home session with the patient's outcome, analysed on arrival with its metrics stored,
    // and the same CSV (SHA-256) as the home records export.
    const QString homeCsv = m_homeDir.filePath(QStringLiteral("home.csv"));
    const auto local =
        read(homeUrl(), kHomeAdmin, [&](storage::Database&, storage::ClinicalStore& s) {
          s.exportRecording(m_homeSession, homeCsv.toStdString());
          return s.listSessions(kPatient);
        });
    QCOMPARE(local.size(), std::size_t{1});
    QCOMPARE(local[0].id, m_homeSession);
    // Analysed by the server (the therapist's application analyses only at a sign-in, and
    // nobody has signed in since the code was made); waited for, should it run after the answer.
    // Polled with one plain query on a connection of the test's own (a sign-in per poll would
    // hash a password each time).
    {
      storage::Database probe(clinicUrl(), {});
      const auto states = [&probe] {
        QSqlQuery q = probe.exec(
            QStringLiteral(
                "SELECT s.analysis FROM sessions s JOIN patients p ON p.id = s.patient_id "
                "WHERE p.code = ? AND s.setting = 'home'"),
            {kPatient});
        QStringList out;
        while (q.next()) out << q.value(0).toString();
        return out;
      };
      QTRY_VERIFY2_WITH_TIMEOUT(states().size() == 1 && states()[0] != QLatin1String("pending"),
                                qPrintable(states().join(u',')), 30000);
    }
    const auto stored = clinicHomeSessions();
    QCOMPARE(stored.size(), std::size_t{1});
    const storage::SessionInfo& arrived = stored[0];
    QCOMPARE(arrived.analysis, QString::fromLatin1(storage::kAnalysisDone));
    QCOMPARE(arrived.status, QString::fromLatin1(storage::kStatusComplete));
    QCOMPARE(arrived.protocolName, kExercise);
    QCOMPARE(arrived.painScore, std::optional<int>(2));
    QCOMPARE(arrived.patientComment, kComment);
    QCOMPARE(arrived.imuSamples, local[0].imuSamples);
    const QString clinicCsv = m_dir.filePath(QStringLiteral("clinic.csv"));
    const auto [metrics, uploads, chunks] =
        read(clinicUrl(), QString::fromLatin1(DemoAccounts::kAdmin),
             [&](storage::Database& db, storage::ClinicalStore& s) {
               s.exportRecording(arrived.id, clinicCsv.toStdString());
               const auto count = [&db](const QString& sql, QVariantList args = {}) {
                 QSqlQuery q = db.exec(sql, args);
                 return q.next() ? q.value(0).toInt() : -1;
               };
               return std::tuple{
                   count(QStringLiteral("SELECT count(*) FROM metrics WHERE session_id = ?"),
                         {arrived.id}),
                   count(QStringLiteral("SELECT count(*) FROM sync_uploads")),
                   count(QStringLiteral("SELECT count(*) FROM sync_upload_chunks"))};
             });
    QCOMPARE(metrics, 1);
    QCOMPARE(uploads, 1);
    QCOMPARE(chunks, 0);  // joined and cleared
    const QString sha = fileSha256(homeCsv);
    QCOMPARE(sha.size(), 64);
    QCOMPARE(fileSha256(clinicCsv), sha);
    // The home install's own account of it: sent, with that checksum.
    const sync::SyncState state(homeController()->syncService()->folder());
    const std::optional<sync::UploadRecord> upload = state.upload(m_homeSession);
    QVERIFY(upload && upload->sent());
    QCOMPARE(upload->sha256, sha);

    // The therapist goes back to the list and opens the patient again, by keyboard.
    QVERIFY(armtrack::gui::test::activate(m_clinic->window()));
    auto* page = qobject_cast<PatientScreen*>(clinicScreen());
    QVERIFY(page);
    findControl<QPushButton>(page, QStringLiteral("Back to patients"))->click();
    PatientListScreen* list = nullptr;
    QTRY_VERIFY((list = qobject_cast<PatientListScreen*>(clinicScreen())));
    auto* patients = findControl<QTableView>(list, QStringLiteral("Patient list"));
    QVERIFY(patients);
    QTRY_VERIFY(patients->model()->rowCount() >= 3);
    const QModelIndexList ada = patients->model()->match(
        patients->model()->index(0, 0), Qt::DisplayRole, kPatient, 1, Qt::MatchExactly);
    QCOMPARE(ada.size(), 1);
    patients->setFocus();
    patients->setCurrentIndex(ada[0]);
    QTest::keyClick(patients, Qt::Key_Return);
    QTRY_VERIFY((page = qobject_cast<PatientScreen*>(clinicScreen())) &&
                page->overview().patient.code == kPatient);
    auto* table = findControl<QTableView>(page, QStringLiteral("Sessions"));
    QVERIFY(table);
    QStringList homeRows;
    for (int row = 0; row < table->model()->rowCount(); ++row) {
      const auto cell = [&](int c) { return table->model()->index(row, c).data().toString(); };
      if (cell(SessionTableModel::Where) == QLatin1String("home"))
        homeRows << cell(SessionTableModel::Status) + u'|' + cell(SessionTableModel::Patient) +
                        u'|' + cell(SessionTableModel::Protocol);
    }
    QCOMPARE(homeRows.size(), 1);
    QVERIFY2(homeRows[0].startsWith(QStringLiteral("complete|")), qPrintable(homeRows[0]));
    QVERIFY2(homeRows[0].contains(QStringLiteral("pain 2/10")), qPrintable(homeRows[0]));
    QVERIFY2(homeRows[0].contains(kComment), qPrintable(homeRows[0]));
    QVERIFY2(homeRows[0].endsWith(kExercise), qPrintable(homeRows[0]));
    // Analysed: in the progress chart's data.
    const auto& progress = page->overview().progress;
    QVERIFY(std::any_of(progress.begin(), progress.end(),
                        [&](const SessionExtremes& e) { return e.id == arrived.id; }));
    for (auto* area : page->findChildren<QScrollArea*>())
      if (area->isAncestorOf(table)) area->ensureWidgetVisible(table);
    shot(page, "home_to_clinic_arrived");
  }

  void theProgrammeChangedAtTheClinicShowsAtHome() {
    // The patient closes the summary (the home window ends) and opens the home window again
    // another day: it syncs at once and shows today's programme, unchanged so far.
    QVERIFY(homeScreen<HomeSummaryScreen>());
    QVERIFY(armtrack::gui::test::activate(homeWindow()));
    press();  // Close
    QTRY_VERIFY_WITH_TIMEOUT(!homeWindow(), 20000);
    signIn(*m_home, kHomeAccount);
    QTRY_VERIFY_WITH_TIMEOUT(homeWindow() && homeWindow()->isVisible(), 20000);
    QVERIFY(armtrack::gui::test::activate(homeWindow()));
    QTRY_VERIFY2_WITH_TIMEOUT(syncLine().contains(QStringLiteral("Everything is sent")),
                              qPrintable(syncLine()), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(startLines().size() == 1, 20000);
    QVERIFY2(startLines()[0].contains(QStringLiteral("1 set of 3")), qPrintable(startLines()[0]));

    // The home programme is edited on the administrator's Programmes page.
    m_clinic->signOut();
    signIn(*m_clinic, QString::fromLatin1(DemoAccounts::kAdmin));
    QVERIFY(armtrack::gui::test::activate(m_clinic->window()));
    QAction* admin = nullptr;
    for (QAction* a : m_clinic->window()->menuBar()->actions().first()->menu()->actions())
      if (a->text().remove(u'&') == QStringLiteral("Administration...")) admin = a;
    QVERIFY(admin && admin->isVisible());
    admin->trigger();
    admin::AdminScreen* screen = nullptr;
    QTRY_VERIFY((screen = qobject_cast<admin::AdminScreen*>(clinicScreen())));
    screen->tabs()->setCurrentWidget(screen->programmes());
    admin::ProgrammePage* programmes = screen->programmes();
    QTRY_VERIFY(programmes->selectPatient(kPatient));
    QTRY_VERIFY(programmes->table()->rowCount() == 1 && programmes->table()->item(0, 0) &&
                programmes->table()->item(0, 0)->text() == kExercise);
    QCOMPARE(programmes->table()->item(0, 1)->text(), QStringLiteral("1 x 3"));
    programmes->table()->setFocus();
    programmes->table()->selectRow(0);
    QTest::keyClick(findControl<QPushButton>(programmes, QStringLiteral("Edit exercise...")),
                    Qt::Key_Space);
    admin::ExerciseDialog* dialog = nullptr;
    QTRY_VERIFY((dialog = screen->findChild<admin::ExerciseDialog*>()) && dialog->isVisible());
    auto* sets = findControl<QSpinBox>(dialog, QStringLiteral("Sets"));
    QVERIFY(sets);
    sets->setFocus();
    sets->selectAll();
    QTest::keyClicks(sets, QStringLiteral("2"));
    QCOMPARE(sets->value(), 2);
    QTest::keyClick(findControl<QPushButton>(dialog, QStringLiteral("Save")), Qt::Key_Space);
    QTRY_VERIFY(!screen->findChild<admin::ExerciseDialog*>());
    QTRY_COMPARE(programmes->table()->item(0, 1)->text(), QStringLiteral("2 x 3"));
    shot(screen, "home_to_clinic_programme");
    const auto clinicProgramme =
        read(clinicUrl(), QString::fromLatin1(DemoAccounts::kAdmin),
             [](storage::Database&, storage::ClinicalStore& s) { return s.programme(kPatient); });
    QCOMPARE(clinicProgramme.size(), std::size_t{1});
    QCOMPARE(clinicProgramme[0].sets, 2);

    // The home window after its next sync (its timer's): the start screen and the home records.
    homeController()->syncService()->syncNow();
    QTRY_VERIFY2_WITH_TIMEOUT(
        !startLines().isEmpty() &&
            startLines()[0].contains(kExercise + QStringLiteral(": 2 sets of 3")),
        qPrintable(startLines().join(u'|')), 30000);
    const auto homeProgramme =
        read(homeUrl(), kHomeAdmin,
             [](storage::Database&, storage::ClinicalStore& s) { return s.programme(kPatient); });
    QCOMPARE(homeProgramme.size(), std::size_t{1});
    QCOMPARE(homeProgramme[0].sets, 2);
    shot(homeWindow(), "home_to_clinic_programme_at_home");
    // Nothing sent twice.
    QCOMPARE(clinicHomeSessions().size(), std::size_t{1});
  }

  void cleanupTestCase() {
    if (homeWindow()) homeWindow()->allowClose();
    m_home.reset();
    m_clinic.reset();
    stopServer();
  }
};

ARMTRACK_APP_TEST_MAIN(TestHomeToClinic)
#include "test_home_to_clinic.moc"
