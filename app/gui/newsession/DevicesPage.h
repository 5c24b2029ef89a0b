// New session, devices: the device plugins found, each one's options as a form, and a
// connection check that runs the chosen devices for a moment and shows their live signal,
// rates and losses. A page a wizard can host (isComplete(), completeChanged()).
#pragma once

#include <QTimer>
#include <QWidget>
#include <functional>

#include "app/gui/services/LiveSessionConfig.h"
#include "app/gui/services/SessionController.h"

class QLabel;
class QListWidget;
class QListWidgetItem;
class QPushButton;

namespace armtrack::ui {
class AngleReadouts;
class DeviceHealthPanel;
class DeviceOptionsForm;
}  // namespace armtrack::ui

namespace armtrack::app::gui {

class DevicesPage : public QWidget {
  Q_OBJECT
 public:
  /// registry: loaded, outlives the page. base: the arm and estimator the check runs with.
  DevicesPage(const PluginRegistry& registry, LiveSessionConfig base, QWidget* parent = nullptr);

  /// The chosen devices as "plugin:key=value,..." specs.
  QStringList devices() const;
  /// Chooses devices from specs (plugins not found are ignored, and said so).
  void setDevices(const QStringList& specs);
  /// At least one device is chosen.
  bool isComplete() const;
  /// Whether the last connection check saw every stream streaming.
  bool checkPassed() const { return m_checkPassed; }
  bool checking() const { return m_checking; }
  QString statusText() const;

  ui::DeviceOptionsForm* optionsForm() const { return m_form; }
  ui::DeviceHealthPanel* health() const { return m_health; }
  QListWidget* pluginList() const { return m_plugins; }
  QPushButton* checkButton() const { return m_check; }

 public slots:
  /// Runs the chosen devices, showing their signal and angles, until stopCheck() (the next step
  /// calls it): after passing (every stream streaming for 2 s) the angles keep following the arm.
  void startCheck();
  void stopCheck();

 signals:
  void completeChanged();
  /// The check's verdict: passed when every stream streamed for 2 s (the devices then go on
  /// streaming until stopCheck()), failed when one did not or the devices could not start (the
  /// check has ended); message says what was seen.
  void checkFinished(bool passed, const QString& message);

 protected:
  void changeEvent(QEvent* event) override;
  /// A page no longer shown lets go of its devices (the next step needs them).
  void hideEvent(QHideEvent* event) override;

 private:
  void retranslateUi();
  /// Shows the check's state in words, made again when the language changes.
  void showStatus(std::function<QString()> text);
  void showPlugin(QListWidgetItem* item);
  void drain();
  /// Ends the check; announce: emit checkFinished() (not for a check that has passed already).
  void finishCheck(std::function<QString()> message, bool announce = true);
  void updateCheckButton();

  const PluginRegistry& m_registry;
  LiveSessionConfig m_base;
  SessionController* m_controller;
  QListWidget* m_plugins;
  ui::DeviceOptionsForm* m_form;
  QLabel* m_listLabel;
  QLabel* m_refused = nullptr;
  QStringList m_refusals;
  QLabel* m_description;
  std::function<QString()> m_statusText;
  QLabel* m_status;
  QPushButton* m_check;
  ui::DeviceHealthPanel* m_health;
  ui::AngleReadouts* m_signal;
  QTimer m_timer;
  QListWidgetItem* m_shown = nullptr;
  bool m_checking = false;
  bool m_checkPassed = false;
  std::function<QString()> m_passedText;  // what the passed check saw
  double m_okSince = -1.0;
  std::vector<session::EstimateRow> m_rows;
};

}  // namespace armtrack::app::gui
