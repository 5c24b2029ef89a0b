// The angle's line and its +-k sigma band inside an AngleChart, painted straight from the
// decimated points. A QLineSeries strokes its whole path at every update to find its shape for
// mouse hits, and a QAreaSeries fills and outlines a polygon: on the live plots, at 40 redraws a
// second, that was the larger part of the GUI thread's plotting time. The item needs no hit
// shape (a click on the plot is the chart view's), and draws the band as one rectangle per
// pixel column.
#pragma once

#include <QColor>
#include <QGraphicsItem>
#include <QPen>
#include <vector>

class QChart;

namespace armtrack::ui {

class AngleTraceItem : public QGraphicsItem {
 public:
  /// chart: the chart whose plot area and axes (the first horizontal and vertical) place the
  /// points; the item becomes its child.
  explicit AngleTraceItem(QChart* chart);

  /// The line's points and the band's upper and lower points (seconds, degrees; the band's in
  /// pairs at the same time). Copies them; the chart repaints the item.
  void setPoints(const std::vector<QPointF>& line, const std::vector<QPointF>& upper,
                 const std::vector<QPointF>& lower);
  void setLinePen(const QPen& pen);
  void setBandColour(const QColor& colour);
  /// The plot area moved or the axes changed: repaint where the chart now is.
  void relayout();

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

 private:
  QChart* m_chart;
  std::vector<QPointF> m_line, m_upper, m_lower;
  QPen m_pen;
  QColor m_band;
  QRectF m_area;
};

}  // namespace armtrack::ui
