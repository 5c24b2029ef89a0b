#include "app/gui/home/SwitchAccess.h"

#include <QAbstractButton>
#include <QApplication>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <algorithm>

#include "app/gui/home/HomeScreen.h"

namespace armtrack::gui::home {

namespace {

bool isSwitchKey(int key) {
  return key == Qt::Key_Space || key == Qt::Key_Return || key == Qt::Key_Enter ||
         key == Qt::Key_Select;
}

QList<QAbstractButton*> usable(const HomeScreen* screen) {
  QList<QAbstractButton*> out;
  if (!screen) return out;
  for (QAbstractButton* b : screen->choices())
    if (b && b->isVisible() && b->isEnabled()) out << b;
  return out;
}

}  // namespace

AccessMode parseAccessMode(const QString& name) {
  if (name == QLatin1String("scanning")) return AccessMode::Scanning;
  if (name == QLatin1String("step")) return AccessMode::Step;
  return AccessMode::Keyboard;
}

QString accessModeName(AccessMode mode) {
  switch (mode) {
    case AccessMode::Scanning:
      return QStringLiteral("scanning");
    case AccessMode::Step:
      return QStringLiteral("step");
    case AccessMode::Keyboard:
      break;
  }
  return QStringLiteral("keyboard");
}

SwitchAccess::SwitchAccess(QWidget* window, QObject* parent) : QObject(parent), m_window(window) {
  m_timer.setInterval(1500);
  connect(&m_timer, &QTimer::timeout, this, &SwitchAccess::step);
  qApp->installEventFilter(this);
}

SwitchAccess::~SwitchAccess() {
  qApp->removeEventFilter(this);
}

void SwitchAccess::setMode(AccessMode mode) {
  if (mode == m_mode) return;
  m_mode = mode;
  restartScan();
  emit modeChanged(mode);
}

void SwitchAccess::setScanInterval(int ms) {
  m_timer.setInterval(std::clamp(ms, 500, 10000));
}

void SwitchAccess::setScreen(HomeScreen* screen) {
  if (m_screen) disconnect(m_screen, nullptr, this, nullptr);
  m_screen = screen;
  if (screen) connect(screen, &HomeScreen::choicesChanged, this, &SwitchAccess::restartScan);
  restartScan();
}

QWidget* SwitchAccess::highlighted() const {
  const QList<QAbstractButton*> c = usable(m_screen);
  if (m_mode != AccessMode::Scanning || m_index < 0 || m_index >= c.size()) return nullptr;
  return c[m_index];
}

void SwitchAccess::restartScan() {
  m_index = -1;
  m_timer.stop();
  if (m_mode != AccessMode::Scanning) return;
  // Scanning starts on the main choice, so one press goes on.
  const QList<QAbstractButton*> c = usable(m_screen);
  QAbstractButton* main = m_screen ? m_screen->defaultChoice() : nullptr;
  m_index = std::max<int>(0, static_cast<int>(c.indexOf(main)));
  if (!c.isEmpty()) c[m_index]->setFocus(Qt::TabFocusReason);
  m_timer.start();
}

void SwitchAccess::step() {
  const QList<QAbstractButton*> c = usable(m_screen);
  if (c.isEmpty()) return;
  m_index = (m_index + 1) % static_cast<int>(c.size());
  c[m_index]->setFocus(Qt::TabFocusReason);
}

bool SwitchAccess::takeSwitch() {
  const QList<QAbstractButton*> c = usable(m_screen);
  if (m_index < 0 || m_index >= c.size()) return false;
  QAbstractButton* chosen = c[m_index];
  m_timer.start();  // a full interval on what comes next
  chosen->click();
  return true;
}

bool SwitchAccess::goOn() {
  QAbstractButton* main = m_screen ? m_screen->defaultChoice() : nullptr;
  if (!main || !main->isVisible() || !main->isEnabled()) return false;
  main->click();
  return true;
}

bool SwitchAccess::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() != QEvent::KeyPress || !m_screen) return false;
  auto* w = qobject_cast<QWidget*>(watched);
  if (!w || w->window() != m_window) return false;
  auto* key = static_cast<QKeyEvent*>(event);
  if (key->key() == Qt::Key_Escape) {
    m_screen->escapePressed();
    return true;
  }
  if (!isSwitchKey(key->key())) return false;
  // Typing in the comment box: Enter and Space are text, whatever the mode (Ctrl+Enter goes
  // on). A switch never puts the focus there: scanning steps through the buttons only.
  if (qobject_cast<QPlainTextEdit*>(w) && !(key->modifiers() & Qt::ControlModifier)) return false;
  // A line (the clinic's address, the code): Space is text, Enter goes on.
  if (qobject_cast<QLineEdit*>(w) && key->key() == Qt::Key_Space) return false;
  if (key->isAutoRepeat()) return true;  // a switch held down is one press
  switch (m_mode) {
    case AccessMode::Scanning:
      return takeSwitch();
    case AccessMode::Step:
      return goOn();
    case AccessMode::Keyboard:
      break;
  }
  // A focused choice takes the key; otherwise the main one.
  if (auto* b = qobject_cast<QAbstractButton*>(w); b && usable(m_screen).contains(b)) {
    b->click();
    return true;
  }
  return goOn();
}

}  // namespace armtrack::gui::home
