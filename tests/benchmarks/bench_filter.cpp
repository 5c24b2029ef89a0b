// Per-sample cost of the estimators and of the measurement model, on simulated data.
// Run: build/tests/benchmarks/bench_filter --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <random>
#include <tuple>
#include <vector>

#include "core/estimation/ArmFilter.h"
#include "core/estimation/MeasurementJacobian.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

constexpr double kWarmUp = 1.5;  // s of data fed before timing: past the iterated start-up (1 s)
constexpr double kPool = 20.0;   // s of data cycled through while timing

// Five-joint motion with Table 5 noise; every sample carries both IMUs, and with kinect (webcam)
// every one also carries elbow and wrist positions (marker pixels): the optical sensors "run" at
// the IMU rate, so every timed step is a worst case.
// With trunk, the trunk leans and turns following the motion and a sternum IMU on the IMU clock
// is worn (issue 26): optical positions are then in the world frame.
Recording makeRecording(bool kinect, bool webcam = false, bool trunk = false) {
  const MultiJointTrajectory traj(1);
  SimulationParams sp = defaultSimulation();
  sp.trunk.enabled = trunk;
  sp.trunk.leanDeg = 20.0;
  sp.trunkImu.enabled = trunk;
  sp.trunkImu.rateHz = sp.upperArm.rateHz;
  sp.duration = kWarmUp + kPool;
  sp.kinect.enabled = kinect;
  sp.kinect.rateHz = sp.upperArm.rateHz;
  sp.webcam.enabled = webcam;
  sp.webcam.rateHz = sp.upperArm.rateHz;
  sp.includeTruth = false;
  return simulateRecording(traj, sp);
}

EstimatorParams params(FilterKind kind, MeasurementModel model) {
  EstimatorParams p;
  p.filter = kind;
  p.model = model;
  p.jointAccelVariance = std::pow(10.0 * kDeg, 2);
  return p;
}

// One benchmark's filter, warmed up on its recording's first kWarmUp seconds, and the next sample
// to time. Google Benchmark calls a benchmark's function several times (growing the iterations
// until the minimum time is reached); each call goes on where the last one stopped instead of
// simulating and warming up again: the warm-up (the iterated start-up) costs far more than the
// steps it precedes, and it was most of this program's run.
struct WarmFilter {
  Recording rec;
  std::unique_ptr<JointEstimator> filter;
  std::size_t first = 0;
  std::size_t next = 0;

  void warmUp() {
    filter->reset();
    for (std::size_t i = 0; i < first; ++i) filter->update(rec.samples[i]);
    next = first;
  }
};

WarmFilter& warmFilter(FilterKind kind, MeasurementModel model, bool kinect, bool webcam,
                       bool trunk) {
  static std::map<std::tuple<FilterKind, MeasurementModel, bool, bool, bool>, WarmFilter> cache;
  const auto key = std::make_tuple(kind, model, kinect, webcam, trunk);
  auto found = cache.find(key);
  if (found != cache.end()) return found->second;
  WarmFilter& w = cache[key];
  w.rec = makeRecording(kinect, webcam, trunk);
  EstimatorParams p = params(kind, model);
  p.camera = w.rec.meta.camera;
  p.trunk = w.rec.meta.trunk;
  w.filter = makeEstimator(p);
  while (w.rec.samples[w.first].t < kWarmUp) ++w.first;
  w.warmUp();
  return w;
}

// Times one update per iteration. When the pool runs out, the filter is reset and warmed up
// again outside the timed region, so timestamps keep increasing and no restart is ever timed.
void filterStep(benchmark::State& state, FilterKind kind, MeasurementModel model, bool kinect,
                bool webcam = false, bool trunk = false) {
  WarmFilter& w = warmFilter(kind, model, kinect, webcam, trunk);
  const std::vector<ArmSample>& samples = w.rec.samples;
  JointEstimator& filter = *w.filter;
  std::size_t i = w.next;
  for (auto _ : state) {
    benchmark::DoNotOptimize(filter.update(samples[i]));
    if (++i == samples.size()) {
      state.PauseTiming();
      w.warmUp();
      i = w.first;
      state.ResumeTiming();
    }
  }
  w.next = i;
  if (filter.counters().restarts != 0 || filter.counters().skippedUpdates != 0)
    state.SkipWithError("filter restarted or skipped updates");
}

