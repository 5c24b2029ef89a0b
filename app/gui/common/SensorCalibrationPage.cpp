#include "app/gui/common/SensorCalibrationPage.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QThread>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "app/gui/common/CalibrationGuide.h"
#include "app/gui/services/RecordsService.h"
#include "core/metrics/RangeOfMotion.h"
#include "ui/ArmView.h"
#include "ui/Fonts.h"

namespace armtrack::app::gui {

namespace {
constexpr double kGoodRms = 1.5, kUsableRms = 3.0;

QString fixed(double v, int decimals = 2) {
  return QLocale().toString(v, 'f', decimals);
}
}  // namespace

CalibrationVerdict judgeCalibration(const CalibrationResult& r, QString* why) {
  const std::pair<const char*, double> kinds[] = {
      {QT_TRANSLATE_NOOP("armtrack::app::gui::SensorCalibrationPage", "upper-arm gyroscope"),
       r.rmsUpperGyro},
      {QT_TRANSLATE_NOOP("armtrack::app::gui::SensorCalibrationPage", "upper-arm accelerometer"),
       r.rmsUpperAcc},
      {QT_TRANSLATE_NOOP("armtrack::app::gui::SensorCalibrationPage", "forearm gyroscope"),
       r.rmsForearmGyro},
      {QT_TRANSLATE_NOOP("armtrack::app::gui::SensorCalibrationPage", "forearm accelerometer"),
       r.rmsForearmAcc},
      {QT_TRANSLATE_NOOP("armtrack::app::gui::SensorCalibrationPage", "optical positions"),
       r.rmsPosition}};
  const auto tr = [](const char* text) { return SensorCalibrationPage::tr(text); };
  double worst = 0;
  QString worstKind;
  for (const auto& [kind, rms] : kinds) {
    if (!std::isfinite(rms)) {
      worst = std::numeric_limits<double>::infinity();
      worstKind = tr(kind);
    } else if (rms > worst) {
      worst = rms;
      worstKind = tr(kind);
    }
  }
  QString text;
  CalibrationVerdict v = CalibrationVerdict::Good;
  if (!r.converged) {
    v = CalibrationVerdict::Poor;
    text = r.calibration.trunk
               ? SensorCalibrationPage::tr(
                     "The fit did not settle. Check that all three sensors "
                     "are strapped tight, then redo the protocol.")
               : SensorCalibrationPage::tr(
                     "The fit did not settle. Check that both sensors are strapped tight, then "
                     "redo the protocol.");
  } else if (worst > kUsableRms) {
    v = CalibrationVerdict::Poor;
    text = SensorCalibrationPage::tr(
               "The movements do not fit the arm model well (%1 off by %2 noise levels). Check "
               "the straps and the start pose, then redo the protocol.")
               .arg(worstKind, fixed(worst, 1));
  } else if (worst > kGoodRms || !r.warnings.empty()) {
    v = CalibrationVerdict::Usable;
    text = SensorCalibrationPage::tr("Usable, not perfect (worst: %1 at %2 noise levels).")
               .arg(worstKind, fixed(worst, 1));
    for (const std::string& w : r.warnings) text += QLatin1Char(' ') + QString::fromStdString(w);
    text += QLatin1Char(' ') + SensorCalibrationPage::tr("Redo the protocol for a better one.");
  } else {
    text = SensorCalibrationPage::tr(
               "Good: the data fit the arm model to the sensors' noise level (worst: %1 at %2).")
               .arg(worstKind, fixed(worst, 2));
  }
  if (why) *why = text;
  return v;
}

namespace {
// The verdict in the patient's words.
QString patientVerdict(CalibrationVerdict v) {
  switch (v) {
    case CalibrationVerdict::Good:
      return SensorCalibrationPage::tr("Done: the calibration is good.");
    case CalibrationVerdict::Usable:
      return SensorCalibrationPage::tr(
          "Done: the calibration can be used. If you have a minute, press Redo for a better "
          "one.");
    case CalibrationVerdict::Poor:
      break;
  }
  return SensorCalibrationPage::tr(
      "That did not work this time. Check that both straps are tight, then press Redo and "
      "follow the screen again, or go on without it.");
}
}  // namespace

SensorCalibrationPage::SensorCalibrationPage(const PluginRegistry& registry,
                                             LiveSessionConfig config, std::filesystem::path folder,
                                             QWidget* parent)
    : QWidget(parent),
      m_registry(registry),
      m_config(std::move(config)),
      m_folder(std::move(folder)),
      m_controller(new SessionController(registry, this)) {
  auto* root = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  m_title = new QLabel(this);
  ui::setScaledFont(m_title, 1.6);
  m_instruction = new QLabel(this);
  m_instruction->setWordWrap(true);
  m_countdown = new QLabel(this);
  ui::setScaledFont(m_countdown, 2.4);
  m_progress = new QProgressBar(this);
  m_progress->setRange(0, 1000);
  auto* buttons = new QHBoxLayout;
  m_start = new QPushButton(this);
  m_cancel = new QPushButton(this);
  buttons->addWidget(m_start);
  buttons->addWidget(m_cancel);
  buttons->addStretch(1);
  m_verdictLabel = new QLabel(this);
  m_verdictLabel->setWordWrap(true);
  m_details = new QPlainTextEdit(this);
  m_details->setReadOnly(true);
  left->addWidget(m_title);
  left->addWidget(m_instruction);
  left->addWidget(m_countdown);
  left->addWidget(m_progress);
  left->addLayout(buttons);
  left->addWidget(m_verdictLabel);
  left->addWidget(m_details, 1);
  root->addLayout(left, 2);
  m_arm = new ui::ArmView(this);
  m_arm->setMinimumSize(200, 200);
  m_arm->setArm(m_config.meta.geometry, m_config.meta.side, m_config.meta.up);
  m_arm->setSternumImu(drawnSternum(m_config));
  m_arm->setRefreshRate(0);
  root->addWidget(m_arm, 3);

  connect(m_start, &QPushButton::clicked, this, &SensorCalibrationPage::start);
  connect(m_cancel, &QPushButton::clicked, this, &SensorCalibrationPage::cancel);
  connect(m_controller, &SessionController::started, this, [this](const QString& error) {
    if (m_state != State::Recording) return;
    if (!error.isEmpty()) {
      showVerdict([error] { return tr("The devices could not start: %1").arg(error); });
      setState(State::Failed);
      emit finished(false);
      return;
    }
    m_timer.start(50);
  });
  connect(m_controller, &SessionController::stopped, this,
          [this](quint64 rows, quint64, const QString& error) {
            if (m_state != State::Recording) return;  // cancelled
            if (!error.isEmpty() || rows == 0) {
              showVerdict([error] {
                return tr("The protocol could not be recorded: %1")
                    .arg(error.isEmpty() ? tr("no data arrived") : error);
              });
              setState(State::Failed);
              emit finished(false);
              return;
            }
            solve();
          });
  connect(m_controller, &SessionController::busyChanged, this,
          &SensorCalibrationPage::updateStartButton);
  connect(&m_timer, &QTimer::timeout, this, &SensorCalibrationPage::drain);
  // With a sternum sensor its mounting is calibrated too (from the upright start pose).
  const bool sternum = hasSternumSensor(m_config.devices);
  showStep([] { return tr("Sensor calibration"); },
           [sternum] {
             return sternum ? tr("The patient sits upright with all three sensors (upper arm, "
                                 "forearm and chest) strapped on. Press Start, then follow the "
                                 "instructions on the screen for about a minute.")
                            : tr("The patient sits upright with both sensors strapped on. Press "
                                 "Start, then follow the instructions on the screen for about a "
                                 "minute.");
           });
  setState(State::Ready);
  retranslateUi();
}

void SensorCalibrationPage::retranslateUi() {
  setAccessibleName(tr("Sensor calibration"));
  m_instruction->setAccessibleName(tr("Instruction"));
  m_countdown->setAccessibleName(tr("Time left in this step"));
  m_progress->setAccessibleName(tr("Protocol progress"));
  m_verdictLabel->setAccessibleName(tr("Calibration verdict"));
  m_details->setAccessibleName(tr("Calibration details"));
  m_start->setText(m_state == State::Ready ? tr("&Start") : tr("&Redo"));
  m_cancel->setText(tr("C&ancel"));
  if (m_titleText) m_title->setText(m_titleText());
  if (m_instructionText) m_instruction->setText(m_instructionText());
  if (m_verdictText) m_verdictLabel->setText(m_verdictText());
}

void SensorCalibrationPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  QWidget::changeEvent(event);
}

