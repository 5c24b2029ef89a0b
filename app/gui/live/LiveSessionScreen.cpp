#include "app/gui/live/LiveSessionScreen.h"

#include <QComboBox>
#include <QElapsedTimer>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>
#include <cmath>

#include "app/gui/services/StrapsText.h"
#include "core/metrics/RangeOfMotion.h"
#include "core/metrics/SessionTime.h"
#include "ui/AnglePlotPanel.h"
#include "ui/AngleReadouts.h"
#include "ui/AngleTableModel.h"
#include "ui/DeviceHealthPanel.h"
#include "ui/DeviceWords.h"
#include "ui/Fonts.h"
#include "ui/RepetitionCounterWidget.h"
#include "ui/Retranslate.h"

namespace armtrack::app::gui {

namespace {
constexpr double kOpticalShownSeconds = 0.5;  // optical marks vanish when no longer measured
constexpr int kStatsEveryTicks = 5;           // device health a few times a second
constexpr int kMaxMessages = 500;

RepetitionParams counterParams(const LiveSessionConfig& c) {
  RepetitionParams p;
  p.primaryAngle = repetitionAngle(c.primaryAngle);  // the analysis counts on the same angle
  if (c.targetDeg && c.targetDeg->second > c.targetDeg->first)
    p.target = TargetRange{c.targetDeg->first * kDegToRad, c.targetDeg->second * kDegToRad};
  return p;
}

QString clock(double seconds) {
  const int s = static_cast<int>(std::max(0.0, seconds));
  return QStringLiteral("%1:%2")
      .arg(s / 60, 2, 10, QLatin1Char('0'))
      .arg(s % 60, 2, 10, QLatin1Char('0'));
}
}  // namespace

LiveSessionScreen::LiveSessionScreen(const PluginRegistry& registry, LiveSessionConfig config,
                                     std::shared_ptr<RecordingTarget> target, QWidget* parent)
    : QWidget(parent),
      m_registry(registry),
      m_config(std::move(config)),
      m_target(std::move(target)),
      m_gate(m_target ? std::make_shared<RecordingGate>(m_target) : nullptr),
      m_controller(new SessionController(registry, this)),
      m_counter(counterParams(m_config)) {
  buildLayout();
  retranslateUi();
  connect(m_controller, &SessionController::started, this, &LiveSessionScreen::onStarted);
  connect(m_controller, &SessionController::stopped, this, &LiveSessionScreen::onStopped);
  connect(m_controller, &SessionController::deviceStateChanged, m_health,
          &ui::DeviceHealthPanel::setDeviceState);
  connect(m_health, &ui::DeviceHealthPanel::summaryChanged, this, [this](const QString&, bool ok) {
    // (Before a session and after it, there are no devices to worry about.)
    if (m_state == State::Failed || m_state == State::Idle || m_state == State::Stopped) return;
    if (ok)
      showBanner({}, false);
    else  // the panel's summary, in the language of the moment
      showBanner(
          [this] {
            return tr("%1. The session goes on with the other sensors; check the device "
                      "(power, cable or distance).")
                .arg(m_health->tracker().summary());
          },
          true);
  });
  // One timer drives every view, so that a tick repaints the window once (with a QOpenGLWidget
  // in it, each repaint composes the whole window in OpenGL).
  m_arm->setRefreshRate(0);
  m_plots->setRefreshRate(0);
  m_readouts->setRefreshRate(0);
  // The big numbers show the sample the table shows, when it shows it (kTableHz): both read
  // the same during fast movement.
  connect(m_plots, &ui::AnglePlotPanel::tableUpdated, m_readouts,
          [this](const ui::AngleSample* current) {
            m_readouts->setSample(current);
            m_readouts->refresh();
          });
  m_drainTimer.setTimerType(Qt::PreciseTimer);
  connect(&m_drainTimer, &QTimer::timeout, this, &LiveSessionScreen::drain);
  setDrainRate(m_drainHz);
  updateButtons();
  updateStatus();
}

LiveSessionScreen::~LiveSessionScreen() = default;

void LiveSessionScreen::buildLayout() {
  auto* root = new QVBoxLayout(this);
  root->setContentsMargins(6, 6, 6, 6);

  // Header: who, state, controls.
  auto* header = new QHBoxLayout;
  m_title = new QLabel(this);
  ui::setScaledFont(m_title, 1.3);
  m_status = new QLabel(this);
  m_record = new QPushButton(this);
  m_record->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
  m_pause = new QPushButton(this);
  m_pause->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_P));
  m_stop = new QPushButton(this);
  m_stop->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
  m_eventLabel = new QComboBox(this);
  m_eventLabel->setEditable(true);
  for (int i = 0; i < 5; ++i) m_eventLabel->addItem(QString());
  m_mark = new QPushButton(this);
  m_mark->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_M));
  header->addWidget(m_title, 1);
  header->addWidget(m_status);
  header->addSpacing(12);
  header->addWidget(m_record);
  header->addWidget(m_pause);
  header->addWidget(m_stop);
  header->addSpacing(12);
  header->addWidget(m_eventLabel);
  header->addWidget(m_mark);
  root->addLayout(header);

  // Banner: the problem that matters now, in words, with what to do.
  auto* bannerRow = new QHBoxLayout;
  m_banner = new QLabel(this);
  m_banner->setWordWrap(true);
  m_banner->setAutoFillBackground(true);
  m_banner->setMargin(6);
  m_banner->hide();
  m_retry = new QPushButton(this);
  m_retry->hide();
  bannerRow->addWidget(m_banner, 1);
  bannerRow->addWidget(m_retry);
  root->addLayout(bannerRow);
  // The straps as the movement shows them (docs/gui.md, "Live session").
  m_straps = new QLabel(this);
  m_straps->setWordWrap(true);
  m_straps->setTextInteractionFlags(Qt::TextSelectableByKeyboard | Qt::TextSelectableByMouse);
  m_straps->setFocusPolicy(Qt::TabFocus);
  m_straps->hide();
  root->addWidget(m_straps);
  // The trunk limit's cue, across the screen while the patient leans past it.
  m_trunk = std::make_unique<LiveTrunkFeedback>(m_config.trunkLimitDeg, this);
  root->addWidget(m_trunk->cueLabel());
  connect(m_retry, &QPushButton::clicked, this, &LiveSessionScreen::start);

  // Body: 3D arm and readouts | plots; below: health, repetitions, messages.
  auto* vertical = new QSplitter(Qt::Vertical, this);
  auto* top = new QSplitter(Qt::Horizontal, vertical);
  auto* left = new QWidget(top);
  auto* leftLayout = new QVBoxLayout(left);
  leftLayout->setContentsMargins(0, 0, 0, 0);
  m_arm = new ui::ArmView(left);
  m_arm->setMinimumSize(160, 120);
  m_arm->setArm(m_config.meta.geometry, m_config.meta.side, m_config.meta.up, m_config.meta.camera);
  m_arm->setSternumImu(drawnSternum(m_config));
  m_readouts = new ui::AngleReadouts(left);
  m_readouts->setColumns(3);
  leftLayout->addWidget(m_arm, 3);
  leftLayout->addWidget(m_readouts, 0);
  leftLayout->addWidget(m_trunk->anglesLabel(), 0);
  m_plots = new ui::AnglePlotPanel(top);
  m_plots->setWindowSeconds(m_config.windowSeconds);
  if (m_config.targetDeg)
    m_plots->setTarget(repetitionAngle(m_config.primaryAngle), m_config.targetDeg->first,
                       m_config.targetDeg->second);
  top->setStretchFactor(0, 2);
  top->setStretchFactor(1, 3);

  auto* bottom = new QWidget(vertical);
  auto* bottomLayout = new QHBoxLayout(bottom);
  bottomLayout->setContentsMargins(0, 0, 0, 0);
  m_health = new ui::DeviceHealthPanel(bottom);
  m_reps = new ui::RepetitionCounterWidget(bottom);
  m_reps->setTarget(m_config.targetRepetitions);
  m_reps->setAngleName(ui::angleDisplayName(repetitionAngle(m_config.primaryAngle)));
  m_messages = new QListWidget(bottom);
  m_messages->setWordWrap(true);
  auto* repsColumn = new QVBoxLayout;
  repsColumn->setContentsMargins(0, 0, 0, 0);
  repsColumn->addWidget(m_reps, 1);
  repsColumn->addWidget(m_trunk->countLabel(), 0);
  bottomLayout->addWidget(m_health, 3);
  bottomLayout->addLayout(repsColumn, 1);
  bottomLayout->addWidget(m_messages, 3);
  vertical->setStretchFactor(0, 4);
  vertical->setStretchFactor(1, 1);
  root->addWidget(vertical, 1);

  connect(m_record, &QPushButton::clicked, this, &LiveSessionScreen::record);
  connect(m_pause, &QPushButton::clicked, this, &LiveSessionScreen::pause);
  connect(m_stop, &QPushButton::clicked, this, &LiveSessionScreen::stop);
  connect(m_mark, &QPushButton::clicked, this, &LiveSessionScreen::markEvent);

  // Keyboard order: controls, then the views.
  setTabOrder(m_record, m_pause);
  setTabOrder(m_pause, m_stop);
  setTabOrder(m_stop, m_eventLabel);
  setTabOrder(m_eventLabel, m_mark);
  setTabOrder(m_mark, m_arm);
  setTabOrder(m_arm, m_plots->tableView());
  setTabOrder(m_plots->tableView(), m_health->view());
  setTabOrder(m_health->view(), m_messages);
  setTabOrder(m_messages, m_straps);
}

