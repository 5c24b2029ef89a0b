#include "devices/kinect/KinectDevice.h"

#include <libfreenect.h>

#include <QTimer>
#include <bitset>
#include <opencv2/imgproc.hpp>

#include "devices/api/Options.h"
#include "devices/vision/CameraFile.h"

namespace armtrack::devices::kinect {

namespace {

constexpr int kWidth = 640, kHeight = 480;
constexpr double kMaxPairAge = 0.05;  // s between a colour frame and the depth frame it goes with

webcam::MarkerDetector makeDetector(const KinectSettings& s) {
  return s.markers == webcam::MarkerKind::Colour ? webcam::MarkerDetector(s.colour)
                                                 : webcam::MarkerDetector(s.aruco);
}

// The shoulder marker's detector: one of the webcam's, with the shoulder marker as its wrist.
// Throws std::invalid_argument for an ArUco id the dictionary does not have.
std::optional<webcam::MarkerDetector> makeShoulderDetector(const KinectSettings& s) {
  if (s.markers == webcam::MarkerKind::Colour && s.shoulderHsv) {
    webcam::ColourMarkerParams c = s.colour;
    c.wrist = c.elbow = *s.shoulderHsv;
    return webcam::MarkerDetector(c);
  }
  if (s.markers == webcam::MarkerKind::Aruco && s.shoulderId) {
    webcam::ArucoMarkerParams a = s.aruco;
    a.wristId = *s.shoulderId;
    a.elbowId = *s.shoulderId == 0 ? 1 : 0;  // any other id: its result is not used
    return webcam::MarkerDetector(a);
  }
  return std::nullopt;
}

// The hues (0-179) an HSV box takes, wrapping through 0 when hueMin > hueMax.
std::bitset<180> hues(const webcam::HsvRange& r) {
  std::bitset<180> h;
  for (int k = 0; k < 180; ++k)
    if (r.hueMin <= r.hueMax ? (k >= r.hueMin && k <= r.hueMax) : (k >= r.hueMin || k <= r.hueMax))
      h.set(static_cast<std::size_t>(k));
  return h;
}

StreamInfo opticalStream(const KinectSettings& s) {
  StreamInfo info{"Kinect elbow and wrist", StreamRole::Optical, 30.0, 0.0, std::nullopt};
  if (s.shoulderHsv || s.shoulderId) {
    info.name = "Kinect elbow, wrist and shoulder";
    info.shoulder = true;  // the session records shoulder_* (StreamInfo::shoulder)
  }
  return info;
}

}  // namespace

std::optional<KinectSettings> readKinectSettings(const QVariantMap& options, QString* error) {
  Options o(options);
  KinectSettings s;
  QStringList problems;
  s.index = o.integer(QStringLiteral("index"), 0, 0, 16);
  const QString markers = o.text(QStringLiteral("markers"), QStringLiteral("colour")).trimmed();
  s.cameraPath = o.text(QStringLiteral("camera")).trimmed();
  const QString wristHsv =
      o.text(QStringLiteral("wrist-hsv"), QString::fromStdString(webcam::toString(s.colour.wrist)));
  const QString elbowHsv =
      o.text(QStringLiteral("elbow-hsv"), QString::fromStdString(webcam::toString(s.colour.elbow)));
  s.colour.minAreaPx = o.number(QStringLiteral("min-area"), s.colour.minAreaPx, 1.0, 1e7);
  s.aruco.dictionary =
      o.text(QStringLiteral("dictionary"), QString::fromStdString(s.aruco.dictionary))
          .toStdString();
  s.aruco.wristId = o.integer(QStringLiteral("wrist-id"), s.aruco.wristId, 0, 100000);
  s.aruco.elbowId = o.integer(QStringLiteral("elbow-id"), s.aruco.elbowId, 0, 100000);
  const QString shoulderHsv = o.text(QStringLiteral("shoulder-hsv")).trimmed();
  if (o.has(QStringLiteral("shoulder-id")))
    s.shoulderId = o.integer(QStringLiteral("shoulder-id"), 0, 0, 100000);
  s.processing.depthWindowPx = o.integer(QStringLiteral("window"), 5, 1, 31);
  s.processing.jointDepth = o.number(QStringLiteral("joint-depth"), 0.0, -0.2, 0.2);
  s.retrySeconds = o.number(QStringLiteral("retry"), 1.0, 0.05, 60.0);
  s.timeoutSeconds = o.number(QStringLiteral("timeout"), 2.0, 0.1, 60.0);
  if (!o.error().isEmpty()) problems << o.error();
  if (s.processing.depthWindowPx % 2 == 0)
    problems << QStringLiteral("window=%1: must be odd").arg(s.processing.depthWindowPx);
  if (markers == u"colour" || markers == u"color")
    s.markers = webcam::MarkerKind::Colour;
  else if (markers == u"aruco")
    s.markers = webcam::MarkerKind::Aruco;
  else
    problems << QStringLiteral("markers=%1: expected colour or aruco").arg(markers);
  for (const auto& [key, text, range] : {std::tuple{"wrist-hsv", wristHsv, &s.colour.wrist},
                                         std::tuple{"elbow-hsv", elbowHsv, &s.colour.elbow}}) {
    if (const auto r = webcam::parseHsvRange(text.toStdString()))
      *range = *r;
    else
      problems << QStringLiteral("%1=%2: expected H1-H2:S1-S2:V1-V2, e.g. 45-75:100-255:70-255")
                      .arg(QLatin1String(key), text);
  }
  if (s.markers == webcam::MarkerKind::Aruco) {
    try {
      webcam::ArucoMarkerDetector check(s.aruco);
    } catch (const std::invalid_argument& e) {
      problems << QString::fromStdString(e.what());
    }
  }
  // The shoulder marker: a third colour, or a third id, that neither arm marker has.
  if (!shoulderHsv.isEmpty()) {
    if (s.markers != webcam::MarkerKind::Colour)
      problems << QStringLiteral(
          "shoulder-hsv is for colour markers; with markers=aruco give shoulder-id");
    else if (const auto r = webcam::parseHsvRange(shoulderHsv.toStdString()); !r)
      problems << QStringLiteral(
                      "shoulder-hsv=%1: expected H1-H2:S1-S2:V1-V2, e.g. 140-170:100-255:70-255 "
                      "(magenta)")
                      .arg(shoulderHsv);
    else if ((hues(*r) & (hues(s.colour.wrist) | hues(s.colour.elbow))).any())
      problems << QStringLiteral(
                      "shoulder-hsv=%1: its hues overlap the wrist's or the elbow's marker; choose "
                      "a third colour, e.g. magenta 140-170:100-255:70-255")
                      .arg(shoulderHsv);
    else
      s.shoulderHsv = *r;
  }
  if (s.shoulderId) {
    if (s.markers != webcam::MarkerKind::Aruco)
      problems << QStringLiteral(
          "shoulder-id is for ArUco markers; with colour markers give shoulder-hsv");
    else if (*s.shoulderId == s.aruco.wristId || *s.shoulderId == s.aruco.elbowId)
      problems << QStringLiteral(
                      "shoulder-id=%1 is the wrist's or the elbow's marker; give the shoulder a "
                      "third id")
                      .arg(*s.shoulderId);
    else {
      try {
        makeShoulderDetector(s);
      } catch (const std::invalid_argument& e) {
        problems << QStringLiteral("shoulder-id: %1").arg(QString::fromStdString(e.what()));
      }
    }
  }
  if (s.cameraPath.isEmpty()) {
    problems << QStringLiteral(
        "camera= is required: the colour camera's calibration file with its "
        "pose (armtrack-cli camera-calibrate, then camera-register)");
  } else {
    try {
      const webcam::CameraFile f = webcam::readCameraFile(s.cameraPath.toStdString());
      if (!f.extrinsics)
        problems << QStringLiteral(
                        "%1 has no pose in the shoulder frame; run armtrack-cli "
                        "camera-register on it")
                        .arg(s.cameraPath);
      else if (f.intrinsics.imageSize != cv::Size(kWidth, kHeight))
        problems << QStringLiteral(
                        "%1 is for %2x%3 images; the Kinect's colour camera gives "
                        "640x480")
                        .arg(s.cameraPath)
                        .arg(f.intrinsics.imageSize.width)
                        .arg(f.intrinsics.imageSize.height);
      else {
        s.processing.colour = f.intrinsics;
        s.processing.pose = *f.extrinsics;
      }
    } catch (const webcam::CameraFileError& e) {
      problems << QString::fromStdString(e.what());
    }
  }
  if (!problems.isEmpty()) {
    if (error) *error = QStringLiteral("kinect: ") + problems.join(QStringLiteral("; "));
    return std::nullopt;
  }
  return s;
}

// ---------------------------------------------------------------------------------------------

KinectDevice::KinectDevice(KinectSettings settings, QObject* parent)
    : Device({opticalStream(settings)}, parent),
      m_settings(std::move(settings)),
      m_processor(m_settings.processing, makeDetector(m_settings),
                  makeShoulderDetector(m_settings)) {}

KinectDevice::~KinectDevice() {
  close();
}

void KinectDevice::start() {
  if (m_running) return;
  m_running = true;
  m_pollTimer = new QTimer(this);
  m_pollTimer->setInterval(5);
  connect(m_pollTimer, &QTimer::timeout, this, &KinectDevice::poll);
  m_retryTimer = new QTimer(this);
  m_retryTimer->setSingleShot(true);
  connect(m_retryTimer, &QTimer::timeout, this, &KinectDevice::open);
  m_lost = false;
  m_streamedBefore = false;
  // open() sets Connecting with its own reason: set here first, a failure's reason would not be
  // emitted (the state would not change).
  open();
}

void KinectDevice::stop() {
  if (!m_running) return;
  m_running = false;
  delete m_pollTimer;
  m_pollTimer = nullptr;
  delete m_retryTimer;
  m_retryTimer = nullptr;
  close();
  setState(DeviceState::Disconnected, QStringLiteral("stopped"));
}

void KinectDevice::close() {
  if (m_dev) {
    freenect_stop_depth(m_dev);
    freenect_stop_video(m_dev);
    freenect_close_device(m_dev);
    m_dev = nullptr;
  }
  if (m_ctx) {
    freenect_shutdown(m_ctx);
    m_ctx = nullptr;
  }
}

void KinectDevice::lost(const QString& reason) {
  close();
  if (m_pollTimer) m_pollTimer->stop();
  const bool first = !m_lost;
  m_lost = true;
  setState(DeviceState::Connecting, reason);
  if (first) reportProblem(reason);
  if (m_retryTimer) m_retryTimer->start(static_cast<int>(m_settings.retrySeconds * 1000.0));
}

void KinectDevice::open() {
  if (!m_running) return;
  const QString retry = QStringLiteral("; retrying every %1 s").arg(m_settings.retrySeconds);
  if (freenect_init(&m_ctx, nullptr) < 0) {
    m_ctx = nullptr;
    lost(QStringLiteral("libfreenect could not start (USB)") + retry);
    return;
  }
  freenect_set_log_level(m_ctx, FREENECT_LOG_ERROR);
  freenect_select_subdevices(m_ctx, FREENECT_DEVICE_CAMERA);
  const int count = freenect_num_devices(m_ctx);
  if (count <= m_settings.index) {
    lost(QStringLiteral("no Kinect v1 number %1 (%2 found); check its USB cable and its mains "
                        "power supply")
             .arg(m_settings.index)
             .arg(std::max(0, count)) +
         retry);
    return;
  }
  if (freenect_open_device(m_ctx, &m_dev, m_settings.index) < 0) {
    m_dev = nullptr;
    lost(QStringLiteral("Kinect %1 cannot be opened (in use, or no permission on its USB device: "
                        "install libfreenect's udev rules)")
             .arg(m_settings.index) +
         retry);
    return;
  }
  freenect_set_user(m_dev, this);
  freenect_set_video_callback(m_dev, &KinectDevice::onVideo);
  freenect_set_depth_callback(m_dev, &KinectDevice::onDepth);
  const bool modes =
      freenect_set_video_mode(
          m_dev, freenect_find_video_mode(FREENECT_RESOLUTION_MEDIUM, FREENECT_VIDEO_RGB)) == 0 &&
      freenect_set_depth_mode(m_dev, freenect_find_depth_mode(FREENECT_RESOLUTION_MEDIUM,
                                                              FREENECT_DEPTH_REGISTERED)) == 0;
  if (!modes || freenect_start_video(m_dev) < 0 || freenect_start_depth(m_dev) < 0) {
    lost(QStringLiteral("Kinect %1 refused 640x480 colour with registered depth")
             .arg(m_settings.index) +
         retry);
    return;
  }
  m_lastDepthHost = hostNow();
  m_pollTimer->start();
  setState(DeviceState::Connecting,
           QStringLiteral("Kinect %1 opened; waiting for frames").arg(m_settings.index));
}

void KinectDevice::poll() {
  if (!m_ctx) return;
  timeval zero{0, 0};
  if (freenect_process_events_timeout(m_ctx, &zero) < 0) {
    lost(QStringLiteral("the Kinect's USB connection failed; reopening every %1 s")
             .arg(m_settings.retrySeconds));
    return;
  }
  if (hostNow() - m_lastDepthHost > m_settings.timeoutSeconds)
    lost(QStringLiteral("the Kinect sent no depth frame for %1 s; reopening every %2 s")
             .arg(m_settings.timeoutSeconds)
             .arg(m_settings.retrySeconds));
}

void KinectDevice::onVideo(_freenect_device* dev, void* data, std::uint32_t) {
  auto* self = static_cast<KinectDevice*>(freenect_get_user(dev));
  if (!self || !data) return;
  const cv::Mat rgb(kHeight, kWidth, CV_8UC3, data);
  cv::cvtColor(rgb, self->m_bgr, cv::COLOR_RGB2BGR);
  self->m_bgrHost = hostNow();
}

void KinectDevice::onDepth(_freenect_device* dev, void* data, std::uint32_t) {
  auto* self = static_cast<KinectDevice*>(freenect_get_user(dev));
  if (!self || !data) return;
  self->handleDepth(static_cast<const std::uint16_t*>(data));
}

void KinectDevice::handleDepth(const std::uint16_t* depth) {
  const double now = hostNow();
  m_lastDepthHost = now;
  if (m_bgr.empty() || now - m_bgrHost > kMaxPairAge) return;  // wait for its colour frame
  const cv::Mat depthMm(kHeight, kWidth, CV_16UC1, const_cast<std::uint16_t*>(depth));
  KinectFrame f;
  try {
    f = m_processor.process(m_bgr, depthMm);
  } catch (const std::exception& e) {
    countCorrupt(0, 1);
    if (now - m_lastProblemHost >= 1.0) {
      m_lastProblemHost = now;
      reportProblem(QStringLiteral("a Kinect frame could not be processed: %1").arg(e.what()));
    }
    return;
  }
  OpticalPositions p;
  if (f.wrist) p.wrist = Eigen::Vector3d((*f.wrist)[0], (*f.wrist)[1], (*f.wrist)[2]);
  if (f.elbow) p.elbow = Eigen::Vector3d((*f.elbow)[0], (*f.elbow)[1], (*f.elbow)[2]);
  if (f.shoulder)
    p.shoulder = Eigen::Vector3d((*f.shoulder)[0], (*f.shoulder)[1], (*f.shoulder)[2]);
  if (f.depthMissing > 0) {
    m_depthMissingReported += static_cast<std::uint64_t>(f.depthMissing);
    if (now - m_lastProblemHost >= 1.0) {
      m_lastProblemHost = now;
      reportProblem(QStringLiteral("%1 marker(s) seen without depth so far (too close, too far, or "
                                   "on a reflective surface)")
                        .arg(m_depthMissingReported));
    }
  }
  publish({DeviceSample{0, now, hostNow(), p}});
  if (m_lost) {
    m_lost = false;
    if (m_streamedBefore) countReconnect();
  }
  if (state() != DeviceState::Streaming)
    setState(DeviceState::Streaming,
             QStringLiteral("Kinect %1 is streaming").arg(m_settings.index));
  m_streamedBefore = true;
}

}  // namespace armtrack::devices::kinect