void SensorCalibrationPage::showStep(Text title, Text instruction) {
  m_titleText = std::move(title);
  if (instruction) m_instructionText = std::move(instruction);
  m_title->setText(m_titleText());
  m_instruction->setText(m_instructionText ? m_instructionText() : QString());
}

void SensorCalibrationPage::showVerdict(Text verdict) {
  m_verdictText = std::move(verdict);
  m_verdictLabel->setText(m_verdictText ? m_verdictText() : QString());
}

QString SensorCalibrationPage::verdictText() const {
  return m_verdictLabel->text();
}

void SensorCalibrationPage::setIntroduction(std::function<QString()> text) {
  if (m_state != State::Ready || !text) return;
  m_instructionText = std::move(text);
  m_instruction->setText(m_instructionText());
}

QString SensorCalibrationPage::instructionTitle() const {
  return m_title->text();
}

QString SensorCalibrationPage::instructionText() const {
  return m_instruction->text();
}

bool SensorCalibrationPage::isComplete() const {
  return m_state == State::Done && m_verdict && *m_verdict != CalibrationVerdict::Poor;
}

void SensorCalibrationPage::setForPatient(bool forPatient) {
  m_forPatient = forPatient;
  m_details->setVisible(!forPatient);
}

QString SensorCalibrationPage::detailsText() const {
  return m_details->isVisible() ? m_details->toPlainText() : QString();
}

