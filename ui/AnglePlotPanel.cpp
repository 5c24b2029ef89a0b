#include "ui/AnglePlotPanel.h"

#include <QEvent>
#include <QFontMetrics>
#include <QHeaderView>
#include <QScrollArea>
#include <QScrollBar>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace armtrack::ui {

namespace {
bool isDark(const QPalette& p) {
  return p.color(QPalette::Window).lightness() < 128;
}
}  // namespace

AnglePlotPanel::AnglePlotPanel(QWidget* parent)
    : QWidget(parent), m_trace(m_window + 1.0), m_trunkTrace(m_window + 1.0) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  m_splitter = new QSplitter(Qt::Horizontal, this);
  m_splitter->setChildrenCollapsible(true);
  layout->addWidget(m_splitter);

  // The plots scroll when the panel is too low for each to be at least kMinPlotHeight high.
  m_scroll = new QScrollArea(m_splitter);
  m_scroll->setWidgetResizable(true);
  m_scroll->setFrameShape(QFrame::NoFrame);
  m_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  auto* plots = new QWidget(m_scroll);
  m_scroll->setWidget(plots);
  auto* plotLayout = new QVBoxLayout(plots);
  plotLayout->setContentsMargins(0, 0, 0, 0);
  plotLayout->setSpacing(0);
  for (int a = 0; a < kAngleCount; ++a) {
    auto* c = new AngleChart(a, plots);
    c->setMinimumHeight(kMinPlotHeight);
    c->setIncremental(m_mode == Mode::Live);
    connect(c, &AngleChart::clicked, this, [this](double t) {
      if (m_mode == Mode::Review) emit cursorRequested(t);
    });
    m_charts[static_cast<std::size_t>(a)] = c;
    plotLayout->addWidget(c, 1);
  }
  m_trunkChart = new TrunkChart(plots);
  m_trunkChart->setMinimumHeight(kMinPlotHeight);
  m_trunkChart->hide();  // until rows carry trunk angles
  connect(m_trunkChart, &TrunkChart::clicked, this, [this](double t) {
    if (m_mode == Mode::Review) emit cursorRequested(t);
  });
  plotLayout->addWidget(m_trunkChart, 1);
  m_table = new AngleTableModel(this);
  m_tableView = new QTableView(m_splitter);
  m_tableView->setModel(m_table);
  m_tableView->verticalHeader()->hide();
  m_tableView->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
  m_tableView->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_tableView->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_tableView->setTabKeyNavigation(false);
  // Angle names wrap onto a second line when the panel is narrow, so the numbers stay in view.
  m_tableView->setWordWrap(true);
  m_tableView->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_tableView->verticalHeader()->setMinimumSectionSize(
      m_tableView->verticalHeader()->defaultSectionSize());
  m_tableView->setColumnHidden(AngleTableModel::Target, true);  // until there is a target
  m_splitter->setStretchFactor(0, 4);
  m_splitter->setStretchFactor(1, 1);

  const bool dark = isDark(palette());
  for (AngleChart* c : m_charts) c->setDark(dark);
  m_trunkChart->setDark(dark);
  connect(&m_timer, &QTimer::timeout, this, [this] {
    if (m_dirty && isVisible()) redraw(false);
  });
  setRefreshRate(30.0);
  retranslateUi();
}

void AnglePlotPanel::retranslateUi() {
  setAccessibleName(tr("Joint angle plots"));
  m_tableView->setAccessibleName(tr("Joint angles table"));
  m_tableView->setAccessibleDescription(
      tr("The current value of each angle, its uncertainty, the range over the plotted time "
         "and the target"));
  m_sized = false;  // the names' widths change with the language
  sizeTable();
  markDirty();
}

void AnglePlotPanel::setMode(Mode mode) {
  m_mode = mode;
  for (AngleChart* c : m_charts) c->setIncremental(mode == Mode::Live);
  m_trace.setKeepSeconds(mode == Mode::Live ? m_window + 1.0
                                            : std::numeric_limits<double>::infinity());
  m_trunkTrace.setKeepSeconds(mode == Mode::Live ? m_window + 1.0
                                                 : std::numeric_limits<double>::infinity());
  markDirty();
}

