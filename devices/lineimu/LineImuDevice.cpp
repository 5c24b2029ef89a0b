#include "devices/lineimu/LineImuDevice.h"

#include <QLoggingCategory>
#include <QTimer>
#include <QUdpSocket>
#include <algorithm>
#include <cmath>
#include <string>

#include "devices/api/Options.h"
#include "devices/api/TimerMs.h"
#include "devices/net/UdpListen.h"

Q_LOGGING_CATEGORY(lcLineImu, "armtrack.devices.lineimu")

namespace armtrack::devices::lineimu {
namespace {

StreamInfo imuStream(StreamRole role) {
  StreamInfo info;
  info.name = std::string(imuPlaceName(role)) + " line IMU";
  info.role = role;
  return info;  // the rate comes with $HELLO; the time is unwrapped by the parser
}

}  // namespace

std::optional<LineImuSettings> readLineImuSettings(const QVariantMap& options, QString* error) {
  Options opts(options);
  LineImuSettings s;
  QStringList problems;
  s.serialPort = opts.text(QStringLiteral("port")).trimmed();
  const int udp = opts.integer(QStringLiteral("udp"), 0, 1, 65535);
  s.baud = opts.integer(QStringLiteral("baud"), 115200, 300, 4000000);
  s.role = opts.imuRole();
  s.retrySeconds = opts.number(QStringLiteral("retry"), 1.0, 0.1, 60.0);
  s.timeoutSeconds = opts.number(QStringLiteral("timeout"), 3.0, 0.2, 60.0);
  s.udpPort = static_cast<std::uint16_t>(udp);
  const bool hasPort = opts.has(QStringLiteral("port")), hasUdp = opts.has(QStringLiteral("udp"));
  if (hasPort == hasUdp)
    problems << QStringLiteral(
                    "give either 'port' (a serial port, e.g. port=/dev/ttyUSB0) or "
                    "'udp' (a local UDP port, e.g. udp=9871), not %1")
                    .arg(hasPort ? QStringLiteral("both") : QStringLiteral("neither"));
  else if (hasPort && s.serialPort.isEmpty())
    problems << QStringLiteral("option 'port' must name a serial port, e.g. port=/dev/ttyUSB0");
  if (hasUdp && opts.has(QStringLiteral("baud")))
    problems << QStringLiteral("option 'baud' is for a serial port; remove it with 'udp'");
  if (const QString e = opts.error(); !e.isEmpty()) problems << e;
  if (!problems.isEmpty()) {
    if (error) *error = problems.join(QStringLiteral("; "));
    return std::nullopt;
  }
  return s;
}

LineImuDevice::LineImuDevice(const LineImuSettings& settings, QObject* parent)
    : Device({imuStream(settings.role)}, parent), m_settings(settings) {}

LineImuDevice::~LineImuDevice() = default;

QString LineImuDevice::source() const {
  return m_settings.udpPort ? QStringLiteral("UDP port %1").arg(m_settings.udpPort)
                            : m_settings.serialPort;
}

void LineImuDevice::createObjects() {
  if (m_retryTimer) return;
  if (m_settings.udpPort) {
    m_udp = new QUdpSocket(this);
    connect(m_udp, &QUdpSocket::readyRead, this, &LineImuDevice::onUdpReadyRead);
  } else {
    m_serial = new QSerialPort(this);
    m_serial->setBaudRate(m_settings.baud);
    m_serial->setDataBits(QSerialPort::Data8);
    m_serial->setParity(QSerialPort::NoParity);
    m_serial->setStopBits(QSerialPort::OneStop);
    m_serial->setFlowControl(QSerialPort::NoFlowControl);
    connect(m_serial, &QSerialPort::readyRead, this, &LineImuDevice::onSerialReadyRead);
    connect(m_serial, &QSerialPort::errorOccurred, this, &LineImuDevice::onSerialError);
  }
  m_retryTimer = new QTimer(this);
  m_retryTimer->setSingleShot(true);
  connect(m_retryTimer, &QTimer::timeout, this, &LineImuDevice::tryOpenSerial);
  m_silenceTimer = new QTimer(this);
  m_silenceTimer->setSingleShot(true);
  connect(m_silenceTimer, &QTimer::timeout, this, &LineImuDevice::onSilence);
  m_problems = std::make_unique<ProblemLimiter>(
      this, [this](const QString& message) { reportProblem(message); });
}

void LineImuDevice::start() {
  createObjects();
  if (m_running) return;
  m_running = true;
  m_streaming = false;
  m_everStreamed = false;
  m_openedOnce = false;
  m_lastEpoch.reset();
  m_parser.reset();
  m_errorsSeen = m_parser.errors().count();
  m_droppedSeen = m_parser.droppedSamples();
  m_reorderedSeen = m_parser.reorderedSamples();
  m_duplicatesSeen = m_parser.duplicateSamples();
  if (m_udp)
    openUdp();
  else
    tryOpenSerial();
}

void LineImuDevice::stop() {
  if (!m_retryTimer) return;  // never started
  m_running = false;          // also after an Error: the state goes to Disconnected whatever it was
  if (m_serial && m_serial->isOpen()) m_serial->close();
  if (m_udp) m_udp->close();
  m_retryTimer->stop();
  m_silenceTimer->stop();
  m_problems->flush();
  setState(DeviceState::Disconnected, QStringLiteral("stopped"));
}

void LineImuDevice::tryOpenSerial() {
  if (!m_running) return;
  m_serial->setPortName(m_settings.serialPort);
  if (!m_serial->open(QIODevice::ReadOnly)) {
    const QSerialPort::SerialPortError err = m_serial->error();
    const QString why = m_serial->errorString();
    m_serial->clearError();
    if (err == QSerialPort::PermissionError && !m_openedOnce)
      return fail(QStringLiteral("no permission to open %1 (%2): add your user to the 'dialout' "
                                 "group and log in again, or close the program that holds it")
                      .arg(m_settings.serialPort, why));
    const QString retry =
        QStringLiteral("retrying every %1 s").arg(m_settings.retrySeconds, 0, 'g', 3);
    setState(DeviceState::Connecting,
             err == QSerialPort::DeviceNotFoundError
                 ? QStringLiteral("%1 does not exist (not plugged in?); %2")
                       .arg(m_settings.serialPort, retry)
                 : QStringLiteral("cannot open %1: %2; %3").arg(m_settings.serialPort, why, retry));
    m_retryTimer->start(timerMs(m_settings.retrySeconds));
    return;
  }
  m_openedOnce = true;
  qCInfo(lcLineImu) << "opened" << m_settings.serialPort << "at" << m_settings.baud << "bit/s";
  m_parser.reset();  // a partial sentence from before does not continue here
  m_streaming = false;
  setState(DeviceState::Connecting,
           QStringLiteral("%1 open, waiting for $IMU sentences").arg(m_settings.serialPort));
  m_silenceTimer->start(timerMs(m_settings.timeoutSeconds));
}

void LineImuDevice::openUdp() {
  if (const QString why = listenUdp(*m_udp, m_settings.udpPort, QStringLiteral("udp"), lcLineImu());
      !why.isEmpty())
    return fail(why);
  setState(DeviceState::Connecting,
           QStringLiteral("listening on UDP port %1, waiting for $IMU sentences")
               .arg(m_settings.udpPort));
  m_silenceTimer->start(timerMs(m_settings.timeoutSeconds));
}

void LineImuDevice::onSerialReadyRead() {
  const double arrival = hostNow();
  const QByteArray bytes = m_serial->readAll();
  if (!m_running || bytes.isEmpty()) return;
  m_samples.clear();
  m_parser.feed(std::span(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                          static_cast<std::size_t>(bytes.size())),
                m_samples);
  m_arrivals.assign(m_samples.size(), arrival);
  publishSamples();
}

void LineImuDevice::onUdpReadyRead() {
  m_samples.clear();
  m_arrivals.clear();
  readDatagrams(*m_udp, m_datagram, [this](std::span<const char> bytes, double arrival) {
    m_parser.feed(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()),
                  m_samples);
    m_parser.endOfDatagram();  // a sentence never continues in the next datagram
    m_arrivals.resize(m_samples.size(), arrival);
  });
  if (m_running) publishSamples();
}

