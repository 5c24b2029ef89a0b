// The clinical angles' names as the user reads them, translated (core/kinematics/ClinicalAngles.h
// keeps the English ones for files and the command line).
#pragma once

#include <QString>

namespace armtrack::gui {

/// index in clinicalAngleInfo() order: "Shoulder flexion", ... (translated).
QString angleName(int index);
/// The index of a key such as "shoulder_flexion", or -1.
int angleIndex(const QString& key);

}  // namespace armtrack::gui
