// The joint-angle plots: the five clinical angles in degrees, each with its +-2 sigma band from
// the estimator's uncertainty, the protocol's target band, event markers and, beside them, the
// same numbers in a table for screen readers. Live: a scrolling 10-30 s window fed in batches;
// review: a whole session with a time cursor and a second session overlaid.
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>
#include <array>
#include <optional>
#include <vector>

#include "ui/AngleChart.h"
#include "ui/AngleTableModel.h"
#include "ui/AngleTrace.h"
#include "ui/TrunkChart.h"

class QScrollArea;
class QTableView;
class QSplitter;

namespace armtrack::ui {

/// Appending only stores rows: the plots redraw at most refreshRate() times a second, each angle
/// decimated to the pixels shown, so a 1 kHz stream costs no more than a 30 Hz one. GUI thread
/// only.
class AnglePlotPanel : public QWidget {
  Q_OBJECT
 public:
  enum class Mode { Live, Review };

  explicit AnglePlotPanel(QWidget* parent = nullptr);

  void setMode(Mode mode);
  Mode mode() const { return m_mode; }
  /// The live window (s), clamped to 10-30 s. Default 20 s.
  void setWindowSeconds(double seconds);
  double windowSeconds() const { return m_window; }

  /// Live: rows in time order (degrees). Rows out of order or with a non-finite time are
  /// refused and counted (trace().refused()).
  void append(const std::vector<AngleSample>& rows);
  /// Forgets every row, event and cursor (a new session).
  void clear();
  /// Review: the whole session, shown from its first to its last time.
  void setSession(const std::vector<AngleSample>& rows);
  /// Review: a second session drawn dashed over the first, on its own times.
  void setOverlay(const std::vector<AngleSample>& rows);
  void clearOverlay();
  /// Review: the time cursor (s); empty hides it.
  void setCursor(std::optional<double> t);
  /// The protocol's target range of one angle (deg); other angles' targets are cleared.
  void setTarget(int angle, double minDeg, double maxDeg);
  void clearTarget();
  /// A marker at time t (s) on every plot, e.g. "pain" or "rest".
  void addEvent(double t, const QString& label);
  /// Which angles get a plot (all five by default); the table always lists all five.
  void setAnglesShown(const std::vector<int>& angles);
  /// Shows or hides the numeric table beside the plots.
  void setTableVisible(bool visible);

  /// Live, the table's figures change at most this many times a second (refreshIfChanged()).
  static constexpr double kTableHz = 5.0;
  /// Each plot is at least this high (px); when the panel is lower, the plots scroll.
  static constexpr int kMinPlotHeight = 120;
  /// At most this many redraws a second (default 30); 0 redraws only on refresh().
  void setRefreshRate(double hz);

  AngleTableModel* tableModel() const { return m_table; }
  QTableView* tableView() const { return m_tableView; }
  const AngleTrace& trace() const { return m_trace; }
  AngleChart* chart(int angle) const { return m_charts[static_cast<std::size_t>(angle)]; }
  /// The trunk's plot: shown once rows carry trunk angles (a sternum sensor), hidden otherwise.
  TrunkChart* trunkChart() const { return m_trunkChart; }
  /// The trunk's angles as plotted (deg[0..2]: flexion, lateral bending, axial rotation).
  const AngleTrace& trunkTrace() const { return m_trunkTrace; }
  /// The time span plotted (s).
  std::pair<double, double> timeSpan() const { return {m_t0, m_t1}; }
  std::uint64_t redraws() const { return m_redraws; }

 public slots:
  /// Redraws now, the table too.
  void refresh() { redraw(true); }
  /// Redraws if something changed since the last redraw (for an owner that drives the redraws
  /// from its own timer, with setRefreshRate(0), so that every view repaints in one pass). Live,
  /// the table's figures change at most kTableHz times a second: enough to read, and the table
  /// repainting at the plots' rate cost as much as a plot.
  void refreshIfChanged() {
    if (m_dirty) redraw(false);
  }

 signals:
  /// Review: the user clicked a time on a plot.
  void cursorRequested(double t);
  /// The table now shows current (nullptr: none): a view that shows the same angles elsewhere
  /// (the live screen's big numbers) follows it, so that both always show the same sample.
  void tableUpdated(const armtrack::ui::AngleSample* current);

 protected:
  void changeEvent(QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  void markDirty() { m_dirty = true; }
  void retranslateUi();
  /// When first shown wide enough, and again when the language or the target column changes:
  /// the table as wide as its columns, within 55 % of the panel (names wrap before numbers hide).
  void sizeTable();
  void showTargetColumn(bool show);
  /// Keeps the rows' trunk angles in m_trunkTrace; shows the trunk's plot when there are some.
  void appendTrunk(const std::vector<AngleSample>& rows);

  Mode m_mode = Mode::Live;
  double m_window = 20.0;
  AngleTrace m_trace;
  std::optional<AngleTrace> m_overlay;
  std::array<AngleChart*, kAngleCount> m_charts{};
  AngleTrace m_trunkTrace;
  TrunkChart* m_trunkChart = nullptr;
  QSplitter* m_splitter = nullptr;
  QScrollArea* m_scroll = nullptr;
  QTableView* m_tableView = nullptr;
  AngleTableModel* m_table = nullptr;
  ChartDecor m_decor;
  std::optional<int> m_targetAngle;
  void redraw(bool table);
  QTimer m_timer;
  QElapsedTimer m_tableClock;
  bool m_dirty = true;
  double m_t0 = 0.0, m_t1 = 20.0;
  std::uint64_t m_redraws = 0;
  bool m_sized = false;
  int m_laidOutFor = -1;  // the width the table was last laid out for
  int m_numbersWidth = 0, m_nameWidth = 0, m_twoLinesWidth = 0;
};

}  // namespace armtrack::ui
