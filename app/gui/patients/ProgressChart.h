// One motion of a clinical angle over a patient's sessions (Qt Charts): the largest angle each
// session reached in that direction, against the motion's normal range from the neutral position
// (AAOS, core/metrics/NormativeRanges.h) shaded; a motion chooser, and the same numbers in a
// table beside it for screen readers. The motions are each angle's named direction (flexion,
// abduction, internal rotation, elbow flexion, pronation) and the opposite one where the normal
// range gives a limit for it (shoulder extension, external rotation, supination). The largest
// angle, not the range (largest - smallest): a normal range counts motion in one direction only,
// and a range would add the opposite motion to it. When sessions measured the trunk, the chooser
// also offers the largest trunk flexion per session: compensation over the weeks.
#pragma once

#include <QWidget>
#include <vector>

#include "app/gui/services/PatientRecords.h"
#include "core/metrics/NormativeRanges.h"
#include "core/metrics/PatientNorms.h"

class QChart;
class QBoxLayout;
class QChartView;
class QAbstractAxis;
class QValueAxis;
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
  /// The patient's birth date (YYYY-MM-DD) and sex ("f", "m"), which choose the normal ranges
  /// (patientNorms(): Soucie et al. where they cover the patient, else AAOS) as the reports do.
  void setPatient(const QString& birthDate, const QString& sex);
  /// Shows angles in radians instead of degrees (the settings' unit).
  void setRadians(bool radians);
  /// Draws the named direction of a clinical angle (clinicalAngleInfo() order).
  void setAngle(int index);
  /// Draws one direction of a clinical angle: opposite = extension, external rotation,
  /// supination; ignored (the named direction drawn) where the normal range has no such limit.
  void setMotion(int index, bool opposite);
  /// Draws the largest trunk flexion per session (trunk compensation over the weeks), when some
  /// session measured it (the chooser then offers it last); otherwise nothing changes.
  void showTrunk();
  /// Whether the trunk's compensation is drawn.
  bool trunkShown() const;
  /// The clinical angle drawn, and whether in its opposite direction.
  int angle() const;
  bool opposite() const;
  /// Points drawn (sessions with a value for the angle).
  int points() const;
  QChart* chart() const;
  /// The motion drawn, as the chooser names it ("Shoulder external rotation").
  QString motionName() const;
  /// The numbers drawn: date, largest angle (deg or rad), percent of the normal range.
  const QStandardItemModel* table() const { return m_table; }

 protected:
  void changeEvent(QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  using Motion = MotionDirection;
  static QString nameOf(const Motion& m);
  void retranslateUi();
  void redraw();
  void redrawTrunk();
  void showChart(QChart* chart, QAbstractAxis* x, QValueAxis* y, double step);
  void fillChooser();
  Motion current() const;

  std::vector<SessionExtremes> m_sessions;
  std::vector<Motion> m_motions;  // the chooser's entries, in its order (then the trunk's)
  bool m_hasTrunk = false;        // some session measured the trunk: the chooser offers it
  QLabel* m_angleLabel;
  QComboBox* m_angle;
  QChartView* m_view;
  QStandardItemModel* m_table;
  QTableView* m_tableView;
  QBoxLayout* m_row = nullptr;  // chart and table: side by side, or stacked when narrow
  static constexpr int kBesideWidth = 960;
  int m_points = 0;
  bool m_radians = false;
  std::optional<CivilDate> m_birth;
  Sex m_sex = Sex::Unknown;
};

}  // namespace armtrack::gui
