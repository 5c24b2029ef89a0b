#include "app/gui/common/MessageScreen.h"

#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace armtrack::gui {

MessageScreen::MessageScreen(TextFn title, TextFn text, QWidget* parent)
    : QWidget(parent),
      m_titleText(std::move(title)),
      m_bodyText(std::move(text)),
      m_text(new QLabel(this)),
      m_progress(new QProgressBar(this)),
      m_buttons(new QHBoxLayout) {
  QWidget* column = nullptr;
  auto* layout = centredColumn(this, 600, &column);
  m_heading = heading(QString(), column);
  layout->addWidget(m_heading);
  m_text->setWordWrap(true);
  m_text->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  layout->addWidget(m_text);
  m_progress->hide();
  layout->addWidget(m_progress);
  m_buttons->addStretch();
  layout->addLayout(m_buttons);
  layout->addStretch();
  retranslateUi();
}

void MessageScreen::retranslateUi() {
  const QString title = m_titleText ? m_titleText() : QString();
  setWindowTitle(title);
  setHeading(m_heading, title);
  m_text->setText(m_bodyText ? m_bodyText() : QString());
  m_text->setAccessibleName(tr("Message"));
  m_progress->setAccessibleName(tr("Progress"));
  for (const auto& [button, text] : m_actions) button->setText(text());
}

void MessageScreen::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWidget::changeEvent(event);
}

QPushButton* MessageScreen::addAction(TextFn text, std::function<void()> action) {
  auto* button = new QPushButton(text(), this);
  if (m_buttons->count() == 1) {
    button->setDefault(true);
    setFocusProxy(button);
  }
  connect(button, &QPushButton::clicked, this, [action = std::move(action)] { action(); });
  m_buttons->addWidget(button);
  m_actions.emplace_back(button, std::move(text));
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

void MessageScreen::setText(TextFn text) {
  m_bodyText = std::move(text);
  m_text->setText(m_bodyText ? m_bodyText() : QString());
}

}  // namespace armtrack::gui
