// What the application shows when: the first-run assistant, sign-in, the patients, a session,
// a review. It owns the services (records, plugins, settings) and hands them to the screens; the
// screens know nothing of each other.
#pragma once

#include <QObject>
#include <QPointer>
#include <memory>

#include "app/gui/AppOptions.h"
#include "app/gui/Appearance.h"
#include "app/gui/newsession/NewSessionSteps.h"
#include "app/gui/services/AppSettings.h"
#include "app/gui/services/LiveSessionConfig.h"
#include "app/gui/services/RecordsService.h"
#include "app/gui/services/SessionPlan.h"
#include "app/plugins/PluginRegistry.h"

namespace armtrack::gui {

namespace home {
class HomeController;
}

class MainWindow;
class CloseWhileRecording;
class MessageScreen;

class AppController : public QObject {
  Q_OBJECT
 public:
  explicit AppController(AppOptions options, QObject* parent = nullptr);
  ~AppController() override;

  /// Loads the settings and plugins, shows the window and its first screen.
  void start();

  MainWindow* window() const { return m_window.get(); }
  /// What the window asks when it is closed during a recording.
  CloseWhileRecording* closeGuard() const { return m_closeGuard; }
  /// The home window's course while a home account is signed in (else null).
  home::HomeController* home() const { return m_home.get(); }
  RecordsService& records() { return *m_records; }
  const app::PluginRegistry& plugins() const { return m_plugins; }
  const AppSettings& settings() const { return m_settings; }

  // Where the application goes; public so that a test can drive it.
  void openRecords();
  void showFirstRun();
  void showSignIn();
  void signOut();
  void showPatients();
  void showPatientList(const QString& select);
  void showPatient(const QString& code);
  /// The administrator's screen: accounts, protocols, home programmes (administrators only).
  void showAdmin();
  void startNewSession(const QString& code);
  void showReview(qint64 sessionId);
  void showSettings();
  /// The home window for the signed-in home account, in place of the main window.
  void showHome();
  /// Saves s (and the theme) and applies what can change at once.
  void applySettings(const AppSettings& s, Theme theme);
  /// `--demo`: fresh demo records, signed in as the demo therapist, then the live session.
  void startDemo();
  /// The live session of plan with these devices ("plugin:options"), recording into the records;
  /// when it stops after recording, the new session is analysed and reviewed.
  void showLiveSession(const SessionPlan& plan, const NewSessionChoices& choices);
  /// Analyses a stored session (a job with progress, with the session's sensor calibration when
  /// one was made), then opens its review.
  void analyseThenReview(qint64 sessionId, const QString& patientCode,
                         const std::optional<Calibration>& calibration = {});
  /// The devices a new session starts with (settings "devices/default", else the virtual arm).
  QStringList defaultDevices() const;
  /// Writes what the screen shows of the window to path (PNG).
  bool saveWindowImage(const QString& path) const;
  /// An account's role in words, in the current language.
  static QString roleText(storage::Role role);

 signals:
  /// Someone signed in (after the first-run assistant too).
  void signedIn(const QString& name);
  /// The demo records are made, the demo therapist signed in and the live session shown.
  void demoReady();
  void settingsApplied();
  /// A live session screen was shown (and started).
  void liveSessionShown(QWidget* screen);
  /// The home window was shown (a home account signed in).
  void homeShown();

 private:
  void loadPlugins();
  void saveSettings();
  /// The records in effect (--db, else the settings); throws StorageError(Usage).
  storage::DatabaseUrl databaseUrl() const;
  void onSignedIn(const storage::User& user);
  /// Analyses the sessions left with a pending analysis in the background, one job a session
  /// (staff only), those after session `after`; analysedSoFar counts those done before, for the
  /// status bar.
  void analysePending(int analysedSoFar = 0, qint64 after = 0);
  /// One step of analysePending: the session tried (0: none left), whether it was analysed, and
  /// whether to go on.
  struct Step {
    qint64 id = 0;
    bool analysed = false;
    bool more = false;
  };
  /// The analysis shown by wait has ended without a review: Skip goes, Review and Back come.
  void endAnalysisWait(MessageScreen* wait, qint64 sessionId, const QString& code);
  void showDatabaseProblem(const RecordsFailure& failure);
  void closeHome();
  storage::DatabaseUrl demoDatabaseUrl() const;
  void startDemoSession();
  /// --quit-when-live: quits (saving --screenshot) once screen has shown 2 s of estimates.
  void quitOnceLive(QWidget* screen);
  /// --quit-after: saves --screenshot and quits (status 1 with --quit-when-live: not live).
  void quitAfterLimit();
  /// Ends the application with status code. The home window is closed as its own close button
  /// would (an exercise under way kept as interrupted, the results saved) and the application
  /// ends once it has: a plain quit() was refused by the home window, which ignores the close
  /// event until it has done so, and the application never ended.
  void quitApplication(int code);

  AppOptions m_options;
  std::optional<int> m_quitCode;  // quitApplication() waits for the home window to close
  std::optional<storage::DatabaseUrl> m_demoUrl;  // in demo mode
  AppSettings m_settings;
  app::PluginRegistry m_plugins;
  std::unique_ptr<RecordsService> m_records;
  std::unique_ptr<MainWindow> m_window;
  std::unique_ptr<home::HomeController> m_home;
  CloseWhileRecording* m_closeGuard;  // owned by the window
};

}  // namespace armtrack::gui
