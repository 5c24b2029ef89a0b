// Before the first exercise: a short guided check that the two sensors are on the right segments
// and the right way round (core/calibration/SensorCheck). The arm hangs still, then the elbow
// bends three times, guided by words, a countdown and a translucent arm doing it; the recording
// is judged off the GUI thread; a problem is explained in plain words with a picture of the arm
// as the sensors sit now beside how they should sit.
#pragma once

#include <QTimer>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/gui/home/HomeScreen.h"
#include "app/gui/services/GatedRecordingSink.h"
#include "app/gui/services/LiveSessionConfig.h"
#include "app/gui/services/SensorCheckJob.h"
#include "app/gui/services/SessionController.h"
#include "core/calibration/SensorCheck.h"

class QLabel;
class QPushButton;

namespace armtrack::ui {
class ArmView;
}

namespace armtrack::gui::home {

class StrapPicture;

class SensorCheckScreen : public HomeScreen {
  Q_OBJECT
 public:
  enum class State { Ready, Recording, Judging, Passed, Problem };

  /// config: the check's devices and arm; folder: where its recording goes.
  SensorCheckScreen(const app::PluginRegistry& registry, app::gui::LiveSessionConfig config,
                    std::filesystem::path folder, QWidget* parent = nullptr);

  State state() const { return m_state; }
  const std::optional<SensorCheckResult>& result() const { return m_result; }
  /// What the screen says now (heading and text).
  QString title() const;
  QString message() const;
  StrapPicture* picture() const { return m_picture; }
  ui::ArmView* armView() const { return m_arm; }

  QList<QAbstractButton*> choices() const override;
  QAbstractButton* defaultChoice() const override;
  void escapePressed() override;

  /// The words for a result: what is wrong and what to do (empty when all is right).
  static QString explain(const SensorCheckResult& result);

 public slots:
  void start();

 signals:
  /// Go on to the calibration (passed: the check found nothing wrong).
  void done(bool passed);

 protected:
  void retranslate() override;

 private:
  void setState(State s);
  void drain();
  void judge();
  void showResult(const SensorCheckResult& r);

  const app::PluginRegistry& m_registry;
  app::gui::LiveSessionConfig m_config;
  std::filesystem::path m_folder, m_csv;
  app::gui::SessionController* m_controller;
  SensorCheckJob* m_judge;  // judges the recording off the GUI thread
  std::shared_ptr<app::gui::RecordingGate> m_gate;
  State m_state = State::Ready;
  std::optional<SensorCheckResult> m_result;
  int m_generation = 0;
  bool m_withTrunk = false;  // the check's session has a sternum sensor
  QTimer m_timer;
  std::vector<session::EstimateRow> m_rows;

  QLabel* m_title;
  QLabel* m_text;
  QLabel* m_banner;
  StrapPicture* m_picture;
  ui::ArmView* m_arm;
  QPushButton* m_start;
  QPushButton* m_goOn;
  QPushButton* m_skip;
};

}  // namespace armtrack::gui::home
