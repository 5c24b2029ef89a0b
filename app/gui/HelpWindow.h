// The user guide (docs/user-guide.md, built into the program with its pictures) in a window of
// its own, in the user's language where the guide is translated (docs/user-guide.<code>.md),
// otherwise in English with a note that says so. F1 opens it at the section about the screen
// shown, under a line that says what to do on that screen.
#pragma once

#include <QString>
#include <QWidget>

class QLabel;
class QTextBrowser;

namespace armtrack::gui {

class HelpWindow : public QWidget {
  Q_OBJECT
 public:
  explicit HelpWindow(QWidget* parent = nullptr);

  /// Shows the guide in the current language, scrolled to the first heading found of
  /// headings (none found, or empty: the top), with hint ("what to do here") above it.
  void showFor(const QString& hint, const QStringList& headings);

  /// The guide's resource for a language: ":/help/user-guide.<code>.md" when it exists,
  /// else the English ":/help/user-guide.md".
  static QString guideFor(const QString& language);

  QTextBrowser* browser() const { return m_browser; }
  /// The line above the guide (the screen's hint and, for an untranslated guide, a note).
  QString hintText() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void load();
  void retranslateUi();

  QLabel* m_hint;
  QTextBrowser* m_browser;
  QString m_loaded;  // the resource shown
  QString m_hintText;
  QStringList m_headings;
};

/// What to do on a screen, in one or two sentences of the current language, and the guide's
/// headings (English and translated) of the section about it; by the screen's class.
struct ScreenHelp {
  QString hint;
  QStringList headings;
};
ScreenHelp screenHelp(const QWidget* screen);

}  // namespace armtrack::gui
