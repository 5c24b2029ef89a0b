// The home set-up as the therapist left it: the devices (the two IMUs and the computer's own
// webcam), the arm and estimator of each live session, and a folder for the check's and the
// calibration's recordings. With virtual arms (the demo, the tests) each step's devices play that
// step's movement: the check, the calibration protocol, the exercise.
#pragma once

#include <QStringList>
#include <functional>
#include <optional>

#include "app/gui/services/HomeRecords.h"
#include "app/gui/services/LiveSessionConfig.h"
#include "app/gui/services/SessionPlan.h"
#include "core/calibration/Calibration.h"

namespace armtrack::gui::home {

struct HomeSetup {
  /// The devices as "plugin:key=value,..." (the settings' devices, or the demo's virtual arm).
  QStringList devices;
  /// A live session's set-up for a plan, these devices and a calibration (the application's
  /// liveSessionConfig: the patient's arm, the estimator of the settings, the protocol's target).
  std::function<app::gui::LiveSessionConfig(const SessionPlan&, const QStringList&,
                                            const std::optional<Calibration>&)>
      configure;
  /// Where the check's and the calibration's recordings go (a temporary folder).
  QString workFolder;
  /// Where the home sync keeps its state and outgoing copies (docs/sync.md, "The home
  /// install"); empty: this install does not sync (the demo, the tests).
  QString syncFolder;

  /// Every device is a virtual arm: each step's devices play its movement.
  bool virtualArm() const;
  /// A camera or a Kinect is among the devices (the shoulder's angles can be trusted).
  bool opticalConfigured() const;
  /// The devices of the sensor check, the calibration and an exercise.
  QStringList checkDevices() const;
  QStringList calibrationDevices() const;
  QStringList exerciseDevices(const HomeExercise& exercise) const;

 private:
  QStringList withMotion(const QString& motion) const;
};

}  // namespace armtrack::gui::home
