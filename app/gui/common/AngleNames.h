// The clinical angles' names as the user reads them, translated (core/kinematics/ClinicalAngles.h
// keeps the English ones for files and the command line).
#pragma once

#include <QString>

#include "app/gui/services/AngleKeys.h"

namespace armtrack::gui {

/// index in clinicalAngleInfo() order: "Shoulder flexion", ... (translated).
QString angleName(int index);

}  // namespace armtrack::gui
