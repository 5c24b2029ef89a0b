#include "core/studies/Studies.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <numbers>
#include <thread>

#include "core/metrics/Accuracy.h"
#include "core/simulation/SensorSimulator.h"

namespace armtrack {
namespace {

constexpr double kStartupSeconds = 1.0;  // errors count after the filter's start-up

struct RunError {
  double rmse = 0.0;  // deg, th0
  double peak = 0.0;  // deg, th0
};

struct SegmentCase {
  ArmGeometry geometry;
  double frequencyHz;
  MeasurementModel model;
  FilterKind filter;
  std::uint64_t seed;
};

// One run of the paper's one-segment simulation: th0 sinusoid, upper-arm IMU only, Table 5
// noise on the sensors and Table 5 values in the filter, only th0 estimated.
RunError runSegment(const SegmentCase& c, const StudySetup& setup) {
  SinusoidTrajectory traj;
  traj.amplitude(0) = setup.amplitudeDeg * kDeg;
  traj.frequency(0) = c.frequencyHz;
  // th0 = A sin(2 pi f t): every run starts at the zero pose at full speed, as the paper's
  // sinusoid does. Method B is sensitive to the start phase (docs/estimator.md); A is not.
  traj.phase(0) = 0.0;

  SimulationParams sim = defaultSimulation();
  sim.duration = setup.duration;
  sim.geometry = c.geometry;
  sim.forearm.enabled = false;
  sim.kinect.enabled = false;
  sim.seed = c.seed;
  const Recording rec = simulateRecording(traj, sim);

  EstimatorParams p;
  p.filter = c.filter;
  p.model = c.model;
  p.geometry = c.geometry;
  p.gUp = sim.g * sim.up;
  p.activeJoints = {true, false, false, false, false};
  auto filter = makeEstimator(p);
  ErrorAccumulator acc;
  for (const ArmSample& s : rec.samples) {
    filter->update(s);
    if (s.trueAngles && s.t >= kStartupSeconds) acc.add(filter->estimate().th, *s.trueAngles);
  }
  return {acc.rmse()(0) / kDeg, acc.peak()(0) / kDeg};
}

Stat stat(const std::vector<double>& v) {
  Stat s;
  if (v.empty()) return s;
  for (double x : v) s.mean += x;
  s.mean /= static_cast<double>(v.size());
  if (v.size() > 1) {
    double ss = 0.0;
    for (double x : v) ss += (x - s.mean) * (x - s.mean);
    s.std = std::sqrt(ss / static_cast<double>(v.size() - 1));
  }
  return s;
}

// Runs every case on all cores; results keep the cases' order, so output is deterministic.
std::vector<RunError> runAll(const std::vector<SegmentCase>& cases, const StudySetup& setup,
                             const StudyProgress& progress) {
  std::vector<RunError> out(cases.size());
  std::atomic<std::size_t> next{0};
  std::atomic<int> done{0};
  std::mutex progressMutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < cases.size(); i = next++) {
      out[i] = runSegment(cases[i], setup);
      const int d = ++done;
      if (progress) {
        std::lock_guard lock(progressMutex);
        progress(d, static_cast<int>(cases.size()));
      }
    }
  };
  const unsigned n = std::max(1u, std::min(std::thread::hardware_concurrency(), 8u));
  std::vector<std::thread> threads;
  for (unsigned i = 1; i < n; ++i) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  return out;
}

std::string fmt(const char* f, double a, double b) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, a, b);
  return buf;
}

std::string filterName(FilterKind f) {
  return f == FilterKind::Ekf ? "EKF" : "UKF";
}

}  // namespace

std::vector<Table6Row> runTable6(const StudySetup& setup, const StudyProgress& progress) {
  // Section 3.3: the IMU sits near the elbow, 20 cm down the 22 cm upper arm.
  ArmGeometry geo;
  geo.lu3 = 0.20;
  const std::array<MeasurementModel, 3> methods{MeasurementModel::AccelGyro,
                                                MeasurementModel::AugmentedBodyAccel,
                                                MeasurementModel::InclinometerGyro};
  std::vector<SegmentCase> cases;
  for (MeasurementModel m : methods)
    for (int r = 0; r < setup.runs; ++r)
      cases.push_back({geo, 1.0, m, setup.filter, static_cast<std::uint64_t>(r + 1)});
  const std::vector<RunError> err = runAll(cases, setup, progress);

  // The paper's Table 6 (deg): RMSE mean, std; peak mean, std.
  const std::array<std::array<double, 4>, 3> paper{
      {{0.20, 0.02, 0.35, 0.02}, {2.51, 0.51, 8.48, 0.74}, {7.39, 0.23, 13.43, 0.62}}};
  std::vector<Table6Row> rows;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    std::vector<double> rmse, peak;
    for (int r = 0; r < setup.runs; ++r) {
      rmse.push_back(err[m * setup.runs + r].rmse);
      peak.push_back(err[m * setup.runs + r].peak);
    }
    rows.push_back(
        {methods[m], stat(rmse), stat(peak), paper[m][0], paper[m][1], paper[m][2], paper[m][3]});
  }
  return rows;
}

