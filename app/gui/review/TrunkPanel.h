// The review's "Trunk" block: how far the patient leaned and turned the trunk and how far the
// shoulder moved over the session (docs/metrics.md, "Trunk compensation"), and how many
// repetitions were made with compensation when a limit was set; "not measured" where the session
// had no sensor for a value.
#pragma once

#include <QGroupBox>
#include <QJsonObject>
#include <array>
#include <optional>

class QLabel;

namespace armtrack::gui {

class TrunkPanel : public QGroupBox {
  Q_OBJECT
 public:
  explicit TrunkPanel(QWidget* parent = nullptr);
  /// Shows the trunk of a metrics JSON (none: not analysed); angles in radians when asked.
  void setMetrics(const std::optional<QJsonObject>& metrics, bool radians);
  /// The four values' texts (flexion, lateral bending, axial rotation, shoulder), for tests.
  QString valueText(int index) const;
  /// The compensation line ("" when no limit was set).
  QString compensationText() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();

  std::array<QLabel*, 4> m_names{};
  std::array<QLabel*, 4> m_values{};
  QLabel* m_compensation;
  std::optional<QJsonObject> m_metrics;
  bool m_radians = false;
};

}  // namespace armtrack::gui
