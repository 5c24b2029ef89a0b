#include "app/gui/home/HomeCalibrationScreen.h"

#include <QHBoxLayout>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>

#include "app/gui/common/SensorCalibrationPage.h"
#include "app/gui/home/HomeStyle.h"
#include "ui/Retranslate.h"

namespace armtrack::gui::home {

HomeCalibrationScreen::HomeCalibrationScreen(const app::PluginRegistry& registry,
                                             app::gui::LiveSessionConfig config,
                                             const QString& folder, QWidget* parent)
    : HomeScreen(parent),
      m_page(new app::gui::SensorCalibrationPage(registry, std::move(config), folder.toStdString(),
                                                 this)),
      m_goOn(bigButton({}, this, true)),
      m_skip(bigButton({}, this)) {
  m_page->setIntroduction([] {
    return tr(
        "Now ArmTrack learns how the sensors sit on your arm today. It takes about a "
        "minute: press Start, then do what the screen says and what the light arm shows.");
  });
  m_page->setForPatient(true);
  setHomeFont(m_page);
  // While the protocol runs the focus rests on the screen, not on a button: a stray Space or
  // Enter does nothing.
  setFocusPolicy(Qt::StrongFocus);
  auto* root = new QVBoxLayout(this);
  root->addWidget(m_page, 1);
  auto* buttons = new QHBoxLayout;
  buttons->addStretch(1);
  buttons->addWidget(m_goOn, 2);
  buttons->addWidget(m_skip, 1);
  root->addLayout(buttons);
  m_page->startButton()->setProperty("primary", true);
  m_page->startButton()->setMinimumHeight(m_goOn->sizeHint().height());
  connect(m_page, &app::gui::SensorCalibrationPage::completeChanged, this,
          &HomeCalibrationScreen::update);
  connect(m_goOn, &QPushButton::clicked, this, [this] {
    std::optional<Calibration> c;
    if (m_page->isComplete() && m_page->result()) c = m_page->result()->calibration;
    emit done(c);
  });
  connect(m_skip, &QPushButton::clicked, this, &HomeCalibrationScreen::askToSkip);
  retranslate();
}

void HomeCalibrationScreen::retranslate() {
  setAccessibleName(tr("Calibration"));
  ui::setButtonText(m_skip, tr("S&kip the calibration"));
  m_skip->setAccessibleName(QString(m_skip->text()).remove(u'&'));
  update();
}

void HomeCalibrationScreen::update() {
  using State = app::gui::SensorCalibrationPage::State;
  const State s = m_page->state();
  const bool finished = s == State::Done || s == State::Failed;
  m_goOn->setVisible(finished);
  ui::setButtonText(m_goOn, m_page->isComplete() ? tr("&Go on") : tr("&Go on without it"));
  m_goOn->setAccessibleName(QString(m_goOn->text()).remove(u'&'));
  // After a good verdict going on is the main choice; after a poor one, doing it again.
  m_goOn->setProperty("primary", m_page->isComplete());
  m_page->startButton()->setProperty("primary", !m_page->isComplete());
  for (QWidget* w : {static_cast<QWidget*>(m_goOn), static_cast<QWidget*>(m_page->startButton())}) {
    w->style()->unpolish(w);
    w->style()->polish(w);
  }
  m_skip->setVisible(!finished || !m_page->isComplete());
  if (QAbstractButton* main = defaultChoice())
    main->setFocus(Qt::OtherFocusReason);
  else if (isVisible())
    setFocus(Qt::OtherFocusReason);
  emit choicesChanged();
}

QList<QAbstractButton*> HomeCalibrationScreen::choices() const {
  return {m_page->startButton(), m_goOn, m_skip};
}

QAbstractButton* HomeCalibrationScreen::defaultChoice() const {
  using State = app::gui::SensorCalibrationPage::State;
  switch (m_page->state()) {
    case State::Ready:
      return m_page->startButton();
    case State::Done:
      return m_page->isComplete() ? static_cast<QAbstractButton*>(m_goOn) : m_page->startButton();
    case State::Failed:
      return m_page->startButton();
    case State::Recording:
    case State::Solving:
      break;  // nothing to press while the protocol runs: Skip asks first
  }
  return nullptr;
}

void HomeCalibrationScreen::askToSkip() {
  if (m_question) return m_question->raise();
  auto* box = new QMessageBox(QMessageBox::Question, tr("Skip the calibration?"),
                              tr("Do you want to go on without the calibration?"),
                              QMessageBox::NoButton, this);
  box->setInformativeText(
      tr("Without it, ArmTrack measures your arm a little less exactly "
         "today. The calibration takes about a minute."));
  QPushButton* skip = box->addButton(tr("&Skip it"), QMessageBox::AcceptRole);
  QPushButton* keep = box->addButton(tr("&Do the calibration"), QMessageBox::RejectRole);
  box->setDefaultButton(keep);
  box->setEscapeButton(keep);
  box->setAttribute(Qt::WA_DeleteOnClose);
  m_question = box;
  connect(skip, &QPushButton::clicked, this, [this] {
    m_page->cancel();
    emit done(std::nullopt);
  });
  box->open();
}

void HomeCalibrationScreen::escapePressed() {
  m_page->cancel();
}

}  // namespace armtrack::gui::home
