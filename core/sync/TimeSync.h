// Time synchronisation of several device streams onto the host's monotonic clock: a per-device
// clock model (offset and drift fitted to the lower envelope of the arrival delays, with wrap
// unwrapping, gap tolerance and clock-jump re-locking) and a merger that releases samples from all
// devices in host-time order after a bounded latency window. See docs/time-sync.md.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace armtrack {

/// Unwraps a device timestamp that counts modulo a period (e.g. Shimmer3's 24-bit counter at
/// 32768 Hz wraps every 512 s). A step back by more than half a period is taken for a wrap; a step
/// forward by more than half a period for a straggler from before the last wrap. Plain data.
struct TimestampUnwrapper {
  double period = 0.0;  ///< wrap period (s); 0 = the timestamps do not wrap
  double offset = 0.0;  ///< s added to raw timestamps (a whole number of periods)
  double last = 0.0;    ///< last raw timestamp that moved the unwrapper (s)
  bool started = false;
  std::uint64_t wraps = 0;  ///< wraps seen

  /// Raw timestamp (s, in [0, period)) to a continuous one (s). Finite input only.
  double unwrap(double raw);
};

/// Tuning of DeviceClock. Times in seconds, drift dimensionless (1e-6 = 1 ppm).
struct ClockParams {
  /// Wrap period of the raw device timestamps (s); 0 when the parser already unwraps. Default 0.
  double wrapPeriod = 0.0;
  /// Width of the bins over device time in which the smallest delay is kept (s). Default 0.5.
  double binSeconds = 0.5;
  /// Device time covered by the fit (s): older bins are dropped. Default 30.
  double windowSeconds = 30.0;
  /// Smallest span of bins (s) before drift is fitted; until then drift stays at its prior (the
  /// last fitted value, or initialDrift). Default 4.
  double minDriftSpan = 4.0;
  /// Bin minima further than this above the lower hull are left out of the drift fit (s), e.g.
  /// bins that fell entirely inside a transmission stall. Default 0.002.
  double envelopeGate = 0.002;
  /// Drift prior before the first fit (dimensionless). Default 0.
  double initialDrift = 0.0;
  /// Largest drift accepted (dimensionless); the fit is clamped to it. Quartz oscillators are
  /// within about +-100 ppm; the limit keeps a fit that arrivals delayed by a flood or a backlog
  /// could still bend from going beyond what a clock can do. Default 5e-4 (500 ppm).
  double maxDrift = 5e-4;
  /// A sample that arrives this much earlier than the model allows is a clock jump candidate (s).
  /// Default 0.05.
  double jumpThreshold = 0.05;
  /// Samples delayed by more than this above the envelope count as delayed (s). A stall's backlog
  /// arrives in a burst and is mapped by the model as usual; delayed samples that keep arriving
  /// for stallConfirmSeconds of host time with a steady delay mean the device clock fell back:
  /// it re-locks. Default 1.
  double maxDelay = 1.0;
  /// Host time over which delayed samples must keep arriving, their delay above the envelope
  /// staying within delaySteadiness, before the clock re-locks (s). Default 1.
  double stallConfirmSeconds = 1.0;
  /// Largest spread of the delays of a delayed run that still counts as steady (s). A clock that
  /// fell back shows one constant extra delay; a backlog (a flood on the port, a reader that fell
  /// behind) one that grows and drains, which must not move the model. Default 0.05.
  double delaySteadiness = 0.05;
  /// A device timestamp this much behind the previous one is a clock jump candidate (s); smaller
  /// steps back are accepted and counted. Default 0.01.
  double backwardTolerance = 0.01;
  /// Consecutive candidates that agree with each other before a jump is confirmed and the clock
  /// re-locks; a candidate followed by a sample that fits the old model is a glitch. Default 3.
  int jumpConfirmSamples = 3;
  /// A device-time step longer than this counts as a gap (s); the model is kept. Default 0.25.
  double gapSeconds = 0.25;
  /// Weight of each new sample in the rate and jitter averages (dimensionless). Default 0.01.
  double statsAlpha = 0.01;
};

/// How DeviceClock mapped a sample.
enum class ClockStatus {
  Locked,       ///< mapped by the fitted model
  Provisional,  ///< jump candidate: mapped by a provisional model built from the candidates
  Rejected,     ///< non-finite timestamp; not mapped
};

