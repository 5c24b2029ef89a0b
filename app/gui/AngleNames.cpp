#include "app/gui/AngleNames.h"

#include <QCoreApplication>

#include "core/kinematics/ClinicalAngles.h"

namespace armtrack::gui {

QString angleName(int index) {
  static const char* const kNames[] = {
      QT_TRANSLATE_NOOP("armtrack::gui::AngleNames", "Shoulder flexion"),
      QT_TRANSLATE_NOOP("armtrack::gui::AngleNames", "Shoulder abduction"),
      QT_TRANSLATE_NOOP("armtrack::gui::AngleNames", "Shoulder internal rotation"),
      QT_TRANSLATE_NOOP("armtrack::gui::AngleNames", "Elbow flexion"),
      QT_TRANSLATE_NOOP("armtrack::gui::AngleNames", "Forearm pronation"),
  };
  static_assert(std::size(kNames) == 5);
  if (index < 0 || index >= 5) return {};
  return QCoreApplication::translate("armtrack::gui::AngleNames", kNames[index]);
}

int angleIndex(const QString& key) {
  const auto& info = clinicalAngleInfo();
  for (std::size_t i = 0; i < info.size(); ++i)
    if (key == QLatin1String(info[i].key.data(), static_cast<qsizetype>(info[i].key.size())))
      return static_cast<int>(i);
  return -1;
}

}  // namespace armtrack::gui
