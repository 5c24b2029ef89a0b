#include "core/reports/Charts.h"

#include "core/reports/ReportText.h"

#include <QFontMetricsF>
#include <QLocale>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace armtrack::reports {
namespace {

const QColor kLine(30, 80, 200);              // the patient's data
const QColor kBand(120, 200, 120, 90);        // protocol target
const QColor kNormal(150, 150, 150, 80);      // normal range, bars
const QColor kNormalSpan(150, 150, 150, 45);  // normal range of motion behind a ROM line
const QColor kGrid(225, 225, 225);

/// Data area of a chart inside its outer rect, with the mapping from data to device units.
struct Frame {
  QRectF plot;
  double xlo = 0, xhi = 1, ylo = 0, yhi = 1;
  double px(double x) const { return plot.left() + (x - xlo) / (xhi - xlo) * plot.width(); }
  double py(double y) const { return plot.bottom() - (y - ylo) / (yhi - ylo) * plot.height(); }
};

QString number(double v) {
  if (std::abs(v) < 1e-9) v = 0;
  return reportLocale().toString(v, 'g', 6);
}

/// Title, grid, frame, ticks and their labels, axis titles.
void drawAxes(PageWriter& w, const Frame& f, const QRectF& outer, const QString& title,
              const std::vector<double>& xTicks, const std::function<QString(double)>& xLabel,
              const QString& xTitle, const std::vector<double>& yTicks, const QString& yTitle) {
  QPainter& p = w.painter();
  const QFontMetricsF fm(w.fonts().small, w.device());
  p.save();
  p.setFont(w.fonts().smallBold);
  p.setPen(Qt::black);
  p.drawText(QRectF(f.plot.left(), outer.top(), f.plot.width(), fm.height()),
             Qt::AlignLeft | Qt::AlignVCenter, title);
  p.setFont(w.fonts().small);
  p.setPen(QPen(kGrid, w.mm(0.15)));
  for (double y : yTicks)
    p.drawLine(QPointF(f.plot.left(), f.py(y)), QPointF(f.plot.right(), f.py(y)));
  p.setPen(QPen(Qt::black, w.mm(0.2)));
  p.drawRect(f.plot);
  const double tick = w.mm(1.0);
  const double labelTop = fm.height() * 0.5 + w.mm(0.3);
  for (double y : yTicks) {
    p.drawLine(QPointF(f.plot.left() - tick, f.py(y)), QPointF(f.plot.left(), f.py(y)));
    p.drawText(QRectF(outer.left(), f.py(y) - fm.height() / 2,
                      f.plot.left() - outer.left() - tick * 1.5, fm.height()),
               Qt::AlignRight | Qt::AlignVCenter, number(y));
  }
  for (double x : xTicks) {
    p.drawLine(QPointF(f.px(x), f.plot.bottom()), QPointF(f.px(x), f.plot.bottom() + tick));
    const QString label = xLabel(x);
    const double lw = fm.horizontalAdvance(label) + w.mm(1);
    p.drawText(QRectF(f.px(x) - lw / 2, f.plot.bottom() + labelTop, lw, fm.height()),
               Qt::AlignHCenter | Qt::AlignTop, label);
  }
  p.drawText(
      QRectF(f.plot.left(), f.plot.bottom() + labelTop + fm.height(), f.plot.width(), fm.height()),
      Qt::AlignRight | Qt::AlignTop, xTitle);
  // The y unit above the tick labels, horizontal so it reads (and extracts) as text.
  p.drawText(QRectF(outer.left(), outer.top(), f.plot.left() - outer.left(), fm.height()),
             Qt::AlignLeft | Qt::AlignVCenter, yTitle);
  p.restore();
}

Frame frameIn(PageWriter& w, const QRectF& r) {
  const QFontMetricsF fm(w.fonts().small, w.device());
  Frame f;
  // Title row above; below: tick labels (starting half a line down, clear of the lowest y
  // label) and the axis title.
  f.plot = QRectF(r.left() + w.mm(14), r.top() + fm.height() + w.mm(1.5), r.width() - w.mm(16),
                  r.height() - 3.5 * fm.height() - w.mm(2.5));
  return f;
}

}  // namespace

std::vector<double> niceTicks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi) || target < 1) return ticks;
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  // The candidate step nearest to the raw one (on a log scale).
  double step = mag;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (std::abs(std::log(m * mag / raw)) < std::abs(std::log(step / raw))) step = m * mag;
  const double first = std::ceil(lo / step - 1e-9);
  for (double k = first; k * step <= hi + step * 1e-9; k += 1) ticks.push_back(k * step + 0.0);
  return ticks;
}

