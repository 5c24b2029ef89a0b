#include "app/gui/home/SensorCheckScreen.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>
#include <cmath>

#include "app/gui/home/HomeStyle.h"
#include "app/gui/home/StrapPicture.h"
#include "core/simulation/Trajectory.h"
#include "ui/ArmView.h"
#include "ui/Retranslate.h"

namespace armtrack::gui::home {

namespace {
constexpr double kEndMarginS = 0.5;  // recorded past the movement's end
}

SensorCheckScreen::SensorCheckScreen(const app::PluginRegistry& registry,
                                     app::gui::LiveSessionConfig config,
                                     std::filesystem::path folder, QWidget* parent)
    : HomeScreen(parent),
      m_registry(registry),
      m_config(std::move(config)),
      m_folder(std::move(folder)),
      m_controller(new app::gui::SessionController(registry, this)),
      m_judge(new SensorCheckJob(this)) {
  auto* root = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  m_title = heading({}, this);
  m_text = bodyText({}, this);
  m_banner = bodyText({}, this);
  m_banner->hide();
  m_picture = new StrapPicture(this);
  m_picture->setSide(m_config.meta.side);
  m_start = bigButton(tr("&Start the check"), this, true);
  m_goOn = bigButton(tr("&Go on"), this, true);
  m_skip = bigButton(tr("S&kip the check"), this);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_start, 2);
  buttons->addWidget(m_goOn, 2);
  buttons->addWidget(m_skip, 1);
  left->addWidget(m_title);
  left->addWidget(m_text);
  left->addWidget(m_banner);
  left->addWidget(m_picture, 3);
  left->addStretch(1);  // takes the room while the picture is hidden
  left->addLayout(buttons);
  root->addLayout(left, 3);
  m_arm = new ui::ArmView(this);
  m_arm->setMinimumSize(240, 240);
  m_arm->setArm(m_config.meta.geometry, m_config.meta.side, m_config.meta.up);
  m_arm->setSternumImu(app::gui::drawnSternum(m_config));
  m_arm->setRefreshRate(0);
  m_arm->setPose(JointVector::Zero());
  root->addWidget(m_arm, 2);

  connect(m_start, &QPushButton::clicked, this, &SensorCheckScreen::start);
  connect(m_goOn, &QPushButton::clicked, this, [this] { emit done(m_state == State::Passed); });
  connect(m_skip, &QPushButton::clicked, this, [this] {
    if (m_state == State::Recording) {
      ++m_generation;
      m_timer.stop();
      m_controller->stop();
    }
    emit done(false);
  });
  connect(m_controller, &app::gui::SessionController::started, this, [this](const QString& e) {
    if (m_state != State::Recording) return;
    if (!e.isEmpty()) {
      m_result.reset();
      setState(State::Problem);
      setBanner(m_banner, tr("The sensors could not be started: %1").arg(e), Tone::Problem);
      return;
    }
    m_timer.start(33);
  });
  connect(m_controller, &app::gui::SessionController::stopped, this,
          [this](quint64 rows, quint64, const QString& error) {
            if (m_state != State::Recording) return;
            if (rows == 0 || !error.isEmpty()) {
              setState(State::Problem);
              setBanner(m_banner,
                        tr("The check could not be recorded: %1")
                            .arg(error.isEmpty() ? tr("no data came from the sensors") : error),
                        Tone::Problem);
              return;
            }
            judge();
          });
  connect(&m_timer, &QTimer::timeout, this, &SensorCheckScreen::drain);
  connect(m_judge, &SensorCheckJob::judged, this, &SensorCheckScreen::showResult);
  setState(State::Ready);
  retranslate();
}

void SensorCheckScreen::retranslate() {
  setAccessibleName(tr("Sensor check"));
  m_text->setAccessibleName(tr("Instruction"));
  m_banner->setAccessibleName(tr("Result of the check"));
  if ((m_state == State::Passed || m_state == State::Problem) && m_result)
    showResult(*m_result);
  else if (m_state != State::Recording && m_state != State::Judging)
    setState(m_state);
  // While recording, the next tick says the step again.
}

QString SensorCheckScreen::title() const {
  return m_title->text();
}

QString SensorCheckScreen::message() const {
  QString t = m_text->text();
  if (!m_banner->isHidden()) t += u'\n' + m_banner->text();
  return t;
}

