#include "app/gui/review/TrunkPanel.h"

#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <numbers>

#include "app/gui/common/Forms.h"
#include "core/storage/SessionAnalysis.h"

namespace armtrack::gui {

TrunkPanel::TrunkPanel(QWidget* parent) : QGroupBox(parent) {
  m_form = new QFormLayout(this);
  for (std::size_t i = 0; i < m_values.size(); ++i) {
    m_names[i] = new QLabel(this);
    m_values[i] = new QLabel(this);
    m_values[i]->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_form->addRow(m_names[i], m_values[i]);
  }
  retranslateUi();
}

void TrunkPanel::setMetrics(const std::optional<QJsonObject>& metrics, bool radians) {
  m_metrics = metrics;
  m_radians = radians;
  retranslateUi();
}

QString TrunkPanel::valueText(int index) const {
  return index >= 0 && index < 4 ? m_values[static_cast<std::size_t>(index)]->text() : QString();
}

QString TrunkPanel::compensationText() const {
  return m_values[4]->text();
}

void TrunkPanel::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QGroupBox::changeEvent(event);
}

void TrunkPanel::retranslateUi() {
  setTitle(tr("Trunk"));
  m_names[0]->setText(tr("Largest trunk flexion:"));
  m_names[1]->setText(tr("Largest lateral bending:"));
  m_names[2]->setText(tr("Largest axial rotation:"));
  m_names[3]->setText(tr("Largest shoulder displacement:"));
  m_names[4]->setText(tr("Repetitions with compensation:"));
  const std::optional<TrunkCompensation> t =
      m_metrics ? storage::trunkCompensationFromJson(*m_metrics) : std::nullopt;
  const TrunkExtremes x = t ? t->session : TrunkExtremes{};
  const auto angle = [&](const std::optional<double>& deg) {
    if (!deg) return tr("not measured");
    return m_radians ? tr("%L1 rad").arg(*deg * std::numbers::pi / 180.0, 0, 'f', 3)
                     : tr("%L1\u00b0").arg(*deg, 0, 'f', 1);
  };
  m_values[0]->setText(angle(x.maxFlexionDeg));
  m_values[1]->setText(angle(x.maxLateralDeg));
  m_values[2]->setText(angle(x.maxRotationDeg));
  m_values[3]->setText(x.maxShoulderDisplacementCm
                           ? tr("%L1 cm").arg(*x.maxShoulderDisplacementCm, 0, 'f', 1)
                           : tr("not measured"));
  for (std::size_t i = 0; i < m_values.size(); ++i)
    m_values[i]->setAccessibleName(m_names[i]->text());
  QString line;
  if (t && t->repetitionsWithCompensation) {
    const QJsonValue limit = (*m_metrics)["trunk"].toObject()["flexion_limit_deg"];
    line = tr("%1 of %2 (flexion over %3)")
               .arg(*t->repetitionsWithCompensation)
               .arg(t->repetitions.size())
               .arg(angle(limit.isDouble() ? std::optional(limit.toDouble()) : std::nullopt));
  }
  m_values[4]->setText(line);
  m_form->setRowVisible(4, !line.isEmpty());
}

}  // namespace armtrack::gui
