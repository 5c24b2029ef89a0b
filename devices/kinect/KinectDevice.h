// The Kinect v1 device: colour and registered depth frames from libfreenect, turned into elbow,
// wrist and (with a shoulder marker) shoulder positions in the registered frame by KinectProcessor
// (docs/devices/kinect.md).
#pragma once

#include <QString>
#include <QVariantMap>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>

#include "devices/api/Device.h"
#include "devices/kinect/KinectProcessing.h"

class QTimer;
struct _freenect_context;
struct _freenect_device;

namespace armtrack::devices::kinect {

struct KinectSettings {
  int index = 0;  ///< which Kinect, when several are plugged in
  KinectProcessingParams processing;
  webcam::MarkerKind markers = webcam::MarkerKind::Colour;
  webcam::ColourMarkerParams colour;
  webcam::ArucoMarkerParams aruco;
  /// A third marker on the shoulder (acromion): its HSV box (colour markers) or its id (ArUco);
  /// neither: no shoulder is published.
  std::optional<webcam::HsvRange> shoulderHsv;
  std::optional<int> shoulderId;
  QString cameraPath;
  double retrySeconds = 1.0;    ///< s between attempts to (re)open
  double timeoutSeconds = 2.0;  ///< s without a depth frame before reopening
};

/// Reads the options (see KinectPlugin::optionsHelp()); empty with *error saying what to change.
/// camera= is required: the colour camera's calibration file with its pose (camera-register).
std::optional<KinectSettings> readKinectSettings(const QVariantMap& options, QString* error);

/// One Kinect v1 as one Optical stream of OpticalPositions (the shoulder too, declared on the
/// stream, when a shoulder marker is set). libfreenect runs in the device thread:
/// a 5 ms timer calls freenect_process_events_timeout with a zero timeout, and the video and depth
/// callbacks run inside that call. Each depth frame is paired with the newest colour frame (if it
/// is under 50 ms older) and published; device time is the host time (hostNow()) when the depth
/// frame arrived, since the Kinect's own frame counter has no documented unit.
///
/// No Kinect, or one that stops delivering for timeoutSeconds, is Connecting with the reason and
/// is reopened every retrySeconds; when frames flow again the device counts a reconnect.
/// Threads: construct anywhere, then use only from the device's thread (see Device).
class KinectDevice final : public Device {
  Q_OBJECT
 public:
  explicit KinectDevice(KinectSettings settings, QObject* parent = nullptr);
  ~KinectDevice() override;

 public slots:
  void start() override;
  void stop() override;

 private:
  static void onVideo(_freenect_device* dev, void* data, std::uint32_t timestamp);
  static void onDepth(_freenect_device* dev, void* data, std::uint32_t timestamp);
  void open();
  void poll();
  void close();
  void lost(const QString& reason);
  void handleDepth(const std::uint16_t* depth);

  const KinectSettings m_settings;
  KinectProcessor m_processor;
  _freenect_context* m_ctx = nullptr;
  _freenect_device* m_dev = nullptr;
  QTimer* m_pollTimer = nullptr;
  QTimer* m_retryTimer = nullptr;
  bool m_running = false;
  bool m_lost = false;
  bool m_streamedBefore = false;
  double m_lastDepthHost = 0.0;
  cv::Mat m_bgr;            // newest colour frame
  double m_bgrHost = -1e9;  // its arrival time
  std::uint64_t m_depthMissingReported = 0;
  double m_lastProblemHost = -1e9;
};

}  // namespace armtrack::devices::kinect
