#include "devices/virtual_arm/VirtualArmDevice.h"

#include <algorithm>
#include <mutex>

namespace armtrack::devices::virtualarm {

namespace {
std::mutex g_epochMutex;
double g_epoch = 0.0;
int g_running = 0;
}  // namespace

double acquireEpoch() {
  std::lock_guard lock(g_epochMutex);
  if (g_running++ == 0) g_epoch = hostNow();
  return g_epoch;
}

void releaseEpoch() {
  std::lock_guard lock(g_epochMutex);
  --g_running;
}

std::vector<StreamInfo> VirtualArmDevice::describe(const VirtualArmSource& source) {
  std::vector<StreamInfo> out;
  for (const VirtualStream& v : source.streams()) {
    StreamInfo s;
    s.name = v.name;
    s.nominalRateHz = v.rateHz;
    s.role = v.role;
    if (v.role == StreamRole::Camera) s.camera = source.meta().camera;
    if (v.role == StreamRole::TrunkImu) s.trunkMount = source.meta().trunk;
    s.shoulder = v.shoulder;
    s.trueTrunk = v.trueTrunk;
    out.push_back(std::move(s));
  }
  return out;
}

VirtualArmDevice::VirtualArmDevice(const VirtualArmParams& params, double tickSeconds)
    : VirtualArmDevice(VirtualArmSource(params), params, tickSeconds) {}

VirtualArmDevice::VirtualArmDevice(const VirtualArmSource& source, const VirtualArmParams& params,
                                   double tickSeconds)
    : Device(describe(source)), m_params(params), m_tick(tickSeconds), m_meta(source.meta()) {}

VirtualArmDevice::~VirtualArmDevice() {
  if (m_source) releaseEpoch();
}

void VirtualArmDevice::start() {
  if (m_timer) return;
  setState(DeviceState::Connecting);
  m_source = std::make_unique<VirtualArmSource>(m_params);
  m_epoch = acquireEpoch();
  m_source->skipTo(hostNow() - m_epoch);
  m_reportedDrops.assign(streams().size(), 0);
  m_started = hostNow();
  m_batteryShown = -1e9;
  setBattery(m_params.batteryPercent);
  m_timer = new QTimer(this);
  m_timer->setTimerType(Qt::PreciseTimer);
  m_timer->setInterval(std::max(1, static_cast<int>(m_tick * 1000.0 + 0.5)));
  connect(m_timer, &QTimer::timeout, this, &VirtualArmDevice::tick);
  m_timer->start();
  setState(DeviceState::Streaming);
}

void VirtualArmDevice::stop() {
  if (m_timer) {
    m_timer->stop();
    delete m_timer;
    m_timer = nullptr;
  }
  if (m_source) releaseEpoch();
  m_source.reset();
  setState(DeviceState::Disconnected, QStringLiteral("stopped"));
}

void VirtualArmDevice::tick() {
  if (!m_source) return;
  std::vector<VirtualSample> due;
  std::vector<SourceEvent> events;
  m_source->advance(hostNow() - m_epoch, due, events);
  const double arrival = hostNow();
  SampleBatch batch;
  batch.reserve(due.size());
  for (VirtualSample& v : due)
    batch.push_back({v.stream, v.deviceTime, arrival, std::move(v.payload)});
  for (std::size_t i = 0; i < m_reportedDrops.size(); ++i) {
    const std::uint64_t d = m_source->dropped(static_cast<int>(i));
    if (d > m_reportedDrops[i]) countDropped(static_cast<int>(i), d - m_reportedDrops[i]);
    m_reportedDrops[i] = d;
  }
  publish(batch);
  if (m_params.batteryPercent && arrival - m_batteryShown >= 1.0) {  // a real one: every second
    m_batteryShown = arrival;
    const double minutes = (arrival - m_started) / 60.0;
    setBattery(std::max(0.0, *m_params.batteryPercent - m_params.batteryDrainPerMinute * minutes));
  }
  for (const SourceEvent& e : events) {
    const QString text = QString::fromStdString(e.text);
    switch (e.kind) {
      case SourceEventKind::LinkLost:
        setState(DeviceState::Connecting, text);
        reportProblem(text);
        break;
      case SourceEventKind::LinkBack:
        countReconnect();
        setState(DeviceState::Streaming, text);
        reportProblem(text);
        break;
      case SourceEventKind::Finished:
        m_timer->stop();
        setState(DeviceState::Disconnected, text);
        break;
      default:
        reportProblem(text);
        break;
    }
  }
}

}  // namespace armtrack::devices::virtualarm