void LineImuDevice::countLosses() {
  if (const std::uint64_t d = m_parser.droppedSamples(); d != m_droppedSeen) {
    countDropped(0, d - m_droppedSeen);
    m_droppedSeen = d;
  }
  if (const std::uint64_t r = m_parser.reorderedSamples(); r != m_reorderedSeen) {
    countReordered(0, r - m_reorderedSeen);
    m_reorderedSeen = r;
  }
  if (const std::uint64_t d = m_parser.duplicateSamples(); d != m_duplicatesSeen) {
    m_problems->note(d - m_duplicatesSeen,
                     QStringLiteral("%1: $IMU sentence with a seq seen before (a duplicated or "
                                    "very late datagram) dropped")
                         .arg(source()));
    m_duplicatesSeen = d;
  }
}

void LineImuDevice::publishSamples() {
  countLosses();
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
  for (std::size_t i = 0; i < m_samples.size(); ++i) {
    const Sample& s = m_samples[i];
    if (m_lastEpoch && s.epoch != *m_lastEpoch)
      m_problems->note(
          1,
          QStringLiteral("%1 restarted ($HELLO): its clock starts again")
              .arg(m_parser.hello() ? QString::fromStdString(m_parser.hello()->device) : source()));
    m_lastEpoch = s.epoch;
    ImuReading r;
    r.gyr = Eigen::Vector3d(s.gyr[0], s.gyr[1], s.gyr[2]);
    r.acc = Eigen::Vector3d(s.acc[0], s.acc[1], s.acc[2]);
    batch.push_back(DeviceSample{0, s.t, m_arrivals[i], r});
  }
  m_silenceTimer->start(timerMs(m_settings.timeoutSeconds));
  if (!m_streaming) {
    m_streaming = true;
    if (m_everStreamed) countReconnect();
    m_everStreamed = true;
    setState(DeviceState::Streaming, QStringLiteral("streaming from %1").arg(source()));
  }
  publish(batch);
}

