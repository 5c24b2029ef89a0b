// What every screen of the home window offers the window: the buttons a single switch steps
// through, the one Space or Enter presses ("go on"), and what Escape does (pause). One class per
// screen derives from it (docs/user-guide.md, "At home").
#pragma once

#include <QAbstractButton>
#include <QEvent>
#include <QList>
#include <QWidget>

namespace armtrack::gui::home {

class HomeScreen : public QWidget {
  Q_OBJECT
 public:
  using QWidget::QWidget;

  /// The choices, in the order a single switch scans them (hidden or disabled ones are skipped).
  virtual QList<QAbstractButton*> choices() const = 0;
  /// The choice Space, Enter or a "press to go on" switch takes (may be null: nothing to do).
  virtual QAbstractButton* defaultChoice() const = 0;
  /// Escape: pause what is running, or nothing.
  virtual void escapePressed() {}

 signals:
  /// The choices or the default one changed (a new phase of the screen).
  void choicesChanged();

 protected:
  /// Sets every word again in the language now in effect (after a LanguageChange).
  virtual void retranslate() {}
  void changeEvent(QEvent* event) override {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
  }
};

}  // namespace armtrack::gui::home
