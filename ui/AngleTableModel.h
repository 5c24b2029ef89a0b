// The numbers behind the angle plots, as a table a screen reader can read: one row per clinical
// angle with its current value, uncertainty, the range over the plotted window and the target.
#pragma once

#include <QAbstractTableModel>
#include <array>
#include <optional>

#include "ui/AngleTrace.h"

namespace armtrack::ui {

/// Why an angle is not to be trusted, in the order a therapist should act on it.
enum class AngleDoubt {
  None,        ///< to be trusted within its confidence
  SensorLost,  ///< no value, or no new data from the IMUs (the filter only predicts)
  Heading,     ///< a shoulder angle whose heading rests on the start pose (no camera)
  Uncertain,   ///< the confidence is wider than the limit, for another reason
};

/// An angle's confidence as a therapist reads it: "±3°", the range the angle lies in with
/// about 95 % probability (two standard deviations, rounded up to whole degrees, at least 1°:
/// never "±0°"); an en dash when unknown.
QString confidenceText(double sigmaDeg);

/// Whether and why the angle of sample s is not to be trusted: a confidence wider than
/// limitDeg (half-width, deg) or a lost sensor.
AngleDoubt angleDoubt(const AngleSample& s, int angle, double limitDeg = 10.0);

/// The reason in a few words ("heading from the start pose", "sensor lost", "uncertain"); ""
/// for None. shortForm: one or two words, for a table cell.
QString doubtText(AngleDoubt doubt, bool shortForm = false);

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
  AngleDoubt doubt(int angle) const { return m_doubt[static_cast<std::size_t>(angle)]; }
  /// An angle is in doubt when its confidence is wider than this (deg, default 10).
  void setDoubtAboveDeg(double deg) { m_doubtAbove = deg; }

 private:
  double m_doubtAbove = 10.0;

 public:
 private:
  std::array<double, kAngleCount> m_value{}, m_sigma{}, m_min{}, m_max{};
  std::array<AngleDoubt, kAngleCount> m_doubt{};
  std::array<std::optional<std::pair<double, double>>, kAngleCount> m_target;
};

/// The clinical angle's name in the user's language (index in clinicalAngleInfo() order).
QString angleDisplayName(int angle);

/// "12.3°", or an en dash for a value that is not known.
QString formatDegrees(double deg, int decimals = 1);

}  // namespace armtrack::ui