void AnglePlotPanel::setWindowSeconds(double seconds) {
  m_window = std::clamp(std::isfinite(seconds) ? seconds : 20.0, 10.0, 30.0);
  if (m_mode == Mode::Live) {
    m_trace.setKeepSeconds(m_window + 1.0);
    m_trunkTrace.setKeepSeconds(m_window + 1.0);
  }
  markDirty();
}

void AnglePlotPanel::append(const std::vector<AngleSample>& rows) {
  if (m_trace.append(rows) > 0) markDirty();
  appendTrunk(rows);
}

void AnglePlotPanel::appendTrunk(const std::vector<AngleSample>& rows) {
  std::vector<AngleSample> trunk;
  for (const AngleSample& r : rows) {
    if (!r.hasTrunk()) continue;
    AngleSample s;
    s.t = r.t;
    s.deg.fill(kNoAngle);
    for (std::size_t i = 0; i < kTrunkAngleCount; ++i) {
      s.deg[i] = r.trunkDeg[i];
      s.sigmaDeg[i] = r.trunkSigmaDeg[i];
    }
    trunk.push_back(s);
  }
  if (trunk.empty() || m_trunkTrace.append(trunk) == 0) return;
  if (m_trunkChart->isHidden()) m_trunkChart->show();
  markDirty();
}

void AnglePlotPanel::clear() {
  m_trace.clear();
  m_trunkTrace.clear();
  m_trunkChart->hide();
  m_overlay.reset();
  m_decor.events.clear();
  m_decor.cursor.reset();
  markDirty();
}

void AnglePlotPanel::setSession(const std::vector<AngleSample>& rows) {
  setMode(Mode::Review);
  m_trace.clear();
  m_trace.append(rows);
  // Stored analyses without trunk angles show no trunk plot.
  m_trunkTrace.clear();
  m_trunkChart->hide();
  appendTrunk(rows);
  markDirty();
}

void AnglePlotPanel::setOverlay(const std::vector<AngleSample>& rows) {
  m_overlay.emplace();
  m_overlay->append(rows);
  markDirty();
}

void AnglePlotPanel::clearOverlay() {
  m_overlay.reset();
  markDirty();
}

void AnglePlotPanel::setCursor(std::optional<double> t) {
  m_decor.cursor = t && std::isfinite(*t) ? t : std::nullopt;
  markDirty();
}

void AnglePlotPanel::setTarget(int angle, double minDeg, double maxDeg) {
  if (angle < 0 || angle >= kAngleCount || !std::isfinite(minDeg) || !std::isfinite(maxDeg)) return;
  if (m_targetAngle) m_table->setTarget(*m_targetAngle, std::nullopt);
  m_targetAngle = angle;
  m_decor.targetDeg = std::make_pair(std::min(minDeg, maxDeg), std::max(minDeg, maxDeg));
  m_table->setTarget(angle, m_decor.targetDeg);
  showTargetColumn(true);
  markDirty();
}

void AnglePlotPanel::clearTarget() {
  if (m_targetAngle) m_table->setTarget(*m_targetAngle, std::nullopt);
  m_targetAngle.reset();
  m_decor.targetDeg.reset();
  showTargetColumn(false);
  markDirty();
}

void AnglePlotPanel::showTargetColumn(bool show) {
  if (m_tableView->isColumnHidden(AngleTableModel::Target) != show) return;
  m_tableView->setColumnHidden(AngleTableModel::Target, !show);
  m_laidOutFor = -1;
  m_sized = false;  // the table's width changed
  sizeTable();
}

void AnglePlotPanel::addEvent(double t, const QString& label) {
  if (!std::isfinite(t)) return;
  m_decor.events.emplace_back(t, label);
  markDirty();
}

