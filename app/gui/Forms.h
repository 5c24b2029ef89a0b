// Small helpers the screens share: a message line for errors and notices, and a heading.
#pragma once

#include <QFrame>
#include <QLabel>
#include <QString>

class QVBoxLayout;

namespace armtrack::gui {

/// A line that tells the user what went wrong (or went right) and what to do next. Hidden when
/// empty; screen readers announce it (accessible name "Message").
class MessageLine : public QFrame {
  Q_OBJECT
 public:
  enum class Kind { Error, Notice };
  explicit MessageLine(QWidget* parent = nullptr);
  void showMessage(const QString& text, Kind kind = Kind::Error);
  void clear();
  QString text() const { return m_label->text(); }
  Kind kind() const { return m_kind; }

 private:
  QLabel* m_label;
  Kind m_kind = Kind::Error;
};

/// Lays screen out as one column of at most width (device-independent pixels), centred, and
/// returns the column's layout (its widget in *column).
QVBoxLayout* centredColumn(QWidget* screen, int width, QWidget** column);

/// A bold, larger label for the top of a screen.
QLabel* heading(const QString& text, QWidget* parent);

}  // namespace armtrack::gui
