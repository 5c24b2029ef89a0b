// Per-sample cost of the time synchroniser: two 1 kHz streams with exponential delays, each sample
// pushed and polled. Run build/tests/benchmarks/bench_time_sync.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <vector>

#include "core/sync/TimeSync.h"

namespace {

void BM_TimeSyncPushPoll(benchmark::State& state) {
  constexpr int kSamples = 20000;
  std::mt19937_64 rng(1);
  std::exponential_distribution<double> delay(1000.0);
  std::vector<double> arrival(2 * kSamples);
  for (int k = 0; k < 2 * kSamples; ++k) arrival[k] = (k / 2) * 1e-3 + 0.002 + delay(rng);
  for (auto _ : state) {
    armtrack::TimeSync<std::uint32_t> sync({}, {armtrack::ClockParams{}, armtrack::ClockParams{}});
    std::uint64_t n = 0;
    auto sink = [&n](const armtrack::SyncEvent<std::uint32_t>&) { ++n; };
    for (int k = 0; k < 2 * kSamples; ++k) {
      const int dev = k % 2;
      sync.push(dev, (k / 2) * 1e-3 * (1.0 + 80e-6 * dev), arrival[k], k, sink);
      sync.poll(arrival[k], sink);
    }
    sync.flush(sink);
    benchmark::DoNotOptimize(n);
  }
  state.SetItemsProcessed(state.iterations() * 2 * kSamples);
}
BENCHMARK(BM_TimeSyncPushPoll)->Unit(benchmark::kMillisecond);

}  // namespace
