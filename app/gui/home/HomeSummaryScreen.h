// The end of a home session: what was done (repetitions, the range reached against the target
// and the last sessions, a chart), the patient's pain score (0-10) and comment, saved with the
// sessions for the therapist.
#pragma once

#include <optional>
#include <vector>

#include "app/gui/home/HomeScreen.h"
#include "app/gui/services/HomeRecords.h"

class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace armtrack::gui::home {

class HomeSummaryChart;

class HomeSummaryScreen : public HomeScreen {
  Q_OBJECT
 public:
  HomeSummaryScreen(const HomePlan& plan, const std::vector<HomeExerciseResult>& results,
                    QWidget* parent = nullptr);

  /// The pain score chosen (none until one is).
  std::optional<int> painScore() const;
  void setPainScore(std::optional<int> score);
  QString comment() const;
  void setComment(const QString& text);
  /// One line per exercise, as shown.
  QStringList lines() const { return m_lines; }
  HomeSummaryChart* chart() const { return m_chart; }
  /// After saving: saved, or why not (the patient can try again).
  void showSaved(bool ok, const QString& message);
  QString status() const;

  QList<QAbstractButton*> choices() const override;
  QAbstractButton* defaultChoice() const override;

  /// "Elbow flexion: 10 of 10 repetitions; ..." for one exercise (translated).
  static QString line(const HomeExerciseResult& r, const std::vector<HomeHistoryEntry>& history);

 signals:
  void saveRequested(std::optional<int> painScore, const QString& comment);
  void closeRequested();

 protected:
  void retranslate() override;

 private:
  void showPain();

  HomePlan m_plan;
  std::vector<HomeExerciseResult> m_results;
  int m_pain = -1;  // -1: not said
  bool m_saved = false;
  QStringList m_lines;
  QList<QLabel*> m_lineLabels;
  HomeSummaryChart* m_chart;
  QLabel* m_heading;
  QLabel* m_painQuestion;
  QLabel* m_commentQuestion;
  QLabel* m_painValue;
  QLabel* m_status;
  QPlainTextEdit* m_comment;
  QPushButton* m_less;
  QPushButton* m_more;
  QPushButton* m_save;
  QPushButton* m_close;
};

}  // namespace armtrack::gui::home
