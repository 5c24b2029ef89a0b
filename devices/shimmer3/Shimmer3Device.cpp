#include "devices/shimmer3/Shimmer3Device.h"

#include <QLoggingCategory>
#include <QTimer>
#include <cmath>
#include <string>

#include "devices/api/Options.h"
#include "devices/api/TimerMs.h"

Q_LOGGING_CATEGORY(lcShimmer3, "armtrack.devices.shimmer3")

namespace armtrack::devices::shimmer3 {
namespace {

constexpr int kDrainMs = 200;  // after the stop command, input is dropped for this long
constexpr double kWrapSeconds = static_cast<double>(kTimestampWrap) / kTickHz;  // 512 s

StreamInfo imuStream(StreamRole role) {
  StreamInfo info;
  info.name = std::string(imuPlaceName(role)) + " Shimmer3";
  info.role = role;
  return info;  // rate unknown until the inquiry; the time is unwrapped here
}

}  // namespace

std::optional<Shimmer3Settings> readShimmer3Settings(const QVariantMap& options, QString* error) {
  Options opts(options);
  Shimmer3Settings s;
  QStringList problems;
  s.port = opts.text(QStringLiteral("port")).trimmed();
  s.role = opts.imuRole();
  s.retrySeconds = opts.number(QStringLiteral("retry"), 1.0, 0.1, 60.0);
  s.timeoutSeconds = opts.number(QStringLiteral("timeout"), 3.0, 0.2, 60.0);
  if (s.port.isEmpty())
    problems << QStringLiteral(
        "option 'port' is required: the Shimmer's serial port, e.g. "
        "port=/dev/rfcomm0");
  if (const QString e = opts.error(); !e.isEmpty()) problems << e;
  if (!problems.isEmpty()) {
    if (error) *error = problems.join(QStringLiteral("; "));
    return std::nullopt;
  }
  return s;
}

Shimmer3Device::Shimmer3Device(const Shimmer3Settings& settings, QObject* parent)
    : Device({imuStream(settings.role)}, parent), m_settings(settings) {}

Shimmer3Device::~Shimmer3Device() = default;

void Shimmer3Device::start() {
  if (!m_port) {
    m_port = new QSerialPort(this);
    m_port->setBaudRate(QSerialPort::Baud115200);  // ignored by RFCOMM, used by the USB dock
    m_port->setDataBits(QSerialPort::Data8);
    m_port->setParity(QSerialPort::NoParity);
    m_port->setStopBits(QSerialPort::OneStop);
    m_port->setFlowControl(QSerialPort::NoFlowControl);
    connect(m_port, &QSerialPort::readyRead, this, &Shimmer3Device::onReadyRead);
    connect(m_port, &QSerialPort::errorOccurred, this, &Shimmer3Device::onPortError);
    m_phaseTimer = new QTimer(this);
    m_phaseTimer->setSingleShot(true);
    connect(m_phaseTimer, &QTimer::timeout, this, &Shimmer3Device::onPhaseTimeout);
    m_problems = std::make_unique<ProblemLimiter>(
        this, [this](const QString& message) { reportProblem(message); });
  }
  if (m_phase != Phase::Idle) return;  // already running
  m_everStreamed = false;
  m_openedOnce = false;
  m_haveLast = false;
  tryOpen();
}

void Shimmer3Device::stop() {
  if (!m_port) return;  // never started
  // Also after an Error: the state goes to Disconnected whatever it was.
  if (m_port->isOpen()) {
    sendCommand(kStopStreamingCommand);
    m_port->waitForBytesWritten(100);
  }
  closePort();
  m_phaseTimer->stop();
  m_phase = Phase::Idle;
  m_problems->flush();
  setState(DeviceState::Disconnected, QStringLiteral("stopped"));
}

void Shimmer3Device::tryOpen() {
  m_port->setPortName(m_settings.port);
  if (!m_port->open(QIODevice::ReadWrite)) {
    const QSerialPort::SerialPortError err = m_port->error();
    const QString why = m_port->errorString();
    m_port->clearError();
    if (err == QSerialPort::PermissionError && !m_openedOnce)
      return fail(QStringLiteral("no permission to open %1 (%2): add your user to the 'dialout' "
                                 "group and log in again, or close the program that holds it")
                      .arg(m_settings.port, why));
    const QString retry =
        QStringLiteral("retrying every %1 s").arg(m_settings.retrySeconds, 0, 'g', 3);
    setState(DeviceState::Connecting,
             err == QSerialPort::DeviceNotFoundError
                 ? QStringLiteral("%1 does not exist (Bluetooth not bound or connected, or "
                                  "adapter unplugged); %2")
                       .arg(m_settings.port, retry)
                 : QStringLiteral("cannot open %1: %2; %3").arg(m_settings.port, why, retry));
    m_phase = Phase::WaitingToOpen;
    m_phaseTimer->start(timerMs(m_settings.retrySeconds));
    return;
  }
  m_openedOnce = true;
  qCInfo(lcShimmer3) << "opened" << m_settings.port;
  setState(DeviceState::Connecting,
           QStringLiteral("%1 open, asking the Shimmer what it streams").arg(m_settings.port));
  // A Shimmer may still be streaming from an earlier session: stop it and drop the tail.
  m_parser.reset();
  m_needTimeBase = true;
  m_phase = Phase::Draining;
  sendCommand(kStopStreamingCommand);
  m_phaseTimer->start(kDrainMs);
}

void Shimmer3Device::beginInquiry() {
  m_port->clear(QSerialPort::Input);
  m_parser.reset();
  m_inquiriesBefore = m_parser.inquiries();
  m_errorsSeen = m_parser.errors().count();
  m_droppedSeen = m_parser.droppedPackets();
  m_phase = Phase::Inquiring;
  sendCommand(kInquiryCommand);
  m_phaseTimer->start(timerMs(m_settings.timeoutSeconds));
}

void Shimmer3Device::onPhaseTimeout() {
  switch (m_phase) {
    case Phase::WaitingToOpen:
      tryOpen();
      break;
    case Phase::Draining:
      beginInquiry();
      break;
    case Phase::Inquiring:
      linkLost(QStringLiteral("no inquiry response from %1 within %2 s (is it a Shimmer3 with "
                              "LogAndStream firmware?)")
                   .arg(m_settings.port)
                   .arg(m_settings.timeoutSeconds));
      break;
    case Phase::Starting:
      linkLost(QStringLiteral("no data from %1 within %2 s of the start command")
                   .arg(m_settings.port)
                   .arg(m_settings.timeoutSeconds));
      break;
    case Phase::Streaming:
      linkLost(QStringLiteral("no data from %1 for %2 s")
                   .arg(m_settings.port)
                   .arg(m_settings.timeoutSeconds));
      break;
    case Phase::Idle:
      break;
  }
}

void Shimmer3Device::onReadyRead() {
  const double arrival = hostNow();
  const QByteArray bytes = m_port->readAll();
  if (bytes.isEmpty() || m_phase == Phase::Draining || m_phase == Phase::Idle) return;
  m_samples.clear();
  m_parser.feed(std::span(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                          static_cast<std::size_t>(bytes.size())),
                m_samples);

  if (m_phase == Phase::Inquiring && m_parser.inquiries() > m_inquiriesBefore) {
    const Config& config = *m_parser.config();
    const auto has = [&config](std::uint8_t first) {
      int n = 0;
      for (std::uint8_t c : config.channels) n += (c >= first && c <= first + 2) ? 1 : 0;
      return n == 3;
    };
    if (!has(kGyroX) || !(has(kLowNoiseAccelX) || has(kWideRangeAccelX))) {
      sendCommand(kStopStreamingCommand);
      return fail(QStringLiteral("the Shimmer on %1 does not stream the gyroscope and an "
                                 "accelerometer: enable them (e.g. in Consensys) and start again")
                      .arg(m_settings.port));
    }
    qCInfo(lcShimmer3) << m_settings.port << "streams" << config.channels.size() << "channels at"
                       << config.samplingRateHz() << "Hz";
    m_phase = Phase::Starting;
    sendCommand(kStartStreamingCommand);
    m_phaseTimer->start(timerMs(m_settings.timeoutSeconds));
  }
  if (m_phase == Phase::Streaming) m_phaseTimer->start(timerMs(m_settings.timeoutSeconds));

  publishSamples(arrival);
  takeParserProblems();
}

void Shimmer3Device::publishSamples(double arrival) {
  if (const std::uint64_t d = m_parser.droppedPackets(); d != m_droppedSeen) {
    countDropped(0, d - m_droppedSeen);
    m_droppedSeen = d;
  }
  if (m_samples.empty()) return;
  if (m_needTimeBase) {
    // The parser counts from this connection's first raw timestamp. Add the whole number of wraps
    // that puts it closest to where the device clock should be by now.
    m_tickOffset = 0;
    if (m_haveLast) {
      const double expected = m_lastDeviceTime + (arrival - m_lastArrival);
      const double wraps = std::round(
          (expected - static_cast<double>(m_samples.front().ticks) / kTickHz) / kWrapSeconds);
      if (wraps > 0) m_tickOffset = static_cast<std::uint64_t>(wraps) * kTimestampWrap;
    }
    m_needTimeBase = false;
  }
  SampleBatch batch;
  batch.reserve(m_samples.size());
  for (const Sample& s : m_samples) {
    if (!s.hasGyro || !s.hasAcc) continue;  // excluded by the inquiry check
    ImuReading r;
    r.gyr = Eigen::Vector3d(s.gyr[0], s.gyr[1], s.gyr[2]);
    r.acc = Eigen::Vector3d(s.acc[0], s.acc[1], s.acc[2]);
    batch.push_back(
        DeviceSample{0, static_cast<double>(s.ticks + m_tickOffset) / kTickHz, arrival, r});
  }
  if (batch.empty()) return;
  m_haveLast = true;
  m_lastDeviceTime = batch.back().deviceTime;
  m_lastArrival = arrival;
  if (m_phase != Phase::Streaming) {
    m_phase = Phase::Streaming;
    m_phaseTimer->start(timerMs(m_settings.timeoutSeconds));
    if (m_everStreamed) countReconnect();
    m_everStreamed = true;
    setState(DeviceState::Streaming, QStringLiteral("streaming from %1").arg(m_settings.port));
  }
  publish(batch);
}

void Shimmer3Device::onPortError(QSerialPort::SerialPortError error) {
  if (error == QSerialPort::NoError || error == QSerialPort::TimeoutError) return;
  if (!m_port->isOpen()) return;  // open() failures are handled in tryOpen()
  // A hang-up shows as a failed read whose errno text is meaningless; say what it means.
  if (error == QSerialPort::ReadError || error == QSerialPort::ResourceError)
    return linkLost(QStringLiteral("%1 closed (Bluetooth link dropped or adapter unplugged)")
                        .arg(m_settings.port));
  linkLost(QStringLiteral("%1 failed: %2").arg(m_settings.port, m_port->errorString()));
}

void Shimmer3Device::linkLost(const QString& reason) {
  if (m_phase == Phase::Idle) return;
  qCInfo(lcShimmer3).noquote() << "link lost:" << reason;
  if (m_phase == Phase::Streaming) {
    // A whole packet may be waiting for its successor, which will not come now.
    m_samples.clear();
    m_parser.flush(m_samples);
    publishSamples(hostNow());
    takeParserProblems();
  }
  closePort();
  m_phase = Phase::WaitingToOpen;
  setState(DeviceState::Connecting,
           QStringLiteral("%1; reopening every %2 s").arg(reason).arg(m_settings.retrySeconds));
  m_phaseTimer->start(timerMs(m_settings.retrySeconds));
}

void Shimmer3Device::closePort() {
  if (m_port && m_port->isOpen()) m_port->close();
  if (m_port) m_port->clearError();
}

void Shimmer3Device::fail(const QString& reason) {
  qCWarning(lcShimmer3).noquote() << reason;
  closePort();
  m_phaseTimer->stop();
  m_phase = Phase::Idle;
  setState(DeviceState::Error, reason);
}

void Shimmer3Device::sendCommand(std::uint8_t command) {
  const char byte = static_cast<char>(command);
  m_port->write(&byte, 1);
}

void Shimmer3Device::takeParserProblems() {
  const ParseErrorLog& log = m_parser.errors();
  if (log.count() == m_errorsSeen) return;
  const std::uint64_t n = log.count() - m_errorsSeen;
  m_errorsSeen = log.count();
  countCorrupt(0, n);
  m_problems->note(n, QString::fromStdString(log.last()));
}

}  // namespace armtrack::devices::shimmer3
