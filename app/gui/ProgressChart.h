// One clinical angle over a patient's sessions (Qt Charts): the largest angle each session
// reached in the direction of the angle's name (flexion, abduction, internal rotation, elbow
// flexion, pronation), against that motion's normal range from the neutral position (AAOS,
// core/metrics/NormativeRanges.h) shaded; an angle chooser, and the same numbers in a table
// beside it for screen readers. The largest angle, not the range (largest - smallest): the
// normal range counts motion in one direction only, and a range would add the opposite motion
// (extension, external rotation, supination) to it.
#pragma once

#include <QWidget>
#include <vector>

#include "app/gui/services/PatientRecords.h"

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
  void setSessions(std::vector<SessionExtremes> sessions);
  /// Shows angles in radians instead of degrees (the settings' unit).
  void setRadians(bool radians);
  /// Which clinical angle (clinicalAngleInfo() order) is drawn.
  void setAngle(int index);
  int angle() const;
  /// Points drawn (sessions with a value for the angle).
  int points() const;
  QChart* chart() const;
  /// The numbers drawn: date, largest angle (deg or rad), percent of the normal range.
  const QStandardItemModel* table() const { return m_table; }

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  void redraw();

  std::vector<SessionExtremes> m_sessions;
  QLabel* m_angleLabel;
  QComboBox* m_angle;
  QChartView* m_view;
  QStandardItemModel* m_table;
  QTableView* m_tableView;
  int m_points = 0;
  bool m_radians = false;
};

}  // namespace armtrack::gui
