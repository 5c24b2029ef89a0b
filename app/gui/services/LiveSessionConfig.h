// What a live session screen needs to start a session: the devices as the command line names
// them, the arm, the estimator, and the protocol's targets for the counter and the plots.
#pragma once

#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <algorithm>
#include <optional>
#include <utility>

#include "core/calibration/Calibration.h"
#include "core/estimation/ArmFilter.h"
#include "core/io/Recording.h"
#include "core/session/LiveCalibration.h"

namespace armtrack::app::gui {

struct LiveSessionConfig {
  /// Devices as "plugin:key=value,..." (armtrack-cli record --device), e.g.
  /// "virtual-arm:sensors=upper+forearm+kinect+webcam".
  QStringList devices;
  /// Arm geometry, up direction, gravity, side (and a camera, if no device brings one).
  RecordingMeta meta;
  /// Estimator settings (filter, method, noise); the geometry comes from meta.
  EstimatorParams estimator;
  /// Shown in the screen's header, e.g. "P01 Ada Example".
  QString patientLabel;
  /// The protocol's primary angle (clinicalAngleInfo() index) and its target range (deg); the
  /// counter counts on the primary angle (shoulder flexion when none is given).
  std::optional<int> primaryAngle;
  std::optional<std::pair<double, double>> targetDeg;
  /// The protocol's number of repetitions.
  std::optional<int> targetRepetitions;
  /// The protocol's trunk limit (deg of trunk flexion; storage::Protocol::trunkLimitDeg): past
  /// it the screen cues "Keep your back against the chair" and counts the repetitions made so.
  std::optional<double> trunkLimitDeg;
  /// The plots' window (s, 10-30).
  double windowSeconds = 20.0;
  /// Record from the start (when a recording target was given), without pressing Record.
  bool recordFromStart = false;
  /// The sensor calibration made for this session (liveSessionConfig: for this arm): applied to
  /// the live readings from the first row (session::SessionParams::calibration).
  std::optional<Calibration> calibration;
  /// The sensor calibration made for this session, stored with it for the report: "good",
  /// "usable" or "poor" ("" = none made) and its reason in words.
  QString calibrationVerdict, calibrationReason;
  /// The straps fitted from the movement while the session runs (docs/session.md, "Calibration
  /// from movement"): on unless a sensor calibration is used (liveSessionConfig switches it off
  /// then).
  session::LiveCalibrationParams movementCalibration = [] {
    session::LiveCalibrationParams p;
    p.enabled = true;
    return p;
  }();
};

/// Whether the device specs include a sternum (trunk) IMU: the virtual arm's `trunk` sensor, or
/// an IMU plugin given role=trunk (or role=sternum). A sensor calibration's sternum mounting is
/// passed to the session only then: without the sensor the estimator must not expect a trunk.
inline bool hasSternumSensor(const QStringList& devices) {
  // "virtual-arm:sensors=upper+forearm+trunk,...", "shimmer:port=...,role=trunk".
  static const QRegularExpression sternum(
      QStringLiteral("[:,](?:sensors=(?:[^,]*\\+)?trunk|role=(?:trunk|sternum))(?:[+,]|$)"));
  return std::any_of(devices.begin(), devices.end(),
                     [](const QString& d) { return sternum.match(d).hasMatch(); });
}

/// The sternum IMU as the 3D view draws it: the session's mounting (a sensor calibration's),
/// or where the sensor is put by default when only its presence is known; none without one.
inline std::optional<TrunkMount> drawnSternum(const LiveSessionConfig& c) {
  if (!hasSternumSensor(c.devices)) return std::nullopt;
  return c.meta.trunk ? c.meta.trunk : std::optional<TrunkMount>(defaultTrunkMount(c.meta.side));
}

/// The demo's devices: the virtual arm with both IMUs, a Kinect and a webcam.
inline QStringList demoDevices() {
  return {QStringLiteral("virtual-arm:sensors=upper+forearm+kinect+webcam")};
}

}  // namespace armtrack::app::gui
