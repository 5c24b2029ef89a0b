#include "app/gui/newsession/DevicesPage.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHideEvent>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>
#include <tuple>

#include "app/plugins/PluginRegistry.h"
#include "devices/api/Options.h"
#include "ui/AngleReadouts.h"
#include "ui/AngleTrace.h"
#include "ui/DeviceHealthPanel.h"
#include "ui/DeviceOptionsForm.h"
#include "ui/DeviceWords.h"

namespace armtrack::app::gui {

namespace {
constexpr int kOptionsRole = Qt::UserRole + 1;  // the plugin's options text
constexpr double kPassAfterSeconds = 2.0;       // every stream streaming this long: passed
constexpr double kGiveUpSeconds = 15.0;
}  // namespace

DevicesPage::DevicesPage(const PluginRegistry& registry, LiveSessionConfig base, QWidget* parent)
    : QWidget(parent),
      m_registry(registry),
      m_base(std::move(base)),
      m_controller(new SessionController(registry, this)) {
  auto* root = new QHBoxLayout(this);

  auto* left = new QVBoxLayout;
  m_listLabel = new QLabel(this);
  m_plugins = new QListWidget(this);
  m_listLabel->setBuddy(m_plugins);
  for (const PluginRecord& r : registry.records()) {
    if (!r.loaded) continue;
    devices::DevicePlugin* p = registry.plugin(r.name);
    auto* item = new QListWidgetItem(r.name, m_plugins);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(Qt::Unchecked);
    item->setToolTip(p ? ui::pluginDescriptionText(p->description()) : QString());
    item->setData(kOptionsRole, QString());
  }
  for (const PluginRecord& r : registry.records())
    if (!r.loaded) m_refusals << QStringLiteral("%1: %2").arg(r.file, r.refusal);
  left->addWidget(m_listLabel);
  left->addWidget(m_plugins, 1);
  if (!m_refusals.isEmpty()) {
    m_refused = new QLabel(this);
    m_refused->setWordWrap(true);
    left->addWidget(m_refused);
  }
  root->addLayout(left, 1);

  auto* middle = new QVBoxLayout;
  m_description = new QLabel(this);
  m_description->setWordWrap(true);
  m_form = new ui::DeviceOptionsForm(this);
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setWidget(m_form);
  middle->addWidget(m_description);
  middle->addWidget(scroll, 1);
  root->addLayout(middle, 2);

  auto* right = new QVBoxLayout;
  m_check = new QPushButton(this);
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  m_signal = new ui::AngleReadouts(this);
  m_signal->setColumns(2);
  m_health = new ui::DeviceHealthPanel(this);
  right->addWidget(m_check);
  right->addWidget(m_status);
  right->addWidget(m_signal);
  right->addWidget(m_health, 1);
  root->addLayout(right, 2);

  connect(m_plugins, &QListWidget::currentItemChanged, this,
          [this](QListWidgetItem* current, QListWidgetItem*) { showPlugin(current); });
  connect(m_plugins, &QListWidget::itemChanged, this, [this] { emit completeChanged(); });
  connect(m_form, &ui::DeviceOptionsForm::changed, this, [this] {
    if (m_shown) m_shown->setData(kOptionsRole, m_form->optionsText());
  });
  connect(m_check, &QPushButton::clicked, this, [this] {
    if (m_checking)
      stopCheck();
    else
      startCheck();
  });
  connect(m_controller, &SessionController::started, this, [this](const QString& error) {
    if (!error.isEmpty()) {
      finishCheck([error] { return tr("The devices could not start: %1").arg(error); });
      return;
    }
    m_timer.start(100);
  });
  // Off between a finished check and its devices being released (well under a second): a check
  // started then would be refused.
  connect(m_controller, &SessionController::busyChanged, this, &DevicesPage::updateCheckButton);
  connect(m_controller, &SessionController::deviceStateChanged, m_health,
          &ui::DeviceHealthPanel::setDeviceState);
  connect(&m_timer, &QTimer::timeout, this, &DevicesPage::drain);
  showStatus([] { return tr("Choose the devices, then check their connection."); });
  retranslateUi();
  if (m_plugins->count() > 0) m_plugins->setCurrentRow(0);
}

void DevicesPage::retranslateUi() {
  setAccessibleName(tr("Devices"));
  m_listLabel->setText(tr("&Devices found (tick the ones to use):"));
  m_plugins->setAccessibleName(tr("Device plugins"));
  if (m_refused)
    m_refused->setText(tr("Not loaded: %1").arg(m_refusals.join(QStringLiteral("; "))));
  m_check->setText(m_checking ? tr("Stop &check") : tr("&Check connection"));
  m_check->setAccessibleName(tr("Check connection"));
  m_status->setAccessibleName(tr("Connection check"));
  if (m_statusText) m_status->setText(m_statusText());
}

void DevicesPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  QWidget::changeEvent(event);
}

