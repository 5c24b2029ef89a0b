// The numbers behind the angle plots, as a table a screen reader can read: one row per clinical
// angle with its current value, uncertainty, the range over the plotted window and the target.
#pragma once

#include <QAbstractTableModel>
#include <array>
#include <optional>

#include "ui/AngleTrace.h"

namespace armtrack::ui {

class AngleTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Name, Value, Uncertainty, Minimum, Maximum, Target, ColumnCount };

  explicit AngleTableModel(QObject* parent = nullptr);

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation,
                      int role = Qt::DisplayRole) const override;
  /// A LanguageChange (passed on by the owning widget) refreshes the views' words.
  bool event(QEvent* event) override;

  /// The current values (the sample, or none), and each angle's min and max over the window
  /// (NaN when unknown). Emits dataChanged for what changed.
  void setValues(const AngleSample* current, const std::array<double, kAngleCount>& minDeg,
                 const std::array<double, kAngleCount>& maxDeg);
  void setTarget(int angle, std::optional<std::pair<double, double>> rangeDeg);
  /// The value shown for an angle (NaN when none), for tests.
  double value(int angle) const { return m_value[static_cast<std::size_t>(angle)]; }

 private:
  std::array<double, kAngleCount> m_value{}, m_sigma{}, m_min{}, m_max{};
  std::array<std::optional<std::pair<double, double>>, kAngleCount> m_target;
};

/// The clinical angle's name in the user's language (index in clinicalAngleInfo() order).
QString angleDisplayName(int angle);

/// "12.3°", or an en dash for a value that is not known.
QString formatDegrees(double deg, int decimals = 1);

}  // namespace armtrack::ui
