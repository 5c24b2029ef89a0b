// The calibration protocol after the sensor check, as the therapist's new-session step does it
// (app/gui/newsession SensorCalibrationPage: guided poses and movements, the fit off the GUI
// thread, a verdict), in the home window's words, large and driven by the keyboard or a switch.
#pragma once

#include <QMessageBox>
#include <QPointer>
#include <optional>

#include "app/gui/home/HomeScreen.h"
#include "app/gui/services/LiveSessionConfig.h"
#include "core/calibration/Calibration.h"

class QLabel;
class QPushButton;

namespace armtrack::app::gui {
class SensorCalibrationPage;
}

namespace armtrack::app {
class PluginRegistry;
}

namespace armtrack::gui::home {

class HomeCalibrationScreen : public HomeScreen {
  Q_OBJECT
 public:
  HomeCalibrationScreen(const app::PluginRegistry& registry, app::gui::LiveSessionConfig config,
                        const QString& folder, QWidget* parent = nullptr);

  app::gui::SensorCalibrationPage* page() const { return m_page; }
  /// The question "Skip the calibration?" while it is open (for tests).
  QMessageBox* skipQuestion() const { return m_question; }
  QList<QAbstractButton*> choices() const override;
  QAbstractButton* defaultChoice() const override;
  void escapePressed() override;

 signals:
  /// Go on; the calibration when one was made and is usable.
  void done(const std::optional<armtrack::Calibration>& calibration);

 protected:
  void retranslate() override;

 private:
  void update();
  /// Skip asks first: without the calibration the angles are less exact today.
  void askToSkip();

  app::gui::SensorCalibrationPage* m_page;
  QPushButton* m_goOn;
  QPushButton* m_skip;
  QPointer<QMessageBox> m_question;
};

}  // namespace armtrack::gui::home
