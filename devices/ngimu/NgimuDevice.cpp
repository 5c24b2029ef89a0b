#include "devices/ngimu/NgimuDevice.h"

#include <QLoggingCategory>
#include <QTimer>
#include <QUdpSocket>
#include <algorithm>
#include <cmath>
#include <string>

#include "devices/api/Options.h"
#include "devices/api/TimerMs.h"
#include "devices/net/UdpListen.h"

Q_LOGGING_CATEGORY(lcNgimu, "armtrack.devices.ngimu")

namespace armtrack::devices::ngimu {
namespace {

StreamInfo imuStream(StreamRole role) {
  StreamInfo info;
  info.name = std::string(imuPlaceName(role)) + " NGIMU";
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
  m_sequence = TimetagSequence{};
  m_droppedSeen = m_reorderedSeen = m_duplicatesSeen = 0;
  if (const QString why = listenUdp(*m_socket, m_settings.port, QStringLiteral("port"), lcNgimu());
      !why.isEmpty())
    return fail(why);
  setState(DeviceState::Connecting,
           QStringLiteral("listening on UDP port %1, waiting for /sensors").arg(m_settings.port));
  m_silenceTimer->start(timerMs(m_settings.timeoutSeconds));
}

bool TimetagSequence::accept(double t) {
  if (!m_started) {
    m_started = true;
    m_last = t;
    m_tracker.add(m_seq);
    return true;
  }
  const double step = t - m_last;
  if (step > 0.0) {
    std::uint64_t k = 1;
    if (m_period <= 0.0 || step < 0.75 * m_period) {
      m_period = step;  // the first step, or the rate went up (or the first step spanned a loss)
    } else {
      k = static_cast<std::uint64_t>(std::max(1.0, std::round(step / m_period)));
      if (k == 1) m_period += 0.01 * (step - m_period);
    }
    m_seq += k;
    m_last = t;
    m_tracker.add(m_seq);
    return true;
  }
  const double back = m_period > 0.0 ? std::round(-step / m_period) : 0.0;
  if (back >= static_cast<double>(m_seq)) return false;
  m_tracker.add(m_seq - static_cast<std::uint64_t>(back));
  return false;  // not published: time never goes back (counted reordered or duplicate)
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
  m_samples.clear();
  m_arrivals.clear();
  readDatagrams(*m_socket, m_datagram, [this](std::span<const char> bytes, double arrival) {
    m_parser.parseDatagram(
        std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), m_samples);
    m_arrivals.resize(m_samples.size(), arrival);
  });
  if (!m_running) return;

  const ParseErrorLog& log = m_parser.errors();
  if (log.count() != m_errorsSeen) {
    const std::uint64_t n = log.count() - m_errorsSeen;
    m_errorsSeen = log.count();
    countCorrupt(0, n);
    m_problems->note(n, QString::fromStdString(log.last()));
  }
  // /sensors carries no sequence number: losses and reordering are inferred from the time tags,
  // which advance by one sample period per message (docs/devices/ngimu.md).
  std::size_t kept = 0;
  for (std::size_t i = 0; i < m_samples.size(); ++i) {
    if (m_samples[i].hasTimetag && !m_sequence.accept(m_samples[i].t)) continue;  // counted
    m_samples[kept] = m_samples[i];
    m_arrivals[kept] = m_arrivals[i];
    ++kept;
  }
  m_samples.resize(kept);
  const SequenceTracker& seq = m_sequence.tracker();
  if (seq.missing() != m_droppedSeen) {
    countDropped(0, seq.missing() - m_droppedSeen);
    m_droppedSeen = seq.missing();
  }
  if (seq.reordered() != m_reorderedSeen) {
    countReordered(0, seq.reordered() - m_reorderedSeen);
    m_reorderedSeen = seq.reordered();
  }
  if (const std::uint64_t d = seq.duplicates() + seq.tooLate(); d != m_duplicatesSeen) {
    m_problems->note(d - m_duplicatesSeen,
                     QStringLiteral("/sensors with a time tag seen before (a duplicated or very "
                                    "late datagram) on UDP port %1: dropped")
                         .arg(m_settings.port));
    m_duplicatesSeen = d;
  }
  if (m_samples.empty()) return;

  SampleBatch batch;
  batch.reserve(m_samples.size());
  for (std::size_t i = 0; i < m_samples.size(); ++i) {
    const SensorsSample& s = m_samples[i];
    if (!s.hasTimetag && !m_toldNoTimetag) {
      m_toldNoTimetag = true;
      m_problems->note(1, QStringLiteral("/sensors messages come without a bundle time tag: their "
                                         "arrival time is used as device time"));
    }
    ImuReading r;
    r.gyr = Eigen::Vector3d(s.gyr[0], s.gyr[1], s.gyr[2]);
    r.acc = Eigen::Vector3d(s.acc[0], s.acc[1], s.acc[2]);
    batch.push_back(DeviceSample{0, s.hasTimetag ? s.t : m_arrivals[i], m_arrivals[i], r});
  }
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