/// Result of DeviceClock::update.
struct ClockUpdate {
  double hostTime = std::numeric_limits<double>::quiet_NaN();    ///< synchronised time (s)
  double deviceTime = std::numeric_limits<double>::quiet_NaN();  ///< unwrapped device time (s)
  ClockStatus status = ClockStatus::Rejected;
  bool relocked = false;  ///< this sample confirmed a clock jump
};

/// One bin of the lower envelope: the sample of smallest delay y = arrival - device time.
struct ClockBin {
  std::int64_t index = 0;  ///< bin number since the lock
  double t = 0.0;          ///< device time of that sample (s)
  double y = 0.0;          ///< its delay arrival - t (s)
};

/// Counters of DeviceClock; never reset except by reset().
struct ClockCounters {
  std::uint64_t accepted = 0;           ///< samples mapped by the model
  std::uint64_t rejectedNonFinite = 0;  ///< NaN/inf device or arrival time
  std::uint64_t provisional = 0;        ///< samples mapped while a jump was a candidate
  std::uint64_t jumps = 0;              ///< confirmed clock jumps (re-locks)
  std::uint64_t glitches = 0;           ///< candidate jumps the next sample refuted
  std::uint64_t gaps = 0;               ///< device-time steps longer than gapSeconds
  std::uint64_t backwards = 0;          ///< small steps back in device time (accepted)
  std::uint64_t delayed = 0;            ///< samples delayed by more than maxDelay (accepted)
  std::uint64_t unsteady = 0;  ///< delayed runs restarted because the delay changed (backlogs)
  std::uint64_t refits = 0;    ///< model refits (one per closed bin)
};

/// Everything DeviceClock carries between samples (plain data; copy it to save/restore). The model
/// is host = t + a + b (t - tc): a the delay floor at device time tc, b the drift.
struct ClockState {
  bool locked = false;
  double a = 0.0;              ///< s
  double b = 0.0;              ///< drift (dimensionless)
  double tc = 0.0;             ///< model reference device time (s)
  bool driftFitted = false;    ///< b comes from a fit (kept across jumps), not the prior
  double origin = 0.0;         ///< device time of bin 0 (s)
  std::vector<ClockBin> bins;  ///< closed bins in the window, oldest first
  ClockBin open;               ///< the bin being filled
  double lastT = 0.0;          ///< newest accepted device time (s)

  // Jump candidate.
  bool candidate = false;
  double candT0 = 0.0;  ///< device time of the first candidate (s)
  double candA = 0.0;   ///< provisional delay floor at candT0 (s)
  double candLastT = 0.0;
  int candCount = 0;
  // A run of delayed samples (above maxDelay) with a steady delay.
  bool delayedRun = false;
  double delayedSince = 0.0;  ///< host arrival time of the first of the run (s)
  double delayedMin = 0.0;    ///< smallest delay above the line in the run (s)
  double delayedMax = 0.0;    ///< largest delay above the line in the run (s)

  // Statistics.
  double dtMean = 0.0;     ///< average device-time step (s), gaps excluded
  double delayMean = 0.0;  ///< average delay above the envelope (s)
  double delaySq = 0.0;    ///< average squared delay above the envelope (s^2)
  TimestampUnwrapper unwrapper;
  ClockCounters counters;
};

/// Clock model of one device: maps device timestamps onto the host clock from (device time,
/// arrival time) pairs. Arrival = true time + delay, delay >= a floor and jittery, so the model is
/// fitted to the lower envelope of the delays (docs/time-sync.md). The synchronised time includes
/// the floor (the smallest transmission delay), which no timestamp can reveal. Not thread-safe;
/// update() does no heap allocation.
class DeviceClock {
 public:
  /// Throws std::invalid_argument for non-positive bin, window, gate, thresholds or confirm count.
  explicit DeviceClock(const ClockParams& params = {});

  /// One sample: device time (s; raw when params.wrapPeriod > 0) and host monotonic arrival time
  /// (s). Non-finite input is rejected and counted.
  ClockUpdate update(double deviceTime, double arrivalTime);

  /// Host time of an (unwrapped) device time under the current model (s).
  double toHost(double deviceTime) const {
    return deviceTime + m_s.a + m_s.b * (deviceTime - m_s.tc);
  }
  bool locked() const { return m_s.locked; }
  double offset() const { return m_s.a - m_s.b * m_s.tc; }  ///< host - device at t = 0 (s)
  double drift() const { return m_s.b; }                    ///< dimensionless
  double rateHz() const { return m_s.dtMean > 0.0 ? 1.0 / m_s.dtMean : 0.0; }
  double meanDelay() const { return m_s.delayMean; }  ///< s above the envelope
  double jitter() const;                              ///< std of the delay (s)