std::string formatTable6(const std::vector<Table6Row>& rows, const StudySetup& setup) {
  std::string s =
      "Table 6: body-acceleration compensation, th0 = " +
      fmt("%.0f deg sin(2 pi 1 Hz t), %.0f s runs", setup.amplitudeDeg, setup.duration) + ", " +
      std::to_string(setup.runs) + " runs, " + filterName(setup.filter) +
      ", Table 5 noise, first second skipped\n\n";
  s += "| Method | RMSE mean (deg) | RMSE std | PE mean (deg) | PE std | Paper RMSE | Paper PE |\n";
  s += "|---|---|---|---|---|---|---|\n";
  for (const Table6Row& r : rows) {
    s += "| " + methodName(r.method) + " | " + fmt("%.3f | %.3f", r.rmse.mean, r.rmse.std) + " | " +
         fmt("%.3f | %.3f", r.peak.mean, r.peak.std) + " | " +
         fmt("%.2f +/- %.2f", r.paperRmse, r.paperRmseStd) + " | " +
         fmt("%.2f +/- %.2f", r.paperPeak, r.paperPeakStd) + " |\n";
  }
  return s;
}

std::vector<Fig5Point> runFig5(const StudySetup& setup, const StudyProgress& progress) {
  // Section 3.1: the IMU at the shoulder's centre of rotation, so there is no body acceleration.
  ArmGeometry geo;
  geo.lu3 = 0.0;
  geo.lu5 = 0.0;
  const std::array<MeasurementModel, 3> models{MeasurementModel::Inclinometer,
                                               MeasurementModel::InclinometerGyro,
                                               MeasurementModel::AccelGyro};
  const std::array<FilterKind, 2> filters{FilterKind::Ekf, FilterKind::Ukf};
  std::vector<double> freqs;
  for (int i = 0; i <= 10; ++i) freqs.push_back(0.25 * i);

  std::vector<SegmentCase> cases;
  for (double f : freqs)
    for (MeasurementModel m : models)
      for (FilterKind k : filters)
        for (int r = 0; r < setup.runs; ++r)
          cases.push_back({geo, f, m, k, static_cast<std::uint64_t>(r + 1)});
  const std::vector<RunError> err = runAll(cases, setup, progress);

  std::vector<Fig5Point> points;
  std::size_t i = 0;
  for (double f : freqs)
    for (MeasurementModel m : models)
      for (FilterKind k : filters) {
        std::vector<double> rmse;
        for (int r = 0; r < setup.runs; ++r) rmse.push_back(err[i++].rmse);
        points.push_back({f, m, k, stat(rmse)});
      }
  return points;
}

std::string formatFig5(const std::vector<Fig5Point>& points, const StudySetup& setup) {
  std::string s = "Fig. 5: th0 RMSE (deg, mean over " + std::to_string(setup.runs) +
                  " runs) against motion frequency, IMU at the shoulder's centre of rotation, " +
                  fmt("%.0f deg amplitude, %.0f s runs", setup.amplitudeDeg, setup.duration) +
                  ", Table 5 noise\n\n";
  s += "| f (Hz) | Inclinometer EKF | Inclinometer UKF | Incl./gyro EKF | Incl./gyro UKF | "
       "Acc./gyro EKF | Acc./gyro UKF |\n";
  s += "|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < points.size(); i += 6) {
    char head[32];
    std::snprintf(head, sizeof head, "| %.2f |", points[i].frequencyHz);
    s += head;
    for (std::size_t k = i; k < i + 6 && k < points.size(); ++k) {
      char cell[32];
      std::snprintf(cell, sizeof cell, " %.3f |", points[k].rmse.mean);
      s += cell;
    }
    s += "\n";
  }
  return s;
}

}  // namespace armtrack