void AnglePlotPanel::setAnglesShown(const std::vector<int>& angles) {
  for (int a = 0; a < kAngleCount; ++a)
    m_charts[static_cast<std::size_t>(a)]->setVisible(std::find(angles.begin(), angles.end(), a) !=
                                                      angles.end());
  markDirty();
}

void AnglePlotPanel::setTableVisible(bool visible) {
  m_tableView->setVisible(visible);
}

void AnglePlotPanel::setRefreshRate(double hz) {
  if (std::isfinite(hz) && hz > 0.0) {
    m_timer.start(static_cast<int>(std::lround(1000.0 / std::min(hz, 120.0))));
  } else {
    m_timer.stop();
  }
}

void AnglePlotPanel::redraw(bool table) {
  m_dirty = false;
  ++m_redraws;
  if (m_mode == Mode::Live) {
    m_t1 = std::max(m_trace.lastTime(), m_window);
    m_t0 = m_t1 - m_window;
  } else {
    m_t0 = m_trace.firstTime();
    m_t1 = m_trace.lastTime();
    if (m_overlay && !m_overlay->empty()) {
      m_t0 = std::min(m_t0, m_overlay->firstTime());
      m_t1 = std::max(m_t1, m_overlay->lastTime());
    }
    if (!(m_t1 > m_t0)) m_t1 = m_t0 + 1.0;
  }
  const AngleTrace* overlay = m_overlay ? &*m_overlay : nullptr;
  for (std::size_t a = 0; a < kAngleCount; ++a) {
    ChartDecor decor = m_decor;
    if (!m_targetAngle || *m_targetAngle != static_cast<int>(a)) decor.targetDeg.reset();
    if (m_charts[a]->isVisible()) m_charts[a]->draw(m_trace, overlay, m_t0, m_t1, decor);
  }
  if (!m_trunkChart->isHidden())
    m_trunkChart->draw(m_trunkTrace, m_t0, m_t1,
                       m_mode == Mode::Review ? m_decor.cursor : std::nullopt);
  // The table: the value at the cursor (review) or the newest (live), and the plotted range.
  if (m_mode == Mode::Live && !table && m_tableClock.isValid() &&
      m_tableClock.elapsed() < 1000.0 / kTableHz)
    return;
  m_tableClock.start();
  std::array<double, kAngleCount> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  const auto& rows = m_trace.samples();
  // A plotted angle's extremes are those of its drawn columns; a hidden one is scanned.
  std::array<bool, kAngleCount> scan{};
  for (std::size_t a = 0; a < kAngleCount; ++a) {
    scan[a] = !m_charts[a]->isVisible();
    if (!scan[a]) std::tie(lo[a], hi[a]) = m_charts[a]->plottedRange();
  }
  if (std::find(scan.begin(), scan.end(), true) != scan.end())
    for (std::size_t i = m_trace.lowerBound(m_t0); i < rows.size() && rows[i].t <= m_t1; ++i)
      for (std::size_t a = 0; a < kAngleCount; ++a) {
        const double v = rows[i].deg[a];
        if (!scan[a] || !std::isfinite(v)) continue;
        lo[a] = std::min(lo[a], v);
        hi[a] = std::max(hi[a], v);
      }
  for (std::size_t a = 0; a < kAngleCount; ++a)
    if (!std::isfinite(lo[a])) lo[a] = hi[a] = std::numeric_limits<double>::quiet_NaN();
  const AngleSample* current = nullptr;
  if (m_mode == Mode::Review && m_decor.cursor)
    current = m_trace.at(*m_decor.cursor);
  else if (!rows.empty())
    current = &rows.back();
  m_table->setValues(current, lo, hi);
  emit tableUpdated(current);
}

void AnglePlotPanel::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  if (event->type() == QEvent::PaletteChange) {
    const bool dark = isDark(palette());
    for (AngleChart* c : m_charts) c->setDark(dark);
    m_trunkChart->setDark(dark);
    markDirty();
  }
  QWidget::changeEvent(event);
}

void AnglePlotPanel::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  sizeTable();
}

