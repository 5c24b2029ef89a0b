#include "ui/ScreenStack.h"

namespace armtrack::ui {

ScreenStack::ScreenStack(QWidget* parent) : QStackedWidget(parent) {}

void ScreenStack::showScreen(QWidget* screen) {
  if (m_current) {
    removeWidget(m_current);
    m_current->deleteLater();
  }
  m_current = screen;
  addWidget(screen);
  setCurrentWidget(screen);
}

}  // namespace armtrack::ui
