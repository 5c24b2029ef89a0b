// The trunk's plot (internal to AnglePlotPanel): flexion, lateral bending and axial rotation
// (degrees, relative to the start pose) over time, three lines with a legend, shown when the
// session has a sternum sensor (docs/trunk.md).
#pragma once

#include <QChartView>
#include <array>
#include <optional>
#include <vector>

#include "ui/AngleTrace.h"

class QLineSeries;
class QValueAxis;

namespace armtrack::ui {

class TrunkChart : public QChartView {
  Q_OBJECT
 public:
  explicit TrunkChart(QWidget* parent = nullptr);

  void setDark(bool dark);
  /// Redraws from a trace whose deg[0..2] are the trunk's three angles, over [t0, t1], with the
  /// review's time cursor.
  void draw(const AngleTrace& trunk, double t0, double t1, std::optional<double> cursor);
  /// One line per angle (flexion, lateral bending, axial rotation), for the tests.
  QLineSeries* series(int angle) const { return m_lines[static_cast<std::size_t>(angle)]; }
  std::pair<double, double> yRange() const { return {m_yMin, m_yMax}; }

  /// The angles' names as the legend and the table show them.
  static QString angleName(int angle);
  /// Each line's colour, distinct from one another and from the arm's angles.
  static QColor colour(int angle, bool dark);

 signals:
  void clicked(double t);

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();

  QChart* m_chart;
  QValueAxis* m_x;
  QValueAxis* m_y;
  std::array<QLineSeries*, kTrunkAngleCount> m_lines{};
  QLineSeries* m_cursor;
  double m_yMin = -10.0, m_yMax = 10.0;
  std::vector<QPointF> m_points;
};

}  // namespace armtrack::ui
