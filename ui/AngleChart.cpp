#include "ui/AngleChart.h"

#include <QAreaSeries>
#include <QEvent>
#include <QLineSeries>
#include <QLocale>
#include <QMouseEvent>
#include <QValueAxis>
#include <algorithm>
#include <cmath>

#include "ui/AngleTableModel.h"
#include "ui/AngleTraceItem.h"
#include "ui/TimeChart.h"

namespace armtrack::ui {

namespace {
constexpr std::size_t kMaxMarkers = 16;
constexpr double kMinSpanDeg = 20.0;
constexpr double kAxisLimitDeg = 360.0;  // a multiple of every tick step

/// The smallest of the usual steps that splits span into at most maxTicks intervals.
double niceStep(double span, int maxTicks, std::initializer_list<double> steps) {
  double last = 1.0;
  for (double s : steps) {
    last = s;
    if (span / s <= maxTicks) return s;
  }
  while (span / last > maxTicks) last *= 2;
  return last;
}

QList<QPointF> toList(const std::vector<QPointF>& v) {
  return QList<QPointF>(v.begin(), v.end());
}
}  // namespace

QColor angleColour(int angle, bool dark) {
  static const QColor light[kAngleCount] = {QColor(0x1f, 0x5f, 0xbf), QColor(0xc2, 0x4b, 0x0f),
                                            QColor(0x2c, 0x8a, 0x3c), QColor(0x8a, 0x2b, 0xb0),
                                            QColor(0xb0, 0x1e, 0x4a)};
  static const QColor darkColours[kAngleCount] = {
      QColor(0x6a, 0xa8, 0xff), QColor(0xff, 0x9b, 0x5a), QColor(0x6f, 0xd6, 0x7f),
      QColor(0xc9, 0x8b, 0xff), QColor(0xff, 0x7a, 0xa2)};
  if (angle < 0 || angle >= kAngleCount) return Qt::gray;
  return dark ? darkColours[angle] : light[angle];
}

AngleChart::AngleChart(int angle, QWidget* parent)
    : QChartView(parent), m_angle(angle), m_chart(new QChart) {
  m_chart->legend()->hide();
  const TimeAxes axes = setUpTimeChart(*this, *m_chart);
  m_x = axes.x;
  m_y = axes.y;
  m_y->setTickCount(6);
  auto attach = [&](QAbstractSeries* s) { attachToAxes(*m_chart, s, axes); };
  m_targetUpper = new QLineSeries(this);
  m_targetLower = new QLineSeries(this);
  m_target = new QAreaSeries(m_targetUpper, m_targetLower);
  attach(m_target);
  m_bandUpper = new QLineSeries(this);
  m_bandLower = new QLineSeries(this);
  m_band = new QAreaSeries(m_bandUpper, m_bandLower);
  attach(m_band);
  m_overlay = new QLineSeries;
  attach(m_overlay);
  m_line = new QLineSeries;  // empty: placed for mapToValue(); AngleTraceItem draws the angle
  attach(m_line);
  m_trace = new AngleTraceItem(m_chart);
  m_trace->setZValue(1000);  // above the series (the target band, the overlay)
  connect(m_chart, &QChart::plotAreaChanged, this, [this] { m_trace->relayout(); });
  m_cursor = new QLineSeries;
  attach(m_cursor);
  m_x->setRange(0, 10);
  m_y->setRange(m_yMin, m_yMax);
  setDark(false);
  retranslateUi();
}

void AngleChart::retranslateUi() {
  const QString name = angleDisplayName(m_angle);
  m_chart->setTitle(tr("%1 (\u00b0)").arg(name));
  m_chart->setLocale(QLocale());
  m_chart->setLocalizeNumbers(true);
  setAccessibleName(name);
  setAccessibleDescription(
      tr("Plot of %1 over time in degrees; the table beside it holds the same numbers").arg(name));
  m_target->setName(tr("Target"));
  m_band->setName(tr("likely range"));
  m_overlay->setName(tr("Compared session"));
  m_line->setName(name);
}

void AngleChart::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  QChartView::changeEvent(event);
}

