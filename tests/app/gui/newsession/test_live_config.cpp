// The live session's set-up from the new-session flow: a sensor calibration's sternum mounting
// reaches the session only when the devices include a sternum sensor, and a sensor calibration
// of the arm is applied to the live readings and switches the fit of the straps from the
// movement off.
#include <QTest>

#include <Eigen/Geometry>

#include "app/gui/newsession/LiveConfig.h"

using namespace armtrack;

class TestLiveConfig : public QObject {
  Q_OBJECT
 private slots:
  void sternumCalibrationReachesTheSessionOnlyWithTheSensor() {
    Calibration cal;
    TrunkMount m;
    m.imuRotation = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()).toRotationMatrix();
    cal.trunk = m;
    const gui::SessionPlan plan;
    const gui::AppSettings settings;
    for (const QString& spec : {QStringLiteral("virtual-arm:sensors=upper+forearm+trunk"),
                                QStringLiteral("virtual-arm:sensors=trunk+upper,trunk-lean=10"),
                                QStringLiteral("shimmer:port=/dev/rfcomm2,role=trunk")}) {
      QVERIFY2(gui::hasSternumSensor({QStringLiteral("virtual-arm:sensors=upper"), spec}),
               qPrintable(spec));
      const auto c = gui::liveSessionConfig(plan, {spec}, settings, cal);
      QVERIFY2(c.meta.trunk && c.meta.trunk->imuRotation.isApprox(m.imuRotation), qPrintable(spec));
    }
    // Without a sternum sensor (a lean simulated, a role that is not the trunk's), none.
    for (const QString& spec : {QStringLiteral("virtual-arm:sensors=upper+forearm,trunk-lean=10"),
                                QStringLiteral("shimmer:port=/dev/rfcomm2,role=forearm"),
                                QStringLiteral("virtual-arm:sensors=upper+trunkish")}) {
      QVERIFY2(!gui::hasSternumSensor({spec}), qPrintable(spec));
      QVERIFY2(!gui::liveSessionConfig(plan, {spec}, settings, cal).meta.trunk, qPrintable(spec));
    }
    // The calibration of the other arm brings nothing.
    gui::SessionPlan left;
    left.side = Side::Left;
    QVERIFY(!gui::liveSessionConfig(left, {QStringLiteral("shimmer:role=trunk")}, settings, cal)
                 .meta.trunk);
  }

  // The straps are fitted from the movement only when no sensor calibration of this arm is used
  // (docs/session.md, "Calibration from movement").
  void aSensorCalibrationMeansNoFitFromTheMovement() {
    const gui::SessionPlan plan;
    const gui::AppSettings settings;
    const QStringList devices = {QStringLiteral("virtual-arm:sensors=upper+forearm")};
    QVERIFY(
        gui::liveSessionConfig(plan, devices, settings, std::nullopt).movementCalibration.enabled);
    QVERIFY(!gui::liveSessionConfig(plan, devices, settings, std::nullopt).calibration);
    Calibration cal;
    cal.upperArm.rotation = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const auto used = gui::liveSessionConfig(plan, devices, settings, cal);
    QVERIFY(!used.movementCalibration.enabled);
    // ... and the session applies it to the readings (the straps' rotations), not only its
    // geometry.
    QVERIFY(used.calibration &&
            used.calibration->upperArm.rotation.isApprox(cal.upperArm.rotation));
    // A calibration of the other arm is none for this one.
    gui::SessionPlan left;
    left.side = Side::Left;
    const auto other =
        gui::liveSessionConfig(left, {QStringLiteral("shimmer:port=/dev/rfcomm2")}, settings, cal);
    QVERIFY(other.movementCalibration.enabled);
    QVERIFY(!other.calibration);
  }
};

QTEST_GUILESS_MAIN(TestLiveConfig)
#include "test_live_config.moc"
