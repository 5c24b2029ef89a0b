#include "app/gui/AppController.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>
#include <cstdio>

#include "app/gui/Appearance.h"
#include "app/gui/CloseWhileRecording.h"
#include "app/gui/MainWindow.h"
#include "app/gui/SettingsDialog.h"
#include "app/gui/admin/AdminScreen.h"
#include "app/gui/common/AngleNames.h"
#include "app/gui/common/MessageScreen.h"
#include "app/gui/home/HomeController.h"
#include "app/gui/home/HomeWindow.h"
#include "app/gui/live/LiveSessionScreen.h"
#include "app/gui/newsession/LiveConfig.h"
#include "app/gui/newsession/NewSessionScreen.h"
#include "app/gui/patients/PatientListScreen.h"
#include "app/gui/patients/PatientScreen.h"
#include "app/gui/review/ReviewScreen.h"
#include "app/gui/services/AnalyseRecording.h"
#include "app/gui/services/DemoData.h"
#include "app/gui/services/PatientRecords.h"
#include "app/gui/services/RecordsRecordingTarget.h"
#include "app/gui/signin/FirstRunScreen.h"
#include "app/gui/signin/SignInScreen.h"
#include "app/i18n/Language.h"
#include "core/storage/DatabaseFiles.h"
#include "core/storage/SessionAnalysis.h"

namespace armtrack::gui {

namespace {
constexpr auto kLastUser = "signIn/lastUser";
}

QString AppController::roleText(storage::Role role) {
  switch (role) {
    case storage::Role::Admin:
      return tr("administrator");
    case storage::Role::Therapist:
      return tr("therapist");
    case storage::Role::Home:
      return tr("home account");
  }
  return storage::roleName(role);
}

AppController::AppController(AppOptions options, QObject* parent)
    : QObject(parent),
      m_options(std::move(options)),
      m_records(std::make_unique<RecordsService>()),
      m_window(std::make_unique<MainWindow>()),
      m_closeGuard(new CloseWhileRecording(*m_window)) {
  m_window->setCloseGuard([guard = m_closeGuard] { return guard->mayClose(); });
  connect(m_window.get(), &MainWindow::signOutRequested, this, &AppController::signOut);
  connect(m_window.get(), &MainWindow::patientsRequested, this, &AppController::showPatients);
  connect(m_window.get(), &MainWindow::settingsRequested, this, &AppController::showSettings);
  connect(m_window.get(), &MainWindow::adminRequested, this, &AppController::showAdmin);
  connect(m_records.get(), &RecordsService::problem, this,
          [this](const QString& text) { m_window->showStatus(text, 0); });
}

AppController::~AppController() {
  m_home.reset();
  m_window.reset();  // screens first: their pending answers are dropped
  m_records.reset();
}

void AppController::start() {
  QSettings settings;
  m_settings = AppSettings::load(settings);
  i18n::setLanguage(m_options.language.isEmpty() ? m_settings.language : m_options.language);
  applyTheme(parseTheme(settings.value(QStringLiteral("display/theme")).toString()));
  loadPlugins();
  m_window->show();
  if (m_options.quitAfterSeconds > 0)
    QTimer::singleShot(static_cast<int>(m_options.quitAfterSeconds * 1000), this,
                       &AppController::quitAfterLimit);
  if (m_options.quitWhenLive)
    connect(this, &AppController::liveSessionShown, this, &AppController::quitOnceLive);
  m_options.demo ? startDemo() : openRecords();
}

void AppController::showSettings() {
  const Theme theme = parseTheme(QSettings().value(QStringLiteral("display/theme")).toString());
  auto* dialog = new SettingsDialog(m_settings, theme, m_window.get());
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this,
          [this, dialog] { applySettings(dialog->settings(), dialog->theme()); });
  dialog->open();
}