void LineImuDevice::onSilence() {
  if (!m_running) return;
  m_streaming = false;
  setState(DeviceState::Connecting, QStringLiteral("no $IMU sentence from %1 for %2 s; waiting")
                                        .arg(source())
                                        .arg(m_settings.timeoutSeconds));
}

void LineImuDevice::onSerialError(QSerialPort::SerialPortError error) {
  if (error == QSerialPort::NoError || error == QSerialPort::TimeoutError) return;
  if (!m_serial->isOpen()) return;  // open() failures are handled in tryOpenSerial()
  if (error == QSerialPort::ReadError || error == QSerialPort::ResourceError)
    return linkLost(QStringLiteral("%1 closed (unplugged or link dropped)").arg(source()));
  linkLost(QStringLiteral("%1 failed: %2").arg(source(), m_serial->errorString()));
}

void LineImuDevice::linkLost(const QString& reason) {
  if (!m_running) return;
  qCInfo(lcLineImu).noquote() << "link lost:" << reason;
  m_serial->close();
  m_serial->clearError();
  m_parser.reset();
  m_streaming = false;
  m_silenceTimer->stop();
  setState(DeviceState::Connecting,
           QStringLiteral("%1; reopening every %2 s").arg(reason).arg(m_settings.retrySeconds));
  m_retryTimer->start(timerMs(m_settings.retrySeconds));
}

void LineImuDevice::fail(const QString& reason) {
  qCWarning(lcLineImu).noquote() << reason;
  m_running = false;
  m_retryTimer->stop();
  m_silenceTimer->stop();
  setState(DeviceState::Error, reason);
}

}  // namespace armtrack::devices::lineimu
