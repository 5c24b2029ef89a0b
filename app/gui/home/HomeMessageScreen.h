// A message in the home window: a heading, words, and one or two large buttons (loading, a
// problem with what to do, the goodbye). Its words are functions, so they are said again in the
// new language when it changes.
#pragma once

#include <functional>
#include <vector>

#include "app/gui/home/HomeScreen.h"

class QLabel;
class QPushButton;

namespace armtrack::gui::home {

class HomeMessageScreen : public HomeScreen {
  Q_OBJECT
 public:
  using Text = std::function<QString()>;
  HomeMessageScreen(Text title, Text text, QWidget* parent = nullptr);

  /// Adds a large button; the first added is the main choice.
  QPushButton* addChoice(Text label, std::function<void()> action);
  QString title() const;
  QString text() const;

  QList<QAbstractButton*> choices() const override;
  QAbstractButton* defaultChoice() const override;

 protected:
  void retranslate() override;

 private:
  Text m_titleText, m_bodyText;
  QLabel* m_title;
  QLabel* m_text;
  QWidget* m_buttons;
  std::vector<std::pair<QPushButton*, Text>> m_choices;
};

}  // namespace armtrack::gui::home