void BM_EkfStep_TwoImusAndKinect(benchmark::State& state) {
  filterStep(state, FilterKind::Ekf, MeasurementModel::AccelGyro, true);
}
// Acceptance: under 1.5 x BM_EkfStep_TwoImusAndKinect.
void BM_EkfStep_TwoImusTrunkAndKinect(benchmark::State& state) {
  filterStep(state, FilterKind::Ekf, MeasurementModel::AccelGyro, true, false, true);
}
void BM_EkfStep_TwoImus(benchmark::State& state) {
  filterStep(state, FilterKind::Ekf, MeasurementModel::AccelGyro, false);
}
void BM_UkfStep_TwoImusAndKinect(benchmark::State& state) {
  filterStep(state, FilterKind::Ukf, MeasurementModel::AccelGyro, true);
}
void BM_EkfStep_TwoImusKinectAndWebcam(benchmark::State& state) {
  filterStep(state, FilterKind::Ekf, MeasurementModel::AccelGyro, true, true);
}
void BM_UkfStep_TwoImusKinectAndWebcam(benchmark::State& state) {
  filterStep(state, FilterKind::Ukf, MeasurementModel::AccelGyro, true, true);
}
void BM_EkfStep_MethodB(benchmark::State& state) {
  filterStep(state, FilterKind::Ekf, MeasurementModel::AugmentedBodyAccel, true);
}

// Random states (angles in [-pi, pi], rates to 3 rad/s, accelerations to 30 rad/s^2).
std::vector<Eigen::Matrix<double, 15, 1>> randomStates() {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Matrix<double, 15, 1>> xs(256);
  for (auto& x : xs)
    for (int j = 0; j < 5; ++j) {
      x(j) = 30.0 * u(rng);
      x(5 + j) = 3.0 * u(rng);
      x(10 + j) = 3.14159 * u(rng);
    }
  return xs;
}

void BM_MeasurementJacobian(benchmark::State& state) {
  const EstimatorParams p = params(FilterKind::Ekf, MeasurementModel::AccelGyro);
  const auto xs = randomStates();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(predictAllJacobian(p, xs[i]));
    i = (i + 1) % xs.size();
  }
}

// The same Jacobian differentiated by hand through the recursion (MeasurementJacobian.h).
void BM_MeasurementJacobianByHand(benchmark::State& state) {
  const EstimatorParams p = params(FilterKind::Ekf, MeasurementModel::AccelGyro);
  const auto xs = randomStates();
  ModelReadings h;
  ModelJacobian jac;
  std::size_t i = 0;
  for (auto _ : state) {
    predictReadings(p.geometry, p.gUp, true, xs[i], h, &jac);
    benchmark::DoNotOptimize(jac.data());
    benchmark::ClobberMemory();
    i = (i + 1) % xs.size();
  }
}

void BM_MeasurementPrediction(benchmark::State& state) {
  const EstimatorParams p = params(FilterKind::Ekf, MeasurementModel::AccelGyro);
  const auto xs = randomStates();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(predictAll(p, xs[i]));
    i = (i + 1) % xs.size();
  }
}

BENCHMARK(BM_EkfStep_TwoImusAndKinect)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EkfStep_TwoImusTrunkAndKinect)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EkfStep_TwoImus)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_UkfStep_TwoImusAndKinect)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EkfStep_TwoImusKinectAndWebcam)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_UkfStep_TwoImusKinectAndWebcam)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EkfStep_MethodB)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MeasurementJacobian)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MeasurementJacobianByHand)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MeasurementPrediction)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace armtrack
