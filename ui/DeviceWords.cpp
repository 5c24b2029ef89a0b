#include "ui/DeviceWords.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace armtrack::ui {

namespace {
constexpr const char* kContext = "armtrack::ui::DeviceWords";
}

QString deviceStateText(const QString& english) {
  static const char* const kStates[] = {
      QT_TRANSLATE_NOOP("armtrack::ui::DeviceWords", "disconnected"),
      QT_TRANSLATE_NOOP("armtrack::ui::DeviceWords", "connecting"),
      QT_TRANSLATE_NOOP("armtrack::ui::DeviceWords", "streaming"),
      QT_TRANSLATE_NOOP("armtrack::ui::DeviceWords", "error"),
  };
  for (const char* s : kStates)
    if (english == QLatin1String(s)) return QCoreApplication::translate(kContext, s);
  return english;
}

QString pluginDescriptionText(const QString& english) {
  // The descriptions of the plugins in devices/ (their description() methods), word for word.
  static const char* const kDescriptions[] = {
      QT_TRANSLATE_NOOP("armtrack::ui::DeviceWords",
                        "simulated IMUs, Kinect and webcam in real time, with fault injection"),
      QT_TRANSLATE_NOOP("armtrack::ui::DeviceWords",
                        "Kinect v1 (libfreenect): elbow and wrist markers in 3D, shoulder frame"),
      QT_TRANSLATE_NOOP("armtrack::ui::DeviceWords",
                        "do-it-yourself IMU (ESP32/Arduino) sending ArmTrack's $IMU text lines "
                        "over a serial port or UDP"),
      QT_TRANSLATE_NOOP("armtrack::ui::DeviceWords",
                        "x-io NGIMU over Wi-Fi (OSC over UDP, /sensors messages)"),
      QT_TRANSLATE_NOOP("armtrack::ui::DeviceWords",
                        "Shimmer3 IMU (LogAndStream firmware) over its Bluetooth serial port"),
      QT_TRANSLATE_NOOP("armtrack::ui::DeviceWords",
                        "elbow and wrist positions from an external body tracker (Kinect SDK, "
                        "pose estimator), JSON over UDP"),
      QT_TRANSLATE_NOOP("armtrack::ui::DeviceWords",
                        "wrist and elbow marker pixels from a camera or a video file (OpenCV)"),
  };
  for (const char* s : kDescriptions)
    if (english == QLatin1String(s)) return QCoreApplication::translate(kContext, s);
  return english;
}

QString sessionEventText(const QString& line) {
  static const QRegularExpression state(
      QStringLiteral("^(.+): (disconnected|connecting|streaming|error)( \\(.*\\))?$"));
  const QRegularExpressionMatch m = state.match(line);
  if (!m.hasMatch()) return line;
  return QStringLiteral("%1: %2%3")
      .arg(m.captured(1), deviceStateText(m.captured(2)), m.captured(3));
}

}  // namespace armtrack::ui
