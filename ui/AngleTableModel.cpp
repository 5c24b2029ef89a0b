#include "ui/AngleTableModel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QColor>
#include <QCoreApplication>

#include "ui/Retranslate.h"

namespace armtrack::ui {

QString angleDisplayName(int angle) {
  static const char* const kNames[kAngleCount] = {
      QT_TRANSLATE_NOOP("armtrack::ui::Angles", "Shoulder flexion"),
      QT_TRANSLATE_NOOP("armtrack::ui::Angles", "Shoulder abduction"),
      QT_TRANSLATE_NOOP("armtrack::ui::Angles", "Shoulder internal rotation"),
      QT_TRANSLATE_NOOP("armtrack::ui::Angles", "Elbow flexion"),
      QT_TRANSLATE_NOOP("armtrack::ui::Angles", "Forearm pronation"),
  };
  if (angle < 0 || angle >= kAngleCount) return {};
  return QCoreApplication::translate("armtrack::ui::Angles", kNames[angle]);
}

QString formatDegrees(double deg, int decimals) {
  if (!std::isfinite(deg)) return QStringLiteral("\u2013");
  // A value that rounds to zero is shown as 0, never "-0" (a sign that says nothing).
  if (std::abs(deg) < 0.5 * std::pow(10.0, -decimals)) deg = 0.0;
  return QStringLiteral("%L1\u00b0").arg(deg, 0, 'f', decimals);
}

QString confidenceText(double sigmaDeg) {
  if (!std::isfinite(sigmaDeg)) return QStringLiteral("\u2013");
  // Rounded up, and at least 1 deg: "±0°" would read as an exact angle, which no sensor gives
  // (and a simulation's sd of 0.1-0.2 deg leaves out what real straps and sensors add).
  const double halfWidth = std::max(1.0, std::ceil(2.0 * std::abs(sigmaDeg) - 1e-9));
  return QStringLiteral("\u00b1") + formatDegrees(halfWidth, 0);
}

AngleDoubt angleDoubt(const AngleSample& s, int angle, double limitDeg) {
  if (angle < 0 || angle >= kAngleCount) return AngleDoubt::None;
  const auto a = static_cast<std::size_t>(angle);
  if (!std::isfinite(s.deg[a]) || s.predicted) return AngleDoubt::SensorLost;
  const double twoSigma = 2.0 * s.sigmaDeg[a];
  if (std::isfinite(twoSigma) && twoSigma <= limitDeg) return AngleDoubt::None;
  // The three shoulder angles hang on the arm's heading about the vertical.
  if (s.headingFromStartPose && angle <= 2) return AngleDoubt::Heading;
  return AngleDoubt::Uncertain;
}

QString doubtText(AngleDoubt doubt, bool shortForm) {
  switch (doubt) {
    case AngleDoubt::None:
      return {};
    case AngleDoubt::SensorLost:
      return QCoreApplication::translate("armtrack::ui::Angles", "sensor lost");
    case AngleDoubt::Heading:
      return shortForm ? QCoreApplication::translate("armtrack::ui::Angles", "heading")
                       : QCoreApplication::translate("armtrack::ui::Angles",
                                                     "heading from the start pose");
    case AngleDoubt::Uncertain:
      return QCoreApplication::translate("armtrack::ui::Angles", "uncertain");
  }
  return {};
}

AngleTableModel::AngleTableModel(QObject* parent) : QAbstractTableModel(parent) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m_value.fill(nan);
  m_sigma.fill(nan);
  m_min.fill(nan);
  m_max.fill(nan);
}

int AngleTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : kAngleCount;
}

int AngleTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant AngleTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= kAngleCount) return {};
  const auto r = static_cast<std::size_t>(index.row());
  if (role == Qt::TextAlignmentRole && index.column() != Name)
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  // An angle in doubt: its value and confidence on amber, the reason in the confidence cell.
  const bool doubted =
      m_doubt[r] != AngleDoubt::None && (index.column() == Value || index.column() == Uncertainty);
  if (role == Qt::BackgroundRole && doubted) return QColor(0xff, 0xd5, 0x80);
  if (role == Qt::ForegroundRole && doubted) return QColor(Qt::black);
  if (role == Qt::ToolTipRole && doubted) return doubtText(m_doubt[r]);
  if (role != Qt::DisplayRole && role != Qt::AccessibleTextRole) return {};
  switch (index.column()) {
    case Name:
      return angleDisplayName(index.row());
    case Value:
      return formatDegrees(m_value[r]);
    case Uncertainty:
      if (m_doubt[r] == AngleDoubt::SensorLost) return doubtText(m_doubt[r], true);
      if (m_doubt[r] != AngleDoubt::None)
        return QStringLiteral("%1 %2").arg(confidenceText(m_sigma[r]), doubtText(m_doubt[r], true));
      return confidenceText(m_sigma[r]);
    case Minimum:
      return formatDegrees(m_min[r]);
    case Maximum:
      return formatDegrees(m_max[r]);
    case Target:
      if (!m_target[r]) return QString();
      return QStringLiteral("%1 \u2013 %2")
          .arg(formatDegrees(m_target[r]->first, 0), formatDegrees(m_target[r]->second, 0));
    default:
      return {};
  }
}

QVariant AngleTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (role != Qt::DisplayRole || orientation != Qt::Horizontal) return {};
  switch (section) {
    case Name:
      return tr("Angle");
    case Value:
      return tr("Now");
    case Uncertainty:
      return tr("Confidence");
    case Minimum:
      return tr("Min");
    case Maximum:
      return tr("Max");
    case Target:
      return tr("Target");
    default:
      return {};
  }
}

bool AngleTableModel::event(QEvent* event) {
  refreshOnLanguageChange(this, event);
  return QAbstractTableModel::event(event);
}

void AngleTableModel::setValues(const AngleSample* current,
                                const std::array<double, kAngleCount>& minDeg,
                                const std::array<double, kAngleCount>& maxDeg) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < kAngleCount; ++i) {
    m_value[i] = current ? current->deg[i] : nan;
    m_sigma[i] = current ? current->sigmaDeg[i] : nan;
    m_doubt[i] =
        current ? angleDoubt(*current, static_cast<int>(i), m_doubtAbove) : AngleDoubt::None;
  }
  m_min = minDeg;
  m_max = maxDeg;
  emit dataChanged(index(0, Value), index(kAngleCount - 1, Maximum));
}

void AngleTableModel::setTarget(int angle, std::optional<std::pair<double, double>> rangeDeg) {
  if (angle < 0 || angle >= kAngleCount) return;
  m_target[static_cast<std::size_t>(angle)] = rangeDeg;
  emit dataChanged(index(angle, Target), index(angle, Target));
}

}  // namespace armtrack::ui
