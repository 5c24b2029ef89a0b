#include "app/gui/home/HomeSetup.h"

#include <algorithm>

#include "app/gui/services/AngleKeys.h"

namespace armtrack::gui::home {

namespace {

QString pluginOf(const QString& spec) {
  return spec.section(u':', 0, 0).trimmed();
}

QStringList optionsOf(const QString& spec) {
  const qsizetype colon = spec.indexOf(u':');
  return colon < 0 ? QStringList() : spec.mid(colon + 1).split(u',', Qt::SkipEmptyParts);
}

}  // namespace

bool HomeSetup::virtualArm() const {
  return !devices.isEmpty() && std::all_of(devices.begin(), devices.end(), [](const QString& d) {
    return pluginOf(d) == QLatin1String("virtual-arm");
  });
}

bool HomeSetup::opticalConfigured() const {
  for (const QString& d : devices) {
    const QString plugin = pluginOf(d);
    if (plugin == QLatin1String("webcam") || plugin == QLatin1String("kinect") ||
        plugin == QLatin1String("skeleton-udp"))
      return true;
    if (plugin != QLatin1String("virtual-arm")) continue;
    // The virtual arm's sensors (upper+forearm+kinect by default).
    QString sensors = QStringLiteral("upper+forearm+kinect");
    for (const QString& o : optionsOf(d))
      if (o.startsWith(QLatin1String("sensors="))) sensors = o.mid(8);
    const QStringList s = sensors.split(u'+');
    if (s.contains(QLatin1String("webcam")) || s.contains(QLatin1String("kinect"))) return true;
  }
  return false;
}

QStringList HomeSetup::withMotion(const QString& motion) const {
  if (!virtualArm()) return devices;
  QStringList out;
  for (const QString& d : devices) {
    QStringList options;
    for (const QString& o : optionsOf(d))
      // The step's movement replaces any other; an exercise's compensation (a test's, the
      // demo's) is kept.
      if (!o.startsWith(QLatin1String("trajectory=")) &&
          !(o.startsWith(QLatin1String("exercise")) &&
            !o.startsWith(QLatin1String("exercise-compensation="))))
        options << o;
    options << motion;
    out << pluginOf(d) + u':' + options.join(u',');
  }
  return out;
}

QStringList HomeSetup::checkDevices() const {
  return withMotion(QStringLiteral("trajectory=sensor-check"));
}

QStringList HomeSetup::calibrationDevices() const {
  return withMotion(QStringLiteral("trajectory=calibration"));
}

QStringList HomeSetup::exerciseDevices(const HomeExercise& e) const {
  // The demonstration's pace: a repetition every 4 s with a 1 s pause, the first after 3 s.
  return withMotion(QStringLiteral("trajectory=exercise,exercise=%1,exercise-range=%2:%3,"
                                   "exercise-period=4,exercise-pause=1,exercise-start=3")
                        .arg(angleKey(e.angle))
                        .arg(e.targetMinDeg)
                        .arg(e.targetMaxDeg));
}

}  // namespace armtrack::gui::home
