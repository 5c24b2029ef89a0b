// The review's "Trunk" block: how far the patient leaned and turned the trunk and how far the
// shoulder moved over the session (docs/metrics.md, "Trunk compensation"), and how many
// repetitions were made with compensation when a limit was set; "not measured" where the session
// had no sensor for a value. One line a row, so it fits beside the repetitions on a small screen.
#pragma once

#include <QGroupBox>
#include <QJsonObject>
#include <array>
#include <optional>

class QFormLayout;
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
  /// The repetitions made with compensation ("" when no limit was set).
  QString compensationText() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();

  std::array<QLabel*, 5> m_names{};  // the four values, then the repetitions with compensation
  std::array<QLabel*, 5> m_values{};
  QFormLayout* m_form;
  std::optional<QJsonObject> m_metrics;
  bool m_radians = false;
};

}  // namespace armtrack::gui
