// The time synchroniser against simulated device clocks with known offset and drift, positive
// jittery transmission delays with Bluetooth-like stalls, reboots, wraps and dropouts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "core/sync/ArmSampleAssembler.h"
#include "core/sync/SequenceTracker.h"
#include "core/sync/TimeSync.h"

namespace armtrack {
namespace {

constexpr double kPpm = 1e-6;

// A simulated device: its clock runs as host = offset + (1 + drift) * device time; each sample
// reaches the host after floor + Exp(jitterMean), and during a stall nothing arrives until it ends
// (then the backlog arrives at once). Arrivals are first-in first-out.
struct SimDevice {
  double rateHz = 1000.0;
  double offset = 0.0;  ///< s
  double drift = 0.0;
  double floor = 0.002;       ///< s, smallest transmission delay
  double jitterMean = 0.001;  ///< s
  double stallsPerSecond = 0.0;
  double stallSeconds = 0.2;
  double deviceStart = 0.0;  ///< device time of the first sample (s)
};

struct SimSample {
  int device = 0;
  double deviceTime = 0.0;  ///< as the device reports it
  double trueHost = 0.0;    ///< host time the sample was taken (s)
  double arrival = 0.0;     ///< host arrival time (s)
  std::uint64_t seq = 0;    ///< index in the device's stream
};

// Samples of one device taken between host times [hostStart, hostEnd), skipping the
// silent intervals (host time) given.
std::vector<SimSample> simulate(const SimDevice& d, int id, double hostStart, double hostEnd,
                                std::uint32_t seed,
                                const std::vector<std::pair<double, double>>& silent = {}) {
  std::mt19937_64 rng(seed);
  std::exponential_distribution<double> jitter(1.0 / d.jitterMean);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<std::pair<double, double>> stalls;
  if (d.stallsPerSecond > 0.0) {
    std::exponential_distribution<double> next(d.stallsPerSecond);
    for (double s = hostStart + next(rng); s < hostEnd; s += d.stallSeconds + next(rng))
      stalls.emplace_back(s, s + d.stallSeconds);
  }
  std::vector<SimSample> out;
  const double td0 = (hostStart - d.offset) / (1.0 + d.drift);
  double prevArrival = -std::numeric_limits<double>::infinity();
  for (std::uint64_t k = 0;; ++k) {
    const double td = td0 + static_cast<double>(k) / d.rateHz;
    const double host = d.offset + (1.0 + d.drift) * td;
    if (host >= hostEnd) break;
    bool quiet = false;
    for (const auto& [a, b] : silent) quiet = quiet || (host >= a && host < b);
    if (quiet) continue;
    double arrival = host + d.floor + jitter(rng);
    for (const auto& [a, b] : stalls)
      if (arrival >= a && arrival < b) arrival = b + 1e-5 * uni(rng);
    arrival = std::max(arrival, prevArrival);
    prevArrival = arrival;
    SimSample s;
    s.device = id;
    s.deviceTime = td - td0 + d.deviceStart;
    s.trueHost = host;
    s.arrival = arrival;
    s.seq = out.size();
    out.push_back(s);
  }
  return out;
}

// With deviceStart shifting the device time, the offset the clock should find.
double trueOffset(const SimDevice& d, double hostStart) {
  const double td0 = (hostStart - d.offset) / (1.0 + d.drift);
  // host = offset + (1 + drift) (t - deviceStart + td0)
  return d.offset + (1.0 + d.drift) * (td0 - d.deviceStart) + d.floor;
}

std::vector<SimSample> byArrival(std::vector<std::vector<SimSample>> streams) {
  std::vector<SimSample> all;
  for (auto& s : streams) all.insert(all.end(), s.begin(), s.end());
  std::stable_sort(all.begin(), all.end(),
                   [](const SimSample& a, const SimSample& b) { return a.arrival < b.arrival; });
  return all;
}

// Feeds one device stream through a DeviceClock; returns the largest |mapped - (true + floor)|
// over samples whose true host time is at least `from`.
double maxClockError(DeviceClock& clock, const std::vector<SimSample>& samples, double floor,
                     double from) {
  double worst = 0.0;
  for (const auto& s : samples) {
    const ClockUpdate u = clock.update(s.deviceTime, s.arrival);
    EXPECT_NE(u.status, ClockStatus::Rejected);
    if (s.trueHost >= from) worst = std::max(worst, std::abs(u.hostTime - (s.trueHost + floor)));
  }
  return worst;
}

// ---------------------------------------------------------------------------------------------

TEST(TimeSyncUnwrapper, UnwrapsAndKeepsStragglers) {
  TimestampUnwrapper u;
  u.period = 512.0;
  EXPECT_DOUBLE_EQ(u.unwrap(500.0), 500.0);
  EXPECT_DOUBLE_EQ(u.unwrap(511.9), 511.9);
  EXPECT_DOUBLE_EQ(u.unwrap(0.1), 512.1);
  EXPECT_DOUBLE_EQ(u.unwrap(511.95), 511.95);  // straggler from before the wrap
  EXPECT_DOUBLE_EQ(u.unwrap(0.2), 512.2);
  EXPECT_DOUBLE_EQ(u.unwrap(100.0), 612.0);  // a step back of < half a period is not a wrap
  EXPECT_DOUBLE_EQ(u.unwrap(50.0), 562.0);
  EXPECT_EQ(u.wraps, 1u);
  TimestampUnwrapper none;
  EXPECT_DOUBLE_EQ(none.unwrap(-3.0), -3.0);
}

TEST(TimeSyncClock, RecoversOffsetAndDriftUnderJitterAndStalls) {
  SimDevice d;
  d.offset = 12.345;
  d.drift = 80 * kPpm;
  d.stallsPerSecond = 0.2;  // 200 ms Bluetooth stalls, one every ~5 s
  const auto samples = simulate(d, 0, 100.0, 160.0, 1);
  DeviceClock clock;
  const double err = maxClockError(clock, samples, d.floor, 110.0);
  EXPECT_LT(err, 0.2e-3);
  EXPECT_NEAR(clock.drift(), d.drift, 2 * kPpm);
  EXPECT_NEAR(clock.offset(), trueOffset(d, 100.0), 1e-3);
  EXPECT_NEAR(clock.rateHz(), 1000.0, 1.0);
  EXPECT_GT(clock.jitter(), 0.5e-3);  // stalls and Exp(1 ms) delays are visible in the jitter
  EXPECT_EQ(clock.counters().jumps, 0u);
  EXPECT_EQ(clock.counters().glitches, 0u);
  // Locks within a second: the error after 1 s is already small.
  DeviceClock early;
  EXPECT_LT(maxClockError(early, samples, d.floor, 101.0), 1e-3);
}

TEST(TimeSyncClock, CameraAt30HzWithLargeJitter) {
  SimDevice d;
  d.rateHz = 30.0;
  d.offset = -1234.5;
  d.drift = -45 * kPpm;
  d.floor = 0.010;
  d.jitterMean = 0.005;
  d.stallsPerSecond = 0.1;
  const auto samples = simulate(d, 0, 10.0, 70.0, 2);
  DeviceClock clock;
  const double err = maxClockError(clock, samples, d.floor, 25.0);
  EXPECT_LT(err, 1e-3);
  EXPECT_NEAR(clock.drift(), d.drift, 5 * kPpm);
  EXPECT_NEAR(clock.offset(), trueOffset(d, 10.0), 1e-3);
}

// The test data must be able to defeat a naive estimator: an ordinary least-squares line through
// (device time, arrival) is biased by the mean delay and pulled by the stalls.
TEST(TimeSyncClock, PlainLeastSquaresWouldFailTheSameData) {
  SimDevice d;
  d.offset = 12.345;
  d.drift = 80 * kPpm;
  d.stallsPerSecond = 0.2;
  const auto samples = simulate(d, 0, 100.0, 160.0, 1);
  double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
  const double t0 = samples.front().deviceTime;
  for (const auto& s : samples) {
    const double t = s.deviceTime - t0, y = s.arrival - s.deviceTime;
    n += 1;
    st += t;
    sy += y;
    stt += t * t;
    sty += t * y;
  }
  const double b = (n * sty - st * sy) / (n * stt - st * st);
  const double a = (sy - b * st) / n - b * t0;
  EXPECT_GT(std::abs(a - trueOffset(d, 100.0)), 1e-3);
}

TEST(TimeSyncClock, RebootRelocksWithinASecondAndIsCounted) {
  SimDevice d;
  d.offset = 3.0;
  d.drift = 80 * kPpm;
  auto before = simulate(d, 0, 0.0, 20.0, 3);
  // Reboot: silent for 0.3 s, then the device clock restarts at 0.
  SimDevice after = d;
  after.deviceStart = 0.0;
  auto rest = simulate(after, 0, 20.3, 40.0, 4);
  DeviceClock clock;
  maxClockError(clock, before, d.floor, 1e9);
  const double afterOffset = trueOffset(after, 20.3);
  double worst = 0.0;
  for (const auto& s : rest) {
    const ClockUpdate u = clock.update(s.deviceTime, s.arrival);
    if (s.trueHost >= 20.3 + 1.0)
      worst = std::max(worst, std::abs(u.hostTime - (s.trueHost + d.floor)));
  }
  EXPECT_EQ(clock.counters().jumps, 1u);
  EXPECT_LT(worst, 1e-3);
  EXPECT_NEAR(clock.offset(), afterOffset, 1e-3);
  EXPECT_NEAR(clock.drift(), d.drift, 5 * kPpm);
}

TEST(TimeSyncClock, ForwardLeapIsAJumpAndASingleBadTimestampIsAGlitch) {
  SimDevice d;
  d.offset = 1.0;
  const auto samples = simulate(d, 0, 0.0, 20.0, 5);
  DeviceClock clock;
  double worst = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto& s = samples[i];
    double td = s.deviceTime;
    if (i == 5000) td += 1000.0;  // one corrupted timestamp
    if (i >= 12000) td += 60.0;   // the clock leaps forward by a minute
    const ClockUpdate u = clock.update(td, s.arrival);
    if (i == 5000) {
      EXPECT_EQ(u.status, ClockStatus::Provisional);
    }
    if (i >= 13000) worst = std::max(worst, std::abs(u.hostTime - (s.trueHost + d.floor)));
  }
  EXPECT_EQ(clock.counters().glitches, 1u);
  EXPECT_EQ(clock.counters().jumps, 1u);
  EXPECT_LT(worst, 1e-3);
}

TEST(TimeSyncClock, Shimmer24BitCounterWraps) {
  SimDevice d;
  d.rateHz = 512.0;
  d.offset = 40.0;
  d.drift = 80 * kPpm;
  d.deviceStart = 500.0;  // wraps 12 s in
  d.stallsPerSecond = 0.1;
  const auto samples = simulate(d, 0, 0.0, 40.0, 6);
  ClockParams p;
  p.wrapPeriod = 16777216.0 / 32768.0;  // 2^24 ticks at 32768 Hz = 512 s
  DeviceClock clock(p);
  double worst = 0.0;
  for (const auto& s : samples) {
    const double ticks = std::fmod(std::round(s.deviceTime * 32768.0), 16777216.0);
    const ClockUpdate u = clock.update(ticks / 32768.0, s.arrival);
    if (s.trueHost >= 5.0) worst = std::max(worst, std::abs(u.hostTime - (s.trueHost + d.floor)));
  }
  EXPECT_EQ(clock.state().unwrapper.wraps, 1u);
  EXPECT_EQ(clock.counters().jumps, 0u);
  EXPECT_LT(worst, 1e-3);
  EXPECT_NEAR(clock.drift(), d.drift, 5 * kPpm);
}

TEST(TimeSyncClock, DropoutKeepsTheModel) {
  SimDevice d;
  d.offset = 7.0;
  d.drift = -60 * kPpm;
  const auto samples = simulate(d, 0, 0.0, 40.0, 7, {{20.0, 25.0}});
  DeviceClock clock;
  double worstAfter = 0.0;
  for (const auto& s : samples) {
    const ClockUpdate u = clock.update(s.deviceTime, s.arrival);
    if (s.trueHost >= 25.0 && s.trueHost < 25.1)  // straight after the return
      worstAfter = std::max(worstAfter, std::abs(u.hostTime - (s.trueHost + d.floor)));
  }
  EXPECT_EQ(clock.counters().gaps, 1u);
  EXPECT_EQ(clock.counters().jumps, 0u);
  EXPECT_LT(worstAfter, 0.2e-3);
  EXPECT_NEAR(clock.drift(), d.drift, 5 * kPpm);
}

// A flood on a device's UDP port from host time 20 s to 25 s: its reader falls behind, so its
// samples wait in the socket buffer and arrive late by a backlog that grows by 0.4 s per second
// (up to 2 s), then drains in 1 s once the flood stops; arrivals stay first-in first-out. The
// clock must not take the growing delay for drift, and must map the samples correctly again soon
// after the flood, so they are not released late for the rest of the run.
std::vector<SimSample> floodedStream(const SimDevice& d, double hostEnd, std::uint32_t seed) {
  auto samples = simulate(d, 0, 0.0, hostEnd, seed);
  double prev = 0.0;
  for (auto& s : samples) {
    const double x = s.trueHost;
    double backlog = 0.0;
    if (x >= 20.0 && x < 25.0) backlog = 0.4 * (x - 20.0);
    if (x >= 25.0) backlog = std::max(0.0, 2.0 - 2.0 * (x - 25.0));
    s.arrival = std::max(prev, s.arrival + backlog);
    prev = s.arrival;
  }
  return samples;
}

TEST(TimeSyncClock, FloodBacklogDoesNotDragTheDriftAndTheModelRecovers) {
  SimDevice d;
  d.rateHz = 500.0;
  d.offset = 7.0;
  d.drift = 40 * kPpm;
  const auto samples = floodedStream(d, 60.0, 21);
  DeviceClock clock;
  double worstDrift = 0.0, worstAfter = 0.0;
  for (const auto& s : samples) {
    const ClockUpdate u = clock.update(s.deviceTime, s.arrival);
    worstDrift = std::max(worstDrift, std::abs(clock.drift() - d.drift));
    if (s.trueHost >= 28.0)
      worstAfter = std::max(worstAfter, std::abs(u.hostTime - (s.trueHost + d.floor)));
  }
  std::printf(
      "flood backlog: worst drift error %.0f ppm, drift at the end %.1f ppm (true %.0f), "
      "worst mapping error from 3 s after the flood %.3f ms, jumps %llu\n",
      worstDrift / kPpm, clock.drift() / kPpm, d.drift / kPpm, worstAfter * 1e3,
      static_cast<unsigned long long>(clock.counters().jumps));
  EXPECT_LT(worstDrift, 300 * kPpm);
  EXPECT_LT(worstAfter, 1e-3);
  EXPECT_NEAR(clock.drift(), d.drift, 5 * kPpm);
}

TEST(TimeSyncClock, AClockThatFellBackStillRelocks) {
  // The device sleeps for 3 s with its clock stopped: afterwards every sample is 3 s later than
  // the model expects, steadily. That is a clock that fell back, not a backlog: it re-locks.
  SimDevice d;
  d.rateHz = 500.0;
  d.offset = 2.0;
  auto samples = simulate(d, 0, 0.0, 30.0, 24, {{10.0, 13.0}});
  for (auto& s : samples)
    if (s.trueHost >= 13.0) s.deviceTime -= 3.0;
  DeviceClock clock;
  double worst = 0.0;
  for (const auto& s : samples) {
    const ClockUpdate u = clock.update(s.deviceTime, s.arrival);
    if (s.trueHost >= 15.0) worst = std::max(worst, std::abs(u.hostTime - (s.trueHost + d.floor)));
  }
  EXPECT_EQ(clock.counters().jumps, 1u);
  EXPECT_LT(worst, 1e-3);
}

TEST(TimeSyncMerger, AfterAFloodTheFloodedDeviceIsNotReleasedLate) {
  SimDevice calm, flooded;
  calm.rateHz = 500.0;
  calm.offset = 3.0;
  calm.drift = -30 * kPpm;
  flooded.rateHz = 500.0;
  flooded.offset = 7.0;
  flooded.drift = 40 * kPpm;
  auto a = simulate(calm, 0, 0.0, 60.0, 22);
  auto b = floodedStream(flooded, 60.0, 23);
  for (auto& s : b) s.device = 1;
  TimeSync<std::uint64_t> sync({}, {ClockParams{}, ClockParams{}});
  std::uint64_t lateAfter = 0, releasedAfter = 0;
  auto sink = [&](const SyncEvent<std::uint64_t>& e) {
    if (e.device == 1 && e.arrivalTime >= 28.0) {
      ++releasedAfter;
      lateAfter += e.late;
    }
  };
  for (const auto& s : byArrival({a, b})) {
    sync.poll(s.arrival, sink);
    sync.push(s.device, s.deviceTime, s.arrival, s.seq, sink);
  }
  sync.flush(sink);
  std::printf("after the flood: %llu of %llu samples of the flooded device released late\n",
              static_cast<unsigned long long>(lateAfter),
              static_cast<unsigned long long>(releasedAfter));
  EXPECT_GT(releasedAfter, 15000u);
  EXPECT_LT(lateAfter, releasedAfter / 100);
}

TEST(TimeSyncClock, NonFiniteTimestampsAreRejected) {
  DeviceClock clock;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(clock.update(nan, 1.0).status, ClockStatus::Rejected);
  EXPECT_EQ(clock.update(0.0, inf).status, ClockStatus::Rejected);
  EXPECT_FALSE(clock.locked());
  EXPECT_EQ(clock.update(0.0, 1.0).status, ClockStatus::Locked);
  EXPECT_EQ(clock.update(-inf, 1.001).status, ClockStatus::Rejected);
  EXPECT_EQ(clock.update(0.001, nan).status, ClockStatus::Rejected);
  EXPECT_EQ(clock.counters().rejectedNonFinite, 4u);
  EXPECT_EQ(clock.counters().accepted, 1u);
  EXPECT_DOUBLE_EQ(clock.update(0.001, 1.0015).hostTime, 1.001);
}

TEST(TimeSyncClock, InvalidParametersThrow) {
  ClockParams p;
  p.binSeconds = 0.0;
  EXPECT_THROW(DeviceClock{p}, std::invalid_argument);
  p = {};
  p.jumpConfirmSamples = 0;
  EXPECT_THROW(DeviceClock{p}, std::invalid_argument);
  SyncParams s;
  s.maxQueuedPerDevice = 0;
  EXPECT_THROW(TimeSync<int>(s, {ClockParams{}}), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Merger

struct Collected {
  std::vector<SyncEvent<std::uint64_t>> events;
  void operator()(const SyncEvent<std::uint64_t>& e) { events.push_back(e); }
};

// Checks order and exactly-once delivery: the payload carries the input's index per device.
void expectOrderedExactlyOnce(const std::vector<SyncEvent<std::uint64_t>>& events,
                              const std::vector<std::size_t>& counts,
                              const std::vector<std::vector<bool>>& rejected = {}) {
  std::vector<std::vector<int>> seen(counts.size());
  for (std::size_t d = 0; d < counts.size(); ++d) seen[d].assign(counts[d], 0);
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (i > 0) {
      ASSERT_GE(events[i].t, events[i - 1].t) << "at event " << i;
    }
    const auto& e = events[i];
    ASSERT_LT(e.payload, counts[static_cast<std::size_t>(e.device)]);
    ++seen[static_cast<std::size_t>(e.device)][e.payload];
    EXPECT_EQ(e.sequence, e.payload);
  }
  for (std::size_t d = 0; d < counts.size(); ++d)
    for (std::size_t k = 0; k < counts[d]; ++k) {
      const int want = (!rejected.empty() && rejected[d][k]) ? 0 : 1;
      ASSERT_EQ(seen[d][k], want) << "device " << d << " sample " << k;
    }
}

TEST(TimeSyncMerger, TwoImusAndACameraInOrderExactlyOnce) {
  SimDevice ua, fa, cam;
  ua.offset = 12.3;
  ua.drift = 80 * kPpm;
  ua.stallsPerSecond = 0.2;
  fa.offset = -3.7;
  fa.drift = -45 * kPpm;
  fa.stallsPerSecond = 0.2;
  cam.rateHz = 30.0;
  cam.offset = 1000.0;
  cam.drift = 20 * kPpm;
  cam.floor = 0.015;
  cam.jitterMean = 0.004;
  const auto all = byArrival({simulate(ua, 0, 0.0, 60.0, 11), simulate(fa, 1, 0.0, 60.0, 12),
                              simulate(cam, 2, 0.0, 60.0, 13)});
  SyncParams sp;
  sp.latencyWindow = 0.05;
  TimeSync<std::uint64_t> sync(sp, {ClockParams{}, ClockParams{}, ClockParams{}});
  Collected out;
  std::vector<std::size_t> counts(3, 0);
  std::vector<double> truth[3];
  const double floors[3] = {ua.floor, fa.floor, cam.floor};
  double worstLatency = 0.0;
  std::size_t released = 0;
  double tick = 0.0;  // the caller polls on a 1 ms host timer
  for (const auto& s : all) {
    for (; tick < s.arrival; tick += 1e-3) {
      sync.poll(tick, out);
      for (; released < out.events.size(); ++released)
        worstLatency = std::max(worstLatency, tick - out.events[released].arrivalTime);
    }
    sync.push(s.device, s.deviceTime, s.arrival, s.seq, out);
    truth[s.device].push_back(s.trueHost + floors[s.device]);
    ++counts[static_cast<std::size_t>(s.device)];
  }
  sync.flush(out);
  expectOrderedExactlyOnce(out.events, counts);

  // Every sample that was not late carries its true time (within 1 ms after 10 s).
  double worst = 0.0;
  std::uint64_t late = 0;
  for (const auto& e : out.events) {
    if (e.late) {
      ++late;
      EXPECT_LT(e.syncTime, e.t);
      continue;
    }
    const double want = truth[e.device][e.payload];
    if (want > 10.0) worst = std::max(worst, std::abs(e.t - want));
  }
  EXPECT_LT(worst, 1e-3);
  std::uint64_t lateCounted = 0;
  for (int d = 0; d < 3; ++d) lateCounted += sync.counters(d).late;
  EXPECT_EQ(late, lateCounted);
  EXPECT_GT(late, 0u);  // 200 ms stalls are beyond a 50 ms window
  // Released within the window after arrival (plus one timer tick); late ones at the next tick.
  EXPECT_LE(worstLatency, sp.latencyWindow + 1e-3);

  const auto s0 = sync.stats(0), s1 = sync.stats(1), s2 = sync.stats(2);
  EXPECT_NEAR(s0.driftPpm, 80.0, 5.0);
  EXPECT_NEAR(s1.driftPpm, -45.0, 5.0);
  EXPECT_NEAR(s2.driftPpm, 20.0, 10.0);
  EXPECT_NEAR(s0.offset, trueOffset(ua, 0.0), 1e-3);
  EXPECT_NEAR(s1.offset, trueOffset(fa, 0.0), 1e-3);
  EXPECT_NEAR(s2.offset, trueOffset(cam, 0.0), 1e-3);
  EXPECT_NEAR(s2.rateHz, 30.0, 0.1);
  // A few dozen queued samples per IMU (1 kHz times the 50 ms window), never thousands.
  EXPECT_LE(s0.merge.maxQueued, 400u);
}

TEST(TimeSyncMerger, LateSampleIsClampedAndCounted) {
  TimeSync<std::uint64_t> sync({}, {ClockParams{}, ClockParams{}});
  Collected out;
  EXPECT_EQ(sync.push(0, 50.0, 1.0, 0, out), PushResult::Queued);
  sync.poll(2.0, out);
  ASSERT_EQ(out.events.size(), 1u);
  EXPECT_EQ(sync.push(1, 0.0, 0.5, 0, out), PushResult::Late);
  sync.poll(2.0, out);
  ASSERT_EQ(out.events.size(), 2u);
  EXPECT_TRUE(out.events[1].late);
  EXPECT_DOUBLE_EQ(out.events[1].t, 1.0);
  EXPECT_DOUBLE_EQ(out.events[1].syncTime, 0.5);
  EXPECT_EQ(sync.counters(1).late, 1u);
}

TEST(TimeSyncMerger, StalledDeviceKeepsQueuesBounded) {
  SimDevice a, b;
  a.offset = 5.0;
  b.offset = -5.0;
  b.drift = 50 * kPpm;
  auto sa = simulate(a, 0, 0.0, 20.0, 21);
  auto sb = simulate(b, 1, 0.0, 20.0, 22);
  for (auto& s : sb)  // a 3 s stall: nothing from b arrives between 8 and 11 s
    if (s.arrival >= 8.0 && s.arrival < 11.0) s.arrival = 11.0;
  const auto all = byArrival({sa, sb});
  TimeSync<std::uint64_t> sync({}, {ClockParams{}, ClockParams{}});
  Collected out;
  std::vector<std::size_t> counts(2, 0);
  for (const auto& s : all) {
    sync.push(s.device, s.deviceTime, s.arrival, s.seq, out);
    ++counts[static_cast<std::size_t>(s.device)];
    sync.poll(s.arrival, out);
  }
  sync.flush(out);
  expectOrderedExactlyOnce(out.events, counts);
  EXPECT_LE(sync.counters(0).maxQueued, 100u);  // ~1 kHz x 50 ms: a never waits for b
  EXPECT_GE(sync.counters(1).late, 2900u);      // b's backlog comes out late, not lost
  EXPECT_EQ(sync.counters(1).overflow, 0u);
  EXPECT_EQ(sync.stats(1).clock.jumps, 0u);  // a burst after a stall is not a clock jump
  EXPECT_GT(sync.stats(1).clock.delayed, 1000u);
}

TEST(TimeSyncMerger, QueueCapReleasesEarlyAndLosesNothing) {
  SimDevice a, b;
  b.offset = 0.3;
  const auto all = byArrival({simulate(a, 0, 0.0, 2.0, 31), simulate(b, 1, 0.0, 2.0, 32)});
  SyncParams sp;
  sp.maxQueuedPerDevice = 64;
  TimeSync<std::uint64_t> sync(sp, {ClockParams{}, ClockParams{}});
  Collected out;
  std::vector<std::size_t> counts(2, 0);
  for (const auto& s : all) {  // nobody polls
    sync.push(s.device, s.deviceTime, s.arrival, s.seq, out);
    ++counts[static_cast<std::size_t>(s.device)];
    ASSERT_LE(sync.queued(), 2 * sp.maxQueuedPerDevice);
  }
  EXPECT_GT(sync.counters(0).overflow + sync.counters(1).overflow, 0u);
  EXPECT_LE(sync.counters(0).maxQueued, 64u);
  EXPECT_LE(sync.counters(1).maxQueued, 64u);
  sync.flush(out);
  expectOrderedExactlyOnce(out.events, counts);
  EXPECT_TRUE(
      std::any_of(out.events.begin(), out.events.end(), [](const auto& e) { return e.forced; }));
}

TEST(TimeSyncMerger, RebootDropoutAndNonFiniteInputs) {
  SimDevice a, b;
  a.offset = 2.0;
  a.drift = 80 * kPpm;
  b.offset = -1.0;
  auto sa = simulate(a, 0, 0.0, 30.0, 41, {{10.0, 15.0}});  // a drops out for 5 s
  // b reboots at 20 s: its clock restarts at 0.
  auto sb = simulate(b, 1, 0.0, 20.0, 42);
  SimDevice b2 = b;
  auto sb2 = simulate(b2, 1, 20.2, 30.0, 43);
  for (auto& s : sb2) s.seq += sb.size();
  sb.insert(sb.end(), sb2.begin(), sb2.end());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::vector<bool>> rejected(2);
  rejected[0].assign(sa.size(), false);
  rejected[1].assign(sb.size(), false);
  for (std::size_t k = 100; k < sa.size(); k += 997) {  // corrupt timestamps from the parser
    sa[k].deviceTime = (k % 2) ? nan : std::numeric_limits<double>::infinity();
    rejected[0][k] = true;
  }
  const auto all = byArrival({sa, sb});
  TimeSync<std::uint64_t> sync({}, {ClockParams{}, ClockParams{}});
  Collected out;
  std::size_t nRejected = 0;
  double worstB = 0.0;
  std::vector<double> truthB(sb.size());
  for (const auto& s : sb) truthB[s.seq] = s.trueHost + b.floor;
  for (const auto& s : all) {
    const PushResult r = sync.push(s.device, s.deviceTime, s.arrival, s.seq, out);
    if (r == PushResult::Rejected) ++nRejected;
    sync.poll(s.arrival, out);
  }
  sync.flush(out);
  expectOrderedExactlyOnce(out.events, {sa.size(), sb.size()}, rejected);
  for (const auto& e : out.events)
    if (e.device == 1 && !e.late && e.deviceTime > 1.0 && e.t > 21.2)
      worstB = std::max(worstB, std::abs(e.t - truthB[e.payload]));
  EXPECT_EQ(nRejected, sync.stats(0).clock.rejectedNonFinite);
  EXPECT_GT(nRejected, 20u);
  EXPECT_EQ(sync.stats(0).clock.gaps, 1u);
  EXPECT_EQ(sync.stats(0).clock.jumps, 0u);
  EXPECT_EQ(sync.stats(1).clock.jumps, 1u);
  EXPECT_LT(worstB, 1e-3);
  EXPECT_LE(sync.counters(1).maxQueued, 100u);
}

// ---------------------------------------------------------------------------------------------
// Rows for the estimator

TEST(SequenceTracker, CountsLossesReorderingAndDuplicates) {
  SequenceTracker t;
  using S = SequenceStatus;
  EXPECT_EQ(t.add(100), S::InOrder);
  EXPECT_EQ(t.add(101), S::InOrder);
  EXPECT_EQ(t.add(104), S::InOrder);  // 102 and 103 missing
  EXPECT_EQ(t.missing(), 2u);
  EXPECT_EQ(t.add(103), S::Reordered);
  EXPECT_EQ(t.add(103), S::Duplicate);
  EXPECT_EQ(t.add(101), S::Duplicate);
  EXPECT_EQ(t.lost(), 1u);                  // 102
  EXPECT_EQ(t.add(104 + 200), S::InOrder);  // a long gap: 199 missing
  EXPECT_EQ(t.add(102), S::TooLate);        // long after it was counted lost
  EXPECT_EQ(t.missing(), 201u);
  EXPECT_EQ(t.reordered(), 1u);
  EXPECT_EQ(t.duplicates(), 2u);
  EXPECT_EQ(t.tooLate(), 1u);
  EXPECT_EQ(t.add(304 - 63), S::Reordered);  // the oldest still in the window
  t.restart();
  EXPECT_EQ(t.add(5), S::InOrder);  // a restarted counter is not a step back
  EXPECT_EQ(t.missing(), 201u);
}

TEST(TimeSyncAssembler, MergesCloseEventsIntoRows) {
  ArmSampleAssembler rows({StreamRole::UpperArmImu, StreamRole::ForearmImu, StreamRole::Optical});
  auto ev = [](int device, double t, SensorPayload p) {
    SensorEvent e;
    e.device = device;
    e.t = t;
    e.payload = std::move(p);
    return e;
  };
  ImuReading imu;
  imu.acc = Eigen::Vector3d(0, 0, 9.81);
  OpticalPositions opt;
  opt.wrist = Eigen::Vector3d(0.1, 0.2, 0.3);
  std::vector<ArmSample> got;
  auto take = [&](std::optional<ArmSample> r) {
    if (r) got.push_back(*r);
  };
  take(rows.add(ev(0, 1.0000, imu)));
  take(rows.add(ev(1, 1.0002, imu)));
  take(rows.add(ev(2, 1.0004, opt)));
  take(rows.add(ev(0, 1.0010, imu)));  // new row: too far from 1.0000
  take(rows.add(ev(0, 1.0011, imu)));  // new row: slot already filled
  take(rows.add(ev(2, 1.0012, imu)));  // wrong payload for an optical device
  take(rows.add(ev(1, 1.0013, imu)));
  take(rows.flush());
  ASSERT_EQ(got.size(), 3u);
  EXPECT_DOUBLE_EQ(got[0].t, 1.0);
  EXPECT_TRUE(got[0].upperArm && got[0].forearm && got[0].wrist && !got[0].elbow);
  EXPECT_TRUE(got[1].upperArm && !got[1].forearm);
  EXPECT_DOUBLE_EQ(got[2].t, 1.0011);
  EXPECT_TRUE(got[2].upperArm && got[2].forearm);
  EXPECT_EQ(rows.mismatched(), 1u);
}

}  // namespace
}  // namespace armtrack
