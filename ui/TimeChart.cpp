#include "ui/TimeChart.h"

#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QValueAxis>

#include "ui/Fonts.h"

namespace armtrack::ui {

TimeAxes setUpTimeChart(QChartView& view, QChart& chart) {
  chart.setAnimationOptions(QChart::NoAnimation);
  chart.setMargins(QMargins(4, 2, 4, 2));
  chart.setBackgroundRoundness(0);
  chart.setTitleFont(scaledFont(chart.titleFont(), 0.9));
  view.setChart(&chart);
  view.setRenderHint(QPainter::Antialiasing, false);
  view.setMinimumSize(1, 1);
  view.setFocusPolicy(Qt::NoFocus);
  TimeAxes axes{new QValueAxis, new QValueAxis};
  axes.x->setLabelFormat(QStringLiteral("%.0f s"));
  axes.y->setLabelFormat(QStringLiteral("%.0f"));
  // Qt Charts elides labels ("...") it sized while the chart was tiny and keeps them so.
  axes.x->setTruncateLabels(false);
  axes.y->setTruncateLabels(false);
  axes.x->setTickType(QValueAxis::TicksDynamic);
  axes.x->setTickAnchor(0.0);
  axes.x->setTickInterval(5.0);
  chart.addAxis(axes.x, Qt::AlignBottom);
  chart.addAxis(axes.y, Qt::AlignLeft);
  return axes;
}

void attachToAxes(QChart& chart, QAbstractSeries* series, const TimeAxes& axes) {
  chart.addSeries(series);
  series->attachAxis(axes.x);
  series->attachAxis(axes.y);
}

QColor applyTimeChartColours(QChart& chart, const TimeAxes& axes, bool dark) {
  const QColor bg = dark ? QColor(0x23, 0x25, 0x29) : QColor(Qt::white);
  const QColor fg = dark ? QColor(0xe6, 0xe6, 0xe6) : QColor(0x20, 0x20, 0x20);
  const QColor grid = dark ? QColor(0x3c, 0x40, 0x46) : QColor(0xdd, 0xdd, 0xdd);
  chart.setBackgroundBrush(bg);
  chart.setPlotAreaBackgroundVisible(false);
  chart.setTitleBrush(fg);
  for (QValueAxis* a : {axes.x, axes.y}) {
    a->setLabelsBrush(fg);
    a->setGridLineColor(grid);
    a->setLinePenColor(grid);
  }
  return fg;
}

void setSeriesPen(QLineSeries* series, const QColor& colour, double width, Qt::PenStyle style) {
  QPen pen(colour);
  pen.setWidthF(width);
  pen.setStyle(style);
  pen.setCosmetic(true);
  series->setPen(pen);
}

}  // namespace armtrack::ui
