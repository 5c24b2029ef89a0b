#include "ui/AngleTraceItem.h"

#include <QChart>
#include <QPainter>
#include <QValueAxis>
#include <algorithm>

namespace armtrack::ui {

AngleTraceItem::AngleTraceItem(QChart* chart) : QGraphicsItem(chart), m_chart(chart) {
  setFlag(QGraphicsItem::ItemHasNoContents, false);
  setAcceptedMouseButtons(Qt::NoButton);
  setAcceptHoverEvents(false);
  m_area = chart->plotArea();
}

void AngleTraceItem::setPoints(const std::vector<QPointF>& line, const std::vector<QPointF>& upper,
                               const std::vector<QPointF>& lower) {
  m_line = line;
  m_upper = upper;
  m_lower = lower;
  m_lower.resize(std::min(m_upper.size(), m_lower.size()));
  update();
}

void AngleTraceItem::setLinePen(const QPen& pen) {
  m_pen = pen;
  update();
}

void AngleTraceItem::setBandColour(const QColor& colour) {
  m_band = colour;
  update();
}

void AngleTraceItem::relayout() {
  prepareGeometryChange();
  m_area = m_chart->plotArea();
  update();
}

QRectF AngleTraceItem::boundingRect() const {
  // The line's pen reaches a little beyond the plot area's edge.
  return m_area.adjusted(-2, -2, 2, 2);
}

void AngleTraceItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  const auto horizontal = m_chart->axes(Qt::Horizontal);
  const auto vertical = m_chart->axes(Qt::Vertical);
  const auto* x = horizontal.isEmpty() ? nullptr : qobject_cast<QValueAxis*>(horizontal.first());
  const auto* y = vertical.isEmpty() ? nullptr : qobject_cast<QValueAxis*>(vertical.first());
  const QRectF area = m_chart->plotArea();
  if (!x || !y || area.isEmpty() || !(x->max() > x->min()) || !(y->max() > y->min())) return;
  const double sx = area.width() / (x->max() - x->min());
  const double sy = area.height() / (y->max() - y->min());
  const double x0 = area.left() - x->min() * sx, y0 = area.bottom() + y->min() * sy;
  const auto px = [&](double t) { return x0 + t * sx; };
  const auto py = [&](double deg) { return y0 - deg * sy; };

  painter->save();
  painter->setClipRect(area);
  painter->setRenderHint(QPainter::Antialiasing, false);
  if (!m_upper.empty() && m_band.alpha() > 0) {
    // One rectangle per column, as wide as the gap to the next column (at most 4 px).
    std::vector<QRectF> rects;
    rects.reserve(m_upper.size());
    for (std::size_t i = 0; i < m_upper.size(); ++i) {
      const double left = px(m_upper[i].x());
      const double next = i + 1 < m_upper.size() ? px(m_upper[i + 1].x()) : left + 2.0;
      const double width = std::clamp(next - left, 1.0, 4.0);
      const double top = py(m_upper[i].y()), bottom = py(m_lower[i].y());
      rects.emplace_back(left - width / 2, top, width, bottom - top);
    }
    painter->setPen(Qt::NoPen);
    painter->setBrush(m_band);
    painter->drawRects(rects.data(), static_cast<int>(rects.size()));
  }
  if (m_line.size() >= 1) {
    QPolygonF line;
    line.reserve(static_cast<qsizetype>(m_line.size()));
    for (const QPointF& p : m_line) line.append(QPointF(px(p.x()), py(p.y())));
    painter->setPen(m_pen);
    painter->setBrush(Qt::NoBrush);
    if (line.size() == 1)
      painter->drawPoint(line.front());
    else
      painter->drawPolyline(line);
  }
  painter->restore();
}

}  // namespace armtrack::ui