void AppController::applySettings(const AppSettings& s, Theme theme) {
  const AppSettings before = m_settings;
  m_settings = s;
  saveSettings();
  QSettings().setValue(QStringLiteral("display/theme"), themeName(theme));
  applyTheme(theme);
  if (s.language != before.language) {
    // The choice made now wins over --lang; every screen shown switches at once.
    m_options.language.clear();
    i18n::setLanguage(s.language);
  }
  if (s.pluginFolders != before.pluginFolders) m_plugins.load(s.pluginFolders);
  const bool moved = s.effectiveDatabase().display() != before.effectiveDatabase().display();
  m_window->showStatus([moved] {
    QString note = tr("Settings saved.");
    if (moved) note += u' ' + tr("The new records location is used at the next sign-in.");
    return note;
  });
  emit settingsApplied();
}

void AppController::loadPlugins() {
  QStringList folders = m_options.pluginFolders;
  folders << m_settings.pluginFolders << app::PluginRegistry::defaultFolders();
  m_plugins.load(folders);
}

void AppController::saveSettings() {
  QSettings settings;
  m_settings.save(settings);
}

storage::DatabaseUrl AppController::databaseUrl() const {
  if (m_demoUrl) return *m_demoUrl;
  if (!m_options.database.isEmpty()) return storage::DatabaseUrl::parse(m_options.database);
  return m_settings.effectiveDatabase();
}

void AppController::openRecords() {
  storage::DatabaseUrl url;
  try {
    url = databaseUrl();
  } catch (const storage::StorageError& e) {
    return showDatabaseProblem({e.kind(), QString::fromStdString(e.what())});
  }
  auto* wait =
      new MessageScreen([] { return tr("Opening the records"); },
                        [where = url.display()] { return tr("Opening %1...").arg(where); });
  wait->setProgress(-1);
  m_window->showScreen(wait);
  m_records->probe(
      url, wait,
      [this](DatabaseState state) {
        state == DatabaseState::Ready ? showSignIn() : showFirstRun();
      },
      [this](const RecordsFailure& f) { showDatabaseProblem(f); });
}

void AppController::showFirstRun() {
  QString fixed;
  if (!m_options.database.isEmpty() || !m_settings.databaseUrl.isEmpty())
    fixed = databaseUrl().display();
  auto* screen = new FirstRunScreen(m_settings.effectiveDataFolder(), fixed);
  connect(screen, &FirstRunScreen::createRequested, this,
          [this, screen](const QString& folder, const QString& admin, const QString& password) {
            const AppSettings before = m_settings;
            if (m_options.database.isEmpty() && m_settings.databaseUrl.isEmpty())
              m_settings.dataFolder = folder;
            storage::DatabaseUrl url;
            try {
              url = databaseUrl();
            } catch (const storage::StorageError& e) {
              m_settings = before;
              return screen->showError(QString::fromStdString(e.what()));
            }
            screen->setBusy(true);
            m_records->create(
                url, admin, password, screen,
                [this](const storage::User& user) {
                  saveSettings();
                  QSettings().setValue(kLastUser, user.name);
                  onSignedIn(user);
                },
                [this, screen, before](const RecordsFailure& f) {
                  m_settings = before;
                  screen->showError(f.message);
                });
          });
  m_window->showScreen(screen);
}

void AppController::showSignIn() {
  QString where;
  try {
    where = databaseUrl().display();
  } catch (const storage::StorageError& e) {
    return showDatabaseProblem({e.kind(), QString::fromStdString(e.what())});
  }
  const QString last = QSettings().value(kLastUser).toString();
  auto* screen = new SignInScreen(where, last);
  connect(screen, &SignInScreen::signInRequested, this,
          [this, screen](const QString& name, const QString& password) {
            screen->setBusy(true);
            m_records->signIn(
                databaseUrl(), name, password, screen,
                [this, name](const storage::User& user) {
                  QSettings().setValue(kLastUser, name);
                  onSignedIn(user);
                },
                [screen](const RecordsFailure& f) { screen->showError(f.message); });
          });
  m_window->showScreen(screen);
}

void AppController::onSignedIn(const storage::User& user) {
  m_window->setSignedIn(
      [name = user.name, role = user.role] { return tr("%1 (%2)").arg(name, roleText(role)); });
  m_window->setAdministrator(user.role == storage::Role::Admin);
  emit signedIn(user.name);
  if (user.role == storage::Role::Home) return showHome();
  showPatients();
  analysePending();
}

