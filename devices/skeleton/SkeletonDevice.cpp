#include "devices/skeleton/SkeletonDevice.h"

#include <QLoggingCategory>
#include <QTimer>
#include <QUdpSocket>
#include <cmath>

#include "devices/api/Options.h"
#include "devices/api/TimerMs.h"
#include "devices/net/UdpListen.h"
#include "devices/vision/CameraFile.h"
#include "devices/vision/CoreCameraParams.h"

Q_LOGGING_CATEGORY(lcSkeleton, "armtrack.devices.skeleton")

namespace armtrack::devices::skeleton {
namespace {

StreamInfo opticalStream(Origin origin) {
  StreamInfo info;
  info.role = StreamRole::Optical;
  // Relative to the moving shoulder, the shoulder would always be zero: it is not published.
  if (origin == Origin::Shoulder) {
    info.name = "tracker elbow and wrist";
  } else {
    info.name = "tracker elbow, wrist and shoulder";
    info.shoulder = true;  // the session records shoulder_* (StreamInfo::shoulder)
  }
  return info;  // the tracker's rate is unknown here; its time does not wrap
}

Eigen::Vector3d vec(const std::array<double, 3>& p) {
  return {p[0], p[1], p[2]};
}

}  // namespace

std::optional<SkeletonSettings> readSkeletonSettings(const QVariantMap& options, QString* error) {
  Options opts(options);
  SkeletonSettings s;
  QStringList problems;
  s.port = static_cast<std::uint16_t>(opts.integer(QStringLiteral("port"), 9870, 1, 65535));
  const QString origin =
      opts.text(QStringLiteral("origin"), QStringLiteral("start")).trimmed().toLower();
  s.timeoutSeconds = opts.number(QStringLiteral("timeout"), 3.0, 0.2, 60.0);
  if (origin == u"shoulder")
    s.origin = Origin::Shoulder;
  else if (origin == u"start")
    s.origin = Origin::Start;
  else if (origin == u"camera")
    s.origin = Origin::Camera;
  else
    problems << QStringLiteral(
                    "option 'origin' must be shoulder, start or camera, not '%1' (start: the "
                    "world frame, for a session with a trunk sensor)")
                    .arg(origin);
  const QString cameraPath = opts.text(QStringLiteral("camera")).trimmed();
  const QString axes = opts.text(QStringLiteral("axes")).trimmed().toLower();
  if (!axes.isEmpty() && axes != u"shoulder")
    problems << QStringLiteral(
                    "option 'axes' can only be 'shoulder' (the tracker already sends "
                    "shoulder-frame axes), not '%1'; otherwise give camera=FILE")
                    .arg(axes);
  else if (!axes.isEmpty() && !cameraPath.isEmpty())
    problems << QStringLiteral(
        "give camera=FILE or axes=shoulder, not both: the camera file's pose turns the "
        "tracker's axes into the shoulder frame's");
  else if (axes.isEmpty() && cameraPath.isEmpty())
    problems << QStringLiteral(
        "the tracker's axes must be registered to the shoulder frame: give camera=FILE (its "
        "camera's file with a pose: armtrack-cli camera-calibrate, then camera-register), or "
        "axes=shoulder if the tracker already sends shoulder-frame axes");
  else if (!cameraPath.isEmpty()) {
    try {
      const webcam::CameraFile f = webcam::readCameraFile(cameraPath.toStdString());
      if (!f.extrinsics)
        problems << QStringLiteral(
                        "%1 has no pose in the shoulder frame; run armtrack-cli camera-register "
                        "on it")
                        .arg(cameraPath);
      else
        s.pose = webcam::toCameraParams(f);
    } catch (const webcam::CameraFileError& e) {
      problems << QString::fromStdString(e.what());
    }
  }
  if (const QString e = opts.error(); !e.isEmpty()) problems << e;
  if (!problems.isEmpty()) {
    if (error) *error = problems.join(QStringLiteral("; "));
    return std::nullopt;
  }
  return s;
}

SkeletonDevice::SkeletonDevice(const SkeletonSettings& settings, QObject* parent)
    : Device({opticalStream(settings.origin)}, parent), m_settings(settings) {}

SkeletonDevice::~SkeletonDevice() = default;

void SkeletonDevice::start() {
  if (!m_socket) {
    m_socket = new QUdpSocket(this);
    connect(m_socket, &QUdpSocket::readyRead, this, &SkeletonDevice::onReadyRead);
    m_silenceTimer = new QTimer(this);
    m_silenceTimer->setSingleShot(true);
    connect(m_silenceTimer, &QTimer::timeout, this, &SkeletonDevice::onSilence);
    m_problems = std::make_unique<ProblemLimiter>(
        this, [this](const QString& message) { reportProblem(message); });
  }
  if (m_running) return;
  m_running = true;
  m_streaming = false;
  m_everStreamed = false;
  m_start.reset();
  m_errorsSeen = m_parser.errors().count();
  m_droppedSeen = m_parser.droppedFrames();
  m_reorderedSeen = m_parser.reorderedFrames();
  m_duplicatesSeen = m_parser.duplicateFrames();
  if (const QString why =
          listenUdp(*m_socket, m_settings.port, QStringLiteral("port"), lcSkeleton());
      !why.isEmpty())
    return fail(why);
  setState(
      DeviceState::Connecting,
      QStringLiteral("listening on UDP port %1, waiting for tracker frames").arg(m_settings.port));
  m_silenceTimer->start(timerMs(m_settings.timeoutSeconds));
}

void SkeletonDevice::stop() {
  if (!m_socket) return;  // never started
  m_running = false;      // also after an Error: the state goes to Disconnected whatever it was
  m_socket->close();
  m_silenceTimer->stop();
  m_problems->flush();
  setState(DeviceState::Disconnected, QStringLiteral("stopped"));
}

void SkeletonDevice::onReadyRead() {
  SampleBatch batch;
  std::uint64_t unusable = 0;
  QString unusableWhy;
  readDatagrams(*m_socket, m_datagram, [&](std::span<const char> bytes, double arrival) {
    const std::optional<Frame> frame =
        m_parser.parseDatagram(std::string_view(bytes.data(), bytes.size()));
    if (!frame) return;
    OpticalPositions p;
    if (m_settings.origin == Origin::Shoulder) {
      if (!frame->shoulder) {
        ++unusable;
        unusableWhy = QStringLiteral(
                          "frame %1 has no shoulder: elbow and wrist cannot be placed "
                          "relative to it (send the shoulder, or set origin=start, which needs "
                          "it only at the start, or origin=camera)")
                          .arg(frame->frame);
        return;
      }
      const Eigen::Vector3d shoulder = vec(frame->shoulder->position);
      if (frame->elbow) p.elbow = toShoulderAxes(vec(frame->elbow->position) - shoulder);
      if (frame->wrist) p.wrist = toShoulderAxes(vec(frame->wrist->position) - shoulder);
    } else {
      Eigen::Vector3d origin = Eigen::Vector3d::Zero();
      if (m_settings.origin == Origin::Start) {
        if (frame->shoulder) m_start.add(frame->t, frame->shoulder->position);
        const auto start = m_start.origin();
        if (!start) {
          ++unusable;
          unusableWhy = QStringLiteral(
                            "frame %1: no shoulder seen yet, so the world origin (where the "
                            "shoulder is at the start) is unknown; have the tracker see the "
                            "shoulder while the patient sits upright at the start")
                            .arg(frame->frame);
          return;
        }
        origin = vec(*start);
      } else if (m_settings.pose) {
        origin = m_settings.pose->t;
      }
      if (frame->elbow) p.elbow = toShoulderAxes(vec(frame->elbow->position) - origin);
      if (frame->wrist) p.wrist = toShoulderAxes(vec(frame->wrist->position) - origin);
      if (frame->shoulder) p.shoulder = toShoulderAxes(vec(frame->shoulder->position) - origin);
    }
    if (!p.elbow && !p.wrist && !p.shoulder) {  // a shoulder alone still shows the trunk
      ++unusable;
      unusableWhy = QStringLiteral("frame %1 tracks neither elbow nor wrist").arg(frame->frame);
      return;
    }
    batch.push_back(DeviceSample{0, frame->t, arrival, p});
  });
  if (!m_running) return;

  const ParseErrorLog& log = m_parser.errors();
  if (log.count() != m_errorsSeen) {
    const std::uint64_t n = log.count() - m_errorsSeen;
    m_errorsSeen = log.count();
    countCorrupt(0, n);
    m_problems->note(n, QString::fromStdString(log.last()));
  }
  if (const std::uint64_t d = m_parser.droppedFrames(); d != m_droppedSeen) {
    countDropped(0, d - m_droppedSeen);
    m_droppedSeen = d;
  }
  if (const std::uint64_t r = m_parser.reorderedFrames(); r != m_reorderedSeen) {
    countReordered(0, r - m_reorderedSeen);
    m_reorderedSeen = r;
  }
  if (const std::uint64_t d = m_parser.duplicateFrames(); d != m_duplicatesSeen) {
    m_problems->note(d - m_duplicatesSeen,
                     QStringLiteral("a frame number seen before (a duplicated or very late "
                                    "datagram) on UDP port %1: dropped")
                         .arg(m_settings.port));
    m_duplicatesSeen = d;
  }
  if (unusable) m_problems->note(unusable, unusableWhy);
  if (batch.empty()) return;

  m_silenceTimer->start(timerMs(m_settings.timeoutSeconds));
  if (!m_streaming) {
    m_streaming = true;
    if (m_everStreamed) countReconnect();
    m_everStreamed = true;
    setState(DeviceState::Streaming,
             QStringLiteral("streaming from UDP port %1").arg(m_settings.port));
  }
  publish(batch);
}

Eigen::Vector3d SkeletonDevice::toShoulderAxes(const Eigen::Vector3d& v) const {
  return m_settings.pose ? Eigen::Vector3d(m_settings.pose->R.transpose() * v) : v;
}

void SkeletonDevice::onSilence() {
  if (!m_running) return;
  m_streaming = false;
  setState(DeviceState::Connecting,
           QStringLiteral("no tracker frame on UDP port %1 for %2 s; waiting")
               .arg(m_settings.port)
               .arg(m_settings.timeoutSeconds));
}

void SkeletonDevice::fail(const QString& reason) {
  qCWarning(lcSkeleton).noquote() << reason;
  m_running = false;
  m_silenceTimer->stop();
  setState(DeviceState::Error, reason);
}

}  // namespace armtrack::devices::skeleton