void LiveSessionScreen::retranslateUi() {
  setAccessibleName(tr("Live session"));
  setWindowTitle(m_config.patientLabel.isEmpty()
                     ? tr("Live session")
                     : tr("Live session: %1").arg(m_config.patientLabel));
  const QString side = m_config.meta.side == Side::Left ? tr("left arm") : tr("right arm");
  m_title->setText(m_config.patientLabel.isEmpty()
                       ? tr("Live session, %1").arg(side)
                       : tr("%1 \u2014 %2").arg(m_config.patientLabel, side));
  m_status->setAccessibleName(tr("Session status"));
  const auto shortcut = [](const QPushButton* b) {
    return b->shortcut().toString(QKeySequence::NativeText);
  };
  ui::setButtonText(m_record, tr("&Record"));
  ui::setButtonText(m_pause, tr("&Pause"));
  m_pause->setToolTip(tr("Pause recording; the live view goes on (%1)").arg(shortcut(m_pause)));
  ui::setButtonText(m_stop, tr("S&top"));
  m_stop->setToolTip(tr("End the session (%1)").arg(shortcut(m_stop)));
  // The event labels offered (a label typed by hand stays as typed).
  const QString typed = m_eventLabel->currentIndex() < 0 ? m_eventLabel->currentText() : QString();
  const QStringList events = {tr("Pain"), tr("Rest"), tr("Fatigue"), tr("Compensation"),
                              tr("Note")};
  for (int i = 0; i < events.size(); ++i) m_eventLabel->setItemText(i, events[i]);
  if (!typed.isEmpty()) m_eventLabel->setEditText(typed);
  m_eventLabel->setAccessibleName(tr("Event label"));
  ui::setButtonText(m_mark, tr("&Mark event"));
  m_mark->setToolTip(tr("Mark the chosen event at the current time (%1)").arg(shortcut(m_mark)));
  for (QPushButton* b : {m_record, m_pause, m_stop, m_mark})
    b->setAccessibleName(b->text().remove(u'&'));
  m_banner->setAccessibleName(tr("Problem"));
  if (m_bannerText) m_banner->setText(m_bannerText());
  m_retry->setText(tr("Try &again"));
  m_messages->setAccessibleName(tr("Session messages"));
  m_straps->setAccessibleName(tr("Straps"));
  updateStraps();
  m_reps->setAngleName(ui::angleDisplayName(repetitionAngle(m_config.primaryAngle)));
  m_trunk->retranslate();
  updateButtons();
  updateStatus();
}