  const ClockParams& params() const { return m_p; }
  const ClockState& state() const { return m_s; }
  const ClockCounters& counters() const { return m_s.counters; }
  void setState(const ClockState& s) { m_s = s; }
  void reset();

 private:
  void lock(double t, double y, double drift);
  void accept(double t, double y);
  void refit();
  double line(double t) const { return m_s.a + m_s.b * (t - m_s.tc); }

  ClockParams m_p;
  std::size_t m_maxBins = 0;
  ClockState m_s;
  std::vector<std::size_t> m_hull;  ///< scratch for refit (reserved)
};

/// Tuning of the merger.
struct SyncParams {
  /// A sample is released once the host clock is this much past its synchronised time (s).
  /// Default 0.05.
  double latencyWindow = 0.05;
  /// Most samples one device may have queued; beyond it the earliest queued samples are released
  /// early (counted as overflow). Default 4096.
  std::size_t maxQueuedPerDevice = 4096;
};

/// One released sample.
template <class Payload>
struct SyncEvent {
  double t = 0.0;            ///< synchronised host time (s); non-decreasing over released events
  double syncTime = 0.0;     ///< time the clock model gave, before the late clamp (s)
  double deviceTime = 0.0;   ///< unwrapped device time (s)
  double arrivalTime = 0.0;  ///< host arrival time (s)
  int device = 0;
  std::uint64_t sequence = 0;  ///< index of the push for this device (rejected pushes included)
  bool late = false;           ///< arrived after its slot was released; t clamped
  bool provisional = false;    ///< mapped while a clock jump was a candidate
  bool forced = false;         ///< released before its window by the queue cap
  Payload payload{};
};

enum class PushResult {
  Queued,    ///< queued in order
  Late,      ///< queued with its time clamped to the last released time
  Rejected,  ///< non-finite timestamp: not queued (counted)
};

/// Merger counters per device; never reset.
struct MergeCounters {
  std::uint64_t pushed = 0;     ///< samples offered
  std::uint64_t released = 0;   ///< samples released
  std::uint64_t late = 0;       ///< samples clamped to the last released time
  std::uint64_t reordered = 0;  ///< synchronised time behind this device's previous sample
  std::uint64_t overflow = 0;   ///< pushes that forced early releases
  std::size_t queued = 0;       ///< samples waiting now
  std::size_t maxQueued = 0;    ///< most samples ever waiting
};

/// Summary of one device for --stats.
struct DeviceSyncStats {
  double rateHz = 0.0;     ///< estimated sample rate (device clock)
  double offset = 0.0;     ///< host - device time at device time 0 (s)
  double driftPpm = 0.0;   ///< clock drift (ppm; positive: device clock slow)
  double meanDelay = 0.0;  ///< average delay above the envelope (s)
  double jitter = 0.0;     ///< std of that delay (s)
  ClockCounters clock;
  MergeCounters merge;
};

/// Merges device streams in host-time order. Each push maps the sample through its device's
/// clock and queues it; poll(hostNow) releases every queued sample older than hostNow minus the
/// latency window, earliest first. A sample whose time is behind the last released one is not
/// dropped: it is queued with its time clamped and marked late. Memory is bounded by
/// maxQueuedPerDevice per device: a push at the cap releases the earliest queued samples first.
/// Not thread-safe; push/poll allocate nothing after construction. Rejected (non-finite) samples
/// are the only ones not released; every other sample comes out exactly once.
template <class Payload>
class TimeSync {
 public:
  using Event = SyncEvent<Payload>;

  /// One ClockParams per device; devices are numbered 0..n-1. Throws std::invalid_argument for a
  /// negative window, a zero cap or an invalid clock parameter.
  TimeSync(const SyncParams& params, const std::vector<ClockParams>& devices) : m_p(params) {
    if (!(params.latencyWindow >= 0.0) || params.maxQueuedPerDevice == 0)
      throw std::invalid_argument("TimeSync: latencyWindow must be >= 0 and the cap > 0");
    m_clocks.reserve(devices.size());
    for (const auto& c : devices) m_clocks.emplace_back(c);
    m_counters.resize(devices.size());
    m_lastSync.assign(devices.size(), -std::numeric_limits<double>::infinity());
    m_seq.assign(devices.size(), 0);
    m_heap.reserve(devices.size() * params.maxQueuedPerDevice + 1);
  }

  int deviceCount() const { return static_cast<int>(m_clocks.size()); }

