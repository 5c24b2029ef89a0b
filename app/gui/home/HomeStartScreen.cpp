#include "app/gui/home/HomeStartScreen.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "app/gui/home/HomeStyle.h"
#include "core/metrics/ExerciseFeedback.h"
#include "ui/Retranslate.h"

namespace armtrack::gui::home {

QString exerciseLine(const HomeExercise& e) {
  return QCoreApplication::translate("armtrack::gui::home::HomeStartScreen",
                                     "%1: %n set(s) of %2 repetitions, %3 s rest", nullptr,
                                     e.item.sets)
      .arg(e.protocol.name)
      .arg(e.repetitions)
      .arg(e.item.restS, 0, 'f', 0);
}

QString firstName(const QString& name) {
  const QString trimmed = name.trimmed();
  return trimmed.section(u' ', 0, 0);
}

HomeStartScreen::HomeStartScreen(const HomePlan& plan, bool optical, AccessMode mode,
                                 QWidget* parent, bool withClinic)
    : HomeScreen(parent), m_plan(plan), m_optical(optical), m_mode(mode) {
  auto* root = new QVBoxLayout(this);
  m_hello = heading({}, this);
  m_intro = bodyText({}, this);
  root->addWidget(m_hello);
  root->addWidget(m_intro);
  for (std::size_t i = 0; i < plan.exercises.size(); ++i) {
    auto* l = bodyText({}, this);
    l->setIndent(24);
    root->addWidget(l);
    m_lineLabels << l;
  }
  m_note = bodyText({}, this);
  root->addWidget(m_note);
  root->addStretch(1);
  auto* buttons = new QHBoxLayout;
  m_start = bigButton({}, this, true);
  m_start->setEnabled(!plan.exercises.empty());
  m_access = bigButton({}, this);
  m_signOut = bigButton({}, this);
  m_clinic = bigButton({}, this);
  m_clinic->setVisible(withClinic);
  buttons->addWidget(m_start, 2);
  buttons->addWidget(m_access, 2);
  buttons->addWidget(m_clinic, 1);
  buttons->addWidget(m_signOut, 1);
  root->addLayout(buttons);
  retranslate();
  connect(m_start, &QPushButton::clicked, this, &HomeStartScreen::startRequested);
  connect(m_signOut, &QPushButton::clicked, this, &HomeStartScreen::signOutRequested);
  connect(m_clinic, &QPushButton::clicked, this, &HomeStartScreen::clinicRequested);
  connect(m_access, &QPushButton::clicked, this, [this] {
    m_mode = m_mode == AccessMode::Keyboard   ? AccessMode::Scanning
             : m_mode == AccessMode::Scanning ? AccessMode::Step
                                              : AccessMode::Keyboard;
    showMode();
    emit accessModeChosen(m_mode);
  });
}

void HomeStartScreen::retranslate() {
  setAccessibleName(tr("Today's exercises"));
  m_hello->setText(tr("Hello, %1").arg(firstName(m_plan.patient.name)));
  m_intro->setText(m_plan.exercises.empty()
                       ? tr("Your therapist has not given you any exercises yet.")
                       : tr("Today's exercises:"));
  bool unmeasured = false;
  m_lines.clear();
  for (std::size_t i = 0; i < m_plan.exercises.size(); ++i) {
    const HomeExercise& e = m_plan.exercises[i];
    QString line = QStringLiteral("%1. %2").arg(i + 1).arg(exerciseLine(e));
    if (!m_optical && angleNeedsOptics(e.angle)) {
      line += u' ' + tr("(not measured without the camera)");
      unmeasured = true;
    }
    m_lines << line;
    m_lineLabels[static_cast<qsizetype>(i)]->setText(line);
  }
  m_note->setAccessibleName(tr("What can be measured"));
  if (!m_optical)
    setBanner(m_note,
              tr("This set-up has no camera. ArmTrack measures your elbow and forearm well "
                 "with the two sensors alone. It cannot trust the shoulder's angles without "
                 "the camera: they drift slowly about the vertical. Do the shoulder exercises "
                 "as your therapist showed you; they are recorded for your therapist, but "
                 "ArmTrack does not count them or show their numbers.%1")
                  .arg(unmeasured ? QString() : u' ' + tr("None of today's exercises needs it.")),
              Tone::Neutral);
  else
    m_note->hide();
  ui::setButtonText(m_start, tr("&Start"));
  ui::setButtonText(m_signOut, tr("Sign &out"));
  ui::setButtonText(m_clinic, tr("C&linic"));
  m_clinic->setToolTip(tr("Connect to the clinic with its address and your therapist's code"));
  for (QPushButton* b : {m_start, m_signOut, m_clinic})
    b->setAccessibleName(QString(b->text()).remove(u'&'));
  showMode();
}

void HomeStartScreen::showMode() {
  QString how;
  switch (m_mode) {
    case AccessMode::Keyboard:
      how = tr("I use the keyboard or the mouse");
      break;
    case AccessMode::Scanning:
      how = tr("I use one switch: the choices light up in turn");
      break;
    case AccessMode::Step:
      how = tr("I use one switch: press to go on");
      break;
  }
  m_access->setText(how);
  m_access->setAccessibleName(tr("How I press: %1").arg(how));
  m_access->setToolTip(tr("Press to change how you use ArmTrack"));
}

QList<QAbstractButton*> HomeStartScreen::choices() const {
  return {m_start, m_access, m_clinic, m_signOut};
}

QAbstractButton* HomeStartScreen::defaultChoice() const {
  return m_start->isEnabled() ? m_start : m_signOut;
}

QString HomeStartScreen::measurementNote() const {
  return m_note->isHidden() ? QString() : m_note->text();
}

}  // namespace armtrack::gui::home
