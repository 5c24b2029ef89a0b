// The home window's course: today's programme, the sensor check, the calibration, each exercise
// in turn, the summary with the patient's pain score and comment, saved for the therapist. It
// owns the window and hands the screens what they need; the screens know nothing of each other.
// Everything it asks of the records runs on the records' threads (RecordsService), and so do its
// temporary folder's making and (QThreadPool) removal: the GUI thread never waits for the disk.
#pragma once

#include <QMessageBox>
#include <QObject>
#include <QPointer>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "app/gui/home/HomeSetup.h"
#include "app/gui/services/HomeRecords.h"

class QMessageBox;
class QTemporaryDir;

namespace armtrack::app {
class PluginRegistry;
}

namespace armtrack::gui {
class RecordsService;
}

namespace armtrack::sync {
class HomeSyncService;
}

namespace armtrack::gui::home {

class FeedbackSound;
class HomeWindow;

class HomeController : public QObject {
  Q_OBJECT
 public:
  /// records: signed in as a home account (patientCode empty: the account's own patient) or as
  /// staff for patientCode; registry: loaded. Both outlive this.
  HomeController(RecordsService& records, const app::PluginRegistry& registry, HomeSetup setup,
                 QString patientCode, QObject* parent = nullptr);
  ~HomeController() override;

  /// Shows the window and loads today's programme.
  void start();
  HomeWindow* window() const { return m_window.get(); }
  const HomePlan& plan() const { return m_plan; }
  const std::vector<HomeExerciseResult>& results() const { return m_results; }
  const HomeSetup& setup() const { return m_setup; }
  FeedbackSound* sound() const { return m_sound; }
  /// The sync with the clinic (null when the set-up names no sync folder).
  sync::HomeSyncService* syncService() const { return m_sync.get(); }
  /// The calibration made in this session, if any.
  const std::optional<Calibration>& calibration() const { return m_calibration; }
  /// The question shown when the window is closed during an exercise (null when none is open).
  QMessageBox* closeQuestion() const { return m_question; }
  /// Closes the window without asking (the application ends): an exercise under way is kept as
  /// interrupted, the results are saved.
  void quit();

 signals:
  void planLoaded();
  /// The patient signed out (from the first screen).
  void signOutRequested();
  /// The window has closed (after saving what could be saved).
  void closed();
  /// The summary was saved (ok) or refused (message).
  void outcomeSaved(bool ok, const QString& message);

 private:
  void showStart();
  void showConnect();
  void showCheck();
  void showCalibration();
  void showExercise(std::size_t index);
  void showSummary();
  void showProblem(const QString& text);
  void loadPlan();
  void setStep(std::function<QString()> step);
  void onCloseRequested();
  void closeNow();
  /// Asks the patient whether to stop the exercise under way and save it.
  void askToStop();
  void saveAll(std::optional<int> pain, const QString& comment,
               const std::function<void(bool, const QString&)>& done);
  app::gui::LiveSessionConfig config(const QStringList& devices,
                                     const std::optional<storage::Protocol>& protocol) const;
  template <class Screen>
  Screen* show(Screen* screen);

  RecordsService& m_records;
  const app::PluginRegistry& m_registry;
  HomeSetup m_setup;
  QString m_patient;
  /// The check's and the calibration's recordings when the set-up names no folder: made with
  /// the plan, removed with everything in it after the window (off the GUI thread).
  std::shared_ptr<QTemporaryDir> m_work;
  std::unique_ptr<HomeWindow> m_window;
  FeedbackSound* m_sound;
  std::unique_ptr<sync::HomeSyncService> m_sync;
  HomePlan m_plan;
  std::vector<HomeExerciseResult> m_results;
  std::optional<Calibration> m_calibration;
  bool m_closing = false;
  QPointer<QMessageBox> m_question;  // "Stop and save?" while open
  bool m_saved = false;
};

}  // namespace armtrack::gui::home
