#include "devices/api/Device.h"

#include <algorithm>

namespace armtrack::devices {

Device::Device(std::vector<StreamInfo> streams, QObject* parent)
    : QObject(parent), m_streams(std::move(streams)) {
  m_health.streams.resize(m_streams.size());
  m_windows.resize(m_streams.size());
}

Device::~Device() = default;

DeviceHealth Device::health() const {
  std::lock_guard lock(m_mutex);
  return m_health;
}

void Device::setState(DeviceState state, const QString& reason) {
  // A new reason is news even when the state stays (e.g. "link lost" then "port missing").
  const bool same = m_state.exchange(state) == state;
  {
    std::lock_guard lock(m_mutex);
    if (same && (reason.isEmpty() || reason == m_lastReason)) return;
    m_lastReason = reason;
  }
  emit stateChanged(state, reason);
}

void Device::publish(const SampleBatch& batch) {
  if (batch.empty()) return;
  {
    std::lock_guard lock(m_mutex);
    const double now = hostNow();
    for (const DeviceSample& s : batch) {
      if (s.stream < 0 || static_cast<std::size_t>(s.stream) >= m_streams.size()) continue;
      ++m_health.streams[static_cast<std::size_t>(s.stream)].samples;
      ++m_windows[static_cast<std::size_t>(s.stream)].count;
    }
    // The rate is the count over the last whole second (or longer, when samples are sparse).
    for (std::size_t i = 0; i < m_windows.size(); ++i) {
      RateWindow& w = m_windows[i];
      if (w.start < 0.0) {
        w.start = now;
        w.count = 0;
      } else if (now - w.start >= 1.0) {
        m_health.streams[i].rateHz = static_cast<double>(w.count) / (now - w.start);
        w.start = now;
        w.count = 0;
      }
    }
  }
  emit samplesReady(batch);
}

void Device::reportProblem(const QString& message) {
  {
    std::lock_guard lock(m_mutex);
    m_health.lastProblem = message.toStdString();
  }
  emit problem(message);
}

void Device::countDropped(int stream, std::uint64_t n) {
  std::lock_guard lock(m_mutex);
  if (stream >= 0 && static_cast<std::size_t>(stream) < m_streams.size())
    m_health.streams[static_cast<std::size_t>(stream)].dropped += n;
}

void Device::countCorrupt(int stream, std::uint64_t n) {
  std::lock_guard lock(m_mutex);
  if (stream >= 0 && static_cast<std::size_t>(stream) < m_streams.size())
    m_health.streams[static_cast<std::size_t>(stream)].corrupt += n;
}

void Device::countReordered(int stream, std::uint64_t n) {
  std::lock_guard lock(m_mutex);
  if (stream >= 0 && static_cast<std::size_t>(stream) < m_streams.size()) {
    StreamHealth& h = m_health.streams[static_cast<std::size_t>(stream)];
    h.dropped -= std::min(h.dropped, n);
    h.reordered += n;
  }
}

void Device::countReconnect() {
  std::lock_guard lock(m_mutex);
  ++m_health.reconnects;
}

void Device::setBattery(std::optional<double> percent) {
  std::lock_guard lock(m_mutex);
  m_health.batteryPercent = percent;
}

}  // namespace armtrack::devices
