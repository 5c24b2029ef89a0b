#include "app/gui/AngleNames.h"

#include "core/kinematics/ClinicalAngles.h"
#include "ui/AngleTableModel.h"

namespace armtrack::gui {

QString angleName(int index) {
  return ui::angleDisplayName(index);
}

int angleIndex(const QString& key) {
  const auto& info = clinicalAngleInfo();
  for (std::size_t i = 0; i < info.size(); ++i)
    if (key == QLatin1String(info[i].key.data(), static_cast<qsizetype>(info[i].key.size())))
      return static_cast<int>(i);
  return -1;
}

}  // namespace armtrack::gui
