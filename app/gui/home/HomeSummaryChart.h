// The summary's chart (Qt Charts): for each exercise, the farthest angle reached today beside
// the target's far end and the last home sessions', as bars. An exercise that was not measured
// has no bar of today's, and says so in its category.
#pragma once

#include <QChartView>
#include <vector>

#include "app/gui/services/HomeRecords.h"

namespace armtrack::gui::home {

class HomeSummaryChart : public QChartView {
  Q_OBJECT
 public:
  explicit HomeSummaryChart(QWidget* parent = nullptr);
  /// results: today's, one per exercise; history: the earlier sessions per exercise (same
  /// order), newest last.
  void setResults(const std::vector<HomeExerciseResult>& results,
                  const std::vector<std::vector<HomeHistoryEntry>>& history);
  /// The bars drawn: set name -> value per exercise (deg; NaN where there is none).
  std::vector<std::pair<QString, std::vector<double>>> bars() const { return m_bars; }

 private:
  std::vector<std::pair<QString, std::vector<double>>> m_bars;
};

}  // namespace armtrack::gui::home
