#include "app/gui/services/AngleKeys.h"

#include "core/kinematics/ClinicalAngles.h"

namespace armtrack::gui {

int angleIndex(const QString& key) {
  const auto& info = clinicalAngleInfo();
  for (std::size_t i = 0; i < info.size(); ++i)
    if (key == QLatin1String(info[i].key.data(), static_cast<qsizetype>(info[i].key.size())))
      return static_cast<int>(i);
  return -1;
}

QString angleKey(int index) {
  if (index < 0 || index >= static_cast<int>(clinicalAngleInfo().size())) return {};
  const std::string_view key = clinicalAngleInfo()[static_cast<std::size_t>(index)].key;
  return QString::fromLatin1(key.data(), static_cast<qsizetype>(key.size()));
}

}  // namespace armtrack::gui
