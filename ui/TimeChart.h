// What the time plots (AngleChart, one clinical angle; TrunkChart, the trunk's three angles)
// share: the chart set up in its view with a time axis and an angle axis, series attached to
// both, the light or dark theme's colours, and cosmetic pens. Internal to armtrack_ui.
#pragma once

#include <QColor>
#include <Qt>

class QAbstractSeries;
class QChart;
class QChartView;
class QLineSeries;
class QValueAxis;

namespace armtrack::ui {

struct TimeAxes {
  QValueAxis* x = nullptr;  ///< time (s), below
  QValueAxis* y = nullptr;  ///< angle (deg), at the left
};

/// Sets chart up in view (which takes it): no animation, small margins, square corners, a title a
/// little smaller than Qt's, no antialiasing (thousands of points at 30 Hz), no focus; a time
/// axis below ("%.0f s", ticks every 5 s from 0) and an angle axis at the left ("%.0f"), neither
/// with labels elided.
TimeAxes setUpTimeChart(QChartView& view, QChart& chart);
/// Adds series to chart on both axes.
void attachToAxes(QChart& chart, QAbstractSeries* series, const TimeAxes& axes);
/// The background, the title and the axes in the theme's colours; returns the text colour.
QColor applyTimeChartColours(QChart& chart, const TimeAxes& axes, bool dark);
/// A cosmetic pen (the same width at every size) of colour, width and style on series.
void setSeriesPen(QLineSeries* series, const QColor& colour, double width,
                  Qt::PenStyle style = Qt::SolidLine);

}  // namespace armtrack::ui
