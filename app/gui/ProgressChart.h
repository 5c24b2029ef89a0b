// Range of motion of one clinical angle over a patient's sessions (Qt Charts), with the normal
// range (AAOS, core/metrics/NormativeRanges.h) shaded, an angle chooser, and the same numbers
// in a table beside it for screen readers.
#pragma once

#include <QWidget>
#include <vector>

#include "core/reports/ReportData.h"

class QChart;
class QChartView;
class QComboBox;
class QLabel;
class QStandardItemModel;
class QTableView;

namespace armtrack::gui {

class ProgressChart : public QWidget {
  Q_OBJECT
 public:
  explicit ProgressChart(QWidget* parent = nullptr);

  /// The analysed sessions, any order.
  void setSessions(std::vector<reports::ProgressSession> sessions);
  /// Shows angles in radians instead of degrees (the settings' unit).
  void setRadians(bool radians);
  /// Which clinical angle (clinicalAngleInfo() order) is drawn.
  void setAngle(int index);
  int angle() const;
  /// Points drawn (sessions with a value for the angle).
  int points() const;
  QChart* chart() const;
  /// The numbers drawn: date, range of motion (deg or rad), percent of the normal range.
  const QStandardItemModel* table() const { return m_table; }

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  void redraw();

  std::vector<reports::ProgressSession> m_sessions;
  QLabel* m_angleLabel;
  QComboBox* m_angle;
  QChartView* m_view;
  QStandardItemModel* m_table;
  QTableView* m_tableView;
  int m_points = 0;
  bool m_radians = false;
};

}  // namespace armtrack::gui