void SensorCalibrationPage::setState(State s) {
  m_state = s;
  if (s != State::Solving) m_progress->setRange(0, 1000);
  if (s == State::Done) m_progress->setValue(1000);
  updateStartButton();
  m_start->setText(s == State::Ready ? tr("&Start") : tr("&Redo"));
  m_cancel->setEnabled(s == State::Recording || s == State::Solving);
  emit completeChanged();
}

void SensorCalibrationPage::updateStartButton() {
  // Off while a cancelled recording still holds the devices (well under a second): a start then
  // would be refused.
  m_start->setEnabled(
      (m_state == State::Ready || m_state == State::Done || m_state == State::Failed) &&
      !m_controller->busy());
}

void SensorCalibrationPage::start() {
  if (m_state == State::Recording || m_state == State::Solving) return;
  ++m_generation;
  m_result.reset();
  m_verdict.reset();
  showVerdict({});
  m_details->clear();
  const QString stamp = QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"));
  m_csv = m_folder /
          ("calibration-" + stamp.toStdString() + "-" + std::to_string(m_generation) + ".csv");
  m_gate = std::make_shared<RecordingGate>(std::make_shared<CsvRecordingTarget>(m_csv));
  m_gate->setRecording(true);  // from the first row: the start pose is held from the start
  setState(State::Recording);
  showStep([] { return tr("Starting the sensors\u2026"); }, {});
  // The protocol calibrates the straps itself: no fit from the movement meanwhile.
  LiveSessionConfig config = m_config;
  config.movementCalibration.enabled = false;
  m_controller->start(config, m_gate);
}

void SensorCalibrationPage::drain() {
  std::vector<std::string> events;
  if (!m_controller->drainInto(m_rows, events) || m_rows.empty()) return;
  const double t = m_rows.back().t;
  const CalibrationPhase& phase = phaseAt(t);  // one of calibrationPhases(), which stay
  if (m_title->text() != phase.shownTitle() || m_instruction->text() != phase.shownInstruction())
    showStep([&phase] { return phase.shownTitle(); },
             [&phase] { return phase.shownInstruction(); });
  const int left = static_cast<int>(std::ceil(std::max(0.0, phase.endS - t)));
  m_countdown->setText(phase.hold ? tr("Hold still: %n s", nullptr, left)
                                  : tr("Move: %n s", nullptr, left));
  m_progress->setValue(static_cast<int>(1000 * std::clamp(t / protocolSeconds(), 0.0, 1.0)));
  m_arm->setPose(m_rows.back().th);
  if (phase.poseDeg) {
    JointVector target;
    for (int j = 0; j < kNumJoints; ++j) target(j) = (*phase.poseDeg)[j] * kDegToRad;
    m_arm->setTargetPose(target);
  } else {
    m_arm->setTargetPose(std::nullopt);
  }
  m_arm->updateIfChanged();
  if (t >= protocolSeconds() + 0.3) {
    m_timer.stop();
    if (m_forPatient)
      showStep([] { return tr("Recorded"); }, [] { return tr("You can relax."); });
    else
      showStep([] { return tr("Recorded"); }, [] { return tr("The patient can relax."); });
    m_countdown->clear();
    m_controller->stop();  // solve() follows when the recording is closed
  }
}

