// The webcam device: frames from OpenCV's VideoCapture (a camera or a video file), the wrist and
// elbow markers found in each, published as MarkerPixels (docs/devices/webcam.md).
#pragma once

#include <QString>
#include <QVariantMap>
#include <cstdint>
#include <memory>
#include <optional>

#include "devices/api/Device.h"
#include "devices/api/ProblemLimiter.h"
#include "devices/vision/CameraFile.h"
#include "devices/vision/CoreCameraParams.h"
#include "devices/vision/MarkerDetection.h"

class QTimer;
namespace cv {
class VideoCapture;
class Mat;
}  // namespace cv

namespace armtrack::devices::webcam {

/// What the plugin's options select (see WebcamPlugin::optionsHelp()).
struct WebcamSettings {
  QString source = QStringLiteral("0");  ///< camera index, /dev/videoN, or a video file
  bool isFile = false;                   ///< source names a file (not a number or /dev/video*)
  int deviceIndex = 0;                   ///< when source is a number
  MarkerKind markers = MarkerKind::Colour;
  ColourMarkerParams colour;
  ArucoMarkerParams aruco;
  QString cameraPath;                ///< calibration file, empty when none
  std::optional<CameraFile> camera;  ///< its contents
  bool loop = false;                 ///< files: start again at the end
  double speed = 1.0;           ///< files: 1 = the file's own frame rate, 0 = as fast as possible
  double retrySeconds = 1.0;    ///< cameras: s between attempts to (re)open
  double timeoutSeconds = 2.0;  ///< cameras: s without a frame before reopening
  int width = 0, height = 0;    ///< cameras: requested frame size, 0 = the camera's default
};

/// Reads the options; empty with *error saying what to change when one is malformed or unknown,
/// the calibration file cannot be read, or the marker options do not fit. Any thread.
std::optional<WebcamSettings> readWebcamSettings(const QVariantMap& options, QString* error);

/// One camera as one Camera stream of MarkerPixels. Every frame read is published, with a marker
/// absent where it was not found.
///
/// Files: the frames are read from a timer in the device thread, paced at speed x the file's
/// frame rate. Device time is the frame's time in the file (CAP_PROP_POS_MSEC, else index / fps),
/// continuing across loops. At the end: Disconnected ("end of video"), or again from the start
/// with loop. A missing or unreadable file, or one that breaks off before the frame count its
/// header declares (truncated), is Error with the reason; frames that cannot be decoded inside the
/// file are skipped, counted as corrupt and reported (at most one message a second).
///
/// Cameras: device time is the host time (hostNow()) when the frame was grabbed. A camera that
/// cannot be opened, or delivers nothing for timeoutSeconds, is Connecting (with the reason) and is
/// reopened every retrySeconds; when frames flow again the device counts a reconnect.
///
/// Threads: construct anywhere, then use only from the device's thread (see Device).
class WebcamDevice final : public Device {
  Q_OBJECT
 public:
  explicit WebcamDevice(WebcamSettings settings, QObject* parent = nullptr);
  ~WebcamDevice() override;

 public slots:
  void start() override;
  void stop() override;

 private:
  void open();
  bool openFile();
  bool openCamera();
  void tick();
  void tickFile();
  /// What reading the file's next frame gave.
  enum class FileRead { Frame, Skipped, Ended, Failed };
  /// Reads the next frame into batch, or skips a damaged one; failure says why the file cannot
  /// go on (Failed).
  FileRead readFileFrame(SampleBatch& batch, QString& failure);
  /// The file's end: played again (loop=on), or the device ends; no readable frame at all fails.
  void endOfFile();
  void tickCamera();
  /// Detects the markers and appends the sample; false when the frame is unusable.
  bool processFrame(const cv::Mat& frame, double deviceTime, SampleBatch& batch);
  void cameraLost(const QString& reason);
  void fail(const QString& reason);
  void closeCapture();
  QString sourceName() const;

  const WebcamSettings m_settings;
  MarkerDetector m_detector;
  std::unique_ptr<cv::VideoCapture> m_capture;
  QTimer* m_frameTimer = nullptr;              // reads frames; created in start()
  QTimer* m_retryTimer = nullptr;              // reopens a lost camera
  std::unique_ptr<ProblemLimiter> m_problems;  // one problem message per second at most
  bool m_running = false;

  // Files.
  double m_fps = 0.0;                // frames per second of the file (30 when it does not say)
  double m_frameCount = 0.0;         // frames its header declares, 0 when unknown
  double m_playStart = 0.0;          // host time of the first frame of this play-through
  std::uint64_t m_framesPlayed = 0;  // frames read since m_playStart
  double m_loopOffset = 0.0;         // s added to the file time after each loop
  double m_lastFileTime = -1.0;
  int m_failuresInRow = 0;

  // Cameras.
  double m_lastFrameHost = 0.0;
  bool m_streamedBefore = false;
  bool m_lost = false;

  bool m_sizeChecked = false;
};

}  // namespace armtrack::devices::webcam
