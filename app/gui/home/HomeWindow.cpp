#include "app/gui/home/HomeWindow.h"

#include <QCloseEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include "app/gui/home/HomeScreen.h"
#include "app/gui/home/HomeStyle.h"
#include "app/gui/home/SwitchAccess.h"
#include "ui/Fonts.h"
#include "ui/ScreenStack.h"

namespace armtrack::gui::home {

HomeWindow::HomeWindow(QWidget* parent)
    : QWidget(parent, Qt::Window),
      m_who(new QLabel(this)),
      m_step(new QLabel(this)),
      m_sync(new QLabel(this)),
      m_stack(new ui::ScreenStack(this)),
      m_access(new SwitchAccess(this, this)) {
  applyHomeStyle(this);
  auto* root = new QVBoxLayout(this);
  root->setContentsMargins(24, 16, 24, 24);
  auto* top = new QHBoxLayout;
  setHomeFont(m_who, 1.0, true);
  setHomeFont(m_step);
  m_step->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  top->addWidget(m_who, 1);
  top->addWidget(m_step);
  root->addLayout(top);
  root->addWidget(m_stack, 1);
  setHomeFont(m_sync, 0.8);
  m_sync->setWordWrap(true);
  m_sync->hide();
  root->addWidget(m_sync);
  setMinimumSize(800, 560);
  resize(1200, 760);
  retranslate();
}

void HomeWindow::retranslate() {
  setWindowTitle(tr("ArmTrack: my exercises"));
  setAccessibleName(tr("My exercises"));
  m_who->setAccessibleName(tr("Whose exercises"));
  m_step->setAccessibleName(tr("Step"));
  m_sync->setAccessibleName(tr("Sending to the clinic"));
  if (m_stepText) m_step->setText(m_stepText());
}

void HomeWindow::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void HomeWindow::showScreen(HomeScreen* screen) {
  m_stack->showScreen(screen);
  m_access->setScreen(screen);
  if (QAbstractButton* main = screen->defaultChoice()) main->setFocus(Qt::OtherFocusReason);
}

HomeScreen* HomeWindow::currentScreen() const {
  return qobject_cast<HomeScreen*>(m_stack->screen());
}

void HomeWindow::setHeading(const QString& who, std::function<QString()> step) {
  m_who->setText(who);
  m_stepText = std::move(step);
  m_step->setText(m_stepText ? m_stepText() : QString());
}

void HomeWindow::setSyncText(const QString& text) {
  m_sync->setText(text);
  m_sync->setVisible(!text.isEmpty());
}

QString HomeWindow::syncText() const {
  return m_sync->text();
}

QString HomeWindow::stepText() const {
  return m_step->text();
}

void HomeWindow::closeEvent(QCloseEvent* event) {
  if (m_closeAllowed) {
    event->accept();
    return;
  }
  event->ignore();
  emit closeRequested();
}

}  // namespace armtrack::gui::home
