#include "devices/virtual_arm/VirtualArmPlugin.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "core/kinematics/ClinicalAngles.h"
#include "core/simulation/ImuErrors.h"
#include "core/simulation/TrunkOptions.h"
#include "devices/api/Options.h"
#include "devices/virtual_arm/VirtualArmDevice.h"

namespace armtrack::devices::virtualarm {

QString VirtualArmPlugin::description() const {
  return QStringLiteral(
      "simulated IMUs, Kinect and webcam in real time, a leaning trunk, with fault injection");
}

QString VirtualArmPlugin::optionsHelp() const {
  return QStringLiteral(
      "sensors=upper+forearm+kinect  any of upper, forearm, trunk (sternum IMU), kinect, webcam\n"
      "                              joined by '+'\n"
      "trajectory=multi-joint        sinusoid, multi-joint, shoulder-wheel, calibration,\n"
      "                              reaching, sensor-check or exercise\n"
      "exercise=elbow_flexion        trajectory=exercise: the clinical angle repeated\n"
      "exercise-range=20:120         deg, from rest to the top of each repetition\n"
      "exercise-period=4             s per repetition (up and down)\n"
      "exercise-pause=1              s at rest between repetitions\n"
      "exercise-start=1              s at rest before the first\n"
      "exercise-compensation=0       deg another joint moves with each repetition\n"
      "trunk-lean=0                  deg the trunk leans forward at the fullest reach (shoulder\n"
      "                              flexion 90 deg; from 20 deg), turning about the hip;\n"
      "                              0 = a still trunk (0-45)\n"
      "trunk-lateral=0.5             sideways lean per degree of lean (-2-2; negative: left)\n"
      "trunk-rotation=0.5            axial turn per degree of lean (-2-2; negative: the left\n"
      "                              shoulder comes forward)\n"
      "trunk-sway=1                  deg of the leaning trunk's own slow sway (0-5)\n"
      "kinect-shoulder=              on or off: the Kinect also reports the shoulder (default:\n"
      "                              when the trunk leans)\n"
      "seed=1                        noise and trajectory seed\n"
      "imu-rate=1000                 Hz, both IMUs\n"
      "kinect-rate=30                Hz\n"
      "webcam-rate=30                Hz\n"
      "noise=on                      the paper's Table 5 noise (off: noise-free)\n"
      "resolution=full               IMU converter: full (doubles), shimmer3 (65.5 counts per\n"
      "                              deg/s, 83 per m/s^2) or GYRO:ACC counts per deg/s, m/s^2\n"
      "sensor-errors=ideal           ideal (noise only) or realistic: a real MEMS part's errors\n"
      "                              drawn from the seed (scale, cross-axis, walking bias,\n"
      "                              50/25 Hz held on a 90 Hz clock unless imu-rate is given,\n"
      "                              wobble, slip; docs/simulation.md)\n"
      "truth=on                      a stream of the true joint angles beside the IMUs\n"
      "duration=0                    s of simulation, 0 = endless\n"
      "tick=0.002                    s between deliveries (the link's batching)\n"
      "battery=80                    % at the start, reported as a device's battery (off: none)\n"
      "battery-drain=1               % the battery loses per minute\n"
      "Faults (START and SECONDS in simulated seconds, several joined by '|'):\n"
      "dropout=STREAM@START+SECONDS  one stream goes silent\n"
      "disappear=START+SECONDS       the whole device goes away and comes back\n"
      "restart-clock=off             after coming back, its IMU clock restarts from 0\n"
      "stall=START+SECONDS           the link holds samples, then delivers them in a burst\n"
      "jump=AT:SECONDS               the IMU clock steps (negative: goes backwards)\n"
      "spike=STREAM@T[:VALUE]        one sample of absurd but finite values (default 1e6)\n"
      "saturate=STREAM@START+SECONDS IMU readings at full scale (2000 deg/s, 16 g)\n"
      "zeros=STREAM@START+SECONDS    readings of exactly zero\n"
      "corrupt=0                     probability that an IMU sample carries NaN\n"
      "drift=0                       IMU clock rate error, ppm\n"
      "Wearing faults:\n"
      "swap-imus=off                 each IMU on the other's segment (readings exchanged)\n"
      "upside-down=                  upper, forearm or both: strapped end over end");
}

std::unique_ptr<Device> VirtualArmPlugin::create(const QVariantMap& options, QString* error) {
  Options o(options);
  VirtualArmParams p;
  p.sim = defaultSimulation();
  const QStringList sensors =
      o.text(QStringLiteral("sensors"), QStringLiteral("upper+forearm+kinect")).split(u'+');
  const QString trajectory = o.text(QStringLiteral("trajectory"), QStringLiteral("multi-joint"));
  p.sim.seed = static_cast<std::uint64_t>(o.integer(QStringLiteral("seed"), 1, 0, 1 << 30));
  p.trajectoryOptions.seed = static_cast<int>(p.sim.seed);
  const double imuRate = o.number(QStringLiteral("imu-rate"), 1000.0, 1.0, 4000.0);
  p.sim.kinect.rateHz = o.number(QStringLiteral("kinect-rate"), 30.0, 1.0, 200.0);
  p.sim.webcam.rateHz = o.number(QStringLiteral("webcam-rate"), 30.0, 1.0, 200.0);
  const bool noise = o.flag(QStringLiteral("noise"), true);
  p.truth = o.flag(QStringLiteral("truth"), true);
  const double duration = o.number(QStringLiteral("duration"), 0.0, 0.0, 1e7);
  const double tick = o.number(QStringLiteral("tick"), 0.002, 0.001, 0.2);
  const QString dropout = o.text(QStringLiteral("dropout"));
  const QString disappear = o.text(QStringLiteral("disappear"));
  p.faults.restartClock = o.flag(QStringLiteral("restart-clock"), false);
  const QString stall = o.text(QStringLiteral("stall"));
  const QString jump = o.text(QStringLiteral("jump"));
  const QString spike = o.text(QStringLiteral("spike"));
  const QString saturate = o.text(QStringLiteral("saturate"));
  const QString zeros = o.text(QStringLiteral("zeros"));
  p.faults.corruptProbability = o.number(QStringLiteral("corrupt"), 0.0, 0.0, 1.0);
  p.faults.driftPpm = o.number(QStringLiteral("drift"), 0.0, -1000.0, 1000.0);
  p.swapImus = o.flag(QStringLiteral("swap-imus"), false);
  const QString upsideDown = o.text(QStringLiteral("upside-down"));
  const QString resolution = o.text(QStringLiteral("resolution"), QStringLiteral("full"));
  const QString sensorErrors = o.text(QStringLiteral("sensor-errors"), QStringLiteral("ideal"));
  const QString battery = o.text(QStringLiteral("battery"), QStringLiteral("80"));
  p.batteryDrainPerMinute = o.number(QStringLiteral("battery-drain"), 1.0, 0.0, 100.0);
  const QString exercise = o.text(QStringLiteral("exercise"), QStringLiteral("elbow_flexion"));
  const QString range = o.text(QStringLiteral("exercise-range"), QStringLiteral("20:120"));
  ExerciseMotion& motion = p.trajectoryOptions.exercise;
  motion.periodSeconds = o.number(QStringLiteral("exercise-period"), 4.0, 0.2, 600.0);
  motion.pauseSeconds = o.number(QStringLiteral("exercise-pause"), 1.0, 0.0, 600.0);
  motion.startSeconds = o.number(QStringLiteral("exercise-start"), 1.0, 0.0, 600.0);
  motion.compensationDeg = o.number(QStringLiteral("exercise-compensation"), 0.0, -90.0, 90.0);
  TrunkSimOptions trunk;
  const double lean =
      o.number(QStringLiteral("trunk-lean"), 0.0, 0.0, TrunkSimOptions::kMaxLeanDeg);
  if (lean > 0.0) trunk.leanDeg = lean;
  if (o.has(QStringLiteral("trunk-lateral")))
    trunk.lateralRatio = o.number(QStringLiteral("trunk-lateral"), 0.5, -TrunkSimOptions::kMaxRatio,
                                  TrunkSimOptions::kMaxRatio);
  if (o.has(QStringLiteral("trunk-rotation")))
    trunk.rotationRatio = o.number(QStringLiteral("trunk-rotation"), 0.5,
                                   -TrunkSimOptions::kMaxRatio, TrunkSimOptions::kMaxRatio);
  if (o.has(QStringLiteral("trunk-sway")))
    trunk.swayDeg = o.number(QStringLiteral("trunk-sway"), 1.0, 0.0, TrunkSimOptions::kMaxSwayDeg);
  if (o.has(QStringLiteral("kinect-shoulder")))
    trunk.kinectShoulder = o.flag(QStringLiteral("kinect-shoulder"), false);
  QStringList problems;
  if (!o.error().isEmpty()) problems << o.error();
  if (battery == u"off") {
    p.batteryPercent.reset();
  } else {
    bool ok = false;
    p.batteryPercent = battery.toDouble(&ok);
    if (!ok || !std::isfinite(*p.batteryPercent) || *p.batteryPercent < 0 ||
        *p.batteryPercent > 100)
      problems << QStringLiteral("battery=%1: give a level from 0 to 100 (%), or off").arg(battery);
  }
  motion.angle = -1;
  QStringList keys;
  for (std::size_t i = 0; i < clinicalAngleInfo().size(); ++i) {
    const std::string_view key = clinicalAngleInfo()[i].key;
    keys << QString::fromLatin1(key.data(), static_cast<qsizetype>(key.size()));
    if (keys.back() == exercise) motion.angle = static_cast<int>(i);
  }
  if (motion.angle < 0)
    problems << QStringLiteral("exercise=%1 is not a clinical angle (use %2)")
                    .arg(exercise, keys.join(QStringLiteral(", ")));
  const QStringList ends = range.split(u':');
  bool lowOk = false, highOk = false;
  if (ends.size() == 2) {
    motion.fromDeg = ends[0].toDouble(&lowOk);
    motion.toDeg = ends[1].toDouble(&highOk);
  }
  if (!lowOk || !highOk || std::abs(motion.fromDeg) > 360 || std::abs(motion.toDeg) > 360)
    problems
        << QStringLiteral("exercise-range=%1: write FROM:TO in degrees, e.g. 20:120").arg(range);
  // End over end: half a turn about the sensor's z axis, across the segment (the long axis is
  // the sensor's y in the arm model's mounting, whatever the strap's angle around the arm).
  const Eigen::Matrix3d flipped =
      Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  if (upsideDown == u"upper" || upsideDown == u"both") p.sim.upperArm.misalignment = flipped;
  if (upsideDown == u"forearm" || upsideDown == u"both") p.sim.forearm.misalignment = flipped;
  if (!upsideDown.isEmpty() && upsideDown != u"upper" && upsideDown != u"forearm" &&
      upsideDown != u"both")
    problems << QStringLiteral("upside-down=%1: use upper, forearm or both").arg(upsideDown);

  p.sim.upperArm.enabled = sensors.contains(QStringLiteral("upper"));
  p.sim.forearm.enabled = sensors.contains(QStringLiteral("forearm"));
  p.sim.kinect.enabled = sensors.contains(QStringLiteral("kinect"));
  p.sim.webcam.enabled = sensors.contains(QStringLiteral("webcam"));
  trunk.trunkImu = sensors.contains(QStringLiteral("trunk"));
  for (const QString& s : sensors)
    if (s != u"upper" && s != u"forearm" && s != u"trunk" && s != u"kinect" && s != u"webcam")
      problems << QStringLiteral(
                      "unknown sensor '%1' in sensors= (use upper, forearm, trunk, kinect, "
                      "webcam joined by '+')")
                      .arg(s);
  for (ImuSimParams* imu : {&p.sim.upperArm, &p.sim.forearm}) {
    imu->rateHz = imuRate;
    if (!noise) imu->gyroNoiseStd = imu->accelNoiseStd = 0.0;
  }
  if (!noise) p.sim.kinect.noiseStd = p.sim.webcam.noiseStdPx = 0.0;
  // The trunk as `armtrack-cli simulate` maps its --trunk-* flags (the sternum IMU takes the
  // upper-arm IMU's rate and noise).
  try {
    applyTrunkSimOptions(trunk, p.sim);
  } catch (const std::invalid_argument& e) {
    problems << QString::fromStdString(e.what());
  }
  // The realistic preset as `armtrack-cli simulate --sensors realistic` applies it, after the
  // sternum IMU is set so that it draws its own errors.
  try {
    applySensorModel(
        parseSensorModel(sensorErrors.toStdString()), p.sim,
        o.has(QStringLiteral("imu-rate")) ? std::optional<double>(imuRate) : std::nullopt);
  } catch (const std::invalid_argument& e) {
    problems << QStringLiteral("sensor-errors=%1: %2")
                    .arg(sensorErrors, QString::fromStdString(e.what()));
  }
  p.sim.duration = duration > 0.0 ? duration : std::numeric_limits<double>::infinity();
  p.trajectory = trajectory.toStdString();
  try {
    p.faults.dropouts = parseDropouts(dropout.toStdString());
    p.faults.disappear = parseWindows(disappear.toStdString());
    p.faults.stalls = parseWindows(stall.toStdString());
    p.faults.jumps = parseJumps(jump.toStdString());
    p.faults.spikes = parseSpikes(spike.toStdString());
    p.faults.saturations = parseStreamWindows(saturate.toStdString(), "saturation");
    p.faults.zeros = parseStreamWindows(zeros.toStdString(), "zeros window");
    p.resolution = parseResolution(resolution.toStdString());
  } catch (const std::invalid_argument& e) {
    problems << QString::fromStdString(e.what());
  }
  if (problems.isEmpty()) {
    try {
      return std::make_unique<VirtualArmDevice>(p, tick);
    } catch (const std::invalid_argument& e) {
      problems << QString::fromStdString(e.what());
    }
  }
  if (error) *error = QStringLiteral("virtual-arm: ") + problems.join(QStringLiteral("; "));
  return nullptr;
}

}  // namespace armtrack::devices::virtualarm
