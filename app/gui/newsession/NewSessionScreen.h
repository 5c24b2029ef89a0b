// The new-session flow as a wizard inside the main window: the patient, protocol and side (this
// file's first page), then the device check and calibration pages (app/gui/newsession), then the
// live session. Esc or Cancel returns to the patient without recording anything.
#pragma once

#include <QWidget>
#include <QWizardPage>
#include <vector>

#include "app/gui/newsession/NewSessionSteps.h"
#include "app/gui/services/SessionPlan.h"

namespace armtrack::app {
class PluginRegistry;
}

class QComboBox;
class QLabel;
class QRadioButton;
class QWizard;

namespace armtrack::gui {

class MessageLine;
class RecordsService;
struct AppSettings;

/// Step 1: protocol and side for the patient.
class SessionSetupPage : public QWizardPage {
  Q_OBJECT
 public:
  SessionSetupPage(RecordsService& records, const QString& patientCode, QWidget* parent = nullptr);
  bool isComplete() const override;
  SessionPlan plan() const;
  /// Chooses a protocol by name ("" = none); false when there is no such protocol.
  bool selectProtocol(const QString& name);
  void selectSide(Side side);

 signals:
  void loaded();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  void protocolChanged();

  SessionPlan m_plan;
  std::vector<storage::Protocol> m_protocols;
  bool m_loaded = false;
  QLabel* m_patient;
  QLabel* m_patientLabel;
  QLabel* m_protocolLabel;
  QLabel* m_armLabel;
  QComboBox* m_protocol;
  QLabel* m_protocolDetails;
  QRadioButton* m_left;
  QRadioButton* m_right;
  MessageLine* m_message;
};

class NewSessionScreen : public QWidget {
  Q_OBJECT
 public:
  /// plugins: loaded, outlives the screen. devices: the specs the device step starts with.
  NewSessionScreen(RecordsService& records, const app::PluginRegistry& plugins,
                   const AppSettings& settings, const QString& patientCode,
                   const QStringList& devices, QWidget* parent = nullptr);

  QWizard* wizard() const { return m_wizard; }
  SessionSetupPage* setupPage() const { return m_setup; }
  WidgetStep* devicesStep() const { return m_devices; }
  WidgetStep* calibrationStep() const { return m_calibration; }
  WidgetStep* cameraStep() const { return m_camera; }
  SessionPlan plan() const { return m_setup->plan(); }
  const NewSessionChoices& choices() const { return m_choices; }

 signals:
  /// The last step was finished: start the live session.
  void accepted(const armtrack::gui::SessionPlan& plan,
                const armtrack::gui::NewSessionChoices& choices);
  void cancelled();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  void addDeviceSteps(const app::PluginRegistry& plugins, const AppSettings& settings);

  QWizard* m_wizard;
  SessionSetupPage* m_setup;
  WidgetStep* m_devices = nullptr;
  WidgetStep* m_calibration = nullptr;
  WidgetStep* m_camera = nullptr;
  NewSessionChoices m_choices;
};

}  // namespace armtrack::gui