void SensorCheckScreen::setState(State s) {
  m_state = s;
  m_start->setVisible(s == State::Ready || s == State::Problem);
  ui::setButtonText(m_start, s == State::Ready ? tr("&Start the check") : tr("&Check again"));
  m_start->setAccessibleName(QString(m_start->text()).remove(u'&'));
  m_start->setEnabled(s != State::Recording && s != State::Judging);
  m_goOn->setVisible(s == State::Passed || s == State::Problem);
  ui::setButtonText(m_goOn, s == State::Passed ? tr("&Go on") : tr("&Go on anyway"));
  m_goOn->setProperty("primary", s == State::Passed);
  m_goOn->setAccessibleName(QString(m_goOn->text()).remove(u'&'));
  m_goOn->style()->unpolish(m_goOn);
  m_goOn->style()->polish(m_goOn);
  m_skip->setVisible(s == State::Ready || s == State::Recording);
  ui::setButtonText(m_skip, s == State::Recording ? tr("S&top the check") : tr("S&kip the check"));
  m_skip->setAccessibleName(QString(m_skip->text()).remove(u'&'));
  m_picture->setVisible(s != State::Recording && s != State::Judging);
  if (s == State::Ready) {
    m_title->setText(tr("First, a check of the sensors"));
    m_text->setText(
        tr("Strap the upper-arm sensor on your upper arm and the forearm sensor on your "
           "forearm, each with its arrow pointing up towards your shoulder, as in the "
           "picture. Let your arm hang loosely straight down. After Start, keep still for "
           "3 seconds, then bend your elbow up and straighten it again, three times."));
    m_banner->hide();
    m_picture->setFindings({});
  }
  if (QAbstractButton* main = defaultChoice()) main->setFocus(Qt::OtherFocusReason);
  emit choicesChanged();
}

QList<QAbstractButton*> SensorCheckScreen::choices() const {
  return {m_start, m_goOn, m_skip};
}

QAbstractButton* SensorCheckScreen::defaultChoice() const {
  switch (m_state) {
    case State::Ready:
    case State::Problem:
      return m_start;
    case State::Passed:
      return m_goOn;
    case State::Recording:
      return m_skip;
    case State::Judging:
      break;
  }
  return nullptr;
}

void SensorCheckScreen::escapePressed() {
  if (m_state == State::Recording) m_skip->click();
}

void SensorCheckScreen::start() {
  if (m_state == State::Recording || m_state == State::Judging) return;
  ++m_generation;
  m_judge->cancel();
  m_result.reset();
  m_withTrunk = false;
  m_banner->hide();
  m_csv = m_folder /
          ("check-" +
           QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")).toStdString() +
           "-" + std::to_string(m_generation) + ".csv");
  m_gate = std::make_shared<app::gui::RecordingGate>(
      std::make_shared<app::gui::CsvRecordingTarget>(m_csv));
  m_gate->setRecording(true);
  setState(State::Recording);
  m_title->setText(tr("Starting the sensors\u2026"));
  m_text->setText(tr("Let your arm hang loosely straight down."));
  // A check of a few seconds: no fit of the straps from the movement.
  app::gui::LiveSessionConfig config = m_config;
  config.movementCalibration.enabled = false;
  m_controller->start(config, m_gate);
}

void SensorCheckScreen::drain() {
  std::vector<std::string> events;
  if (!m_controller->drainInto(m_rows, events) || m_rows.empty()) return;
  const double t = m_rows.back().t;
  const double rest = SensorCheckTrajectory::restSeconds();
  const double bend = SensorCheckTrajectory::bendSeconds();
  const int bends = SensorCheckTrajectory::bends();
  // With a sternum sensor (its angles in the rows), it is judged from the still start as well.
  m_withTrunk = m_withTrunk || m_rows.back().trunk.has_value();
  if (t < rest) {
    m_title->setText(tr("Keep still: %1").arg(static_cast<int>(std::ceil(rest - t))));
    m_text->setText(m_withTrunk
                        ? tr("Sit upright with your back against the chair, let your arm hang "
                             "loosely straight down, and keep still.")
                        : tr("Let your arm hang loosely straight down, and keep it still."));
  } else if (t < rest + bends * bend) {
    const int n = std::min(bends, static_cast<int>((t - rest) / bend) + 1);
    m_title->setText(tr("Bend your elbow: %1 of %2").arg(n).arg(bends));
    m_text->setText(
        tr("Bend your elbow up as far as is comfortable, then straighten it again. "
           "Keep your upper arm still."));
  } else {
    m_title->setText(tr("Keep still"));
    m_text->setText(tr("Let your arm hang down again."));
  }
  // The translucent arm shows the movement to make.
  static const SensorCheckTrajectory guide;
  m_arm->setTargetPose(guide.at(t).th);
  m_arm->setPose(m_rows.back().th);
  m_arm->setTrunk(m_rows.back().trunk);
  m_arm->updateIfChanged();
  if (t >= SensorCheckTrajectory::duration() + kEndMarginS) {
    m_timer.stop();
    m_controller->stop();  // judge() follows when the recording is closed
  }
}

