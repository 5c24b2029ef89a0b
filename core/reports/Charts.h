// Charts of the PDF reports, drawn with QPainter in vector form: an angle against time, the
// patient's range against the normal range, and range of motion against date. Internal to
// armtrack_reports. Values are in degrees here (the report boundary).
#pragma once

#include <QColor>
#include <QDateTime>
#include <QRectF>
#include <QString>
#include <optional>
#include <vector>

#include "core/reports/PageWriter.h"

namespace armtrack::reports {

/// Ticks at 1, 2, 2.5 or 5 times a power of ten covering [lo, hi], about `target` of them.
std::vector<double> niceTicks(double lo, double hi, int target);

/// A shaded horizontal band (deg), e.g. a protocol's target range.
struct Band {
  double loDeg = 0, hiDeg = 0;
  QString label;
};

/// A label at a time on a time plot, e.g. a repetition's number at its peak.
struct TimeMark {
  double tS = 0;  ///< s, on the same clock as the plot's times
  QString label;
};

/// One clinical angle (deg) against time in rect r, with a shaded band when given, marks along
/// the top edge (a mark too close to the previous one is left out) and events as dashed
/// vertical lines labelled at the bottom. The axis shows time since originS (s, on the clock of
/// tS, marks and events: the recording's first row, so the axis reads recording time), or since
/// the first finite sample when empty. Non-finite values break the line. Long series are
/// reduced to the minimum and maximum per horizontal step, so peaks are kept.
void drawTimePlot(PageWriter& w, const QRectF& r, const QString& title,
                  const std::vector<double>& tS, const std::vector<double>& yDeg,
                  const std::optional<Band>& band, const std::vector<TimeMark>& marks = {},
                  std::optional<double> originS = std::nullopt,
                  const std::vector<TimeMark>& events = {});

struct NormativeBar {
  QString name;
  std::optional<double> normalLoDeg;  ///< empty: the source gives no limit in this direction
  double normalHiDeg = 0;
  double minDeg = 0, maxDeg = 0;  ///< the patient's range this session
  QString caption;                ///< printed right of the bar
};

/// One row per angle: the normal range shaded grey, the patient's range as a bar over it, on a
/// shared degree axis.
void drawNormativeBars(PageWriter& w, const QRectF& r, const std::vector<NormativeBar>& bars);

/// Height (device units) drawNormativeBars needs for n bars.
double normativeBarsHeight(const PageWriter& w, std::size_t n);

/// Values (deg, e.g. the largest angle reached per session) against date in rect r; the normal
/// span (0 to normalSpanDeg) shaded and its limit dashed (none without a normal span: the trunk's
/// compensation). Points with no value are skipped; the axis goes below 0 when a value does.
void drawDateChart(PageWriter& w, const QRectF& r, const QString& title,
                   const std::vector<QDateTime>& when,
                   const std::vector<std::optional<double>>& valuesDeg,
                   std::optional<double> normalSpanDeg);

}  // namespace armtrack::reports
