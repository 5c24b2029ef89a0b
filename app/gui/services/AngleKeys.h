// The clinical angles' stable keys (core/kinematics/ClinicalAngles.h: "shoulder_flexion", ...)
// and their indices, for the screens and the records.
#pragma once

#include <QString>

namespace armtrack::gui {

/// The index of a key such as "shoulder_flexion" in clinicalAngleInfo() order, or -1.
int angleIndex(const QString& key);
/// The key of an index 0-4 ("" for another).
QString angleKey(int index);

}  // namespace armtrack::gui