void SensorCalibrationPage::solve() {
  setState(State::Solving);
  if (m_forPatient) {
    showStep([] { return tr("Calibrating\u2026"); },
             [] {
               return tr(
                   "You can relax. ArmTrack is working this out; it takes a few "
                   "seconds.");
             });
    m_progress->setRange(0, 0);  // busy, without the fit's figures
  } else {
    showStep([] { return tr("Calibrating\u2026"); }, {});
  }
  m_details->appendPlainText(
      tr("Fitting the sensors' mounting to the recording (this takes a "
         "few seconds)."));
  const int generation = m_generation;
  const std::filesystem::path csv = m_csv;
  QPointer<SensorCalibrationPage> self(this);
  auto report = [self, generation](const QString& line, bool done,
                                   std::optional<CalibrationResult> result, const QString& error) {
    QMetaObject::invokeMethod(qApp, [=] {
      if (!self || self->m_generation != generation) return;
      if (!line.isEmpty()) self->m_details->appendPlainText(line);
      if (!done) return;
      if (!result) {
        if (self->m_forPatient)
          self->showVerdict([] { return patientVerdict(CalibrationVerdict::Poor); });
        else
          self->showVerdict(
              [error] { return tr("The calibration failed: %1. Redo the protocol.").arg(error); });
        self->setState(State::Failed);
        emit self->finished(false);
        return;
      }
      self->m_verdict = judgeCalibration(*result, nullptr);
      self->m_result = result;
      if (self->m_forPatient)
        self->showVerdict([v = *self->m_verdict] { return patientVerdict(v); });
      else
        self->showVerdict([result] {
          QString why;
          judgeCalibration(*result, &why);
          return why;
        });
      const Calibration& c = result->calibration;
      self->m_details->appendPlainText(
          tr("Upper-arm strap angle %1 deg, forearm strap angle %2 deg; residuals (noise "
             "levels): upper gyro %3, upper acc %4, forearm gyro %5, forearm acc %6, optical "
             "%7; %8 iterations.")
              .arg(fixed(c.geometry.thu4 * kRadToDeg), fixed(c.geometry.thf7 * kRadToDeg),
                   fixed(result->rmsUpperGyro), fixed(result->rmsUpperAcc),
                   fixed(result->rmsForearmGyro), fixed(result->rmsForearmAcc),
                   fixed(result->rmsPosition))
              .arg(result->iterations));
      if (c.trunk)
        self->m_details->appendPlainText(
            tr("Chest (sternum) sensor: its tilt is taken from the upright start pose; its "
               "heading about the vertical is kept as assumed."));
      self->showStep([] { return tr("Calibration done"); }, {});
      self->setState(State::Done);
      emit self->finished(*self->m_verdict != CalibrationVerdict::Poor);
    });
  };
  QThread* worker = QThread::create([csv, report] {
    try {
      const Recording rec = readRecording(csv);
      CalibrationResult r = calibrate(rec, CalibrationOptions{}, [&](const std::string& line) {
        report(QString::fromStdString(line), false, std::nullopt, {});
      });
      report({}, true, std::move(r), {});
    } catch (const std::exception& e) {
      report({}, true, std::nullopt,
             armtrack::gui::withoutSourceReferences(QString::fromStdString(e.what())));
    }
  });
  worker->setObjectName(QStringLiteral("armtrack-calibrate"));
  connect(worker, &QThread::finished, worker, &QObject::deleteLater);
  worker->start(QThread::LowPriority);
}

void SensorCalibrationPage::cancel() {
  if (m_state == State::Recording) {
    m_timer.stop();
    setState(State::Ready);  // the stopped() that follows is ignored
    m_controller->stop();
  } else if (m_state == State::Solving) {
    ++m_generation;  // the fit's result will be ignored
    setState(State::Ready);
  }
  showStep([] { return tr("Sensor calibration"); },
           [] { return tr("Cancelled. Press Start to begin the protocol again."); });
  m_countdown->clear();
  m_arm->setTargetPose(std::nullopt);
}

}  // namespace armtrack::app::gui
