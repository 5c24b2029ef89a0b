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
  m_chart->setAnimationOptions(QChart::NoAnimation);
  m_chart->setMargins(QMargins(4, 2, 4, 2));
  m_chart->setBackgroundRoundness(0);
  m_chart->setTitleFont(scaledFont(m_chart->titleFont(), 0.9));
  m_chart->legend()->setAlignment(Qt::AlignRight);
  m_chart->legend()->setFont(scaledFont(m_chart->legend()->font(), 0.85));
  setChart(m_chart);
  setRenderHint(QPainter::Antialiasing, false);
  setMinimumSize(1, 1);
  setFocusPolicy(Qt::NoFocus);
  m_x = new QValueAxis;
  m_y = new QValueAxis;
  m_x->setLabelFormat(QStringLiteral("%.0f s"));
  m_y->setLabelFormat(QStringLiteral("%.0f"));
  m_x->setTruncateLabels(false);
  m_y->setTruncateLabels(false);
  m_x->setTickType(QValueAxis::TicksDynamic);
  m_x->setTickAnchor(0.0);
  m_x->setTickInterval(5.0);
  m_chart->addAxis(m_x, Qt::AlignBottom);
  m_chart->addAxis(m_y, Qt::AlignLeft);
  for (auto& line : m_lines) {
    line = new QLineSeries(this);
    m_chart->addSeries(line);
    line->attachAxis(m_x);
    line->attachAxis(m_y);
  }
  m_cursor = new QLineSeries(this);
  m_chart->addSeries(m_cursor);
  m_cursor->attachAxis(m_x);
  m_cursor->attachAxis(m_y);
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
  const QColor bg = dark ? QColor(0x23, 0x25, 0x29) : QColor(Qt::white);
  const QColor fg = dark ? QColor(0xe6, 0xe6, 0xe6) : QColor(0x20, 0x20, 0x20);
  const QColor grid = dark ? QColor(0x3c, 0x40, 0x46) : QColor(0xdd, 0xdd, 0xdd);
  m_chart->setBackgroundBrush(bg);
  m_chart->setPlotAreaBackgroundVisible(false);
  m_chart->setTitleBrush(fg);
  m_chart->legend()->setLabelColor(fg);
  for (QValueAxis* a : {m_x, m_y}) {
    a->setLabelsBrush(fg);
    a->setGridLineColor(grid);
    a->setLinePenColor(grid);
  }
  // Solid, dashed and dotted as well as coloured: told apart without colour too.
  const Qt::PenStyle styles[kTrunkAngleCount] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine};
  for (int a = 0; a < kTrunkAngleCount; ++a) {
    QPen pen(colour(a, dark));
    pen.setWidthF(2.0);
    pen.setStyle(styles[a]);
    pen.setCosmetic(true);
    m_lines[static_cast<std::size_t>(a)]->setPen(pen);
  }
  QPen cursor(fg);
  cursor.setCosmetic(true);
  m_cursor->setPen(cursor);
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