void DevicesPage::showStatus(std::function<QString()> text) {
  m_statusText = std::move(text);
  m_status->setText(m_statusText());
}

void DevicesPage::showPlugin(QListWidgetItem* item) {
  m_shown = nullptr;  // while the form is rebuilt, edits belong to no plugin
  if (!item) return;
  devices::DevicePlugin* p = m_registry.plugin(item->text());
  m_description->setText(p ? ui::pluginDescriptionText(p->description()) : QString());
  m_form->setOptionsHelp(p ? p->optionsHelp() : QString());
  m_form->setValues(devices::Options::parse(item->data(kOptionsRole).toString()));
  m_shown = item;
}

QStringList DevicesPage::devices() const {
  QStringList specs;
  for (int i = 0; i < m_plugins->count(); ++i) {
    const QListWidgetItem* item = m_plugins->item(i);
    if (item->checkState() != Qt::Checked) continue;
    const QString options = item->data(kOptionsRole).toString();
    specs << (options.isEmpty() ? item->text() : item->text() + QLatin1Char(':') + options);
  }
  return specs;
}

void DevicesPage::setDevices(const QStringList& specs) {
  QStringList missing;
  for (const QString& spec : specs) {
    const qsizetype colon = spec.indexOf(u':');
    const QString name = spec.left(colon);
    const auto found = m_plugins->findItems(name, Qt::MatchExactly);
    if (found.isEmpty()) {
      missing << name;
      continue;
    }
    found.front()->setCheckState(Qt::Checked);
    found.front()->setData(kOptionsRole, colon < 0 ? QString() : spec.mid(colon + 1));
    if (found.front() == m_plugins->currentItem()) showPlugin(found.front());
  }
  if (!missing.isEmpty())
    showStatus([missing] {
      return tr("Not found: %1. Check the plugin folders in the settings.")
          .arg(missing.join(QStringLiteral(", ")));
    });
  emit completeChanged();
}

bool DevicesPage::isComplete() const {
  return !devices().isEmpty();
}

QString DevicesPage::statusText() const {
  return m_status->text();
}

void DevicesPage::startCheck() {
  if (m_checking) return;
  LiveSessionConfig c = m_base;
  c.devices = devices();
  c.movementCalibration.enabled = false;  // a device check, not a session
  if (c.devices.isEmpty()) {
    showStatus([] { return tr("Tick at least one device first."); });
    return;
  }
  m_checking = true;
  m_checkPassed = false;
  m_okSince = -1.0;
  m_health->clear();
  m_signal->setSample(nullptr);
  m_check->setText(tr("Stop &check"));
  updateCheckButton();
  showStatus([] { return tr("Starting the devices\u2026"); });
  m_controller->start(c, nullptr);
}

