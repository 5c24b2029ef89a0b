#include "app/gui/services/StrapsText.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace armtrack::app::gui {

namespace {

QString whole(double v) {
  return QString::number(std::lround(v));
}

}  // namespace

QString strapsLine(const session::LiveCalibrationStatus& status) {
  using State = session::LiveCalibrationStatus::State;
  // A fit in use keeps its line while a refit runs.
  if (status.summary && status.calibration) {
    const MountingSummary& m = *status.summary;
    return QCoreApplication::translate(
               "StrapsText",
               "Straps checked from the movement: upper-arm sensor turned %1 deg, forearm sensor "
               "turned %2 deg and %3 cm from the wrist")
        .arg(whole(m.upperTurnDeg), whole(m.forearmTurnDeg), whole(m.forearmFromWristCm));
  }
  switch (status.state) {
    case State::Off:
      return {};
    case State::Collecting:
      return status.fits == 0
                 ? QCoreApplication::translate(
                       "StrapsText",
                       "Straps: checking them from the movement (rest still a moment with the "
                       "upper arm hanging, the elbow bent to a right angle and the thumb up, then "
                       "move)")
                 : QCoreApplication::translate(
                       "StrapsText",
                       "Straps: not checked yet (the arm needs a moment of rest and more "
                       "movement)");
    case State::Fitting:
      return QCoreApplication::translate("StrapsText",
                                         "Straps: checking them from the movement\u2026");
    case State::AsFitted:
      return QCoreApplication::translate("StrapsText",
                                         "Straps as fitted (checked from the movement)");
    case State::Applied:
      break;
  }
  return {};
}

QString strapsPatientLine(const session::LiveCalibrationStatus& status) {
  if (!status.summary || !status.calibration) return {};
  const MountingSummary& m = *status.summary;
  if (std::max(m.upperTurnDeg, m.forearmTurnDeg) <= kStrapsTurnWorthTellingDeg) return {};
  return QCoreApplication::translate(
      "StrapsText",
      "A sensor strap has turned on your arm. Your exercise is still measured; next time, "
      "put the straps on as shown before you start.");
}

}  // namespace armtrack::app::gui
