// The live session screen: the 3D arm, the joint-angle plots with their table, large readouts,
// the repetition counter, device health and messages around a running Session; Record, Pause,
// Stop and event markers. docs/gui.md describes it.
#pragma once

#include <QTimer>
#include <QWidget>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "app/gui/live/LiveTrunkFeedback.h"
#include "app/gui/services/GatedRecordingSink.h"
#include "app/gui/services/LiveSessionConfig.h"
#include "app/gui/services/RecordingTarget.h"
#include "app/gui/services/SessionController.h"
#include "core/metrics/RepetitionCounter.h"
#include "ui/AngleTrace.h"
#include "ui/ArmView.h"

class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;

namespace armtrack::ui {
class AnglePlotPanel;
class AngleReadouts;
class DeviceHealthPanel;
class RepetitionCounterWidget;
}  // namespace armtrack::ui

namespace armtrack::app::gui {

/// The screen drains the session on a timer (drainRate(), 40 Hz by default): estimates go to
/// the plots, readouts, counter and 3D view in batches; messages to the list; figures to the
/// device health a few times a second. Nothing on the GUI thread waits for a device, the disk or
/// the database: the session starts and stops in SessionController's thread, rows are written
/// by the session's recorder thread, and the recording target begins and finishes without the
/// GUI thread waiting (RecordingTarget::beginAsync, finishAsync). GUI thread only.
class LiveSessionScreen : public QWidget {
  Q_OBJECT
 public:
  /// registry: loaded plugins, outlives the screen. target: where Record writes (nullptr: the
  /// session is only watched; Record is disabled).
  LiveSessionScreen(const PluginRegistry& registry, LiveSessionConfig config,
                    std::shared_ptr<RecordingTarget> target = nullptr, QWidget* parent = nullptr);
  ~LiveSessionScreen() override;

  enum class State { Idle, Starting, Live, Recording, Paused, Stopping, Stopped, Failed };
  State state() const { return m_state; }
  /// The newest estimate's session time (s).
  double sessionTime() const { return m_sessionTime; }
  /// The last problem shown in the banner (empty when none).
  QString bannerText() const;
  /// Event markers so far: time (s) and label.
  const std::vector<std::pair<double, QString>>& events() const { return m_events; }
  const RepetitionCounter& repetitionCounter() const { return m_counter; }
  /// The trunk's angles, the trunk limit's cue and its count of repetitions with compensation.
  const LiveTrunkFeedback& trunk() const { return *m_trunk; }

  /// Shows a batch of estimates as the drain does (plots, readouts, counter, 3D view, trunk):
  /// the drain's own path, open so that a test can show rows it made without a session.
  void showEstimates(const std::vector<session::EstimateRow>& rows);

  void setDrainRate(double hz);
  double drainRate() const { return m_drainHz; }
  /// Timer ticks that drained the session, and estimates drained (for tests and the benchmark).
  std::uint64_t drains() const { return m_drains; }
  std::uint64_t estimatesDrained() const { return m_estimates; }

  /// The longest time (ms) each part of a drain took since the last resetDrainTimes(), timed
  /// with QElapsedTimer: taking the results, feeding the views and the counter, redrawing the
  /// plots, updating the 3D view, and the device figures (for the benchmark).
  struct DrainTimes {
    double takeMs = 0, feedMs = 0, plotsMs = 0, armMs = 0, statsMs = 0, wholeMs = 0;
    std::size_t mostRows = 0;  ///< the largest batch of estimates drained at once
  };
  const DrainTimes& drainTimes() const { return m_times; }
  void resetDrainTimes() { m_times = {}; }