void DevicesPage::drain() {
  std::vector<std::string> events;
  if (!m_controller->drainInto(m_rows, events)) return;
  const auto& s = m_controller->session();
  if (!m_rows.empty()) {
    const ui::AngleSample last = ui::angleSample(m_rows.back());
    m_signal->setSample(&last);
  }
  const session::SessionStats st = s->stats();
  m_health->setStats(st);
  const ui::HealthTracker& h = m_health->tracker();
  if (h.allOk()) {
    if (m_okSince < 0) m_okSince = st.elapsed;
    if (!m_checkPassed && st.elapsed - m_okSince >= kPassAfterSeconds) {
      // Passed; the devices go on streaming so that the therapist can see the angles follow
      // the arm, until the check is stopped or the next step is taken.
      m_checkPassed = true;
      // The sternum sensor's name is made again in each language the text is shown in; the
      // other streams' are the devices' own.
      std::vector<std::tuple<QString, QString, double, bool>> rates;
      std::vector<std::pair<QString, double>> batteries;  // per device, where reported
      for (const ui::StreamHealthRow& r : h.rows()) {
        rates.emplace_back(r.device, r.stream, r.rateHz, r.trunkSensor);
        if (r.batteryPercent && (batteries.empty() || batteries.back().first != r.device))
          batteries.emplace_back(r.device, *r.batteryPercent);
      }
      m_passedText = [rates, batteries] {
        QStringList shown, charged;
        for (const auto& [device, stream, hz, trunk] : rates)
          shown << tr("%1 %2 %L3 Hz")
                       .arg(device, trunk ? ui::trunkSensorName() : stream)
                       .arg(hz, 0, 'f', 0);
        for (const auto& [device, percent] : batteries)
          charged << (percent <= ui::DeviceHealthModel::kLowBatteryPercent
                          ? tr("%1 %L2 % (low: charge it after the session)")
                          : tr("%1 %L2 %"))
                         .arg(device)
                         .arg(percent, 0, 'f', 0);
        QString text = tr("Connected: %1.").arg(shown.join(QStringLiteral(", ")));
        if (!charged.isEmpty())
          text += QLatin1Char(' ') + tr("Battery: %1.").arg(charged.join(QStringLiteral(", ")));
        return text;
      };
      showStatus([this] {
        return m_passedText() + QLatin1Char(' ') +
               tr("The angles keep following the arm: move it and check them, then go on "
                  "(or stop the check).");
      });
      emit checkFinished(true, m_status->text());
      return;
    }
    if (!m_checkPassed) showStatus([] { return tr("Receiving from every device\u2026"); });
  } else {
    m_okSince = -1.0;
    showStatus([this] { return m_health->tracker().summary(); });
    if (!m_checkPassed && st.elapsed > kGiveUpSeconds)
      finishCheck([summary = h.summary()] {
        return tr("Not every device is streaming: %1. Check that each is switched on, charged "
                  "and within range, then check again.")
            .arg(summary);
      });
  }
}

void DevicesPage::updateCheckButton() {
  m_check->setEnabled(m_checking || !m_controller->busy());
}

void DevicesPage::hideEvent(QHideEvent* event) {
  if (!event->spontaneous()) stopCheck();  // not when the window is only minimised
  QWidget::hideEvent(event);
}

void DevicesPage::stopCheck() {
  if (!m_checking) return;
  if (m_checkPassed) {
    // Its verdict was given when it passed; the figures seen then stay.
    finishCheck([text = m_passedText] { return text() + QLatin1Char(' ') + tr("Check stopped."); },
                false);
    return;
  }
  finishCheck([] { return tr("Check stopped."); });
}

void DevicesPage::finishCheck(std::function<QString()> message, bool announce) {
  m_timer.stop();
  m_controller->stop();
  m_checking = false;
  m_check->setText(tr("&Check connection"));
  updateCheckButton();
  showStatus(std::move(message));
  if (announce) emit checkFinished(m_checkPassed, m_status->text());
}

}  // namespace armtrack::app::gui