void LiveSessionScreen::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  QWidget::changeEvent(event);
}

void LiveSessionScreen::setDrainRate(double hz) {
  m_drainHz = std::isfinite(hz) && hz > 0 ? std::clamp(hz, 1.0, 120.0) : 40.0;
  m_drainTimer.setInterval(static_cast<int>(std::lround(1000.0 / m_drainHz)));
}

void LiveSessionScreen::start() {
  if (m_state == State::Starting || m_state == State::Live || m_state == State::Recording ||
      m_state == State::Paused || m_state == State::Stopping)
    return;
  showBanner({}, false);
  m_retry->hide();
  m_plots->clear();
  m_health->clear();
  m_counter.reset();
  m_trunk->reset();
  m_events.clear();
  m_sessionTime = 0;
  m_recordedSeconds = 0;
  m_recordingSince = -1;
  m_firstRecordingS = std::numeric_limits<double>::quiet_NaN();
  m_begun = false;
  m_beginning = false;
  setState(State::Starting);
  if (m_gate) m_gate->setRecording(false);
  m_controller->start(m_config, m_gate);
}

void LiveSessionScreen::onStarted(const QString& error) {
  if (!error.isEmpty()) {
    setState(State::Failed);
    showBanner([error] { return tr("Could not start the session: %1").arg(error); }, true);
    m_retry->show();
    addMessage(error);
    emit sessionFailed(error);
    return;
  }
  setState(State::Live);
  m_drainTimer.start();
  addMessage(tr("Session started"));
  emit sessionStarted();
  if (m_config.recordFromStart && m_target) record();
}

