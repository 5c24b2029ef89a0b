// What the calibration from movement of a live session (core/session/LiveCalibration.h) says on
// the screens, in plain words: the therapist's line on the live screen ("Straps checked from the
// movement: upper-arm sensor turned 23 deg, ...") and the patient's, in the home window, only
// when it matters. Translated (QCoreApplication::translate, context "StrapsText"); no widgets.
#pragma once

#include <QString>

#include "core/session/LiveCalibration.h"

namespace armtrack::app::gui {

/// A sensor turned by more than this (deg) is worth telling the patient about.
inline constexpr double kStrapsTurnWorthTellingDeg = 15.0;

/// The therapist's line; empty when the calibration from movement is off (a calibration is in
/// use, or the session does not estimate).
QString strapsLine(const session::LiveCalibrationStatus& status);

/// The patient's words when a strap has turned by more than kStrapsTurnWorthTellingDeg and the
/// fit is in use; empty otherwise (nothing to worry about, so nothing said).
QString strapsPatientLine(const session::LiveCalibrationStatus& status);

}  // namespace armtrack::app::gui
