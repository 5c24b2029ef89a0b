// Named clinical angles (degrees) from the DH joint vector, with the sign conventions and zero
// pose of docs/arm-model.md. The UI and the reports use only these.
#pragma once

#include <array>
#include <string_view>

#include "core/kinematics/ArmModel.h"

namespace armtrack {

/// Degrees, positive in the named direction; 0 everywhere = arm hanging at the side, elbow
/// straight, thumb forward.
struct ClinicalAngles {
  double shoulderFlexion = 0;           ///< + flexion (forward), - extension
  double shoulderAbduction = 0;         ///< + abduction (sideways away from the body)
  double shoulderInternalRotation = 0;  ///< + internal, - external rotation
  double elbowFlexion = 0;              ///< + flexion, 0 = straight
  double forearmPronation = 0;          ///< + pronation, - supination, 0 = thumb forward
};

struct ClinicalAngleInfo {
  std::string_view key;       ///< stable identifier (CSV columns, settings)
  std::string_view name;      ///< English display name
  std::string_view positive;  ///< what a positive value means
  /// Typical active range of motion (deg): the AAOS values (1965, via Norkin & White,
  /// Measurement of Joint Motion, Table A.1), as aaosNormativeRanges() in core/metrics cites
  /// them; shoulder adduction is not in that table, so abduction's range starts at 0.
  double normalMin, normalMax;
};

ClinicalAngles toClinical(const JointVector& th);
JointVector fromClinical(const ClinicalAngles& c);
/// Same order as the fields of ClinicalAngles.
const std::array<ClinicalAngleInfo, 5>& clinicalAngleInfo();
/// The five values in the order of clinicalAngleInfo().
std::array<double, 5> asArray(const ClinicalAngles& c);
/// The five angles in radians (same order and signs), straight from the joints: what the
/// metrics take, without a round trip through degrees.
std::array<double, 5> clinicalRadians(const JointVector& th);

}  // namespace armtrack
