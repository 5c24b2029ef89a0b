// One exercise of the programme, one phase at a time: a demonstration of the movement played on
// the 3D arm's translucent target, then each set live (the patient's own arm beside the target to
// reach, repetitions counted, feedback shown and sounded), rests with a countdown between sets,
// pause and stop at any moment. An exercise whose angle cannot be trusted with this set-up (a
// shoulder angle without a camera) is still guided and recorded, but not counted: the screen says
// so instead of showing drifting numbers.
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <functional>
#include <memory>
#include <optional>

#include "app/gui/home/HomeScreen.h"
#include "app/gui/services/HomeExerciseRules.h"
#include "app/gui/services/HomeRecords.h"
#include "app/gui/services/LiveSessionConfig.h"
#include "core/metrics/ExerciseFeedback.h"
#include "core/metrics/TrunkLimitCue.h"
#include "core/session/Session.h"
#include "core/simulation/Trajectory.h"

class QLabel;
class QPushButton;

namespace armtrack::ui {
class ArmView;
}

namespace armtrack::gui {
class RecordsService;
}

namespace armtrack::app {
class PluginRegistry;
}

namespace armtrack::gui::home {

class ExerciseRecording;
class FeedbackSound;

class ExerciseScreen : public HomeScreen {
  Q_OBJECT
 public:
  enum class Phase { Demonstration, Set, Rest, Paused, Finishing, Done };

  /// index, count: which exercise of how many (1-based). optical: a camera or Kinect is set up.
  /// sound may be null (silent).
  ExerciseScreen(const app::PluginRegistry& registry, RecordsService& records,
                 const HomeExercise& exercise, int index, int count, const QString& patientCode,
                 const app::gui::LiveSessionConfig& config, bool optical, FeedbackSound* sound,
                 QWidget* parent = nullptr);
  ~ExerciseScreen() override;

  Phase phase() const { return m_phase; }
  int currentSet() const { return m_set; }
  /// What was done so far (complete once finished() was emitted).
  const HomeExerciseResult& result() const { return m_result; }
  /// Whether the exercise's angle is counted and shown (trusted with this set-up).
  bool measured() const { return m_measured; }
  QString title() const;
  QString instruction() const;
  QString counterText() const;
  QString feedbackText() const;
  /// Feedback messages shown so far (for tests and the log).
  const QStringList& feedbackShown() const { return m_shown; }
  ui::ArmView* armView() const { return m_arm; }
  /// "Keep your back against the chair": shown while the patient leans past the exercise's trunk
  /// limit during a set (never without a limit).
  bool trunkCueShown() const;
  /// The trunk limit's cue and count (nullptr when the exercise sets no limit).
  const TrunkLimitCue* trunkCue() const { return m_trunkCue ? &*m_trunkCue : nullptr; }
  /// The count shown under the counter ("" when nothing to count).
  QString trunkCountText() const;

  /// Where the screen takes its estimates from: the exercise's session (default), or, given
  /// here, a function that moves new rows and messages into the vectors as
  /// ExerciseRecording::drain does (a test's made rows).
  using EstimateSource =
      std::function<bool(std::vector<session::EstimateRow>&, std::vector<std::string>&)>;
  void setEstimateSource(EstimateSource source) { m_source = std::move(source); }
  /// Where the screen learns what the calibration from movement found: the exercise's session
  /// (default), or, given here, a function (a test's made finding). The patient is told once,
  /// in plain words, only when a strap has turned far (strapsPatientLine).
  using StrapsSource = std::function<session::LiveCalibrationStatus()>;
  void setStrapsSource(StrapsSource source) { m_strapsSource = std::move(source); }

  QList<QAbstractButton*> choices() const override;
  QAbstractButton* defaultChoice() const override;
  void escapePressed() override;

 public slots:
  /// Ends the exercise now (the application ends without asking): the session is finished as
  /// interrupted.
  void cutShort();
  /// Ends the exercise now as "Stop for today" does (the patient chose to close the window):
  /// the session is finished complete, with what was done, and analysed like any other.
  void stopAndSave();

 signals:
  /// The exercise is over and its session finished in the records. stopForToday: the patient
  /// asked to stop the whole session.
  void finished(const armtrack::gui::HomeExerciseResult& result, bool stopForToday);

 protected:
  void retranslate() override;

 private:
  void buildLayout();
  void setPhase(Phase p);
  void startSet();
  void closeSet();
  void endSet();
  void pause();
  void resume();
  void finish(bool stoppedEarly, bool stopForToday);
  void tick();
  void handleEvents(const std::vector<FeedbackEvent>& events);
  void showFeedback(const QString& text, int tone);
  void setMeasured(bool measured);
  void updateCounter();
  void updateTrunk();
  QString demonstrationText() const;

  HomeExercise m_exercise;
  int m_index, m_count;
  bool m_optical;
  FeedbackSound* m_sound;
  app::gui::LiveSessionConfig m_config;
  ExerciseRecording* m_recording;
  ExerciseTrajectory m_demo;
  std::optional<ExerciseFeedback> m_feedback;
  HomeExerciseResult m_result;
  Phase m_phase = Phase::Demonstration;
  Phase m_pausedFrom = Phase::Demonstration;
  int m_set = 1;
  bool m_measured = true;
  bool m_stopForToday = false;
  bool m_closing = false;  // the window is closing: the session is interrupted
  HeadingTrust m_trust;    // whether the exercise's angle can be shown now
  double m_lastT = 0;
  QElapsedTimer m_clock;  // the demonstration's time, and the rest's
  double m_restLeftS = 0;
  QTimer m_timer;
  QTimer m_setDone;  // a moment after the last repetition, the set ends
  std::vector<session::EstimateRow> m_rows;
  QStringList m_shown;
  EstimateSource m_source;
  StrapsSource m_strapsSource;
  int m_strapsTicks = 0;      // ticks since the straps were last looked at
  bool m_toldStraps = false;  // the patient was told about a turned strap
  std::optional<TrunkLimitCue> m_trunkCue;
  std::size_t m_trunkCues = 0;  // cues sounded so far

  QLabel* m_title = nullptr;
  QLabel* m_text = nullptr;
  QLabel* m_counter = nullptr;
  QLabel* m_angle = nullptr;
  QLabel* m_banner = nullptr;
  QLabel* m_trunk = nullptr;
  QLabel* m_trunkCount = nullptr;
  ui::ArmView* m_arm = nullptr;
  QPushButton* m_primary = nullptr;
  QPushButton* m_pause = nullptr;
  QPushButton* m_skip = nullptr;
  QPushButton* m_stop = nullptr;
};

}  // namespace armtrack::gui::home
