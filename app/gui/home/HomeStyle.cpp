#include "app/gui/home/HomeStyle.h"

#include <QApplication>
#include <QLabel>
#include <QPalette>
#include <QPushButton>

#include "ui/Fonts.h"

namespace armtrack::gui::home {

namespace {
// Black on white, a dark blue for the button that goes on, amber focus: contrast above 7:1
// (WCAG AAA) for every pair of text and background used.
const QColor kText(0x10, 0x10, 0x10);
const QColor kBackground(0xff, 0xff, 0xff);
const QColor kPrimary(0x0b, 0x3d, 0x91);
const QColor kFocus(0xff, 0xb0, 0x00);
}  // namespace

QFont homeFont(double scale, bool bold) {
  return ui::scaledFont(QApplication::font(), 1.5 * scale, bold);
}

void setHomeFont(QWidget* w, double scale, bool bold) {
  w->setFont(homeFont(scale, bold));
}

void applyHomeStyle(QWidget* window) {
  QPalette p = window->palette();
  p.setColor(QPalette::Window, kBackground);
  p.setColor(QPalette::WindowText, kText);
  p.setColor(QPalette::Base, kBackground);
  p.setColor(QPalette::Text, kText);
  p.setColor(QPalette::Button, QColor(0xe8, 0xe8, 0xe8));
  p.setColor(QPalette::ButtonText, kText);
  p.setColor(QPalette::Highlight, kPrimary);
  p.setColor(QPalette::HighlightedText, kBackground);
  window->setPalette(p);
  window->setAutoFillBackground(true);
  window->setFont(homeFont());
  // Sizes in em follow the font, hence the system's text size and the screen's DPI.
  window->setStyleSheet(QStringLiteral(
      "QPushButton { min-height: 2.4em; padding: 0.3em 1.2em; border: 3px solid #101010;"
      " border-radius: 0.4em; background: #e8e8e8; color: #101010; }"
      "QPushButton[primary=\"true\"] { background: #0b3d91; color: #ffffff; font-weight: bold; }"
      "QPushButton:focus { border: 6px solid #ffb000; }"
      "QPushButton:disabled { color: #606060; border-color: #909090; }"
      // A disabled main button keeps readable words: dark text on a pale blue (about 10:1).
      "QPushButton[primary=\"true\"]:disabled { background: #c9d4e8; color: #303030;"
      " border-color: #909090; }"
      "QPlainTextEdit { border: 3px solid #101010; }"
      "QPlainTextEdit:focus { border: 6px solid #ffb000; }"));
}

QPushButton* bigButton(const QString& text, QWidget* parent, bool primary) {
  auto* b = new QPushButton(text, parent);
  b->setProperty("primary", primary);
  setHomeFont(b, 1.0, primary);
  b->setAccessibleName(QString(text).remove(u'&'));
  b->setFocusPolicy(Qt::StrongFocus);
  return b;
}

QLabel* heading(const QString& text, QWidget* parent) {
  auto* l = new QLabel(text, parent);
  setHomeFont(l, 1.4, true);
  l->setWordWrap(true);
  return l;
}

QLabel* bodyText(const QString& text, QWidget* parent) {
  auto* l = new QLabel(text, parent);
  setHomeFont(l);
  l->setWordWrap(true);
  l->setTextFormat(Qt::PlainText);
  return l;
}

QColor toneColour(Tone tone) {
  switch (tone) {
    case Tone::Good:
      return {0xc8, 0xf0, 0xc8};
    case Tone::Hint:
      return {0xff, 0xe0, 0x8a};
    case Tone::Problem:
      return {0xff, 0xc8, 0xc8};
    case Tone::Neutral:
      break;
  }
  return {0xe8, 0xee, 0xf8};
}

void setBanner(QLabel* label, const QString& text, Tone tone) {
  label->setText(text);
  label->setVisible(!text.isEmpty());
  label->setAutoFillBackground(true);
  label->setMargin(12);
  QPalette p = label->palette();
  p.setColor(QPalette::Window, toneColour(tone));
  p.setColor(QPalette::WindowText, kText);
  label->setPalette(p);
  static const char* const kTones[] = {
      QT_TRANSLATE_NOOP("armtrack::gui::home::HomeStyle", "information"),
      QT_TRANSLATE_NOOP("armtrack::gui::home::HomeStyle", "well done"),
      QT_TRANSLATE_NOOP("armtrack::gui::home::HomeStyle", "hint"),
      QT_TRANSLATE_NOOP("armtrack::gui::home::HomeStyle", "problem")};
  label->setAccessibleDescription(QCoreApplication::translate("armtrack::gui::home::HomeStyle",
                                                              kTones[static_cast<int>(tone)]));
}

}  // namespace armtrack::gui::home
