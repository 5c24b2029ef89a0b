// Time of a whole sensor-to-segment calibration (core/calibration) on the simulated protocol:
// IMUs only, and IMUs with the Kinect. The calibration test checks accuracy only; how long the
// therapist waits for the result is measured here. Run build/tests/benchmarks/bench_calibration.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include "core/calibration/Calibrator.h"
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

}  // namespace
}  // namespace armtrack

BENCHMARK_MAIN();
