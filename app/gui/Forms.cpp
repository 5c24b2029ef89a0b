#include "app/gui/Forms.h"

#include <QAccessible>
#include <QHBoxLayout>
#include <QVBoxLayout>

namespace armtrack::gui {

MessageLine::MessageLine(QWidget* parent) : QFrame(parent), m_label(new QLabel(this)) {
  m_label->setWordWrap(true);
  m_label->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  m_label->setAccessibleName(tr("Message"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 6, 8, 6);
  layout->addWidget(m_label);
  setObjectName(QStringLiteral("messageLine"));
  setVisible(false);
}

void MessageLine::showMessage(const QString& text, Kind kind) {
  m_kind = kind;
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
  m_label->setText(text);
  setVisible(!text.isEmpty());
  QAccessibleEvent event(m_label, QAccessible::Alert);
  QAccessible::updateAccessibility(&event);
}

void MessageLine::clear() {
  m_label->setText({});
  setVisible(false);
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

}  // namespace armtrack::gui