void SensorCheckScreen::judge() {
  setState(State::Judging);
  m_title->setText(tr("Checking\u2026"));
  m_text->setText(tr("You can relax your arm."));
  SensorCheckParams params;
  params.geometry = m_config.meta.geometry;
  params.side = m_config.meta.side;
  params.up = m_config.meta.up;
  params.g = m_config.meta.g;
  m_judge->start(m_csv, params);
}

void SensorCheckScreen::showResult(const SensorCheckResult& r) {
  m_result = r;
  m_arm->setTargetPose(std::nullopt);
  m_arm->updateIfChanged();
  if (r.ok()) {
    setState(State::Passed);
    m_title->setText(tr("The sensors are right"));
    m_text->setText(std::isfinite(r.trunkAngleDeg)
                        ? tr("All three sensors are on the right places and the right way round.")
                        : tr("Both sensors are on the right places and the right way round."));
    setBanner(m_banner, tr("Well done."), Tone::Good);
    m_picture->setFindings({});
    return;
  }
  setState(State::Problem);
  m_title->setText(r.status == SensorCheckStatus::Judged ? tr("Please change the sensors")
                                                         : tr("Please do the check again"));
  m_text->setText(explain(r));
  setBanner(m_banner,
            r.status == SensorCheckStatus::Judged
                ? tr("Change them as in the picture, then press Check again.")
                : tr("Press Check again when you are ready."),
            Tone::Problem);
  m_picture->setFindings(r.findings);
}

QString SensorCheckScreen::explain(const SensorCheckResult& r) {
  const auto tr = [](const char* s) {
    return QCoreApplication::translate("armtrack::gui::home::SensorCheckScreen", s);
  };
  switch (r.status) {
    case SensorCheckStatus::MissingUpperArm:
      return tr(
          "No data came from the upper-arm sensor. Check that it is switched on and "
          "charged, then press Check again.");
    case SensorCheckStatus::MissingForearm:
      return tr(
          "No data came from the forearm sensor. Check that it is switched on and "
          "charged, then press Check again.");
    case SensorCheckStatus::MissingTrunk:
      return tr(
          "No data came from the chest sensor. Check that it is switched on and charged, "
          "then press Check again.");
    case SensorCheckStatus::NotStill:
      return tr(
          "Your arm was not still at the start. Let it hang loosely and keep it still "
          "until the countdown ends.");
    case SensorCheckStatus::NoMovement:
      return tr(
          "ArmTrack did not see your elbow bend. When asked, bend your elbow up and "
          "straighten it again, three times.");
    case SensorCheckStatus::BothMoved:
      return tr(
          "Both sensors moved the same way. Keep your upper arm still while you bend the "
          "elbow, and check that one sensor is on the upper arm and one on the forearm.");
    case SensorCheckStatus::ImplausibleReadings:
      return tr(
          "A sensor gives readings that do not make sense. Switch it off and on again; "
          "if this happens again, call your therapist.");
    case SensorCheckStatus::Judged:
      break;
  }
  QStringList lines;
  if (r.has(SensorFinding::Swapped))
    lines << tr(
        "The two sensors are swapped: the upper-arm sensor is on your forearm, and the "
        "forearm sensor is on your upper arm. Put each one on the other's place.");
  if (r.has(SensorFinding::UpperArmUpsideDown))
    lines << tr(
        "The sensor on your upper arm is upside down: its arrow points down. Turn it "
        "round so that the arrow points up towards your shoulder.");
  if (r.has(SensorFinding::ForearmUpsideDown))
    lines << tr(
        "The sensor on your forearm is upside down: its arrow points down. Turn it "
        "round so that the arrow points up towards your shoulder.");
  if (r.has(SensorFinding::UpperArmTilted))
    lines << tr(
        "The sensor on your upper arm sits crooked, or your arm was not hanging "
        "straight. Straighten the strap and let your arm hang loosely.");
  if (r.has(SensorFinding::ForearmTilted))
    lines << tr(
        "The sensor on your forearm sits crooked, or your elbow was not straight. "
        "Straighten the strap and let your arm hang loosely.");
  if (r.has(SensorFinding::TrunkUpsideDown))
    lines << tr(
        "The chest sensor seems to be on upside down. Turn it the other way up, as your "
        "therapist showed you, and sit upright.");
  if (r.has(SensorFinding::TrunkTurned))
    lines << tr("The chest sensor seems to be turned: it sits %1\u00b0 off. Put it flat on the "
                "middle of your breastbone, the way your therapist showed you, and sit upright.")
                 .arg(std::lround(r.trunkAngleDeg));
  return lines.join(u'\n');
}

}  // namespace armtrack::gui::home
