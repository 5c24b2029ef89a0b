#include "app/gui/home/HomeSummaryChart.h"

#include <QBarCategoryAxis>
#include <QBarSeries>
#include <QBarSet>
#include <QChart>
#include <QDateTime>
#include <QLocale>
#include <QValueAxis>
#include <cmath>
#include <limits>

namespace armtrack::gui::home {

namespace {
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
}

HomeSummaryChart::HomeSummaryChart(QWidget* parent) : QChartView(parent) {
  setRenderHint(QPainter::Antialiasing);
  setMinimumHeight(220);
  setAccessibleName(tr("Chart of the range reached"));
}

void HomeSummaryChart::setResults(const std::vector<HomeExerciseResult>& results,
                                  const std::vector<std::vector<HomeHistoryEntry>>& history) {
  m_bars.clear();
  QStringList categories;
  std::size_t earlier = 0;
  for (const auto& h : history) earlier = std::max(earlier, h.size());
  // Oldest first: "3 sessions ago", ..., "last time", then today and the target.
  for (std::size_t k = earlier; k > 0; --k) {
    std::vector<double> v;
    for (std::size_t i = 0; i < results.size(); ++i) {
      const auto& h = i < history.size() ? history[i] : std::vector<HomeHistoryEntry>{};
      const std::ptrdiff_t at =
          static_cast<std::ptrdiff_t>(h.size()) - static_cast<std::ptrdiff_t>(k);
      v.push_back(at >= 0 && h[static_cast<std::size_t>(at)].result.rangeMaxDeg
                      ? *h[static_cast<std::size_t>(at)].result.rangeMaxDeg
                      : kNone);
    }
    m_bars.emplace_back(k == 1 ? tr("Last time") : tr("%1 sessions ago").arg(k), v);
  }
  std::vector<double> today, target;
  for (const HomeExerciseResult& r : results) {
    today.push_back(r.rangeMaxDeg.value_or(kNone));
    target.push_back(r.targetMaxDeg);
    categories << (r.measured ? r.exercise : tr("%1 (not measured)").arg(r.exercise));
  }
  m_bars.emplace_back(tr("Today"), today);
  m_bars.emplace_back(tr("Target"), target);

  auto* series = new QBarSeries;
  double top = 10;
  // Colours that stay apart for colour-blind eyes: greys for the past, blue today, green target.
  const QColor colours[] = {QColor(0xb0, 0xb0, 0xb0), QColor(0x80, 0x80, 0x80),
                            QColor(0x50, 0x50, 0x50)};
  for (std::size_t s = 0; s < m_bars.size(); ++s) {
    auto* set = new QBarSet(m_bars[s].first);
    for (double v : m_bars[s].second) {
      *set << (std::isfinite(v) ? v : 0.0);
      if (std::isfinite(v)) top = std::max(top, v);
    }
    if (m_bars[s].first == tr("Today"))
      set->setColor(QColor(0x0b, 0x3d, 0x91));
    else if (m_bars[s].first == tr("Target"))
      set->setColor(QColor(0x00, 0x7a, 0x2e));
    else
      set->setColor(colours[std::min<std::size_t>(earlier - 1 - s, 2)]);
    series->append(set);
  }
  auto* chart = new QChart;
  chart->addSeries(series);
  chart->setTitle(tr("Farthest angle reached (degrees)"));
  auto* x = new QBarCategoryAxis;
  x->append(categories);
  auto* y = new QValueAxis;
  y->setRange(0, std::ceil(top / 10) * 10 + 10);
  y->setLabelFormat(QStringLiteral("%d"));
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  series->attachAxis(x);
  series->attachAxis(y);
  chart->legend()->setAlignment(Qt::AlignBottom);
  QFont f = font();
  chart->setTitleFont(f);
  chart->legend()->setFont(f);
  x->setLabelsFont(f);
  y->setLabelsFont(f);
  QChart* old = this->chart();
  setChart(chart);
  delete old;
}

}  // namespace armtrack::gui::home
