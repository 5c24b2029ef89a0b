// New session, sensor-to-segment calibration (docs/calibration.md): the screen guides the
// protocol (which pose to hold, a countdown, the movement to make, the pose shown on a 3D arm),
// the session records it, core/calibration's calibrator solves it off the GUI thread, and a
// verdict from the fit's residuals says whether to keep it or redo it.
#pragma once

#include <QTimer>
#include <QWidget>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

#include "app/gui/services/GatedRecordingSink.h"
#include "app/gui/services/LiveSessionConfig.h"
#include "app/gui/services/SessionController.h"
#include "core/calibration/Calibrator.h"

class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;

namespace armtrack::ui {
class ArmView;
}

namespace armtrack::app::gui {

enum class CalibrationVerdict { Good, Usable, Poor };

/// Judges a fit: Good when it converged and every residual kind is within 1.5 noise standard
/// deviations (RMS of the whitened residuals; about 1 is a fit to the noise level) with no
/// warning; Usable up to 3, or with warnings (e.g. the start was not held still); Poor beyond 3
/// or when it did not converge. why says it in words, with what to do.
CalibrationVerdict judgeCalibration(const CalibrationResult& result, QString* why);

class SensorCalibrationPage : public QWidget {
  Q_OBJECT
 public:
  enum class State { Ready, Recording, Solving, Done, Failed };

  /// config: the devices and arm (its devices should include both IMUs; the Kinect helps).
  /// folder: where the protocol's recording is kept.
  SensorCalibrationPage(const PluginRegistry& registry, LiveSessionConfig config,
                        std::filesystem::path folder, QWidget* parent = nullptr);

  State state() const { return m_state; }
  /// The fit, once done.
  const std::optional<CalibrationResult>& result() const { return m_result; }
  std::optional<CalibrationVerdict> verdict() const { return m_verdict; }
  QString verdictText() const;
  /// The protocol's recording (after Recording).
  const std::filesystem::path& recordingPath() const { return m_csv; }
  /// Done with a verdict that is not Poor.
  bool isComplete() const;
  QString instructionTitle() const;
  /// The instruction under the title (before the protocol: the introduction).
  QString instructionText() const;
  ui::ArmView* armView() const { return m_arm; }
  QPushButton* startButton() const { return m_start; }
  /// Replaces the words shown before the protocol starts (the home window speaks to the
  /// patient); said again when the language changes.
  void setIntroduction(std::function<QString()> text);
  /// The page speaks to the patient (the home window): words addressed to "you", plain progress
  /// while the fit runs and a plain verdict, without the fit's log and figures.
  void setForPatient(bool forPatient);
  bool forPatient() const { return m_forPatient; }
  /// What the page shows as its log (the fit's lines; empty and hidden for the patient).
  QString detailsText() const;

 public slots:
  /// Starts (or redoes) the protocol.
  void start();
  /// Stops the protocol or forgets a running fit.
  void cancel();

 signals:
  void completeChanged();
  /// The fit is done (or failed); good is false for a Poor verdict or a failure.
  void finished(bool good);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  using Text = std::function<QString()>;
  void retranslateUi();
  /// Shows the step's title and instruction, made again when the language changes.
  void showStep(Text title, Text instruction);
  void showVerdict(Text verdict);
  void setState(State s);
  void updateStartButton();
  void drain();
  void solve();

  const PluginRegistry& m_registry;
  LiveSessionConfig m_config;
  std::filesystem::path m_folder, m_csv;
  SessionController* m_controller;
  std::shared_ptr<RecordingGate> m_gate;
  State m_state = State::Ready;
  bool m_forPatient = false;
  std::optional<CalibrationResult> m_result;
  std::optional<CalibrationVerdict> m_verdict;
  int m_generation = 0;  // a fit started before a cancel or redo is ignored when it ends
  QTimer m_timer;
  std::vector<session::EstimateRow> m_rows;

  Text m_titleText, m_instructionText, m_verdictText;
  QLabel* m_title;
  QLabel* m_instruction;
  QLabel* m_countdown;
  QProgressBar* m_progress;
  ui::ArmView* m_arm;
  QPushButton* m_start;
  QPushButton* m_cancel;
  QLabel* m_verdictLabel;
  QPlainTextEdit* m_details;
};

}  // namespace armtrack::app::gui