void drawTimePlot(PageWriter& w, const QRectF& r, const QString& title,
                  const std::vector<double>& tS, const std::vector<double>& yDeg,
                  const std::optional<Band>& band, const std::vector<TimeMark>& marks,
                  std::optional<double> originS, const std::vector<TimeMark>& events) {
  Frame f = frameIn(w, r);
  const std::size_t n = std::min(tS.size(), yDeg.size());
  double ylo = std::numeric_limits<double>::infinity(), yhi = -ylo;
  for (std::size_t i = 0; i < n; ++i)
    if (std::isfinite(yDeg[i])) {
      ylo = std::min(ylo, yDeg[i]);
      yhi = std::max(yhi, yDeg[i]);
    }
  if (band) {
    ylo = std::min(ylo, band->loDeg);
    yhi = std::max(yhi, band->hiDeg);
  }
  if (!std::isfinite(ylo)) ylo = 0, yhi = 1;
  const double mid = (ylo + yhi) / 2, half = std::max((yhi - ylo) / 2, 5.0) * 1.1;
  f.ylo = mid - half;
  f.yhi = mid + half;
  if (!marks.empty()) f.yhi += 0.25 * half;  // headroom for the marks above the curve
  // Time from the first finite sample; the median step between finite samples.
  std::vector<double> finiteT;
  for (std::size_t i = 0; i < n; ++i)
    if (std::isfinite(tS[i])) finiteT.push_back(tS[i]);
  const double t0 = originS && std::isfinite(*originS) ? *originS
                    : finiteT.empty()                  ? 0.0
                                                       : finiteT.front();
  std::vector<double> steps;
  for (std::size_t i = 1; i < finiteT.size(); ++i) steps.push_back(finiteT[i] - finiteT[i - 1]);
  double medianStep = std::numeric_limits<double>::infinity();
  if (!steps.empty()) {
    std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
    medianStep = steps[steps.size() / 2];
  }
  f.xlo = 0;
  f.xhi = !finiteT.empty() && finiteT.back() > t0 + 1e-9 ? finiteT.back() - t0 : 1.0;
  const std::vector<double> yTicks = niceTicks(f.ylo, f.yhi, 4);
  const std::vector<double> xTicks = niceTicks(f.xlo, f.xhi, 8);

  QPainter& p = w.painter();
  p.save();
  if (band) {
    const QRectF b(f.plot.left(), f.py(band->hiDeg), f.plot.width(),
                   f.py(band->loDeg) - f.py(band->hiDeg));
    p.fillRect(b.intersected(f.plot), kBand);
  }
  drawAxes(w, f, r, title, xTicks, number, Text::tr("time (s)"), yTicks, Text::tr("deg"));
  if (band) {
    p.setFont(w.fonts().small);
    p.setPen(QColor(40, 110, 40));
    p.drawText(QRectF(f.plot.left(), r.top(), f.plot.width(), w.mm(4)),
               Qt::AlignRight | Qt::AlignVCenter, band->label);
  }
  if (!marks.empty()) {
    const QFontMetricsF fm(w.fonts().small, w.device());
    p.setFont(w.fonts().small);
    p.setPen(QColor(60, 60, 60));
    double lastRight = -std::numeric_limits<double>::infinity();
    for (const TimeMark& m : marks) {
      const double x = f.px(m.tS - t0);
      const double width = fm.horizontalAdvance(m.label) + w.mm(1);
      if (x - width / 2 < lastRight || x < f.plot.left() || x > f.plot.right()) continue;
      p.drawText(QRectF(x - width / 2, f.plot.top() + w.mm(0.3), width, fm.height()),
                 Qt::AlignHCenter | Qt::AlignTop, m.label);
      lastRight = x + width / 2;
    }
    // Legend on the axis-title row, left of "time (s)".
    p.drawText(QRectF(f.plot.left(), f.plot.bottom() + fm.height() * 1.5 + w.mm(0.3),
                      f.plot.width() * 0.75, fm.height()),
               Qt::AlignLeft | Qt::AlignTop,
               Text::tr("numbers: repetitions at their peaks (p = partial)"));
  }
  if (!events.empty()) {
    const QFontMetricsF fm(w.fonts().small, w.device());
    p.setFont(w.fonts().small);
    QPen dashed(QColor(170, 60, 20));
    dashed.setStyle(Qt::DashLine);
    dashed.setWidthF(w.mm(0.25));
    for (const TimeMark& e : events) {
      const double x = f.px(e.tS - t0);
      if (!std::isfinite(x) || x < f.plot.left() || x > f.plot.right()) continue;
      p.setPen(dashed);
      p.drawLine(QPointF(x, f.plot.top()), QPointF(x, f.plot.bottom()));
      p.setPen(QColor(170, 60, 20));
      p.drawText(QRectF(x + w.mm(0.5), f.plot.bottom() - fm.height() - w.mm(0.3),
                        fm.horizontalAdvance(e.label) + w.mm(1), fm.height()),
                 Qt::AlignLeft | Qt::AlignVCenter, e.label);
    }
  }
  // Min and max per column of about 0.25 mm keep every peak while bounding the path's size. The
  // line breaks at a non-finite value and across a gap: a step over 10 times the median step.
  const int columns = std::max(1, static_cast<int>(f.plot.width() / w.mm(0.25)));
  const double maxStep = 10.0 * medianStep;
  QPainterPath path;
  bool open = false;
  auto add = [&](std::size_t k) {
    const QPointF pt(f.px(tS[k] - t0), f.py(yDeg[k]));
    if (open)
      path.lineTo(pt);
    else
      path.moveTo(pt);
    open = true;
  };
  auto usable = [&](std::size_t k) { return std::isfinite(yDeg[k]) && std::isfinite(tS[k]); };
  auto column = [&](std::size_t k) {
    return static_cast<int>((tS[k] - t0) / (f.xhi - f.xlo) * columns);
  };
  std::size_t i = 0;
  while (i < n) {
    if (!usable(i)) {
      open = false;
      ++i;
      continue;
    }
    const int col = column(i);
    std::size_t j = i + 1, jmin = i, jmax = i;
    while (j < n && usable(j) && column(j) == col && tS[j] - tS[j - 1] <= maxStep) {
      if (yDeg[j] < yDeg[jmin]) jmin = j;
      if (yDeg[j] > yDeg[jmax]) jmax = j;
      ++j;
    }
    add(std::min(jmin, jmax));
    if (jmin != jmax) add(std::max(jmin, jmax));
    if (j < n && usable(j) && tS[j] - tS[j - 1] > maxStep) open = false;  // a gap follows
    i = j;
  }
  p.setClipRect(f.plot);
  p.setPen(QPen(kLine, w.mm(0.3), Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  p.setBrush(Qt::NoBrush);
  p.drawPath(path);
  p.restore();
}

double normativeBarsHeight(const PageWriter& w, std::size_t n) {
  return w.mm(7.5) * static_cast<double>(n) + w.mm(10);
}

void drawNormativeBars(PageWriter& w, const QRectF& r, const std::vector<NormativeBar>& bars) {
  QPainter& p = w.painter();
  const QFontMetricsF fm(w.fonts().small, w.device());
  double lo = -100, hi = 190;
  for (const NormativeBar& b : bars) {
    lo = std::min({lo, b.minDeg, b.normalLoDeg.value_or(0.0)});
    hi = std::max({hi, b.maxDeg, b.normalHiDeg});
  }
  Frame f;
  f.plot = QRectF(r.left() + w.mm(42), r.top(), r.width() - w.mm(42 + 52), w.mm(7.5) * bars.size());
  f.xlo = lo;
  f.xhi = hi;
  p.save();
  p.setFont(w.fonts().small);
  const std::vector<double> ticks = niceTicks(lo, hi, 8);
  p.setPen(QPen(kGrid, w.mm(0.15)));
  for (double x : ticks)
    p.drawLine(QPointF(f.px(x), f.plot.top()), QPointF(f.px(x), f.plot.bottom()));
  p.setPen(QPen(Qt::black, w.mm(0.25)));
  p.drawLine(QPointF(f.px(0), f.plot.top()), QPointF(f.px(0), f.plot.bottom()));
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const NormativeBar& b = bars[i];
    const double top = f.plot.top() + w.mm(7.5) * i;
    const QRectF row(f.plot.left(), top + w.mm(1), f.plot.width(), w.mm(5.5));
    const double nlo = b.normalLoDeg.value_or(0.0);
    p.fillRect(QRectF(f.px(nlo), row.top(), f.px(b.normalHiDeg) - f.px(nlo), row.height()),
               kNormal);
    const QRectF patient(f.px(b.minDeg), row.top() + w.mm(1.5),
                         std::max(f.px(b.maxDeg) - f.px(b.minDeg), w.mm(0.4)), w.mm(2.5));
    p.fillRect(patient, kLine);
    p.setPen(Qt::black);
    p.drawText(QRectF(r.left(), row.top(), w.mm(40), row.height()),
               Qt::AlignLeft | Qt::AlignVCenter, b.name);
    p.drawText(QRectF(f.plot.right() + w.mm(2), row.top(), w.mm(50), row.height()),
               Qt::AlignLeft | Qt::AlignVCenter, b.caption);
  }
  p.setPen(QPen(Qt::black, w.mm(0.2)));
  p.drawLine(QPointF(f.plot.left(), f.plot.bottom()), QPointF(f.plot.right(), f.plot.bottom()));
  for (double x : ticks) {
    p.drawLine(QPointF(f.px(x), f.plot.bottom()), QPointF(f.px(x), f.plot.bottom() + w.mm(1)));
    const QString label = number(x);
    p.drawText(QRectF(f.px(x) - w.mm(6), f.plot.bottom() + w.mm(1), w.mm(12), fm.height()),
               Qt::AlignHCenter | Qt::AlignTop, label);
  }
  p.drawText(
      QRectF(f.plot.left(), f.plot.bottom() + w.mm(1) + fm.height(), f.plot.width(), fm.height()),
      Qt::AlignRight | Qt::AlignTop, Text::tr("angle (deg)"));
  p.restore();
}

void drawDateChart(PageWriter& w, const QRectF& r, const QString& title,
                   const std::vector<QDateTime>& when,
                   const std::vector<std::optional<double>>& valuesDeg,
                   std::optional<double> normalSpanDeg) {
  Frame f = frameIn(w, r);
  const std::size_t n = std::min(when.size(), valuesDeg.size());
  // Days since the first session, so the x axis is proportional to time.
  const QDateTime origin = n > 0 ? when.front() : QDateTime::currentDateTimeUtc();
  auto day = [&](const QDateTime& t) { return origin.msecsTo(t) / 86400000.0; };
  double last = 0, top = normalSpanDeg.value_or(5.0), bottom = 0;
  for (std::size_t i = 0; i < n; ++i) {
    last = std::max(last, day(when[i]));
    if (valuesDeg[i]) {
      top = std::max(top, *valuesDeg[i]);
      bottom = std::min(bottom, *valuesDeg[i]);  // below 0: never reached the neutral position
    }
  }
  f.xlo = -0.5;
  f.xhi = std::max(last, 1.0) + 0.5;
  f.ylo = bottom < 0 ? bottom * 1.1 - 1 : 0;
  f.yhi = top * 1.1 + 1;
  std::vector<double> xTicks;
  for (double d : niceTicks(0, f.xhi, 5))
    if (std::abs(d - std::round(d)) < 1e-9) xTicks.push_back(d);
  const std::vector<double> yTicks = niceTicks(f.ylo, f.yhi, 4);
  QPainter& p = w.painter();
  p.save();
  if (normalSpanDeg)
    p.fillRect(
        QRectF(f.plot.left(), f.py(*normalSpanDeg), f.plot.width(), f.py(0) - f.py(*normalSpanDeg)),
        kNormalSpan);
  const QDate first = origin.date();
  drawAxes(
      w, f, r, title, xTicks,
      [&](double d) { return formatDate(first.addDays(static_cast<qint64>(std::lround(d)))); },
      Text::tr("date"), yTicks, Text::tr("deg"));
  if (normalSpanDeg) {
    p.setPen(QPen(QColor(90, 90, 90), w.mm(0.25), Qt::DashLine));
    p.drawLine(QPointF(f.plot.left(), f.py(*normalSpanDeg)),
               QPointF(f.plot.right(), f.py(*normalSpanDeg)));
    p.setFont(w.fonts().small);
    p.drawText(QRectF(f.plot.left(), r.top(), f.plot.width(), w.mm(4)),
               Qt::AlignRight | Qt::AlignVCenter,
               Text::tr("shaded: AAOS normal range of motion, 0-%1 deg")
                   .arg(reportLocale().toString(*normalSpanDeg, 'f', 0)));
  }
  QPainterPath path;
  bool open = false;
  p.setPen(QPen(kLine, w.mm(0.35)));
  p.setBrush(kLine);
  for (std::size_t i = 0; i < n; ++i) {
    if (!valuesDeg[i]) continue;
    const QPointF pt(f.px(day(when[i])), f.py(*valuesDeg[i]));
    if (open)
      path.lineTo(pt);
    else
      path.moveTo(pt);
    open = true;
    p.drawEllipse(pt, w.mm(0.8), w.mm(0.8));
  }
  p.setBrush(Qt::NoBrush);
  p.drawPath(path);
  if (!open) {
    p.setPen(Qt::black);
    p.drawText(f.plot, Qt::AlignCenter, Text::tr("not measured in this period"));
  }
  p.restore();
}

}  // namespace armtrack::reports
