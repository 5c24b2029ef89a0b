// The live session's set-up (app/gui/services/LiveSessionConfig.h) from what the new-session flow
// decided: the patient's arm, the protocol's targets, the devices, the settings' estimator.
#pragma once

#include <QStringList>
#include <optional>

#include "app/gui/services/AppSettings.h"
#include "app/gui/services/LiveSessionConfig.h"
#include "app/gui/services/SessionPlan.h"
#include "core/calibration/Calibration.h"

namespace armtrack::gui {

/// The virtual arm simulates the default right arm, so with it alone the default geometry and
/// the right side are used; with real devices, the patient's measured lengths (or the sensor
/// calibration's fitted geometry) and the plan's side.
app::gui::LiveSessionConfig liveSessionConfig(const SessionPlan& plan, const QStringList& devices,
                                              const AppSettings& settings,
                                              const std::optional<Calibration>& calibration = {});

/// app/gui/services/LiveSessionConfig.h (the calibration page asks it too).
using app::gui::hasSternumSensor;

/// The demo's devices for a plan: the virtual arm with both IMUs, a Kinect and a webcam, and,
/// when the plan has a protocol, making its exercise: repetitions of the protocol's angle from
/// rest (20 deg, or the target's lower end if that is lower) to 85 % into the target range, so
/// the live screen's counter counts every one as a full repetition (RepetitionCounter: it enters
/// at 35 % of the target range, leaves below 15 %, and calls one partial below 80 %).
QStringList demoDevicesFor(const SessionPlan& plan);

}  // namespace armtrack::gui
