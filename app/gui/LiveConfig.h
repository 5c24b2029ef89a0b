// The live session's set-up (app/gui/live/LiveSessionConfig.h) from what the new-session flow
// decided: the patient's arm, the protocol's targets, the devices, the settings' estimator.
#pragma once

#include <QStringList>
#include <optional>

#include "app/gui/live/LiveSessionConfig.h"
#include "app/gui/services/AppSettings.h"
#include "app/gui/services/SessionPlan.h"
#include "core/calibration/Calibration.h"

namespace armtrack::gui {

/// The virtual arm simulates the default right arm, so with it alone the default geometry and
/// the right side are used; with real devices, the patient's measured lengths (or the sensor
/// calibration's fitted geometry) and the plan's side.
app::gui::LiveSessionConfig liveSessionConfig(const SessionPlan& plan, const QStringList& devices,
                                              const AppSettings& settings,
                                              const std::optional<Calibration>& calibration = {});

}  // namespace armtrack::gui
