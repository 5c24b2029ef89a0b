// One clinical angle's plot (internal to AnglePlotPanel): the angle, its +-2 sigma band, the
// protocol's target band, event markers, a time cursor and an overlaid second session.
#pragma once

#include <QChartView>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "ui/AngleTrace.h"

class QLineSeries;
class QAreaSeries;
class QValueAxis;

namespace armtrack::ui {

class AngleTraceItem;

/// What is drawn over the angle besides its samples.
struct ChartDecor {
  std::optional<std::pair<double, double>> targetDeg;  ///< min, max
  std::vector<std::pair<double, QString>> events;      ///< time (s), label
  std::optional<double> cursor;                        ///< s
  double sigmaFactor = 2.0;                            ///< band half-width in sigmas
};

class AngleChart : public QChartView {
  Q_OBJECT
 public:
  explicit AngleChart(int angle, QWidget* parent = nullptr);

  int angle() const { return m_angle; }
  void setDark(bool dark);
  /// Redraws from the trace over [t0, t1] (and the overlay, aligned at its own times).
  void draw(const AngleTrace& trace, const AngleTrace* overlay, double t0, double t1,
            const ChartDecor& decor);
  /// The y axis range shown (deg).
  std::pair<double, double> yRange() const { return {m_yMin, m_yMax}; }
  /// Points in the angle's line after the last draw (for tests and the benchmark).
  int pointsDrawn() const { return m_pointsDrawn; }
  /// Pixel columns the last draw decimated to (two pixels each).
  int columnsDrawn() const { return m_columns; }
  /// Live: decimate incrementally (ColumnDecimator, columns anchored to time) instead of the
  /// whole window at every draw. For a trace that only grows at its end and loses its oldest.
  void setIncremental(bool on);
  /// The smallest and largest value of the angle's line in [t0, t1] at the last draw (NaN when
  /// none): the samples the decimation kept, so the extremes of the plotted columns.
  std::pair<double, double> plottedRange() const { return m_plotted; }

 signals:
  /// The user clicked at time t (s) on the plot (review: moves the cursor).
  void clicked(double t);

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  QLineSeries* verticalLine(std::size_t index);
  void fitY(double lo, double hi);

  int m_angle;
  QChart* m_chart;
  QValueAxis* m_x;
  QValueAxis* m_y;
  QLineSeries* m_line;
  QLineSeries* m_overlay;
  QLineSeries* m_bandUpper;
  QLineSeries* m_bandLower;
  QAreaSeries* m_band;
  QLineSeries* m_targetUpper;
  QLineSeries* m_targetLower;
  QAreaSeries* m_target;
  QLineSeries* m_cursor;
  AngleTraceItem* m_trace;
  std::vector<QLineSeries*> m_markers;
  double m_yMin = -30.0, m_yMax = 120.0;  // a multiple of the initial 30 deg step
  bool m_dark = false;
  int m_pointsDrawn = 0;
  int m_columns = 0;
  std::vector<QPointF> m_points, m_upper, m_lower;
  bool m_incremental = false;
  ColumnDecimator m_decimator;
  std::pair<double, double> m_plotted{std::numeric_limits<double>::quiet_NaN(),
                                      std::numeric_limits<double>::quiet_NaN()};
};

/// The colour of each angle's line (distinct in both palettes).
QColor angleColour(int angle, bool dark);

}  // namespace armtrack::ui