void AngleChart::setDark(bool dark) {
  m_dark = dark;
  const QColor fg = applyTimeChartColours(*m_chart, {m_x, m_y}, dark);
  const QColor c = angleColour(m_angle, dark);
  setSeriesPen(m_line, c, 2.0);
  m_trace->setLinePen(m_line->pen());
  QColor band = c;
  band.setAlpha(dark ? 70 : 55);
  m_band->setBrush(band);
  m_band->setPen(Qt::NoPen);
  m_trace->setBandColour(band);
  QColor target = dark ? QColor(0x4c, 0xc2, 0x6a) : QColor(0x2e, 0x9e, 0x4f);
  target.setAlpha(dark ? 60 : 45);
  m_target->setBrush(target);
  QPen tp(target.darker(dark ? 80 : 130));
  tp.setStyle(Qt::DashLine);
  tp.setCosmetic(true);
  m_target->setPen(tp);
  setSeriesPen(m_overlay, dark ? QColor(0xbb, 0xbb, 0xbb) : QColor(0x55, 0x55, 0x55), 1.5,
               Qt::DashLine);
  setSeriesPen(m_cursor, fg, 1.0);
  for (QLineSeries* m : m_markers)
    setSeriesPen(m, dark ? QColor(0xff, 0xd0, 0x40) : QColor(0xb0, 0x70, 0x00), 1.0, Qt::DotLine);
}

QLineSeries* AngleChart::verticalLine(std::size_t index) {
  while (m_markers.size() <= index) {
    auto* s = new QLineSeries;
    attachToAxes(*m_chart, s, {m_x, m_y});
    setSeriesPen(s, m_dark ? QColor(0xff, 0xd0, 0x40) : QColor(0xb0, 0x70, 0x00), 1.0, Qt::DotLine);
    m_markers.push_back(s);
  }
  return m_markers[index];
}

void AngleChart::fitY(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return;
  lo = std::clamp(lo, -kAxisLimitDeg, kAxisLimitDeg);
  hi = std::clamp(hi, -kAxisLimitDeg, kAxisLimitDeg);
  if (hi - lo < kMinSpanDeg) {
    const double mid = (lo + hi) / 2;
    lo = mid - kMinSpanDeg / 2;
    hi = mid + kMinSpanDeg / 2;
  }
  // Round out to a step of 5-180 deg; grow at once, shrink only when the data use under 60 % of
  // the axis, so the axis does not twitch with every frame. Fixed ticks on the step (Qt Charts'
  // dynamic ticks elide labels after a range change).
  const double step = niceStep(hi - lo, 4, {5, 10, 15, 20, 30, 45, 60, 90, 180});
  const double wantLo = std::floor(lo / step) * step, wantHi = std::ceil(hi / step) * step;
  const bool grow = wantLo < m_yMin || wantHi > m_yMax;
  const bool shrink = (wantHi - wantLo) < 0.6 * (m_yMax - m_yMin);
  if (grow || shrink) {
    double newLo = grow && !shrink ? std::min(wantLo, m_yMin) : wantLo;
    double newHi = grow && !shrink ? std::max(wantHi, m_yMax) : wantHi;
    const double newStep = niceStep(newHi - newLo, 4, {5, 10, 15, 20, 30, 45, 60, 90, 180});
    m_yMin = std::floor(newLo / newStep) * newStep;
    m_yMax = std::ceil(newHi / newStep) * newStep;
    m_y->setRange(m_yMin, m_yMax);
    m_y->setTickCount(static_cast<int>(std::lround((m_yMax - m_yMin) / newStep)) + 1);
  }
}