void AnglePlotPanel::sizeTable() {
  if (!isVisible() || width() < 200) return;
  const QFontMetrics metrics(m_tableView->font());
  const int padding = metrics.horizontalAdvance(QStringLiteral("M"));
  if (!m_sized) {
    m_sized = true;
    m_laidOutFor = -1;
    m_tableView->resizeColumnsToContents();
    // The table is sized once, often before the first values arrive: give each number column
    // room for the widest value it can show, so "-179.9°" is never cut to "-1…".
    const QString widestAngle = formatDegrees(-179.9);
    m_numbersWidth = 0;
    for (int c = AngleTableModel::Value; c < AngleTableModel::ColumnCount; ++c) {
      QStringList widest{widestAngle};
      if (c == AngleTableModel::Uncertainty) {
        widest = {confidenceText(179.9), doubtText(AngleDoubt::SensorLost, true)};
        for (AngleDoubt d : {AngleDoubt::Heading, AngleDoubt::Uncertain})
          widest << QStringLiteral("%1 %2").arg(confidenceText(49.9), doubtText(d, true));
      } else if (c == AngleTableModel::Target) {
        widest = {
            QStringLiteral("%1 \u2013 %2").arg(formatDegrees(-180, 0), formatDegrees(180, 0))};
      }
      int need = m_tableView->columnWidth(c);
      for (const QString& w : widest) need = std::max(need, metrics.horizontalAdvance(w) + padding);
      m_tableView->setColumnWidth(c, need);
      if (!m_tableView->isColumnHidden(c)) m_numbersWidth += m_tableView->columnWidth(c);
    }
    m_nameWidth = m_tableView->columnWidth(AngleTableModel::Name);
    m_twoLinesWidth = 0;  // the narrowest width that holds every name in two lines
    for (int a = 0; a < kAngleCount; ++a) {
      const QStringList words = angleDisplayName(a).split(QLatin1Char(' '));
      int best = metrics.horizontalAdvance(words.join(QLatin1Char(' ')));
      for (qsizetype k = 1; k < words.size(); ++k)
        best = std::min(best, std::max(metrics.horizontalAdvance(words.mid(0, k).join(' ')),
                                       metrics.horizontalAdvance(words.mid(k).join(' '))));
      m_twoLinesWidth = std::max(m_twoLinesWidth, best + 2 * padding);
    }
  }
  if (m_laidOutFor == width()) return;
  m_laidOutFor = width();
  const int chrome =
      m_tableView->verticalScrollBar()->sizeHint().width() + 2 * m_tableView->frameWidth();
  // Beside the plots, the table takes at most 55 % of the panel, its names in two lines if
  // need be; narrower than that, it goes below the plots, as wide as the panel, so that every
  // column stays in view.
  const int cap = width() * 11 / 20;
  int name = m_nameWidth;
  if (m_numbersWidth + name + chrome > cap)
    name = std::max(cap - m_numbersWidth - chrome, m_twoLinesWidth);
  const bool beside = m_numbersWidth + name + chrome <= cap;
  if (!beside)
    name = std::max(m_twoLinesWidth, std::min(m_nameWidth, width() - m_numbersWidth - chrome));
  m_tableView->setColumnWidth(AngleTableModel::Name, name);
  m_tableView->resizeRowsToContents();
  if (beside) {
    m_splitter->setOrientation(Qt::Horizontal);
    const int table = std::min(m_tableView->horizontalHeader()->length() + chrome, cap);
    m_splitter->setSizes({width() - table, table});
  } else {
    m_splitter->setOrientation(Qt::Vertical);
    const int table = m_tableView->horizontalHeader()->sizeHint().height() +
                      m_tableView->verticalHeader()->length() + 2 * m_tableView->frameWidth();
    m_splitter->setSizes({std::max(height() - table, kMinPlotHeight), table});
  }
}

void AnglePlotPanel::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  sizeTable();
  markDirty();  // the number of pixel columns changed
}

}  // namespace armtrack::ui