void AppController::analysePending(int analysedSoFar, qint64 after) {
  // Sessions whose analysis never finished (the program that stored them ended first, or a home
  // session waiting for staff) are analysed in the background, one job each: a job the therapist
  // starts meanwhile (a new session's analysis) runs after the current one, not after them all.
  m_records->startJob(
      m_window.get(),
      [after](JobContext& c) {
        // The oldest pending session after the one tried last (ids rise), so that each is tried
        // once in a round whatever happens to it.
        Step step;
        for (const qint64 id : c.store().pendingAnalyses())
          if (id > after) {
            step.id = id;
            break;
          }
        if (step.id == 0 || c.cancelled()) return step;
        storage::AnalysisOptions o;
        o.cancel = c.cancelFlag();
        try {
          const RecordingAnalysis r = analyseRecording(c.store(), step.id, o);
          step.analysed = r.outcome == RecordingAnalysis::Outcome::Analysed;
          step.more = r.outcome != RecordingAnalysis::Outcome::Cancelled;
        } catch (const storage::StorageError& e) {
          // A recording that cannot be analysed is marked so: go on with the others.
          if (e.kind() != storage::StorageError::Kind::Usage &&
              e.kind() != storage::StorageError::Kind::Corrupt)
            throw;
          step.more = true;
        }
        return step;
      },
      [this, analysedSoFar](const Step& step) {
        const int total = analysedSoFar + (step.analysed ? 1 : 0);
        if (step.more && m_records->signedIn()) return analysePending(total, step.id);
        if (total > 0)
          m_window->showStatus(
              [total] { return tr("%n earlier session(s) analysed", nullptr, total); }, 10000);
      },
      [this](const RecordsFailure& f) {
        m_window->showStatus(
            [why = f.message] {
              return tr("Earlier sessions could not be analysed now: %1").arg(why);
            },
            15000);
      });
}

void AppController::signOut() {
  m_records->signOut();
  m_window->setSignedIn({});
  showSignIn();
}

void AppController::showPatients() {
  showPatientList({});
}

void AppController::showPatientList(const QString& select) {
  if (!m_records->signedIn()) return;
  auto* screen = new PatientListScreen(*m_records, select);
  connect(screen, &PatientListScreen::openRequested, this, &AppController::showPatient);
  m_window->showScreen(screen);
}

void AppController::showPatient(const QString& code) {
  if (!m_records->signedIn()) return;
  auto* screen = new PatientScreen(*m_records, m_settings, code);
  connect(screen, &PatientScreen::backRequested, this, [this, code] { showPatientList(code); });
  connect(screen, &PatientScreen::newSessionRequested, this, &AppController::startNewSession);
  connect(screen, &PatientScreen::reviewRequested, this, &AppController::showReview);
  m_window->showScreen(screen);
}

void AppController::showAdmin() {
  if (!m_records->signedIn() || m_records->user().role != storage::Role::Admin) return;
  auto* screen = new admin::AdminScreen(*m_records);
  connect(screen, &admin::AdminScreen::backRequested, this, &AppController::showPatients);
  m_window->showScreen(screen);
}

void AppController::startNewSession(const QString& code) {
  if (!m_records->signedIn()) return;
  auto* screen = new NewSessionScreen(*m_records, m_plugins, m_settings, code, defaultDevices());
  connect(screen, &NewSessionScreen::cancelled, this, [this, code] { showPatient(code); });
  connect(screen, &NewSessionScreen::accepted, this,
          [this](const SessionPlan& plan, const NewSessionChoices& choices) {
            // The next session proposes these devices again.
            QSettings().setValue(QStringLiteral("devices/default"), choices.devices);
            showLiveSession(plan, choices);
          });
  m_window->showScreen(screen);
}

QStringList AppController::defaultDevices() const {
  const QStringList saved = QSettings().value(QStringLiteral("devices/default")).toStringList();
  return saved.isEmpty() ? app::gui::demoDevices() : saved;
}

