#include "app/gui/home/HomeMessageScreen.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "app/gui/home/HomeStyle.h"
#include "ui/Retranslate.h"

namespace armtrack::gui::home {

HomeMessageScreen::HomeMessageScreen(Text title, Text text, QWidget* parent)
    : HomeScreen(parent),
      m_titleText(std::move(title)),
      m_bodyText(std::move(text)),
      m_title(heading({}, this)),
      m_text(bodyText({}, this)),
      m_buttons(new QWidget(this)) {
  auto* root = new QVBoxLayout(this);
  root->addWidget(m_title);
  root->addWidget(m_text);
  root->addStretch(1);
  new QHBoxLayout(m_buttons);
  m_buttons->layout()->setContentsMargins(0, 0, 0, 0);
  root->addWidget(m_buttons);
  retranslate();
}

QPushButton* HomeMessageScreen::addChoice(Text label, std::function<void()> action) {
  QPushButton* b = bigButton(label(), this, m_choices.empty());
  m_buttons->layout()->addWidget(b);
  connect(b, &QPushButton::clicked, this, std::move(action));
  m_choices.emplace_back(b, std::move(label));
  emit choicesChanged();
  return b;
}

QString HomeMessageScreen::title() const {
  return m_title->text();
}

QString HomeMessageScreen::text() const {
  return m_text->text();
}

QList<QAbstractButton*> HomeMessageScreen::choices() const {
  QList<QAbstractButton*> out;
  for (const auto& c : m_choices) out << c.first;
  return out;
}

QAbstractButton* HomeMessageScreen::defaultChoice() const {
  return m_choices.empty() ? nullptr : m_choices.front().first;
}

void HomeMessageScreen::retranslate() {
  m_title->setText(m_titleText ? m_titleText() : QString());
  m_text->setText(m_bodyText ? m_bodyText() : QString());
  for (const auto& [button, label] : m_choices) {
    ui::setButtonText(button, label());
    button->setAccessibleName(QString(button->text()).remove(u'&'));
  }
}

}  // namespace armtrack::gui::home
