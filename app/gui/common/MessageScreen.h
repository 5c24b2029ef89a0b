// A screen that says one thing and offers a few actions: a database that cannot be opened, the
// home mode that arrives later, work in progress with a progress bar. Its texts are made by the
// caller's tr() calls (TextFn), so they follow a switch of language.
#pragma once

#include <QWidget>
#include <functional>
#include <vector>

#include "app/gui/common/Forms.h"

class QLabel;
class QProgressBar;
class QHBoxLayout;
class QPushButton;

namespace armtrack::gui {

class MessageScreen : public QWidget {
  Q_OBJECT
 public:
  MessageScreen(TextFn title, TextFn text, QWidget* parent = nullptr);
  /// Adds a button; the first one added is the default (Enter).
  QPushButton* addAction(TextFn text, std::function<void()> action);
  /// Shows a progress bar (percent 0-100; -1: busy without a known end).
  void setProgress(int percent);
  void setText(TextFn text);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();

  TextFn m_titleText, m_bodyText;
  std::vector<std::pair<QPushButton*, TextFn>> m_actions;
  QLabel* m_heading;
  QLabel* m_text;
  QProgressBar* m_progress;
  QHBoxLayout* m_buttons;
};

}  // namespace armtrack::gui
