#include "devices/ngimu/NgimuDevice.h"

#include <QLoggingCategory>
#include <QNetworkDatagram>
#include <QTimer>
#include <QUdpSocket>
#include <cmath>

#include "devices/api/Options.h"

Q_LOGGING_CATEGORY(lcNgimu, "armtrack.devices.ngimu")

namespace armtrack::devices::ngimu {
namespace {

int toMs(double seconds) {
  return static_cast<int>(std::lround(seconds * 1000.0));
}

StreamInfo imuStream(StreamRole role) {
  StreamInfo info;
  info.name = role == StreamRole::ForearmImu ? "forearm NGIMU" : "upper-arm NGIMU";
  info.role = role;
  return info;  // the send rate is set on the NGIMU; the time tag does not wrap
}

}  // namespace

std::optional<NgimuSettings> readNgimuSettings(const QVariantMap& options, QString* error) {
  Options opts(options);
  NgimuSettings s;
  QStringList problems;
  s.port = static_cast<std::uint16_t>(opts.integer(QStringLiteral("port"), 0, 1, 65535));
  s.role = opts.imuRole();
  s.timeoutSeconds = opts.number(QStringLiteral("timeout"), 3.0, 0.2, 60.0);
  if (!opts.has(QStringLiteral("port")))
    problems << QStringLiteral(
        "option 'port' is required: the UDP port the NGIMU sends to (its "
        "Wi-Fi send port setting), e.g. port=8001");
  if (const QString e = opts.error(); !e.isEmpty()) problems << e;
  if (!problems.isEmpty()) {
    if (error) *error = problems.join(QStringLiteral("; "));
    return std::nullopt;
  }
  return s;
}

NgimuDevice::NgimuDevice(const NgimuSettings& settings, QObject* parent)
    : Device({imuStream(settings.role)}, parent), m_settings(settings) {}

NgimuDevice::~NgimuDevice() = default;

void NgimuDevice::start() {
  if (!m_socket) {
    m_socket = new QUdpSocket(this);
    connect(m_socket, &QUdpSocket::readyRead, this, &NgimuDevice::onReadyRead);
    m_silenceTimer = new QTimer(this);
    m_silenceTimer->setSingleShot(true);
    connect(m_silenceTimer, &QTimer::timeout, this, &NgimuDevice::onSilence);
    m_problems = std::make_unique<ProblemLimiter>(
        this, [this](const QString& message) { reportProblem(message); });
  }
  if (m_running) return;
  m_running = true;
  m_streaming = false;
  m_everStreamed = false;
  m_errorsSeen = m_parser.errors().count();
  if (!m_socket->bind(QHostAddress::Any, m_settings.port, QAbstractSocket::DontShareAddress)) {
    const QString why = m_socket->errorString();
    return fail(
        m_socket->error() == QAbstractSocket::AddressInUseError
            ? QStringLiteral("UDP port %1 is already in use (another device or program "
                             "listens on it): choose another port")
                  .arg(m_settings.port)
            : QStringLiteral("cannot listen on UDP port %1: %2").arg(m_settings.port).arg(why));
  }
  qCInfo(lcNgimu) << "listening on UDP port" << m_settings.port;
  setState(DeviceState::Connecting,
           QStringLiteral("listening on UDP port %1, waiting for /sensors").arg(m_settings.port));
  m_silenceTimer->start(toMs(m_settings.timeoutSeconds));
}

void NgimuDevice::stop() {
  if (!m_socket) return;  // never started
  m_running = false;      // also after an Error: the state goes to Disconnected whatever it was
  m_socket->close();
  m_silenceTimer->stop();
  m_problems->flush();
  setState(DeviceState::Disconnected, QStringLiteral("stopped"));
}

void NgimuDevice::onReadyRead() {
  const double arrival = hostNow();
  m_samples.clear();
  while (m_socket->hasPendingDatagrams()) {
    const QByteArray bytes = m_socket->receiveDatagram().data();
    m_parser.parseDatagram(std::span(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                                     static_cast<std::size_t>(bytes.size())),
                           m_samples);
  }
  if (!m_running) return;

  const ParseErrorLog& log = m_parser.errors();
  if (log.count() != m_errorsSeen) {
    const std::uint64_t n = log.count() - m_errorsSeen;
    m_errorsSeen = log.count();
    countCorrupt(0, n);
    m_problems->note(n, QString::fromStdString(log.last()));
  }
  if (m_samples.empty()) return;

  SampleBatch batch;
  batch.reserve(m_samples.size());
  for (const SensorsSample& s : m_samples) {
    if (!s.hasTimetag && !m_toldNoTimetag) {
      m_toldNoTimetag = true;
      m_problems->note(1, QStringLiteral("/sensors messages come without a bundle time tag: their "
                                         "arrival time is used as device time"));
    }
    ImuReading r;
    r.gyr = Eigen::Vector3d(s.gyr[0], s.gyr[1], s.gyr[2]);
    r.acc = Eigen::Vector3d(s.acc[0], s.acc[1], s.acc[2]);
    batch.push_back(DeviceSample{0, s.hasTimetag ? s.t : arrival, arrival, r});
  }
  m_silenceTimer->start(toMs(m_settings.timeoutSeconds));
  if (!m_streaming) {
    m_streaming = true;
    if (m_everStreamed) countReconnect();
    m_everStreamed = true;
    setState(DeviceState::Streaming,
             QStringLiteral("streaming from UDP port %1").arg(m_settings.port));
  }
  publish(batch);
}

void NgimuDevice::onSilence() {
  if (!m_running) return;
  m_streaming = false;
  setState(DeviceState::Connecting, QStringLiteral("no /sensors on UDP port %1 for %2 s; waiting")
                                        .arg(m_settings.port)
                                        .arg(m_settings.timeoutSeconds));
}

void NgimuDevice::fail(const QString& reason) {
  qCWarning(lcNgimu).noquote() << reason;
  m_running = false;
  m_silenceTimer->stop();
  setState(DeviceState::Error, reason);
}

}  // namespace armtrack::devices::ngimu