void LiveSessionScreen::record() {
  if (!m_gate || (m_state != State::Live && m_state != State::Paused)) return;
  if (m_begun) {
    addMessage(tr("Recording resumed at %L1 s").arg(m_sessionTime, 0, 'f', 1));
    openGate();
    return;
  }
  if (m_beginning) return;
  const auto layout = m_controller->recordingLayout();
  if (!layout) return;
  // The target begins (the records: the session's row) without the GUI thread waiting; rows
  // flow once it has.
  m_beginning = true;
  updateButtons();
  m_target->beginAsync(layout->first, layout->second, this, [this](const QString& why) {
    m_beginning = false;
    if (!why.isEmpty()) {
      showBanner([why] { return why; }, true);
      addMessage(why);
      updateButtons();
      return;
    }
    m_begun = true;
    if (m_state != State::Live && m_state != State::Paused) {
      // Stopped while it began: close what was begun, with nothing in it.
      m_target->finishAsync(0, false, {}, this, [this](const QString& line) { addMessage(line); });
      return;
    }
    addMessage(tr("Recording to %1").arg(m_target->describe()));
    openGate();
  });
}

void LiveSessionScreen::openGate() {
  m_gate->setRecording(true);
  m_recordingSince = m_sessionTime;
  if (!std::isfinite(m_firstRecordingS)) m_firstRecordingS = m_sessionTime;
  setState(State::Recording);
}

void LiveSessionScreen::pause() {
  if (!m_gate || m_state != State::Recording) return;
  m_gate->setRecording(false);
  m_recordedSeconds += m_sessionTime - m_recordingSince;
  m_recordingSince = -1;
  addMessage(tr("Recording paused at %L1 s").arg(m_sessionTime, 0, 'f', 1));
  setState(State::Paused);
}

void LiveSessionScreen::stop() {
  if (m_state != State::Live && m_state != State::Recording && m_state != State::Paused &&
      m_state != State::Starting)
    return;
  drain();             // what has arrived so far
  m_plots->refresh();  // the table too (live, it is refreshed a few times a second)
  if (m_gate) m_gate->setRecording(false);
  if (m_recordingSince >= 0) m_recordedSeconds += m_sessionTime - m_recordingSince;
  m_recordingSince = -1;
  m_drainTimer.stop();
  if (const std::shared_ptr<session::Session>& s = m_controller->session()) {
    m_strapsStatus = s->movementCalibration();  // the last word on the straps
    updateStraps();
  }
  setState(State::Stopping);
  m_controller->stop();
}