void AngleChart::draw(const AngleTrace& trace, const AngleTrace* overlay, double t0, double t1,
                      const ChartDecor& decor) {
  if (!(t1 > t0)) t1 = t0 + 1.0;
  const int columns = std::max(1, static_cast<int>(m_chart->plotArea().width() / 2));
  m_columns = columns;
  if (m_incremental) {
    m_decimator.update(trace, m_angle, (t1 - t0) / columns, decor.sigmaFactor, kAxisLimitDeg);
    m_decimator.points(t0, t1, m_points, m_upper, m_lower);
  } else {
    decimateAngle(trace, m_angle, t0, t1, columns, m_points, kAxisLimitDeg);
    decimateBand(trace, m_angle, t0, t1, columns, decor.sigmaFactor, m_upper, m_lower,
                 kAxisLimitDeg);
  }
  m_pointsDrawn = static_cast<int>(m_points.size());
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const QPointF& p : m_points) {
    if (p.x() < t0 || p.x() > t1) continue;
    lo = std::min(lo, p.y());
    hi = std::max(hi, p.y());
  }
  m_plotted = std::isfinite(lo) ? std::make_pair(lo, hi)
                                : std::make_pair(std::numeric_limits<double>::quiet_NaN(),
                                                 std::numeric_limits<double>::quiet_NaN());
  // The band widens the axis only as far as the data themselves reach plus 30 deg, so a
  // sigma of 1e3 deg (no optical data for a long time) does not squash the angle flat.
  for (std::size_t i = 0; i < m_upper.size(); ++i) {
    m_upper[i].setY(std::min(m_upper[i].y(), hi + 30.0));
    m_lower[i].setY(std::max(m_lower[i].y(), lo - 30.0));
  }
  m_trace->setPoints(m_points, m_upper, m_lower);

  std::vector<QPointF> ov;
  if (overlay) decimateAngle(*overlay, m_angle, t0, t1, columns, ov, kAxisLimitDeg);
  m_overlay->replace(toList(ov));
  for (const QPointF& p : ov) {
    if (p.x() < t0 || p.x() > t1) continue;
    lo = std::min(lo, p.y());
    hi = std::max(hi, p.y());
  }
  if (decor.targetDeg) {
    const auto [tmin, tmax] = *decor.targetDeg;
    m_targetUpper->replace(QList<QPointF>{{t0, tmax}, {t1, tmax}});
    m_targetLower->replace(QList<QPointF>{{t0, tmin}, {t1, tmin}});
    lo = std::min(lo, tmin);
    hi = std::max(hi, tmax);
  } else {
    m_targetUpper->clear();
    m_targetLower->clear();
  }
  m_target->setVisible(decor.targetDeg.has_value());
  if (std::isfinite(lo)) fitY(lo - 3.0, hi + 3.0);

  std::size_t used = 0;
  for (const auto& [t, label] : decor.events) {
    if (t < t0 || t > t1 || used >= kMaxMarkers) continue;
    QLineSeries* s = verticalLine(used++);
    s->replace(QList<QPointF>{{t, m_yMin}, {t, m_yMax}});
    s->setName(label);
    s->setVisible(true);
  }
  for (std::size_t i = used; i < m_markers.size(); ++i) m_markers[i]->setVisible(false);
  if (decor.cursor && *decor.cursor >= t0 && *decor.cursor <= t1) {
    m_cursor->replace(QList<QPointF>{{*decor.cursor, m_yMin}, {*decor.cursor, m_yMax}});
    m_cursor->setVisible(true);
  } else {
    m_cursor->setVisible(false);
  }
  if (m_x->min() != t0 || m_x->max() != t1) {
    m_x->setRange(t0, t1);
    m_x->setTickInterval(niceStep(t1 - t0, 6, {1, 2, 5, 10, 15, 30, 60, 120, 300, 600}));
  }
}

void AngleChart::setIncremental(bool on) {
  m_incremental = on;
  m_decimator.clear();
}

void AngleChart::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && m_chart->plotArea().contains(event->position())) {
    const QPointF v = m_chart->mapToValue(event->position(), m_line);
    emit clicked(v.x());
    event->accept();
    return;
  }
  QChartView::mousePressEvent(event);
}

}  // namespace armtrack::ui
