#include "app/gui/MessageScreen.h"

#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

#include "app/gui/Forms.h"

namespace armtrack::gui {

MessageScreen::MessageScreen(const QString& title, const QString& text, QWidget* parent)
    : QWidget(parent),
      m_text(new QLabel(text, this)),
      m_progress(new QProgressBar(this)),
      m_buttons(new QHBoxLayout) {
  setWindowTitle(title);
  QWidget* column = nullptr;
  auto* layout = centredColumn(this, 600, &column);
  layout->addWidget(heading(title, column));
  m_text->setWordWrap(true);
  m_text->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  m_text->setAccessibleName(tr("Message"));
  layout->addWidget(m_text);
  m_progress->setAccessibleName(tr("Progress"));
  m_progress->hide();
  layout->addWidget(m_progress);
  m_buttons->addStretch();
  layout->addLayout(m_buttons);
  layout->addStretch();
}

QPushButton* MessageScreen::addAction(const QString& text, std::function<void()> action) {
  auto* button = new QPushButton(text, this);
  if (m_buttons->count() == 1) {
    button->setDefault(true);
    setFocusProxy(button);
  }
  connect(button, &QPushButton::clicked, this, [action = std::move(action)] { action(); });
  m_buttons->addWidget(button);
  return button;
}

void MessageScreen::setProgress(int percent) {
  m_progress->show();
  if (percent < 0) {
    m_progress->setRange(0, 0);
  } else {
    m_progress->setRange(0, 100);
    m_progress->setValue(percent);
  }
}

void MessageScreen::setText(const QString& text) {
  m_text->setText(text);
}

}  // namespace armtrack::gui
