// What a new session is for, as chosen before the devices are checked: the patient, the
// protocol (if any) and the arm. The device-check, calibration and live steps add to it.
#pragma once

#include <optional>

#include "core/kinematics/Side.h"
#include "core/storage/Records.h"

namespace armtrack::gui {

struct SessionPlan {
  storage::Patient patient;
  std::optional<storage::Protocol> protocol;  ///< none: a free session
  Side side = Side::Right;                    ///< the arm measured
};

/// The arm to measure by default: the protocol's side when it names one, else the patient's
/// affected side when it is left or right, else the right arm.
inline Side defaultSide(const storage::Patient& p, const std::optional<storage::Protocol>& pr) {
  if (pr && pr->side == "left") return Side::Left;
  if (pr && pr->side == "right") return Side::Right;
  return p.affectedSide == "left" ? Side::Left : Side::Right;
}

}  // namespace armtrack::gui
