#include "ui/TrunkChart.h"

#include <QEvent>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLocale>
#include <QMouseEvent>
#include <QValueAxis>
#include <algorithm>
#include <cmath>

#include "ui/Fonts.h"
#include "ui/TimeChart.h"

namespace armtrack::ui {

namespace {
constexpr double kMinHalfSpanDeg = 10.0;
constexpr double kLimitDeg = 90.0;  // a trunk angle beyond this is not a lean: clamp the axis
}  // namespace

QString TrunkChart::angleName(int angle) {
  switch (angle) {
    case 0:
      return tr("Trunk flexion");
    case 1:
      return tr("Trunk lateral bending");
    case 2:
      return tr("Trunk axial rotation");
    default:
      return {};
  }
}

QColor TrunkChart::colour(int angle, bool dark) {
  // Teal, brown and slate: apart from each other and from the five arm angles' colours.
  static const QColor light[kTrunkAngleCount] = {QColor(0x00, 0x80, 0x80), QColor(0x8b, 0x5a, 0x2b),
                                                 QColor(0x4a, 0x55, 0x6b)};
  static const QColor darkColours[kTrunkAngleCount] = {
      QColor(0x4f, 0xd8, 0xd0), QColor(0xe0, 0xb0, 0x70), QColor(0xb0, 0xbc, 0xd6)};
  if (angle < 0 || angle >= kTrunkAngleCount) return Qt::gray;
  return dark ? darkColours[angle] : light[angle];
}

TrunkChart::TrunkChart(QWidget* parent) : QChartView(parent), m_chart(new QChart) {
  m_chart->legend()->setAlignment(Qt::AlignRight);
  m_chart->legend()->setFont(scaledFont(m_chart->legend()->font(), 0.85));
  const TimeAxes axes = setUpTimeChart(*this, *m_chart);
  m_x = axes.x;
  m_y = axes.y;
  for (auto& line : m_lines) {
    line = new QLineSeries(this);
    attachToAxes(*m_chart, line, axes);
  }
  m_cursor = new QLineSeries(this);
  attachToAxes(*m_chart, m_cursor, axes);
  // The legend names the three angles only.
  for (QLegendMarker* marker : m_chart->legend()->markers(m_cursor)) marker->setVisible(false);
  m_x->setRange(0, 10);
  m_y->setRange(m_yMin, m_yMax);
  m_y->setTickCount(5);
  setDark(false);
  retranslateUi();
}

void TrunkChart::retranslateUi() {
  const QString title = tr("Trunk");
  m_chart->setTitle(tr("%1 (\u00b0)").arg(title));
  m_chart->setLocale(QLocale());
  m_chart->setLocalizeNumbers(true);
  for (int a = 0; a < kTrunkAngleCount; ++a)
    m_lines[static_cast<std::size_t>(a)]->setName(angleName(a));
  setAccessibleName(tr("Trunk plot"));
  setAccessibleDescription(
      tr("Trunk flexion, lateral bending and axial rotation over time in degrees, relative to "
         "the start pose"));
}

void TrunkChart::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  QChartView::changeEvent(event);
}

void TrunkChart::setDark(bool dark) {
  const QColor fg = applyTimeChartColours(*m_chart, {m_x, m_y}, dark);
  m_chart->legend()->setLabelColor(fg);
  // Solid, dashed and dotted as well as coloured: told apart without colour too.
  const Qt::PenStyle styles[kTrunkAngleCount] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine};
  for (int a = 0; a < kTrunkAngleCount; ++a)
    setSeriesPen(m_lines[static_cast<std::size_t>(a)], colour(a, dark), 2.0, styles[a]);
  setSeriesPen(m_cursor, fg, 1.0);
}

void TrunkChart::draw(const AngleTrace& trunk, double t0, double t1, std::optional<double> cursor) {
  m_x->setRange(t0, t1);
  const int columns = std::max(1, static_cast<int>(m_chart->plotArea().width() / 2));
  double lo = 0, hi = 0;
  for (int a = 0; a < kTrunkAngleCount; ++a) {
    decimateAngle(trunk, a, t0, t1, columns, m_points, kLimitDeg);
    for (const QPointF& p : m_points) {
      if (p.x() < t0 || p.x() > t1) continue;
      lo = std::min(lo, p.y());
      hi = std::max(hi, p.y());
    }
    m_lines[static_cast<std::size_t>(a)]->replace(QList<QPointF>(m_points.begin(), m_points.end()));
  }
  // Symmetric about zero (upright), in steps of 5 deg; grows at once, never twitches down.
  const double half = std::max({kMinHalfSpanDeg, -lo, hi});
  const double want = std::min(kLimitDeg, std::ceil(half / 5.0) * 5.0);
  if (want > m_yMax || want < 0.6 * m_yMax) {
    m_yMin = -want;
    m_yMax = want;
    m_y->setRange(m_yMin, m_yMax);
  }
  if (cursor && std::isfinite(*cursor))
    m_cursor->replace({QPointF(*cursor, m_yMin), QPointF(*cursor, m_yMax)});
  else
    m_cursor->clear();
}

void TrunkChart::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && m_chart->plotArea().contains(event->position()))
    emit clicked(m_chart->mapToValue(event->position(), m_lines[0]).x());
  QChartView::mousePressEvent(event);
}

}  // namespace armtrack::ui
