// Per-sample cost of the 6D orientation filter (core/orientation) on simulated IMU data.
// Run: build/tests/benchmarks/bench_orientation --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "core/orientation/OrientationFilter.h"

namespace armtrack {
namespace {

constexpr double kDt = 0.0035;         // s, BROAD's rate (286 Hz)
constexpr std::size_t kN = 20000;      // 70 s of samples, cycled through while timing
constexpr std::size_t kWarmUp = 2000;  // 7 s fed before timing: past every filter's warm-up

// Hand-held-like motion with noise, gyroscope bias and body acceleration.
struct ImuData {
  std::vector<double> gyr, acc, dt;
};

ImuData makeData() {
  ImuData d;
  d.gyr.resize(3 * kN);
  d.acc.resize(3 * kN);
  d.dt.assign(kN, kDt);
  std::mt19937 rng(1);
  std::normal_distribution<double> gyrNoise(0.0, 0.005), accNoise(0.0, 0.05);
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  for (std::size_t i = 0; i < kN; ++i) {
    const double t = static_cast<double>(i) * kDt;
    const Eigen::Vector3d w(0.8 * std::sin(1.3 * t), 0.6 * std::sin(0.7 * t + 1.0),
                            1.0 * std::cos(0.9 * t));
    q = (q * Eigen::Quaterniond(Eigen::AngleAxisd(w.norm() * kDt, w.normalized()))).normalized();
    const Eigen::Vector3d bodyAcc(0.5 * std::sin(3.0 * t), 0.3 * std::cos(2.0 * t), 0.0);
    const Eigen::Vector3d acc = q.conjugate() * (Eigen::Vector3d(0.0, 0.0, 9.81) + bodyAcc);
    for (int j = 0; j < 3; ++j) {
      d.gyr[3 * i + j] = w(j) + 0.01 + gyrNoise(rng);
      d.acc[3 * i + j] = acc(j) + accNoise(rng);
    }
  }
  return d;
}

const ImuData& data() {
  static const ImuData d = makeData();
  return d;
}

void update(benchmark::State& state, OrientationParams params) {
  const ImuData& d = data();
  OrientationFilter f(params);
  std::vector<Eigen::Vector3d> gyr(kN), acc(kN);
  for (std::size_t i = 0; i < kN; ++i) {
    gyr[i] = {d.gyr[3 * i], d.gyr[3 * i + 1], d.gyr[3 * i + 2]};
    acc[i] = {d.acc[3 * i], d.acc[3 * i + 1], d.acc[3 * i + 2]};
  }
  for (std::size_t i = 0; i < kWarmUp; ++i) f.update(gyr[i], acc[i], kDt);
  std::size_t i = kWarmUp;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f.update(gyr[i], acc[i], kDt));
    if (++i == kN) i = 0;  // the jump back in orientation is harmless
  }
  benchmark::DoNotOptimize(f.orientation());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

// One update() per iteration: bias estimation at rest and in motion (the defaults).
void BM_OrientationUpdate(benchmark::State& state) {
  update(state, {});
}
BENCHMARK(BM_OrientationUpdate);

// Without bias estimation: strapdown, low-pass and inclination correction only.
void BM_OrientationUpdateNoBias(benchmark::State& state) {
  OrientationParams p;
  p.restBiasEstEnabled = false;
  p.motionBiasEstEnabled = false;
  update(state, p);
}
BENCHMARK(BM_OrientationUpdateNoBias);

// updateBatch over the whole data set per iteration, writing every quaternion; time per sample
// is the reciprocal of items_per_second.
void BM_OrientationBatch(benchmark::State& state) {
  const ImuData& d = data();
  std::vector<double> out(4 * kN);
  OrientationFilter f;
  for (auto _ : state) {
    f.reset();
    benchmark::DoNotOptimize(f.updateBatch(d.gyr, d.acc, d.dt, out));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kN));
}
BENCHMARK(BM_OrientationBatch)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace armtrack
