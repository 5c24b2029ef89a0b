#include "app/gui/home/ExerciseScreen.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>
#include <cmath>

#include "app/gui/home/ExerciseFraming.h"
#include "app/gui/home/ExerciseRecording.h"
#include "app/gui/home/FeedbackSound.h"
#include "app/gui/home/HomeStyle.h"
#include "app/gui/services/StrapsText.h"
#include "core/kinematics/ClinicalAngles.h"
#include "ui/AngleTableModel.h"
#include "ui/ArmView.h"
#include "ui/Fonts.h"
#include "ui/Retranslate.h"

namespace armtrack::gui::home {

namespace {

constexpr int kSetEndDelayMs = 900;

ExerciseMotion demonstration(const HomeExercise& e) {
  ExerciseMotion m;
  m.angle = e.angle;
  m.fromDeg = e.targetMinDeg;
  m.toDeg = e.targetMaxDeg;
  m.periodSeconds = 4.0;
  m.pauseSeconds = 1.0;
  m.startSeconds = 0.5;
  return m;
}

}  // namespace

ExerciseScreen::ExerciseScreen(const app::PluginRegistry& registry, RecordsService& records,
                               const HomeExercise& exercise, int index, int count,
                               const QString& patientCode,
                               const app::gui::LiveSessionConfig& config, bool optical,
                               FeedbackSound* sound, QWidget* parent)
    : HomeScreen(parent),
      m_exercise(exercise),
      m_index(index),
      m_count(count),
      m_optical(optical),
      m_sound(sound),
      m_config(config),
      m_recording(
          new ExerciseRecording(registry, records, patientCode, exercise.protocol.name, this)),
      m_demo(demonstration(exercise)),
      m_trust(exercise.angle) {
  m_measured = !(angleNeedsOptics(exercise.angle) && !optical);
  m_result = plannedResult(exercise, m_measured);
  if (exercise.trunkLimitDeg) {
    TrunkLimitCueParams trunk;
    trunk.limitDeg = *exercise.trunkLimitDeg;
    m_trunkCue.emplace(trunk);
  }
  buildLayout();
  retranslate();
  connect(m_recording, &ExerciseRecording::started, this, [this](const QString& error) {
    if (error.isEmpty()) return;
    showFeedback(tr("The sensors could not start: %1. Check that they are switched on; you "
                    "can skip this exercise.")
                     .arg(error),
                 static_cast<int>(Tone::Problem));
    m_primary->setEnabled(false);
    emit choicesChanged();
  });
  connect(m_recording, &ExerciseRecording::problem, this,
          [this](const QString& m) { showFeedback(m, static_cast<int>(Tone::Problem)); });
  connect(m_recording, &ExerciseRecording::finished, this,
          [this](qint64 id, bool, const QString& message) {
            m_result.sessionId = id;
            if (!message.isEmpty()) m_shown << message;
            setPhase(Phase::Done);
            emit finished(m_result, m_stopForToday);
          });
  m_setDone.setSingleShot(true);
  connect(&m_setDone, &QTimer::timeout, this, &ExerciseScreen::endSet);
  connect(&m_timer, &QTimer::timeout, this, &ExerciseScreen::tick);
  m_timer.start(33);
  m_clock.start();
  m_recording->start(config);
}

ExerciseScreen::~ExerciseScreen() = default;

void ExerciseScreen::buildLayout() {
  auto* root = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  m_title = heading({}, this);
  m_text = bodyText({}, this);
  m_counter = new QLabel(this);
  setHomeFont(m_counter, 2.0, true);
  m_angle = new QLabel(this);
  setHomeFont(m_angle, 1.3, true);
  m_banner = bodyText({}, this);
  setHomeFont(m_banner, 1.3, true);
  m_banner->hide();
  // The trunk limit's cue: the largest words on the screen while the patient leans too far.
  m_trunk = bodyText({}, this);
  setHomeFont(m_trunk, 1.8, true);
  m_trunk->setAlignment(Qt::AlignCenter);
  m_trunk->hide();
  m_trunkCount = bodyText({}, this);
  m_trunkCount->hide();
  m_primary = bigButton({}, this, true);
  m_pause = bigButton({}, this);
  m_skip = bigButton({}, this);
  m_stop = bigButton({}, this);
  auto* buttons = new QHBoxLayout;
  for (QPushButton* b : {m_primary, m_pause, m_skip, m_stop}) buttons->addWidget(b);
  left->addWidget(m_title);
  left->addWidget(m_text);
  left->addWidget(m_counter);
  left->addWidget(m_angle);
  left->addWidget(m_trunkCount);
  left->addWidget(m_trunk);
  left->addWidget(m_banner);
  left->addStretch(1);
  left->addLayout(buttons);
  root->addLayout(left, 3);
  m_arm = new ui::ArmView(this);
  m_arm->setMinimumSize(280, 280);
  m_arm->setArm(m_config.meta.geometry, m_config.meta.side, m_config.meta.up, m_config.meta.camera);
  m_arm->setSternumImu(app::gui::drawnSternum(m_config));
  m_arm->setRefreshRate(0);
  m_arm->setPose(m_demo.at(0).th);
  // The view holds the light arm all the way: a shoulder raised high leaves the default framing.
  std::vector<JointVector> reach;
  for (double t = 0; t <= 6.0; t += 0.1) reach.push_back(m_demo.at(t).th);
  m_arm->resetView();
  m_arm->setCamera(
      fitView(m_arm->camera(), reachOf(m_config.meta.geometry, m_config.meta.side, reach)));
  root->addWidget(m_arm, 3);

  connect(m_primary, &QPushButton::clicked, this, [this] {
    switch (m_phase) {
      case Phase::Demonstration:
      case Phase::Rest:
        startSet();
        break;
      case Phase::Set:
        endSet();  // an exercise that is not counted: the patient says when the set is done
        break;
      case Phase::Paused:
        resume();
        break;
      default:
        break;
    }
  });
  connect(m_pause, &QPushButton::clicked, this, &ExerciseScreen::pause);
  connect(m_skip, &QPushButton::clicked, this, [this] { finish(true, false); });
  connect(m_stop, &QPushButton::clicked, this, [this] { finish(true, true); });
}

void ExerciseScreen::retranslate() {
  setAccessibleName(tr("Exercise"));
  m_title->setText(
      tr("Exercise %L1 of %L2: %3").arg(m_index).arg(m_count).arg(m_exercise.protocol.name));
  m_text->setAccessibleName(tr("Instruction"));
  m_counter->setAccessibleName(tr("Repetitions"));
  m_angle->setAccessibleName(tr("Your angle now"));
  m_banner->setAccessibleName(tr("Feedback"));
  m_trunk->setAccessibleName(tr("Trunk cue"));
  m_trunkCount->setAccessibleName(tr("Repetitions leaning too far"));
  updateTrunk();
  ui::setButtonText(m_pause, tr("&Pause"));
  m_pause->setToolTip(tr("Pause (Escape)"));
  ui::setButtonText(m_skip, tr("S&kip this exercise"));
  ui::setButtonText(m_stop, tr("S&top for today"));
  for (QPushButton* b : {m_pause, m_skip, m_stop})
    b->setAccessibleName(QString(b->text()).remove(u'&'));
  if (!m_measured)
    m_angle->setText(tr("%1: not measured").arg(ui::angleDisplayName(m_exercise.angle)));
  setPhase(m_phase);
}

QString ExerciseScreen::demonstrationText() const {
  static const char* const kHow[] = {
      QT_TRANSLATE_NOOP("armtrack::gui::home::ExerciseScreen",
                        "Raise your arm forward with the elbow straight, up to where the light "
                        "arm goes, then lower it slowly."),
      QT_TRANSLATE_NOOP("armtrack::gui::home::ExerciseScreen",
                        "Raise your arm out to the side with the elbow straight, up to where the "
                        "light arm goes, then lower it slowly."),
      QT_TRANSLATE_NOOP("armtrack::gui::home::ExerciseScreen",
                        "Keep your elbow at your side, bent at a right angle. Turn your hand in "
                        "towards your belly and out again, as the light arm does."),
      QT_TRANSLATE_NOOP("armtrack::gui::home::ExerciseScreen",
                        "Bend your elbow up as far as the light arm goes, then straighten it "
                        "slowly. Keep your upper arm still."),
      QT_TRANSLATE_NOOP("armtrack::gui::home::ExerciseScreen",
                        "Keep your elbow bent at a right angle. Turn your palm down and up "
                        "again, as the light arm does."),
  };
  QString text = tr(kHow[std::clamp(m_exercise.angle, 0, 4)]);
  text += u' ' + tr("Then press Start: %n set(s) of %1 repetitions.", nullptr, m_exercise.item.sets)
                     .arg(m_exercise.repetitions);
  if (!m_measured)
    text += u'\n' + tr("ArmTrack cannot measure this exercise without the camera. Do it as "
                       "shown and count the repetitions yourself; it is recorded for your "
                       "therapist.");
  if (!m_exercise.item.notes.isEmpty())
    text += u'\n' + tr("Your therapist says: %1").arg(m_exercise.item.notes);
  return text;
}

void ExerciseScreen::setPhase(Phase p) {
  m_phase = p;
  const auto show = [](QPushButton* b, bool visible, const QString& text = {}) {
    b->setVisible(visible);
    if (!text.isEmpty()) {
      b->setText(text);
      b->setAccessibleName(QString(text).remove(u'&'));
    }
  };
  const bool counting = m_measured;
  switch (p) {
    case Phase::Demonstration:
      m_text->setText(demonstrationText());
      show(m_primary, true, tr("&Start set %1").arg(m_set));
      show(m_pause, false);
      show(m_skip, true);
      show(m_stop, true);
      break;
    case Phase::Set:
      m_text->setText(counting
                          ? tr("Set %1 of %2: move like the light arm, %3 times. Take your time.")
                                .arg(m_set)
                                .arg(m_exercise.item.sets)
                                .arg(m_exercise.repetitions)
                          : tr("Set %1 of %2: do the movement %3 times, then press Done.")
                                .arg(m_set)
                                .arg(m_exercise.item.sets)
                                .arg(m_exercise.repetitions));
      show(m_primary, !counting, tr("&Done with this set"));
      show(m_pause, true);
      show(m_skip, false);
      show(m_stop, false);
      break;
    case Phase::Rest:
      m_text->setText(
          tr("Rest with your upper arm hanging, your elbow bent at a right angle and your "
             "thumb up. The next set starts by itself when the time is up."));
      show(m_primary, true, tr("&Start the next set now"));
      show(m_pause, true);
      show(m_skip, false);
      show(m_stop, true);
      break;
    case Phase::Paused:
      m_text->setText(tr("Paused. Press Go on when you are ready."));
      show(m_primary, true, tr("&Go on"));
      show(m_pause, false);
      show(m_skip, true);
      show(m_stop, true);
      break;
    case Phase::Finishing:
    case Phase::Done:
      m_text->setText(tr("Saving this exercise\u2026"));
      for (QPushButton* b : {m_primary, m_pause, m_skip, m_stop}) show(b, false);
      break;
  }
  updateCounter();
  if (QAbstractButton* main = defaultChoice()) main->setFocus(Qt::OtherFocusReason);
  emit choicesChanged();
}

void ExerciseScreen::updateCounter() {
  if (m_phase == Phase::Rest) {
    m_counter->setText(tr("Rest: %1 s").arg(static_cast<int>(std::ceil(m_restLeftS))));
  } else if (m_phase == Phase::Set || m_phase == Phase::Paused) {
    const int done = m_feedback ? static_cast<int>(m_feedback->repetitions()) : 0;
    m_counter->setText(m_measured ? tr("%1 of %2").arg(done).arg(m_exercise.repetitions)
                                  : tr("Count: %1 times").arg(m_exercise.repetitions));
  } else {
    m_counter->setText(tr("Set %1 of %2").arg(m_set).arg(m_exercise.item.sets));
  }
}

void ExerciseScreen::startSet() {
  if (m_phase != Phase::Demonstration && m_phase != Phase::Rest) return;
  ExerciseSpec spec;
  spec.primaryAngle = m_exercise.angle;
  spec.target = {m_exercise.targetMinDeg * kDegToRad, m_exercise.targetMaxDeg * kDegToRad};
  // Other angles are watched only when they can be trusted with this set-up.
  std::vector<int> still;
  for (int a : ExerciseFeedback::defaultStillAngles(m_exercise.angle))
    if (m_optical || !angleNeedsOptics(a)) still.push_back(a);
  spec.stillAngles = still;
  m_feedback.emplace(spec);
  if (m_trunkCue) m_trunkCue->startRepetitions(m_lastT);
  m_banner->hide();
  m_recording->setRecording(true);
  setPhase(Phase::Set);
}

void ExerciseScreen::closeSet() {
  m_recording->setRecording(false);
  if (!m_feedback) return;
  addSet(m_result, *m_feedback, m_measured);
  if (m_trunkCue) m_result.trunkCompensation = static_cast<int>(m_trunkCue->compensated());
  m_feedback.reset();
}

void ExerciseScreen::endSet() {
  if (m_phase != Phase::Set) return;
  m_setDone.stop();
  closeSet();
  if (m_set >= m_exercise.item.sets) {
    finish(false, false);
    return;
  }
  ++m_set;
  m_restLeftS = m_exercise.item.restS;
  m_clock.restart();
  showFeedback(tr("Set %1 done. Well done!").arg(m_set - 1), static_cast<int>(Tone::Good));
  setPhase(Phase::Rest);
  if (m_restLeftS <= 0) startSet();
}

void ExerciseScreen::pause() {
  if (m_phase != Phase::Set && m_phase != Phase::Rest && m_phase != Phase::Demonstration) return;
  m_pausedFrom = m_phase;
  m_setDone.stop();
  m_recording->setRecording(false);
  if (m_phase == Phase::Rest) m_restLeftS -= m_clock.elapsed() / 1000.0;
  setPhase(Phase::Paused);
}

void ExerciseScreen::resume() {
  if (m_phase != Phase::Paused) return;
  if (m_pausedFrom == Phase::Set) m_recording->setRecording(true);
  if (m_pausedFrom == Phase::Rest) m_clock.restart();
  setPhase(m_pausedFrom);
}

void ExerciseScreen::escapePressed() {
  if (m_phase == Phase::Paused)
    resume();
  else
    pause();
}

void ExerciseScreen::cutShort() {
  m_closing = true;
  finish(true, true);
}

void ExerciseScreen::stopAndSave() {
  finish(true, true);
}

void ExerciseScreen::finish(bool stoppedEarly, bool stopForToday) {
  if (m_phase == Phase::Finishing || m_phase == Phase::Done) return;
  m_setDone.stop();
  closeSet();  // a set under way counts for what was done in it
  m_result.stoppedEarly = stoppedEarly || m_result.setsDone < m_result.setsPlanned;
  m_result.measured = m_measured;
  m_stopForToday = stopForToday;
  setPhase(Phase::Finishing);
  // A session ends complete when the patient ends it, interrupted when the window closed.
  m_recording->stop(m_closing);
}

void ExerciseScreen::setMeasured(bool measured) {
  if (measured == m_measured) return;
  m_measured = measured;
  if (!measured) {
    m_angle->setText(tr("%1: not measured").arg(ui::angleDisplayName(m_exercise.angle)));
    showFeedback(tr("The camera does not see you, so ArmTrack cannot measure this shoulder "
                    "exercise now. Go on as shown, count yourself, and press Done after each "
                    "set."),
                 static_cast<int>(Tone::Hint));
  }
  setPhase(m_phase);
}

void ExerciseScreen::tick() {
  std::vector<std::string> events;
  const bool live = m_source ? m_source(m_rows, events) : m_recording->drain(m_rows, events);
  const double clock = m_clock.elapsed() / 1000.0;
  // The light arm: the movement played in the demonstration and the rests; in a set, the far
  // end to reach.
  if (m_phase == Phase::Set)
    m_arm->setTargetPose(m_demo.at(0.5 + 2.0).th);
  else
    m_arm->setTargetPose(m_demo.at(std::fmod(clock, 5.0)).th);
  if (live && !m_rows.empty()) {
    for (const session::EstimateRow& r : m_rows) {
      if (r.t <= m_lastT) continue;
      m_lastT = r.t;
      // A shoulder angle is trusted only while optical data hold the heading.
      m_trust.add(r);
      if (m_trunkCue)
        m_trunkCue->add(r.t, r.trunk ? std::optional((*r.trunk)(0)) : std::nullopt, r.trunkMoved);
      if (m_measured && m_trust.blind(r.t)) setMeasured(false);
      if (m_phase == Phase::Set && m_feedback && m_measured)
        m_feedback->add(r.t, clinicalRadians(r.th));
    }
    const session::EstimateRow& last = m_rows.back();
    m_arm->setPose(last.th);
    const int j = m_exercise.angle;
    if (m_measured && m_trust.shown(last))
      m_angle->setText(
          tr("%1: %2\u00b0")
              .arg(ui::angleDisplayName(j))
              .arg(asArray(toClinical(last.th))[static_cast<std::size_t>(j)], 0, 'f', 0));
    else
      m_angle->setText(tr("%1: not measured").arg(ui::angleDisplayName(j)));
  }
  // About once a second: a strap that turned far is told once, in the patient's words.
  if (!m_toldStraps && ++m_strapsTicks >= 30) {
    m_strapsTicks = 0;
    const QString words = app::gui::strapsPatientLine(
        m_strapsSource ? m_strapsSource() : m_recording->movementCalibration());
    if (!words.isEmpty()) {
      m_toldStraps = true;
      showFeedback(words, static_cast<int>(Tone::Hint));
    }
  }
  if (m_feedback) {
    handleEvents(m_feedback->takeEvents());
    if (m_phase == Phase::Set && m_measured &&
        static_cast<int>(m_feedback->repetitions()) >= m_exercise.repetitions &&
        !m_setDone.isActive())
      m_setDone.start(kSetEndDelayMs);
  }
  updateTrunk();
  if (m_phase == Phase::Rest) {
    const double left = m_restLeftS - clock;
    m_counter->setText(tr("Rest: %1 s").arg(static_cast<int>(std::ceil(std::max(0.0, left)))));
    if (left <= 0) startSet();
  }
  m_arm->updateIfChanged();
}

void ExerciseScreen::handleEvents(const std::vector<FeedbackEvent>& events) {
  if (events.empty()) return;
  // One message and one sound per moment: a hint before praise, the count after each.
  QString good, hint;
  bool counted = false;
  for (const FeedbackEvent& e : events) {
    switch (e.kind) {
      case FeedbackKind::TargetReached:
        good = tr("Target reached!");
        if (m_sound) m_sound->play(FeedbackSound::Cue::Reached);
        break;
      case FeedbackKind::RepetitionCounted:
        counted = true;
        if (m_trunkCue) m_trunkCue->repetitionEnded(e.t);
        if (good.isEmpty()) good = tr("Good: %1 done.").arg(e.repetition);
        break;
      case FeedbackKind::RangeNotReached:
        if (hint.isEmpty())
          hint = e.repetition > 0 ? tr("Try to go a little further next time.")
                                  : tr("Almost: go a little further for it to count.");
        break;
      case FeedbackKind::TooFast:
        hint = tr("A little slower, please.");
        break;
      case FeedbackKind::Compensation:
        hint = e.angle == 3 ? tr("Keep your elbow straight; move only your shoulder.")
                            : tr("Keep your upper arm still; move only your elbow and forearm.");
        break;
    }
  }
  if (!hint.isEmpty()) {
    showFeedback(hint, static_cast<int>(Tone::Hint));
    if (m_sound) m_sound->play(FeedbackSound::Cue::Hint);
  } else if (!good.isEmpty()) {
    showFeedback(good, static_cast<int>(Tone::Good));
  }
  if (counted) {
    if (hint.isEmpty() && m_sound) m_sound->play(FeedbackSound::Cue::Counted);
    updateCounter();
  }
}

void ExerciseScreen::updateTrunk() {
  if (!m_trunkCue) return;
  const bool cue = trunkCueShown();
  const QString words = tr("Keep your back against the chair");
  if (cue && m_trunkCue->cues() > m_trunkCues) {
    // Once each time it comes on: sounded and logged with the other feedback.
    m_trunkCues = m_trunkCue->cues();
    m_shown << words;
    if (m_sound) m_sound->play(FeedbackSound::Cue::Hint);
  }
  if (cue == m_trunk->isHidden() || (cue && m_trunk->text() != words))
    setBanner(m_trunk, cue ? words : QString(), Tone::Hint);
  const QString count = trunkCountText();
  m_trunkCount->setText(count);
  m_trunkCount->setVisible(!count.isEmpty() && (m_phase == Phase::Set || m_phase == Phase::Paused));
}

bool ExerciseScreen::trunkCueShown() const {
  return m_trunkCue && m_phase == Phase::Set && m_trunkCue->cueShown();
}

QString ExerciseScreen::trunkCountText() const {
  if (!m_trunkCue || m_trunkCue->compensated() == 0) return {};
  return tr("%n repetition(s) leaning too far", nullptr,
            static_cast<int>(m_trunkCue->compensated()));
}

void ExerciseScreen::showFeedback(const QString& text, int tone) {
  setBanner(m_banner, text, static_cast<Tone>(tone));
  m_shown << text;
}

QString ExerciseScreen::title() const {
  return m_title->text();
}

QString ExerciseScreen::instruction() const {
  return m_text->text();
}

QString ExerciseScreen::counterText() const {
  return m_counter->text();
}

QString ExerciseScreen::feedbackText() const {
  return m_banner->isHidden() ? QString() : m_banner->text();
}

QList<QAbstractButton*> ExerciseScreen::choices() const {
  return {m_primary, m_pause, m_skip, m_stop};
}

QAbstractButton* ExerciseScreen::defaultChoice() const {
  switch (m_phase) {
    case Phase::Demonstration:
    case Phase::Rest:
    case Phase::Paused:
      return m_primary->isEnabled() ? m_primary : m_skip;
    case Phase::Set:
      return m_measured ? m_pause : m_primary;
    case Phase::Finishing:
    case Phase::Done:
      break;
  }
  return nullptr;
}

}  // namespace armtrack::gui::home