void AppController::showLiveSession(const SessionPlan& plan, const NewSessionChoices& choices) {
  if (!m_records->signedIn()) return;
  auto target = std::make_shared<RecordsRecordingTarget>(
      *m_records, plan.patient.code, plan.protocol ? plan.protocol->name : QString());
  app::gui::LiveSessionConfig config =
      liveSessionConfig(plan, choices.devices, m_settings, choices.calibration);
  config.calibrationVerdict = choices.calibrationVerdict;  // stored with the session
  config.calibrationReason = choices.calibrationReason;
  auto* screen = new app::gui::LiveSessionScreen(m_plugins, config, target);
  const QString code = plan.patient.code;
  connect(screen, &app::gui::LiveSessionScreen::sessionStopped, this,
          [this, screen, target, code, calibration = choices.calibration](const QString& summary) {
            m_window->showStatus(summary, 0);
            // Without a sensor calibration, the straps the session fitted from the movement.
            const std::optional<Calibration> used =
                calibration ? calibration : screen->movementCalibration();
            const qint64 id = target->sessionId();
            // Closed during the recording ("Stop and save"): its analysis waits for the next
            // start (analysePending), which reads the straps the live estimate used from the
            // session, as every later analysis does; kept there before the window closes.
            if (m_closeGuard->closing()) {
              if (!used || id == 0) return void(m_window->close());
              return m_records->call(
                  m_window.get(),
                  [id, c = *used](storage::ClinicalStore& store) {
                    storage::keepSessionCalibration(store, id, c);
                  },
                  [this] { m_window->close(); },
                  [this, id](const RecordsFailure& f) {
                    // Closing goes on: the session is analysed with the straps it is read with.
                    std::fprintf(stderr,
                                 "armtrack: session %lld: the straps used live were not kept "
                                 "(%s); it is analysed without them\n",
                                 static_cast<long long>(id), qPrintable(f.message));
                    m_window->close();
                  });
            }
            if (id)
              analyseThenReview(id, code, used);
            else
              showPatient(code);
          });
  m_window->showScreen(screen);
  screen->start();
  emit liveSessionShown(screen);
}

void AppController::analyseThenReview(qint64 sessionId, const QString& code,
                                      const std::optional<Calibration>& calibration) {
  auto* wait = new MessageScreen([] { return tr("Analysing the session"); },
                                 [sessionId] {
                                   return tr("Estimating the joint angles of session %1 again "
                                             "from its recording and computing its metrics...")
                                       .arg(sessionId);
                                 });
  wait->setProgress(0);
  m_window->showScreen(wait);
  RecordsJob* job = m_records->startJob(
      wait,
      [sessionId, calibration](JobContext& c) {
        storage::AnalysisOptions o;
        o.calibration = calibration;
        o.progress = [&c](int p) { c.progress(p); };
        o.cancel = c.cancelFlag();
        return analyseRecording(c.store(), sessionId, o);
      },
      [this, wait, sessionId, code](const RecordingAnalysis& r) {
        if (r.outcome != RecordingAnalysis::Outcome::TooShort) return showReview(sessionId);
        wait->setProgress(100);
        wait->setText([sessionId, seconds = r.recordedS] {
          return tr("Session %1 was too short to analyse: %2 s were recorded, and at least %3 s "
                    "are needed. It is kept, marked as too short.\nTo measure the movement, "
                    "start a new session, press Record, let the patient do the movement, then "
                    "press Stop.")
              .arg(sessionId)
              .arg(seconds, 0, 'f', 1)
              .arg(kShortestAnalysableS, 0, 'f', 0);
        });
        endAnalysisWait(wait, sessionId, code);
      },
      [this, wait, sessionId, code](const RecordsFailure& f) {
        // The recording is stored whatever happened: say why it has no analysis yet.
        wait->setProgress(100);
        wait->setText([sessionId, why = f.message] {
          return tr("Session %1 is saved, but it could not be analysed: %2\nYou can "
                    "re-estimate it from its review.")
              .arg(sessionId)
              .arg(why);
        });
        endAnalysisWait(wait, sessionId, code);
      });
  connect(job, &RecordsJob::progress, wait, &MessageScreen::setProgress);
  QPushButton* skip =
      wait->addAction([] { return tr("&Skip the analysis"); }, [job] { job->cancel(); });
  skip->setObjectName(QStringLiteral("skipAnalysis"));
}