  /// Offers one sample; at the queue cap, releases the earliest queued samples into sink (a
  /// callable taking const Event&) first. Throws std::out_of_range for an unknown device.
  template <class Sink>
  PushResult push(int device, double deviceTime, double arrivalTime, Payload payload, Sink&& sink) {
    const auto d = static_cast<std::size_t>(device);
    if (device < 0 || d >= m_clocks.size()) throw std::out_of_range("TimeSync: unknown device");
    MergeCounters& c = m_counters[d];
    ++c.pushed;
    const std::uint64_t seq = m_seq[d]++;
    const ClockUpdate u = m_clocks[d].update(deviceTime, arrivalTime);
    if (u.status == ClockStatus::Rejected) return PushResult::Rejected;

    if (c.queued >= m_p.maxQueuedPerDevice) {
      ++c.overflow;
      while (c.queued >= m_p.maxQueuedPerDevice) releaseTop(sink, true);
    }
    if (u.hostTime < m_lastSync[d]) ++c.reordered;
    m_lastSync[d] = u.hostTime;

    Entry e;
    e.ev.t = u.hostTime;
    e.ev.syncTime = u.hostTime;
    e.ev.deviceTime = u.deviceTime;
    e.ev.arrivalTime = arrivalTime;
    e.ev.device = device;
    e.ev.sequence = seq;
    e.ev.provisional = u.status == ClockStatus::Provisional;
    e.ev.payload = std::move(payload);
    e.order = m_order++;
    PushResult r = PushResult::Queued;
    if (m_released && e.ev.t < m_lastReleased) {
      e.ev.t = m_lastReleased;
      e.ev.late = true;
      ++c.late;
      r = PushResult::Late;
    }
    m_heap.push_back(std::move(e));
    std::push_heap(m_heap.begin(), m_heap.end(), Later{});
    c.maxQueued = std::max(c.maxQueued, ++c.queued);
    return r;
  }

  /// Releases, earliest first, every queued sample with t <= hostNow - latencyWindow. Returns the
  /// number released.
  template <class Sink>
  std::size_t poll(double hostNow, Sink&& sink) {
    const double limit = hostNow - m_p.latencyWindow;
    std::size_t n = 0;
    while (!m_heap.empty() && m_heap.front().ev.t <= limit) {
      releaseTop(sink, false);
      ++n;
    }
    return n;
  }

  /// Releases everything queued (end of session).
  template <class Sink>
  std::size_t flush(Sink&& sink) {
    std::size_t n = 0;
    while (!m_heap.empty()) {
      releaseTop(sink, false);
      ++n;
    }
    return n;
  }

  std::size_t queued() const { return m_heap.size(); }
  /// Time of the last released sample (s); -inf before the first.
  double lastReleased() const {
    return m_released ? m_lastReleased : -std::numeric_limits<double>::infinity();
  }
  const DeviceClock& clock(int device) const { return m_clocks.at(device); }
  const MergeCounters& counters(int device) const { return m_counters.at(device); }
  DeviceSyncStats stats(int device) const {
    const DeviceClock& k = clock(device);
    DeviceSyncStats s;
    s.rateHz = k.rateHz();
    s.offset = k.offset();
    s.driftPpm = k.drift() * 1e6;
    s.meanDelay = k.meanDelay();
    s.jitter = k.jitter();
    s.clock = k.counters();
    s.merge = counters(device);
    return s;
  }

 private:
  struct Entry {
    Event ev;
    std::uint64_t order = 0;  ///< push order, breaks ties deterministically
  };
  struct Later {
    bool operator()(const Entry& x, const Entry& y) const {
      return x.ev.t > y.ev.t || (x.ev.t == y.ev.t && x.order > y.order);
    }
  };

  template <class Sink>
  void releaseTop(Sink& sink, bool forced) {
    std::pop_heap(m_heap.begin(), m_heap.end(), Later{});
    Entry& e = m_heap.back();
    e.ev.forced = forced;
    m_lastReleased = e.ev.t;
    m_released = true;
    MergeCounters& c = m_counters[static_cast<std::size_t>(e.ev.device)];
    --c.queued;
    ++c.released;
    std::invoke(sink, std::as_const(e.ev));
    m_heap.pop_back();
  }

  SyncParams m_p;
  std::vector<DeviceClock> m_clocks;
  std::vector<MergeCounters> m_counters;
  std::vector<double> m_lastSync;
  std::vector<std::uint64_t> m_seq;
  std::vector<Entry> m_heap;
  std::uint64_t m_order = 0;
  double m_lastReleased = 0.0;
  bool m_released = false;
};

}  // namespace armtrack