  ui::ArmView* armView() const { return m_arm; }
  ui::AnglePlotPanel* plots() const { return m_plots; }
  ui::AngleReadouts* readouts() const { return m_readouts; }
  ui::DeviceHealthPanel* health() const { return m_health; }
  ui::RepetitionCounterWidget* repetitions() const { return m_reps; }
  QListWidget* messages() const { return m_messages; }
  /// The line on the straps as the calibration from movement found them (hidden when it is
  /// off: a sensor calibration is in use).
  QLabel* strapsLabel() const { return m_straps; }
  /// The calibration from movement the session used last (kept after it stops), for the
  /// session's analysis to estimate with it again; empty when none was applied.
  const std::optional<Calibration>& movementCalibration() const {
    return m_strapsStatus.calibration;
  }
  QPushButton* recordButton() const { return m_record; }
  QPushButton* pauseButton() const { return m_pause; }
  QPushButton* stopButton() const { return m_stop; }
  QPushButton* markButton() const { return m_mark; }

 public slots:
  /// Starts the session (asynchronously: sessionStarted() or sessionFailed() follows).
  void start();
  /// Starts or resumes recording.
  void record();
  /// Pauses recording (the session goes on; rows are not recorded meanwhile).
  void pause();
  /// Ends the session (asynchronously: sessionStopped() follows).
  void stop();
  /// Marks an event now, labelled with the event box's text.
  void markEvent();

 signals:
  void sessionStarted();
  void sessionFailed(const QString& message);
  /// The session has ended; summary says what was recorded where.
  void sessionStopped(const QString& summary);
  void stateChanged(armtrack::app::gui::LiveSessionScreen::State state);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void buildLayout();
  void retranslateUi();
  void setState(State s);
  void drain();
  /// Shows a problem in the banner (empty: hides it), made again when the language changes.
  void showBanner(std::function<QString()> text, bool error);
  void addMessage(const QString& text);
  void onStarted(const QString& error);
  void onStopped(quint64 recordedRows, quint64 rowsToRecord, const QString& recorderError);
  void finishStopping(const QString& summary);
  /// Rows reach the recording from now on.
  void openGate();
  void updateButtons();
  void updateStatus();
  /// The straps' line from the session's calibration from movement (kept after it stops).
  void updateStraps();

  const PluginRegistry& m_registry;
  LiveSessionConfig m_config;
  std::shared_ptr<RecordingTarget> m_target;
  std::shared_ptr<RecordingGate> m_gate;
  SessionController* m_controller;
  State m_state = State::Idle;
  bool m_begun = false;      // the recording target was begun
  bool m_beginning = false;  // it is beginning (Record was pressed; rows flow once it has)
  QTimer m_drainTimer;
  double m_drainHz = 40.0;
  std::uint64_t m_drains = 0, m_estimates = 0;
  DrainTimes m_times;
  double m_sessionTime = 0.0;
  double m_lastOptical = -1e9;
  double m_recordedSeconds = 0.0, m_recordingSince = -1.0;
  // When recording first began (s, session clock): recording time's origin when the gate has not
  // reported its first row.
  double m_firstRecordingS = std::numeric_limits<double>::quiet_NaN();
  std::vector<session::EstimateRow> m_rows;
  std::vector<ui::AngleSample> m_samples;
  std::vector<std::string> m_sessionEvents;
  std::vector<std::pair<double, QString>> m_events;
  ui::OpticalMarks m_marks;
  RepetitionCounter m_counter;
  std::unique_ptr<LiveTrunkFeedback> m_trunk;

  ui::ArmView* m_arm = nullptr;
  ui::AnglePlotPanel* m_plots = nullptr;
  ui::AngleReadouts* m_readouts = nullptr;
  ui::DeviceHealthPanel* m_health = nullptr;
  ui::RepetitionCounterWidget* m_reps = nullptr;
  QListWidget* m_messages = nullptr;
  QLabel* m_title = nullptr;
  QLabel* m_status = nullptr;
  QLabel* m_banner = nullptr;
  QLabel* m_straps = nullptr;
  session::LiveCalibrationStatus m_strapsStatus;
  std::function<QString()> m_bannerText;
  QPushButton* m_retry = nullptr;
  QPushButton* m_record = nullptr;
  QPushButton* m_pause = nullptr;
  QPushButton* m_stop = nullptr;
  QPushButton* m_mark = nullptr;
  QComboBox* m_eventLabel = nullptr;
};

}  // namespace armtrack::app::gui
