// The review screen's side panels: the repetitions table, the re-estimation choices, and the
// report and export buttons. They hold no records; ReviewScreen runs what they ask for.
#pragma once

#include <QAbstractTableModel>
#include <QWidget>
#include <vector>

#include "app/clinical/Outputs.h"
#include "app/gui/services/SessionReview.h"
#include "core/estimation/ArmFilter.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace armtrack::gui {

struct AppSettings;

class RepetitionTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column {
    Number,
    Start,
    End,
    Excursion,
    Rom,
    PeakVelocity,
    Sparc,
    Kind,
    TrunkFlexion,
    TrunkLateral,
    TrunkRotation,
    Shoulder,
    Compensation,
    ColumnCount
  };
  static constexpr int StartRole = Qt::UserRole;  ///< the repetition's start (s)

  using QAbstractTableModel::QAbstractTableModel;
  void setRows(std::vector<RepetitionRow> rows);
  /// Whether some row has a value in column (the view hides the trunk's columns that have none:
  /// a session without a trunk sensor).
  bool hasValues(int column) const;
  /// Angles and velocities in radians instead of degrees (the settings' unit).
  void setRadians(bool radians);
  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation,
                      int role = Qt::DisplayRole) const override;
  /// A LanguageChange (passed on by the owning widget) refreshes the views' words.
  bool event(QEvent* event) override;

 private:
  std::vector<RepetitionRow> m_rows;
  bool m_radians = false;
};

/// How to estimate a stored session again.
struct ReestimateChoice {
  FilterKind filter = FilterKind::Ekf;
  MeasurementModel model = MeasurementModel::AccelGyro;
  bool optical = true;      ///< fuse Kinect positions and webcam pixels
  QString calibrationFile;  ///< "" = none (armtrack-cli calibrate's JSON)
};

class ReestimatePanel : public QWidget {
  Q_OBJECT
 public:
  ReestimatePanel(const AppSettings& settings, QWidget* parent = nullptr);
  ReestimateChoice choice() const;
  void setChoice(const ReestimateChoice& c);
  void setBusy(bool busy);
  /// What the shown estimates were made with, in words.
  void setCurrent(const QString& text);

 signals:
  void reestimateRequested(const armtrack::gui::ReestimateChoice& choice);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();

  QLabel* m_currentLabel;
  QLabel* m_filterLabel;
  QLabel* m_methodLabel;
  QLabel* m_calibrationLabel;
  QComboBox* m_filter;
  QComboBox* m_method;
  QCheckBox* m_optical;
  QLineEdit* m_calibration;
  QPushButton* m_browse;
  QPushButton* m_run;
  QLabel* m_current;
};

class OutputsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit OutputsPanel(QWidget* parent = nullptr);
  void setBusy(bool busy);
  /// The last file written (or what went wrong).
  void setResult(const QString& text);

 signals:
  void reportRequested();
  void exportRequested(armtrack::clinical::ExportFormat format);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();

  std::vector<QPushButton*> m_buttons;
  QLabel* m_result;
};

}  // namespace armtrack::gui
