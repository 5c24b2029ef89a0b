#include "devices/replay/ReplayDevice.h"

#include <array>

namespace armtrack::devices::replay {
namespace {

// The stream rates are measured over the recording's first seconds.
constexpr double kRateWindowSeconds = 10.0;
// StreamRole values, UpperArmImu to TrunkImu.
constexpr std::size_t kRoles = static_cast<std::size_t>(StreamRole::TrunkImu) + 1;

}  // namespace

struct ReplayDevice::Opened {
  std::unique_ptr<RecordingReader> reader;
  ArmSample first;
};

ReplayDevice::Opened ReplayDevice::open(const std::filesystem::path& file) {
  Opened o{std::make_unique<RecordingReader>(file), {}};
  if (!o.reader->next(o.first)) throw RecordingError(file.string(), 0, 0, "holds no samples");
  return o;
}

std::vector<StreamInfo> ReplayDevice::describe(const std::filesystem::path& file) {
  Opened o = open(file);
  const RecordingColumns& c = o.reader->columns();
  // Rows of each stream within the window, and the span they cover.
  std::array<std::uint64_t, kRoles> n{};
  const double t0 = o.first.t;
  double t1 = t0;
  ArmSample s = o.first;
  auto count = [&](StreamRole role, bool has) { n[static_cast<std::size_t>(role)] += has; };
  do {
    if (s.t - t0 > kRateWindowSeconds) break;
    t1 = s.t;
    count(StreamRole::UpperArmImu, s.upperArm.has_value());
    count(StreamRole::ForearmImu, s.forearm.has_value());
    count(StreamRole::TrunkImu, s.trunk.has_value());
    count(StreamRole::Optical, s.elbow || s.wrist || s.shoulder);
    count(StreamRole::Camera, s.camWrist || s.camElbow);
    count(StreamRole::Truth, s.trueAngles.has_value());
  } while (o.reader->next(s));
  const double span = t1 - t0;
  auto rate = [&](StreamRole role) {
    const std::uint64_t k = n[static_cast<std::size_t>(role)];
    return span > 0.0 && k > 1 ? (k - 1) / span : 0.0;
  };
  std::vector<StreamInfo> out;
  auto stream = [&](const char* name, StreamRole role) -> StreamInfo& {
    StreamInfo& info = out.emplace_back();
    info.name = name;
    info.role = role;
    info.nominalRateHz = rate(role);
    return info;
  };
  if (c.upperArm) stream("upper", StreamRole::UpperArmImu);
  if (c.forearm) stream("forearm", StreamRole::ForearmImu);
  // The sternum sensor with the recording's mounting (the reader's assumed one, with its
  // warning, when the sidecar has none).
  if (c.trunk) stream("trunk", StreamRole::TrunkImu).trunkMount = o.reader->meta().trunk;
  if (c.elbow || c.wrist || c.shoulder)
    stream("optical", StreamRole::Optical).shoulder = c.shoulder;
  if (c.camWrist || c.camElbow)
    stream("camera", StreamRole::Camera).camera = o.reader->meta().camera;
  if (c.truth) stream("truth", StreamRole::Truth).trueTrunk = c.trueTrunk;
  return out;
}

ReplayDevice::ReplayDevice(const std::filesystem::path& file, double speed, bool loop)
    : ReplayDevice(file, speed, loop, describe(file)) {}

ReplayDevice::ReplayDevice(const std::filesystem::path& file, double speed, bool loop,
                           std::vector<StreamInfo> streams)
    : Device(std::move(streams)), m_file(file), m_speed(speed), m_loop(loop) {
  m_streamOf.assign(kRoles, -1);
  for (std::size_t i = 0; i < this->streams().size(); ++i)
    m_streamOf[static_cast<std::size_t>(this->streams()[i].role)] = static_cast<int>(i);
}

ReplayDevice::~ReplayDevice() = default;

bool ReplayDevice::rewind() {
  try {
    Opened o = open(m_file);
    m_reader = std::move(o.reader);
    m_pending = std::move(o.first);
    m_hasPending = true;
    m_firstT = m_pending.t;
    m_passRows = 0;
    m_warningsShown = 0;
    return true;
  } catch (const RecordingError& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
}

void ReplayDevice::start() {
  if (m_timer) return;
  m_timeOffset = 0.0;
  if (!rewind()) return;
  reportNewWarnings();  // e.g. no sidecar: default geometry
  m_startHost = hostNow();
  m_timer = new QTimer(this);
  m_timer->setTimerType(Qt::PreciseTimer);
  m_timer->setInterval(2);
  connect(m_timer, &QTimer::timeout, this, &ReplayDevice::tick);
  m_timer->start();
  setState(DeviceState::Streaming, QStringLiteral("replaying %1 at %2x")
                                       .arg(QString::fromStdString(m_file.filename().string()))
                                       .arg(m_speed));
}

void ReplayDevice::stop() {
  delete m_timer;
  m_timer = nullptr;
  m_reader.reset();
  m_hasPending = false;
  setState(DeviceState::Disconnected, QStringLiteral("stopped"));
}

void ReplayDevice::fail(const QString& reason) {
  if (m_timer) m_timer->stop();
  m_reader.reset();
  m_hasPending = false;
  setState(DeviceState::Error, QStringLiteral("%1; the rows before it were played").arg(reason));
  reportProblem(reason);
}

void ReplayDevice::reportNewWarnings() {
  const std::vector<std::string>& w = m_reader->warnings();
  for (; m_warningsShown < w.size(); ++m_warningsShown)
    reportProblem(QStringLiteral("%1: %2").arg(QString::fromStdString(m_file.string()),
                                               QString::fromStdString(w[m_warningsShown])));
}

void ReplayDevice::tick() {
  const double now = hostNow();
  const double due = m_firstT + (now - m_startHost) * m_speed;
  SampleBatch batch;
  auto add = [&](StreamRole role, double t, SensorPayload p) {
    const int k = m_streamOf[static_cast<std::size_t>(role)];
    // Arrival is when the row was due, not when this tick ran: the session's clock fit then
    // sees the recording's own timing, without the timer's jitter (times the speed).
    const double arrival = m_startHost + (t - m_firstT) / m_speed;
    if (k >= 0) batch.push_back({k, t + m_timeOffset, arrival, std::move(p)});
  };
  QString error;
  while (m_hasPending && m_pending.t <= due) {
    const ArmSample& s = m_pending;
    if (s.upperArm) add(StreamRole::UpperArmImu, s.t, *s.upperArm);
    if (s.forearm) add(StreamRole::ForearmImu, s.t, *s.forearm);
    if (s.trunk) add(StreamRole::TrunkImu, s.t, *s.trunk);
    if (s.elbow || s.wrist || s.shoulder)
      add(StreamRole::Optical, s.t, OpticalPositions{s.elbow, s.wrist, s.shoulder});
    if (s.camWrist || s.camElbow)
      add(StreamRole::Camera, s.t, MarkerPixels{s.camWrist, s.camElbow});
    if (s.trueAngles) add(StreamRole::Truth, s.t, TruthAngles{*s.trueAngles, s.trueTrunk});
    m_lastT = s.t;
    ++m_passRows;
    try {
      m_hasPending = m_reader->next(m_pending);
    } catch (const RecordingError& e) {
      m_hasPending = false;
      error = QString::fromStdString(e.what());
    }
  }
  publish(batch);
  if (!error.isEmpty()) {
    fail(error);
    return;
  }
  if (m_hasPending) return;
  if (m_timeOffset == 0.0) reportNewWarnings();  // a line cut short: once, not every loop
  if (m_loop) {
    // Device time continues past the end, one mean row step after the last row.
    const double span = m_lastT - m_firstT;
    const double step = m_passRows > 1 ? span / static_cast<double>(m_passRows - 1) : 0.001;
    m_timeOffset += span + step;
    m_startHost += (span + step) / m_speed;
    rewind();
    return;
  }
  m_timer->stop();
  setState(DeviceState::Disconnected, QStringLiteral("end of the recording"));
}

}  // namespace armtrack::devices::replay
