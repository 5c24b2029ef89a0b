// Small helpers the screens share: a message line for errors and notices, and a heading.
#pragma once

#include <QFrame>
#include <QLabel>
#include <QString>
#include <functional>

class QVBoxLayout;

namespace armtrack::gui {

/// A text in the current language: the tr() call that makes it, run again when the language
/// changes, so that what a screen shows follows a switch of language at run time.
using TextFn = std::function<QString()>;

/// A line that tells the user what went wrong (or went right) and what to do next. Hidden when
/// empty; screen readers announce it (accessible name "Message").
class MessageLine : public QFrame {
  Q_OBJECT
 public:
  enum class Kind { Error, Notice };
  explicit MessageLine(QWidget* parent = nullptr);
  /// Shows text, made again in the new language when the language changes.
  void showMessage(TextFn text, Kind kind = Kind::Error);
  /// Shows a text that stays as it is (e.g. the records' own words).
  void showMessage(const QString& text, Kind kind = Kind::Error);
  void clear();
  QString text() const { return m_label->text(); }
  Kind kind() const { return m_kind; }

 protected:
  void changeEvent(QEvent* event) override;

 private:
  QLabel* m_label;
  TextFn m_text;
  Kind m_kind = Kind::Error;
};

/// A label whose text follows a change of language.
class TranslatedLabel : public QLabel {
  Q_OBJECT
 public:
  explicit TranslatedLabel(TextFn text, QWidget* parent = nullptr);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  TextFn m_text;
};

/// Lays screen out as one column of at most width (device-independent pixels), centred, and
/// returns the column's layout (its widget in *column).
QVBoxLayout* centredColumn(QWidget* screen, int width, QWidget** column);

/// A bold, larger label for the top of a screen.
QLabel* heading(const QString& text, QWidget* parent);
/// Sets a heading's text and its accessible name.
void setHeading(QLabel* heading, const QString& text);

/// Whether event is the one Qt sends every widget when a translator is installed or removed
/// (QEvent::LanguageChange): a screen then sets its texts again (its retranslateUi()).
bool isLanguageChange(const QEvent* event);

}  // namespace armtrack::gui
