#include "app/gui/common/Forms.h"

#include <QAccessible>
#include <QEvent>
#include <QHBoxLayout>
#include <QVBoxLayout>

namespace armtrack::gui {

MessageLine::MessageLine(QWidget* parent) : QFrame(parent), m_label(new QLabel(this)) {
  m_label->setWordWrap(true);
  m_label->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 6, 8, 6);
  layout->addWidget(m_label);
  setObjectName(QStringLiteral("messageLine"));
  setVisible(false);
  m_label->setAccessibleName(tr("Message"));
}

void MessageLine::showMessage(const QString& text, Kind kind) {
  showMessage([text] { return text; }, kind);
}

void MessageLine::showMessage(TextFn text, Kind kind) {
  m_kind = kind;
  m_text = std::move(text);
  const QString shown = m_text ? m_text() : QString();
  // Colours from the palette's own roles keep the contrast in light and dark themes; the frame
  // says "error" without relying on colour alone.
  setStyleSheet(kind == Kind::Error
                    ? QStringLiteral("#messageLine { border: 2px solid #c62828; "
                                     "border-radius: 4px; }")
                    : QStringLiteral("#messageLine { border: 1px solid palette(mid); "
                                     "border-radius: 4px; }"));
  QFont f = m_label->font();
  f.setBold(kind == Kind::Error);
  m_label->setFont(f);
  m_label->setText(shown);
  setVisible(!shown.isEmpty());
  QAccessibleEvent event(m_label, QAccessible::Alert);
  QAccessible::updateAccessibility(&event);
}

void MessageLine::clear() {
  m_text = {};
  m_label->setText({});
  setVisible(false);
}

void MessageLine::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) {
    m_label->setAccessibleName(tr("Message"));
    if (m_text) m_label->setText(m_text());
  }
  QFrame::changeEvent(event);
}

TranslatedLabel::TranslatedLabel(TextFn text, QWidget* parent)
    : QLabel(parent), m_text(std::move(text)) {
  setText(m_text());
}

void TranslatedLabel::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) setText(m_text());
  QLabel::changeEvent(event);
}

bool isLanguageChange(const QEvent* event) {
  return event->type() == QEvent::LanguageChange;
}

QVBoxLayout* centredColumn(QWidget* screen, int width, QWidget** column) {
  auto* outer = new QHBoxLayout(screen);
  *column = new QWidget(screen);
  (*column)->setMaximumWidth(width);
  (*column)->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
  outer->addStretch(1);
  outer->addWidget(*column, 100);
  outer->addStretch(1);
  return new QVBoxLayout(*column);
}

QLabel* heading(const QString& text, QWidget* parent) {
  auto* label = new QLabel(text, parent);
  QFont f = label->font();
  f.setPointSizeF(f.pointSizeF() * 1.5);
  f.setBold(true);
  label->setFont(f);
  label->setAccessibleName(text);
  return label;
}

void setHeading(QLabel* heading, const QString& text) {
  heading->setText(text);
  heading->setAccessibleName(text);
}

}  // namespace armtrack::gui