void LiveSessionScreen::onStopped(quint64 recordedRows, quint64 rowsToRecord,
                                  const QString& recorderError) {
  if (!m_target || !m_begun) return finishStopping(tr("Session ended; nothing was recorded."));
  // The events in recording time, from the first recorded row, as the review and the report
  // show times (core/metrics/SessionTime.h); one "[m:ss.s] label" line each.
  QStringList events;
  const double first = m_gate->firstRecordedS();
  for (const auto& [t, label] : m_events)
    events << QString::fromStdString(eventLine(
        {recordingTime(t, std::isfinite(first) ? first : m_firstRecordingS), label.toStdString()}));
  // Rows the gate dropped while paused were never meant for the recording.
  const bool complete = recorderError.isEmpty() && recordedRows + m_gate->skipped() == rowsToRecord;
  // The trunk limit's count stays with the session, after its events.
  if (const QString trunk = m_trunk->notesLine(); !trunk.isEmpty()) events << trunk;
  m_target->finishAsync(
      recordedRows, complete, events.join(u'\n'), this, [this, recorderError](const QString& line) {
        QString summary = line;
        if (!recorderError.isEmpty())
          summary += QStringLiteral(" ") + tr("Last recording problem: %1").arg(recorderError);
        finishStopping(summary);
      });
}

void LiveSessionScreen::finishStopping(const QString& summary) {
  addMessage(summary);
  setState(State::Stopped);
  emit sessionStopped(summary);
}

void LiveSessionScreen::markEvent() {
  if (m_state != State::Live && m_state != State::Recording && m_state != State::Paused) return;
  QString label = m_eventLabel->currentText().trimmed();
  if (label.isEmpty()) label = tr("Event");
  m_events.emplace_back(m_sessionTime, label);
  m_plots->addEvent(m_sessionTime, label);
  addMessage(tr("%1 marked at %L2 s").arg(label).arg(m_sessionTime, 0, 'f', 1));
}

void LiveSessionScreen::drain() {
  QElapsedTimer clock;
  clock.start();
  double mark = 0;
  const auto lap = [&](double& longest) {
    const double now = static_cast<double>(clock.nsecsElapsed()) * 1e-6;
    longest = std::max(longest, now - mark);
    mark = now;
  };
  if (!m_controller->drainInto(m_rows, m_sessionEvents)) return;
  const std::shared_ptr<session::Session>& s = m_controller->session();
  ++m_drains;
  lap(m_times.takeMs);
  m_times.mostRows = std::max(m_times.mostRows, m_rows.size());
  showEstimates(m_rows);
  for (const std::string& e : m_sessionEvents)
    addMessage(ui::sessionEventText(QString::fromStdString(e)));
  lap(m_times.feedMs);
  m_plots->refreshIfChanged();
  lap(m_times.plotsMs);
  m_arm->updateIfChanged();
  lap(m_times.armMs);
  if (m_drains % kStatsEveryTicks == 0) {
    m_readouts->refreshIfChanged();
    m_health->setStats(s->stats());
    if (m_gate && m_state == State::Recording && !m_gate->recording()) {
      // The recording could not be opened: say why; the session goes on.
      const QString why = m_gate->openError();
      showBanner([why] { return tr("Recording stopped: %1").arg(why); }, true);
      m_recordedSeconds += m_sessionTime - m_recordingSince;
      m_recordingSince = -1;
      setState(State::Paused);
    }
    updateStatus();
    m_strapsStatus = s->movementCalibration();
    updateStraps();
    lap(m_times.statsMs);
  }
  m_times.wholeMs = std::max(m_times.wholeMs, static_cast<double>(clock.nsecsElapsed()) * 1e-6);
}

