#include "devices/webcam/WebcamDevice.h"

#include <QFileInfo>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <opencv2/videoio.hpp>

#include "devices/api/Options.h"

namespace armtrack::devices::webcam {

namespace {

constexpr int kMaxFramesPerTick = 8;  // then back to the event loop, so stop() is never held up
constexpr int kMaxSkipsInRow = 5;     // undecodable frames in a row before the file is given up

StreamInfo describe(const WebcamSettings& s) {
  StreamInfo info;
  info.name = "webcam markers";
  info.role = StreamRole::Camera;
  if (s.camera) info.camera = toCameraParams(*s.camera);
  return info;
}

MarkerDetector makeDetector(const WebcamSettings& s) {
  return s.markers == MarkerKind::Colour ? MarkerDetector(s.colour) : MarkerDetector(s.aruco);
}

QString sizeText(int w, int h) {
  return QStringLiteral("%1x%2").arg(w).arg(h);
}

}  // namespace

std::optional<WebcamSettings> readWebcamSettings(const QVariantMap& options, QString* error) {
  Options o(options);
  WebcamSettings s;
  QStringList problems;
  s.source = o.text(QStringLiteral("source"), QStringLiteral("0")).trimmed();
  const QString markers = o.text(QStringLiteral("markers"), QStringLiteral("colour")).trimmed();
  s.cameraPath = o.text(QStringLiteral("camera")).trimmed();
  s.loop = o.flag(QStringLiteral("loop"), false);
  s.speed = o.number(QStringLiteral("speed"), 1.0, 0.0, 100.0);
  s.retrySeconds = o.number(QStringLiteral("retry"), 1.0, 0.05, 60.0);
  s.timeoutSeconds = o.number(QStringLiteral("timeout"), 2.0, 0.1, 60.0);
  s.width = o.integer(QStringLiteral("width"), 0, 0, 16384);
  s.height = o.integer(QStringLiteral("height"), 0, 0, 16384);
  const QString wristHsv =
      o.text(QStringLiteral("wrist-hsv"), QString::fromStdString(toString(s.colour.wrist)));
  const QString elbowHsv =
      o.text(QStringLiteral("elbow-hsv"), QString::fromStdString(toString(s.colour.elbow)));
  s.colour.minAreaPx = o.number(QStringLiteral("min-area"), s.colour.minAreaPx, 1.0, 1e7);
  s.aruco.dictionary =
      o.text(QStringLiteral("dictionary"), QString::fromStdString(s.aruco.dictionary))
          .toStdString();
  s.aruco.wristId = o.integer(QStringLiteral("wrist-id"), s.aruco.wristId, 0, 100000);
  s.aruco.elbowId = o.integer(QStringLiteral("elbow-id"), s.aruco.elbowId, 0, 100000);
  if (!o.error().isEmpty()) problems << o.error();

  if (s.source.isEmpty())
    problems << QStringLiteral("source= is empty (a camera index or a video file)");
  bool isNumber = false;
  s.deviceIndex = s.source.toInt(&isNumber);
  if (isNumber && s.deviceIndex < 0)
    problems << QStringLiteral("source=%1: a camera index is >= 0").arg(s.source);
  s.isFile = !isNumber && !s.source.startsWith(QStringLiteral("/dev/video"));

  if (markers == u"colour" || markers == u"color") {
    s.markers = MarkerKind::Colour;
  } else if (markers == u"aruco") {
    s.markers = MarkerKind::Aruco;
  } else {
    problems << QStringLiteral("markers=%1: expected colour or aruco").arg(markers);
  }
  for (const auto& [key, text, range] : {std::tuple{"wrist-hsv", wristHsv, &s.colour.wrist},
                                         std::tuple{"elbow-hsv", elbowHsv, &s.colour.elbow}}) {
    const auto r = parseHsvRange(text.toStdString());
    if (!r)
      problems << QStringLiteral(
                      "%1=%2: expected H1-H2:S1-S2:V1-V2 with hue 0-179 and saturation "
                      "and value 0-255, e.g. 45-75:100-255:70-255")
                      .arg(QLatin1String(key), text);
    else
      *range = *r;
  }
  if (s.markers == MarkerKind::Aruco) {
    try {
      ArucoMarkerDetector check(s.aruco);
    } catch (const std::invalid_argument& e) {
      problems << QString::fromStdString(e.what());
    }
  }
  if (!s.isFile &&
      (options.contains(QStringLiteral("loop")) || options.contains(QStringLiteral("speed"))))
    problems << QStringLiteral("loop= and speed= apply to video files only, source=%1 is a camera")
                    .arg(s.source);
  if (!s.cameraPath.isEmpty()) {
    try {
      s.camera = readCameraFile(s.cameraPath.toStdString());
    } catch (const CameraFileError& e) {
      problems << QString::fromStdString(e.what());
    }
  }
  if (!problems.isEmpty()) {
    if (error) *error = QStringLiteral("webcam: ") + problems.join(QStringLiteral("; "));
    return std::nullopt;
  }
  return s;
}

// ---------------------------------------------------------------------------------------------

WebcamDevice::WebcamDevice(WebcamSettings settings, QObject* parent)
    : Device({describe(settings)}, parent),
      m_settings(std::move(settings)),
      m_detector(makeDetector(m_settings)) {}

WebcamDevice::~WebcamDevice() {
  closeCapture();
}

QString WebcamDevice::sourceName() const {
  if (m_settings.isFile) return QStringLiteral("video file %1").arg(m_settings.source);
  return QStringLiteral("camera %1").arg(m_settings.source);
}

void WebcamDevice::start() {
  if (m_running) return;
  m_running = true;
  m_frameTimer = new QTimer(this);
  m_frameTimer->setTimerType(Qt::PreciseTimer);
  connect(m_frameTimer, &QTimer::timeout, this, &WebcamDevice::tick);
  m_retryTimer = new QTimer(this);
  m_retryTimer->setSingleShot(true);
  connect(m_retryTimer, &QTimer::timeout, this, &WebcamDevice::open);
  m_problems = std::make_unique<ProblemLimiter>(
      this, [this](const QString& message) { reportProblem(message); });
  m_streamedBefore = false;
  m_lost = false;
  m_sizeChecked = false;
  m_loopOffset = 0.0;
  m_lastFileTime = -1.0;
  if (m_settings.camera && !m_settings.camera->extrinsics)
    reportProblem(QStringLiteral("camera file %1 has intrinsics but no pose in the shoulder "
                                 "frame; run armtrack-cli camera-register to add it")
                      .arg(m_settings.cameraPath));
  open();
}

void WebcamDevice::stop() {
  if (!m_running) return;
  m_running = false;
  m_problems->flush();
  m_problems.reset();
  for (QTimer** t : {&m_frameTimer, &m_retryTimer}) {
    delete *t;
    *t = nullptr;
  }
  closeCapture();
  setState(DeviceState::Disconnected, QStringLiteral("stopped"));
}

void WebcamDevice::closeCapture() {
  if (m_capture) m_capture->release();
  m_capture.reset();
}

void WebcamDevice::open() {
  if (!m_running) return;
  // Each outcome sets its own state and reason (Connecting before the first frame, Error, or
  // Connecting with why a camera is not there): a reason given with an unchanged state would not
  // be emitted.
  if (m_settings.isFile ? openFile() : openCamera()) {
    m_frameTimer->setInterval(m_settings.isFile && m_settings.speed > 0.0 ? 2 : 0);
    m_frameTimer->start();
    if (state() != DeviceState::Streaming)
      setState(DeviceState::Connecting,
               QStringLiteral("%1 opened; waiting for the first frame").arg(sourceName()));
  }
}

bool WebcamDevice::openFile() {
  const QString path = m_settings.source;
  const QFileInfo info(path);
  if (!info.exists()) {
    fail(QStringLiteral("video file %1 does not exist; check the path in source=").arg(path));
    return false;
  }
  if (!info.isFile() || !info.isReadable()) {
    fail(QStringLiteral("video file %1 is not a readable file; check the path and its permissions")
             .arg(path));
    return false;
  }
  m_capture = std::make_unique<cv::VideoCapture>();
  bool opened = false;
  try {
    // FFmpeg reads every common container; asking for it alone spares the log the other
    // back-ends' complaints about a file that is not a video. A name with '%' is an image
    // sequence (img_%04d.png), which OpenCV's own image back-end reads.
    opened = m_capture->open(path.toStdString(), cv::CAP_FFMPEG) ||
             (path.contains(u'%') && m_capture->open(path.toStdString(), cv::CAP_IMAGES));
  } catch (const cv::Exception&) {
    opened = false;
  }
  if (!opened) {
    closeCapture();
    fail(QStringLiteral("cannot read %1 as a video (not a video file, damaged, or a codec this "
                        "OpenCV lacks); check the file, or re-encode it, e.g. ffmpeg -i IN -c:v "
                        "mjpeg OUT.avi")
             .arg(path));
    return false;
  }
  const double fps = m_capture->get(cv::CAP_PROP_FPS);
  m_fps = std::isfinite(fps) && fps > 0.0 && fps < 10000.0 ? fps : 30.0;
  const double count = m_capture->get(cv::CAP_PROP_FRAME_COUNT);
  m_frameCount = std::isfinite(count) && count > 0.0 ? count : 0.0;
  m_playStart = hostNow();
  m_framesPlayed = 0;
  m_failuresInRow = 0;
  return true;
}

bool WebcamDevice::openCamera() {
  m_capture = std::make_unique<cv::VideoCapture>();
  bool opened = false;
  try {
    opened = m_settings.source.startsWith(QStringLiteral("/dev/video"))
                 ? m_capture->open(m_settings.source.toStdString(), cv::CAP_V4L2)
                 : m_capture->open(m_settings.deviceIndex, cv::CAP_ANY);
    if (opened && m_settings.width > 0) m_capture->set(cv::CAP_PROP_FRAME_WIDTH, m_settings.width);
    if (opened && m_settings.height > 0)
      m_capture->set(cv::CAP_PROP_FRAME_HEIGHT, m_settings.height);
  } catch (const cv::Exception&) {
    opened = false;
  }
  if (!opened) {
    closeCapture();
    const QString reason = QStringLiteral(
                               "%1 cannot be opened (unplugged, or in use by another "
                               "program); retrying every %2 s")
                               .arg(sourceName())
                               .arg(m_settings.retrySeconds);
    setState(DeviceState::Connecting, reason);
    if (!m_lost) {
      m_lost = true;
      reportProblem(reason);
    }
    m_retryTimer->start(static_cast<int>(m_settings.retrySeconds * 1000.0));
    return false;
  }
  m_lastFrameHost = hostNow();
  return true;
}

void WebcamDevice::tick() {
  if (!m_capture) return;
  if (m_settings.isFile)
    tickFile();
  else
    tickCamera();
}

void WebcamDevice::tickFile() {
  SampleBatch batch;
  const double now = hostNow();
  QString failure;
  bool ended = false;
  for (int n = 0; n < kMaxFramesPerTick; ++n) {
    if (m_settings.speed > 0.0) {
      const double due =
          m_playStart + static_cast<double>(m_framesPlayed) / (m_fps * m_settings.speed);
      if (due > now) break;
    }
    const FileRead read = readFileFrame(batch, failure);
    if (read == FileRead::Ended) ended = true;
    if (read == FileRead::Ended || read == FileRead::Failed) break;
  }
  // Samples first: what was read before a failure is not lost.
  if (!batch.empty()) {
    publish(batch);
    if (state() != DeviceState::Streaming && failure.isEmpty())
      setState(DeviceState::Streaming, QStringLiteral("playing %1").arg(sourceName()));
  }
  if (!failure.isEmpty()) {
    fail(failure);
    return;
  }
  if (ended) endOfFile();
}

WebcamDevice::FileRead WebcamDevice::readFileFrame(SampleBatch& batch, QString& failure) {
  cv::Mat frame;
  bool ok = false;
  try {
    ok = m_capture->read(frame);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (ok && !frame.empty()) {
    m_failuresInRow = 0;
    const double index = m_capture->get(cv::CAP_PROP_POS_FRAMES) - 1.0;
    const double ms = m_capture->get(cv::CAP_PROP_POS_MSEC);
    double t = std::isfinite(ms) && ms >= 0.0 ? ms / 1000.0 : std::max(0.0, index) / m_fps;
    t += m_loopOffset;
    // A container with broken timestamps must not make time run backwards.
    if (t <= m_lastFileTime) t = m_lastFileTime + 1.0 / m_fps;
    m_lastFileTime = t;
    ++m_framesPlayed;
    if (!processFrame(frame, t, batch)) {
      countCorrupt(0, 1);
      m_problems->note(1, QStringLiteral("%1: frame %2 could not be processed; skipped")
                              .arg(m_settings.source)
                              .arg(index));
    }
    return FileRead::Frame;
  }
  // The read failed: the end, a damaged frame, or a file that breaks off.
  const double pos = m_capture->get(cv::CAP_PROP_POS_FRAMES);
  if (m_frameCount <= 0.0 || pos >= m_frameCount - 0.5) return FileRead::Ended;
  ++m_failuresInRow;
  bool advanced = false;
  if (m_failuresInRow <= kMaxSkipsInRow) {
    try {
      advanced = m_capture->set(cv::CAP_PROP_POS_FRAMES, pos + 1.0) &&
                 m_capture->get(cv::CAP_PROP_POS_FRAMES) > pos + 0.5;
    } catch (const cv::Exception&) {
      advanced = false;
    }
  }
  if (!advanced) {
    failure = QStringLiteral(
                  "video file %1 breaks off at frame %2 of the %3 its header "
                  "declares (truncated or damaged); the frames before were used. "
                  "Record it again, or re-encode what is readable, e.g. ffmpeg -i "
                  "IN -c:v mjpeg OUT.avi")
                  .arg(m_settings.source)
                  .arg(pos)
                  .arg(m_frameCount);
    return FileRead::Failed;
  }
  ++m_framesPlayed;
  countCorrupt(0, 1);
  m_problems->note(
      1, QStringLiteral("%1: frame %2 cannot be decoded; skipped").arg(m_settings.source).arg(pos));
  return FileRead::Skipped;
}

void WebcamDevice::endOfFile() {
  if (m_framesPlayed == 0 && !m_streamedBefore) {
    fail(QStringLiteral("video file %1 holds no readable frame; check the file or re-encode it")
             .arg(m_settings.source));
    return;
  }
  m_streamedBefore = true;
  if (m_settings.loop) {
    bool rewound = false;
    try {
      rewound = m_capture->set(cv::CAP_PROP_POS_FRAMES, 0.0);
    } catch (const cv::Exception&) {
      rewound = false;
    }
    if (!rewound) {
      // Some containers cannot seek; opening again is the same thing.
      closeCapture();
      if (!openFile()) return;
    }
    m_loopOffset = m_lastFileTime + 1.0 / m_fps;
    m_playStart = hostNow();
    m_framesPlayed = 0;
    return;
  }
  m_frameTimer->stop();
  closeCapture();
  if (m_problems) m_problems->flush();
  setState(DeviceState::Disconnected, QStringLiteral("end of %1").arg(sourceName()));
}

void WebcamDevice::tickCamera() {
  bool grabbed = false;
  try {
    grabbed = m_capture->grab();  // waits for the next frame: at most one frame period
  } catch (const cv::Exception&) {
    grabbed = false;
  }
  const double captured = hostNow();
  if (!grabbed) {
    if (captured - m_lastFrameHost > m_settings.timeoutSeconds)
      cameraLost(QStringLiteral("%1 delivered no frame for %2 s; reopening every %3 s")
                     .arg(sourceName())
                     .arg(m_settings.timeoutSeconds)
                     .arg(m_settings.retrySeconds));
    return;
  }
  m_lastFrameHost = captured;
  cv::Mat frame;
  bool ok = false;
  try {
    ok = m_capture->retrieve(frame) && !frame.empty();
  } catch (const cv::Exception&) {
    ok = false;
  }
  SampleBatch batch;
  if (!ok || !processFrame(frame, captured, batch)) {
    countCorrupt(0, 1);
    m_problems->note(1,
                     QStringLiteral("%1: a frame could not be decoded; skipped").arg(sourceName()));
    return;
  }
  publish(batch);
  if (m_lost) {
    m_lost = false;
    if (m_streamedBefore) countReconnect();
    setState(DeviceState::Streaming, QStringLiteral("%1 is delivering again").arg(sourceName()));
  } else if (state() != DeviceState::Streaming) {
    setState(DeviceState::Streaming, QStringLiteral("%1 is streaming").arg(sourceName()));
  }
  m_streamedBefore = true;
}

bool WebcamDevice::processFrame(const cv::Mat& frame, double deviceTime, SampleBatch& batch) {
  if (frame.empty() || frame.depth() != CV_8U || (frame.channels() != 3 && frame.channels() != 4))
    return false;
  if (!m_sizeChecked && m_settings.camera) {
    m_sizeChecked = true;
    const cv::Size cal = m_settings.camera->intrinsics.imageSize;
    if (frame.cols != cal.width || frame.rows != cal.height)
      reportProblem(QStringLiteral("%1 gives %2 frames but %3 was calibrated at %4; its pixels do "
                                   "not fit the camera model. Calibrate at this size, or ask for "
                                   "it with width= and height=")
                        .arg(sourceName(), sizeText(frame.cols, frame.rows), m_settings.cameraPath,
                             sizeText(cal.width, cal.height)));
  }
  MarkerPair found;
  try {
    found = m_detector.detect(frame);
  } catch (const std::exception&) {
    return false;
  }
  MarkerPixels pixels;
  if (found.wrist) pixels.wrist = Eigen::Vector2d(found.wrist->x, found.wrist->y);
  if (found.elbow) pixels.elbow = Eigen::Vector2d(found.elbow->x, found.elbow->y);
  batch.push_back({0, deviceTime, hostNow(), pixels});
  return true;
}

void WebcamDevice::cameraLost(const QString& reason) {
  closeCapture();
  m_frameTimer->stop();
  m_lost = true;
  setState(DeviceState::Connecting, reason);
  reportProblem(reason);
  m_retryTimer->start(static_cast<int>(m_settings.retrySeconds * 1000.0));
}

void WebcamDevice::fail(const QString& reason) {
  if (m_frameTimer) m_frameTimer->stop();
  closeCapture();
  if (m_problems) m_problems->flush();
  setState(DeviceState::Error, reason);
  reportProblem(reason);
}

}  // namespace armtrack::devices::webcam
