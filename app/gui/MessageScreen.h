// A screen that says one thing and offers a few actions: a database that cannot be opened, the
// home mode that arrives later, work in progress with a progress bar.
#pragma once

#include <QWidget>
#include <functional>

class QLabel;
class QProgressBar;
class QHBoxLayout;
class QPushButton;

namespace armtrack::gui {

class MessageScreen : public QWidget {
  Q_OBJECT
 public:
  MessageScreen(const QString& title, const QString& text, QWidget* parent = nullptr);
  /// Adds a button; the first one added is the default (Enter).
  QPushButton* addAction(const QString& text, std::function<void()> action);
  /// Shows a progress bar (percent 0-100; -1: busy without a known end).
  void setProgress(int percent);
  void setText(const QString& text);

 private:
  QLabel* m_text;
  QProgressBar* m_progress;
  QHBoxLayout* m_buttons;
};

}  // namespace armtrack::gui
