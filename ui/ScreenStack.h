// One screen at a time, for a window that shows its screens in turn (the therapist's main
// window, the home window): showing a screen removes the one before and deletes it.
#pragma once

#include <QPointer>
#include <QStackedWidget>

namespace armtrack::ui {

class ScreenStack : public QStackedWidget {
  Q_OBJECT
 public:
  explicit ScreenStack(QWidget* parent = nullptr);

  /// Shows screen (the stack takes it) in place of the current one, which is removed and
  /// deleted later: it may be what asked for the change, from one of its own slots.
  void showScreen(QWidget* screen);
  /// The screen shown, or nullptr.
  QWidget* screen() const { return m_current; }

 private:
  QPointer<QWidget> m_current;
};

}  // namespace armtrack::ui
