// The repetition counter of a live session: repetitions done of the protocol's target, partial
// ones apart, and whether one is under way. Fed by a core RepetitionCounter.
#pragma once

#include <QWidget>
#include <optional>

class QLabel;
class QProgressBar;

namespace armtrack {
class RepetitionCounter;
}

namespace armtrack::ui {

class RepetitionCounterWidget : public QWidget {
  Q_OBJECT
 public:
  explicit RepetitionCounterWidget(QWidget* parent = nullptr);

  /// The protocol's number of repetitions; empty: no target (the count alone is shown).
  void setTarget(std::optional<int> repetitions);
  /// The angle counted on, named in the caption.
  void setAngleName(const QString& name);
  /// Shows the counter's state (call from the GUI timer).
  void showCount(const RepetitionCounter& counter);
  /// The text shown, for tests and screen readers.
  QString text() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  QString m_angleName;
  QLabel* m_caption;
  QLabel* m_count;
  QLabel* m_detail;
  QProgressBar* m_progress;
  std::optional<int> m_target;
  std::size_t m_full = 0, m_partial = 0;
  bool m_inside = false;
  void render();
};

}  // namespace armtrack::ui