void AppController::endAnalysisWait(MessageScreen* wait, qint64 sessionId, const QString& code) {
  // The analysis has ended: its Skip button goes, and the focus with it to the next step.
  if (auto* skip = wait->findChild<QPushButton*>(QStringLiteral("skipAnalysis"))) skip->hide();
  QPushButton* review = wait->addAction([] { return tr("&Review session"); },
                                        [this, sessionId] { showReview(sessionId); });
  wait->addAction([] { return tr("&Back to the patient"); }, [this, code] { showPatient(code); });
  review->setDefault(true);
  wait->setFocusProxy(review);
  review->setFocus(Qt::OtherFocusReason);
}

void AppController::showReview(qint64 sessionId) {
  if (!m_records->signedIn()) return;
  auto* screen = new ReviewScreen(*m_records, m_settings, sessionId);
  connect(screen, &ReviewScreen::backRequested, this, &AppController::showPatient);
  m_window->showScreen(screen);
}

void AppController::showHome() {
  if (!m_records->signedIn() || m_home) return;
  home::HomeSetup setup;
  // The home set-up: the two IMUs and the computer's own webcam. In the demo the virtual arm
  // plays them; otherwise the devices the therapist set up on this computer.
  setup.devices = m_demoUrl
                      ? QStringList{QStringLiteral("virtual-arm:sensors=upper+forearm+webcam")}
                      : defaultDevices();
  // The sync with the clinic keeps its state in the data folder: on a home install's own SQLite
  // records, never in the demo or on a clinic's PostgreSQL server.
  if (!m_demoUrl && m_records->url().engine == storage::DatabaseUrl::Engine::Sqlite)
    setup.syncFolder =
        QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/home-sync";
  setup.configure = [this](const SessionPlan& plan, const QStringList& devices,
                           const std::optional<Calibration>& calibration) {
    return liveSessionConfig(plan, devices, m_settings, calibration);
  };
  m_home =
      std::make_unique<home::HomeController>(*m_records, m_plugins, std::move(setup), QString());
  // Nothing of the main window stays reachable: it is hidden while the home window is open.
  m_window->hide();
  connect(m_home.get(), &home::HomeController::signOutRequested, this, &AppController::closeHome);
  connect(m_home.get(), &home::HomeController::closed, this, &AppController::closeHome);
  m_home->start();
  emit homeShown();
}

void AppController::closeHome() {
  if (!m_home) return;
  // Not from inside the controller's own signal.
  QTimer::singleShot(0, this, [this] {
    if (m_quitCode) {
      m_home.reset();
      QApplication::exit(*m_quitCode);
      return;
    }
    m_window->show();  // first, so that the application does not end with its last window
    m_home.reset();
    signOut();
  });
}

void AppController::showDatabaseProblem(const RecordsFailure& failure) {
  using Kind = storage::StorageError::Kind;
  const Kind kind = failure.kind.value_or(Kind::Io);
  const auto advice = [kind] {
    switch (kind) {
      case Kind::OlderSchema:
        return tr("Back the file up, then bring it up to date with: armtrack-cli db migrate");
      case Kind::NewerSchema:
        return tr("Install the newer ArmTrack that wrote it.");
      case Kind::Corrupt:
        return tr(
            "The file was left untouched. Restore it from a backup, or choose another "
            "database in the settings.");
      default:
        return tr(
            "Check the location in the settings (or --db) and that you may read and "
            "write it, then try again.");
    }
  };
  auto* screen = new MessageScreen(
      [] { return tr("The records cannot be opened"); },
      [why = failure.message, advice] { return why + QStringLiteral("\n\n") + advice(); });
  screen->addAction([] { return tr("&Try again"); }, [this] { openRecords(); });
  screen->addAction([] { return tr("&Quit"); }, [] { QApplication::quit(); });
  m_window->showScreen(screen);
}

}  // namespace armtrack::gui
