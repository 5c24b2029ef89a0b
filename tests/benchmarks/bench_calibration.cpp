// Time of a whole sensor-to-segment calibration (core/calibration) on the simulated protocol:
// IMUs only, and IMUs with the Kinect. The calibration test checks accuracy only; how long the
// therapist waits for the result is measured here. Run build/tests/benchmarks/bench_calibration.
// Also the live session's per-row cost of collecting rows for a calibration from movement.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include "core/calibration/Calibrator.h"
#include "core/session/LiveCalibration.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

Eigen::Matrix3d tilt(double xDeg, double zDeg) {
  const Eigen::Vector3d v(xDeg * kDeg, 0.0, zDeg * kDeg);
  return Eigen::AngleAxisd(v.norm(), v.normalized()).toRotationMatrix();
}

// The protocol as CalibrationAccuracy.RecoversKnownMounting* simulates it: the IMUs mounted off
// their nominal place and orientation, biased gyroscopes, the sidecar saying nominal; without the
// Kinect the segment lengths stay nominal (they are not observable then).
Recording protocol(bool kinect) {
  const CalibrationProtocolTrajectory traj;
  SimulationParams sim = defaultSimulation();
  sim.duration = traj.duration();
  sim.seed = kinect ? 11 : 12;
  sim.kinect.enabled = kinect;
  sim.geometry.lu3 = 0.14;
  sim.geometry.lu5 = 0.03;
  sim.geometry.thu4 = 105.0 * kDeg;
  sim.geometry.lf6 = 0.17;
  sim.geometry.lf8 = 0.015;
  sim.geometry.thf7 = 80.0 * kDeg;
  if (kinect) {
    sim.geometry.l3 = 0.23;
    sim.geometry.l6 = 0.19;
  }
  sim.upperArm.misalignment = tilt(6.0, -8.0);
  sim.forearm.misalignment = tilt(-7.0, 5.0);
  sim.upperArm.gyroBias = Eigen::Vector3d(0.5, -0.3, 0.4) * kDeg;
  sim.forearm.gyroBias = Eigen::Vector3d(-0.4, 0.5, 0.3) * kDeg;
  Recording rec = simulateRecording(traj, sim);
  rec.meta.geometry = ArmGeometry{};
  return rec;
}

void BM_CalibrateProtocol(benchmark::State& state) {
  const Recording rec = protocol(state.range(0) != 0);
  CalibrationResult r;
  for (auto _ : state) r = calibrate(rec);
  state.counters["iterations"] = static_cast<double>(r.iterations);
  state.counters["converged"] = r.converged ? 1.0 : 0.0;
}
BENCHMARK(BM_CalibrateProtocol)
    ->ArgName("kinect")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

// What a live session's worker spends per row on the calibration from movement while it
// collects (LiveCalibration::add, no fit running): two IMUs at 1 kHz and a 30 Hz Kinect, a
// minute of reaching with rests. Rows per second of CPU: items_per_second.
void BM_LiveCalibrationAdd(benchmark::State& state) {
  SimulationParams sim = defaultSimulation();
  sim.duration = 60.0;
  sim.seed = 13;
  const Recording rec = simulateRecording(SessionTrajectory(13, 2.0, 8.0, 60.0), sim);
  session::LiveCalibrationParams lp;
  lp.enabled = true;
  lp.firstSeconds = 1e9;  // collect only
  std::size_t rows = 0;
  for (auto _ : state) {
    session::LiveCalibration live(lp, rec.meta,
                                  [](const RecordingMeta&) { return EstimatorParams{}; });
    for (const ArmSample& row : rec.samples) live.add(row);
    benchmark::DoNotOptimize(live.atRest());
    rows += rec.samples.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(rows));
}
BENCHMARK(BM_LiveCalibrationAdd)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace armtrack

BENCHMARK_MAIN();
