#include "app/gui/newsession/LiveConfig.h"

#include <algorithm>
#include <cmath>

#include "app/gui/common/AngleNames.h"
#include "app/gui/services/PatientRecords.h"

namespace armtrack::gui {

app::gui::LiveSessionConfig liveSessionConfig(const SessionPlan& plan, const QStringList& devices,
                                              const AppSettings& settings,
                                              const std::optional<Calibration>& calibration) {
  app::gui::LiveSessionConfig c;
  c.devices = devices;
  c.patientLabel = QStringLiteral("%1 %2").arg(plan.patient.code, plan.patient.name);
  const bool virtualArm = std::all_of(devices.begin(), devices.end(), [](const QString& d) {
    return d.startsWith(QLatin1String("virtual-arm"));
  });
  // The virtual arm simulates the default right arm; a real patient's arm gets their measured
  // lengths and the chosen side.
  c.meta.side = virtualArm ? Side::Right : plan.side;
  if (!virtualArm) {
    const SegmentLengths l = SegmentLengths::fromJson(plan.patient.segmentLengthsJson);
    if (l.upperArmM) c.meta.geometry.l3 = *l.upperArmM;
    if (l.forearmM) c.meta.geometry.l6 = *l.forearmM;
    if (l.upperStrapM) c.meta.geometry.lu3 = *l.upperStrapM;
    if (l.forearmStrapM) c.meta.geometry.lf6 = *l.forearmStrapM;
  }
  // A sensor calibration made for this session brings the arm's fitted lengths and mounting.
  if (calibration && calibration->side == c.meta.side) {
    // Applied to the live readings (the straps' rotations, the gyroscopes' biases) and kept in
    // the sidecar's geometry.
    c.calibration = calibration;
    c.meta.geometry = calibration->geometry;
    // The straps are known: no fit from the movement.
    c.movementCalibration.enabled = false;
    // And the sternum sensor's mounting levelled from the start pose, for the same sensor.
    if (calibration->trunk && hasSternumSensor(devices)) c.meta.trunk = calibration->trunk;
  }
  c.estimator.filter = settings.filter == QLatin1String("ukf") ? FilterKind::Ukf : FilterKind::Ekf;
  try {
    c.estimator.model = parseMethod(settings.method.toStdString());
  } catch (const std::invalid_argument&) {
  }
  if (plan.protocol) {
    const int angle = angleIndex(plan.protocol->angleKey);
    if (angle >= 0) c.primaryAngle = angle;
    c.targetDeg = std::make_pair(plan.protocol->targetMinDeg, plan.protocol->targetMaxDeg);
    if (plan.protocol->repetitions > 0) c.targetRepetitions = plan.protocol->repetitions;
    c.trunkLimitDeg = plan.protocol->trunkLimitDeg;
  }
  return c;
}

QStringList demoDevicesFor(const SessionPlan& plan) {
  QStringList devices = app::gui::demoDevices();
  if (!plan.protocol || angleIndex(plan.protocol->angleKey) < 0) return devices;
  const double lo = plan.protocol->targetMinDeg, hi = plan.protocol->targetMaxDeg;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) return devices;
  const double rest = std::min(20.0, lo), top = lo + 0.85 * (hi - lo);
  devices.front() += QStringLiteral(",trajectory=exercise,exercise=%1,exercise-range=%2:%3")
                         .arg(plan.protocol->angleKey)
                         .arg(rest, 0, 'f', 1)
                         .arg(top, 0, 'f', 1);
  return devices;
}

}  // namespace armtrack::gui