void LiveSessionScreen::showEstimates(const std::vector<session::EstimateRow>& rows) {
  if (rows.empty()) return;
  m_estimates += rows.size();
  m_samples.clear();
  m_samples.reserve(rows.size());
  const int primary = m_counter.primaryAngle();
  for (const session::EstimateRow& r : rows) {
    m_samples.push_back(ui::angleSample(r));
    m_trunk->add(r);
    m_counter.add(r.t, m_samples.back().deg[static_cast<std::size_t>(primary)] * kDegToRad);
    m_trunk->judgeRepetitions(m_counter);
    if (r.opticalElbow) m_marks.elbow = r.opticalElbow;
    if (r.opticalWrist) m_marks.wrist = r.opticalWrist;
    if (r.camElbow) m_marks.camElbow = r.camElbow;
    if (r.camWrist) m_marks.camWrist = r.camWrist;
    if (r.opticalElbow || r.opticalWrist || r.camElbow || r.camWrist) m_lastOptical = r.t;
  }
  const session::EstimateRow& last = rows.back();
  m_sessionTime = last.t;
  if (m_sessionTime - m_lastOptical > kOpticalShownSeconds) m_marks = {};
  m_plots->append(m_samples);
  m_arm->setPose(last.th);
  m_arm->setTrunk(last.trunk);  // the sternum sensor's estimate; none: upright
  m_arm->setOptical(m_marks);
  m_reps->showCount(m_counter);
  m_trunk->refresh();
}

void LiveSessionScreen::showBanner(std::function<QString()> text, bool error) {
  m_bannerText = std::move(text);
  const QString shown = m_bannerText ? m_bannerText() : QString();
  m_banner->setText(shown);
  m_banner->setVisible(!shown.isEmpty());
  QPalette p = palette();
  const bool dark = p.color(QPalette::Window).lightness() < 128;
  if (error) {
    p.setColor(QPalette::Window, dark ? QColor(0x5a, 0x1f, 0x1f) : QColor(0xfd, 0xe2, 0xe2));
    p.setColor(QPalette::WindowText, dark ? QColor(0xff, 0xe0, 0xe0) : QColor(0x6b, 0x0c, 0x0c));
  }
  m_banner->setPalette(p);
}

QString LiveSessionScreen::bannerText() const {
  return m_banner->isVisible() ? m_banner->text() : QString();
}

void LiveSessionScreen::addMessage(const QString& text) {
  m_messages->insertItem(0, QStringLiteral("[%1] %2").arg(clock(m_sessionTime), text));
  while (m_messages->count() > kMaxMessages) delete m_messages->takeItem(m_messages->count() - 1);
}

void LiveSessionScreen::setState(State s) {
  if (m_state == s) return;
  m_state = s;
  updateButtons();
  updateStatus();
  emit stateChanged(s);
}

void LiveSessionScreen::updateButtons() {
  const bool running =
      m_state == State::Live || m_state == State::Recording || m_state == State::Paused;
  const bool canRecord =
      m_gate && !m_beginning && (m_state == State::Live || m_state == State::Paused);
  m_record->setEnabled(canRecord);
  m_record->setToolTip(m_gate ? tr("Start or resume recording to %1 (%2)")
                                    .arg(m_target->describe(),
                                         m_record->shortcut().toString(QKeySequence::NativeText))
                              : tr("This session is not recorded"));
  m_pause->setEnabled(m_gate && m_state == State::Recording);
  m_stop->setEnabled(running || m_state == State::Starting);
  m_mark->setEnabled(running);
}

void LiveSessionScreen::updateStraps() {
  const QString line = strapsLine(m_strapsStatus);
  if (line != m_straps->text()) m_straps->setText(line);
  m_straps->setVisible(!line.isEmpty());
}

void LiveSessionScreen::updateStatus() {
  QString text;
  switch (m_state) {
    case State::Idle:
      text = tr("Not started");
      break;
    case State::Starting:
      text = tr("Starting\u2026");
      break;
    case State::Live:
      text = tr("Live %1 (not recording)").arg(clock(m_sessionTime));
      break;
    case State::Recording:
      text = tr("\u25cf Recording %1")
                 .arg(clock(m_recordedSeconds + m_sessionTime - m_recordingSince));
      break;
    case State::Paused:
      text = tr("Paused (%1 recorded)").arg(clock(m_recordedSeconds));
      break;
    case State::Stopping:
      text = tr("Stopping\u2026");
      break;
    case State::Stopped:
      text = tr("Ended");
      break;
    case State::Failed:
      text = tr("Not running");
      break;
  }
  m_status->setText(text);
}

}  // namespace armtrack::app::gui
