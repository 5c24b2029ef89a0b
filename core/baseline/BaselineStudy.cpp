#include "core/baseline/BaselineStudy.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "core/estimation/RecordingEstimator.h"
#include "core/simulation/DoublePendulum.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {

namespace {

// Table 5's white noise: 0.1 (deg/s)^2 and 1e-2 (m/s^2)^2.
constexpr double kTable5GyroStd = 0.0055;  // rad/s
constexpr double kTable5AccelStd = 0.1;    // m/s^2

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

}  // namespace

Eigen::Vector3d pendulumElbowFromForearm(const ArmGeometry& geometry, double zeroOffset) {
  JointVector th = JointVector::Zero();
  const ArmPose model = forwardKinematics(geometry, th);
  th(3) += zeroOffset;
  const ArmPose onRod = forwardKinematics(geometry, th);
  return model.forearmImu.topLeftCorner<3, 3>().transpose() *
         (model.elbow - onRod.forearmImu.topRightCorner<3, 1>());
}

void AngleError::add(double error) {
  if (!std::isfinite(error)) return;
  ++count;
  sumSq += error * error;
  peak = std::max(peak, std::abs(error));
}

double AngleError::rmseDeg() const {
  return count ? std::sqrt(sumSq / static_cast<double>(count)) / kDeg : 0.0;
}

double AngleError::peakDeg() const {
  return peak / kDeg;
}

void JointErrors::add(const JointVector& truth, double flexion, double pron, double elevation,
                      const Eigen::Vector3d& up) {
  if (std::isfinite(flexion)) hinge.add(wrapAngle(flexion - truth(3)));
  if (std::isfinite(pron)) pronation.add(wrapAngle(pron - truth(4)));
  if (std::isfinite(elevation)) swing.add(elevation - humerusElevation(truth, up));
}

BaselineParams baselineParamsFor(const RecordingMeta& meta) {
  BaselineParams p;
  p.geometry = meta.geometry;
  p.gUp = meta.gUp();
  p.side = meta.side;
  return p;
}

BaselineRun runBaseline(const Recording& recording, const BaselineParams& params,
                        const BaselineSink& sink) {
  JointBaseline baseline(params);
  BaselineRun run;
  BaselineRow row;
  const Eigen::Vector3d up = recording.meta.up;
  double settledFrom = 0.0;
  for (const ArmSample& s : recording.samples) {
    if (!baseline.push(s, row)) continue;
    if (sink) sink(row);
    if (row.restarted) settledFrom = row.t + kStartupSeconds;
    if (s.trueAngles && row.t >= settledFrom)
      run.errors.add(*s.trueAngles, row.flexion, row.pronation, row.elevation, up);
  }
  run.counters = baseline.counters();
  return run;
}

JointErrors runDhFilter(const Recording& recording, bool freeElbow) {
  EstimateOptions options;
  options.useOptical = false;
  options.useCamera = false;
  EstimatorParams params = estimatorParamsFor(recording.meta, options);
  if (freeElbow) {
    params.jointLower(3) = -kInf;
    params.jointUpper(3) = kInf;
  }
  // The rows come in the order of the samples with IMU data; the truth is looked up by time.
  std::size_t next = 0;
  double settledFrom = 0.0;
  bool first = true;
  JointErrors errors;
  EstimateCallbacks callbacks;
  callbacks.row = [&](const EstimateRow& r) {
    while (next < recording.samples.size() && recording.samples[next].t < r.t) ++next;
    if (first || r.status == kStatusRestarted || r.status == kStatusRecovered)
      settledFrom = r.t + kStartupSeconds;
    first = false;
    if (next >= recording.samples.size() || recording.samples[next].t != r.t) return;
    const ArmSample& s = recording.samples[next];
    if (!s.trueAngles || r.t < settledFrom) return;
    errors.add(*s.trueAngles, r.th(3), r.th(4), humerusElevation(r.th, recording.meta.up),
               recording.meta.up);
  };
  estimateRecording(recording, params, callbacks);
  return errors;
}

std::vector<BaselineStudyRow> runBaselineStudy(const BaselineStudySetup& setup,
                                               const BaselineStudyProgress& progress) {
  struct Case {
    std::string name;
    double outputHz, gyroHz, accelHz, gyroNoise, accelNoise;
  };
  // The held case has Table 5's noise: noise-free readings that repeat through the still start
  // are taken for a stuck sensor by the DH filter's gate (after 50 rows), which then restarts at
  // the release.
  const std::vector<Case> sensorCases = {
      {"ideal, 1 kHz", 1000.0, 0.0, 0.0, 0.0, 0.0},
      {"50/25 Hz held on 90 Hz, Table 5 noise", 90.0, 50.0, 25.0, kTable5GyroStd, kTable5AccelStd}};
  struct Release {
    std::string name;
    double swingDeg, hingeDeg;
  };
  // A lively release (the hinge beyond +-80 deg, the swing beyond 90) and a gentle one.
  const std::vector<Release> releases = {{"pendulum 80/70", 80.0, 70.0},
                                         {"pendulum 20/-20", 20.0, -20.0}};
  const int total = static_cast<int>(releases.size() * sensorCases.size() * setup.zerosDeg.size()) +
                    std::max(0, setup.reachingRuns);
  int done = 0;
  std::vector<BaselineStudyRow> rows;
  for (const Release& release : releases) {
    for (const Case& c : sensorCases) {
      const std::string name = release.name + ", " + c.name;
      for (double zero : setup.zerosDeg) {
        PendulumSimParams sim;
        sim.duration = setup.pendulumSeconds;
        sim.outputRateHz = c.outputHz;
        sim.gyroRateHz = c.gyroHz;
        sim.accelRateHz = c.accelHz;
        sim.gyroNoiseStd = c.gyroNoise;
        sim.accelNoiseStd = c.accelNoise;
        sim.zeroOffset = zero * kDeg;
        sim.pendulum.swing0 = release.swingDeg * kDeg;
        sim.pendulum.hinge0 = release.hingeDeg * kDeg;
        // Both methods told where the forearm IMU sits on the rod (the sidecar's mounting, as a
        // mounting tool that measured it writes): the zero then only relabels the hinge.
        sim.mountingOnRod = true;
        const Recording rec = simulatePendulum(sim);
        const std::size_t first = rows.size();
        // The filter is told the hinge's range (a rig, not an elbow: it bends both ways through
        // straight), as it is told the rod's lever arm.
        rows.push_back({name, zero, "DH filter", runDhFilter(rec, /*freeElbow=*/true)});
        rows.push_back(
            {name, zero, "baseline", runBaseline(rec, baselineParamsFor(rec.meta)).errors});
        if (zero != 0.0) {
          // The model's default mounting instead, whose lever arm the zero turns off the rod:
          // both methods equally wrong about where the sensor is.
          sim.mountingOnRod = false;
          const Recording off = simulatePendulum(sim);
          rows.push_back(
              {name, zero, "DH filter, model's mounting", runDhFilter(off, /*freeElbow=*/true)});
          rows.push_back({name, zero, "baseline, model's mounting",
                          runBaseline(off, baselineParamsFor(off.meta)).errors});
        }
        double lo = kInf, hi = -kInf;
        for (const ArmSample& smp : rec.samples) {
          lo = std::min(lo, smp.trueAngles->coeff(3));
          hi = std::max(hi, smp.trueAngles->coeff(3));
        }
        for (std::size_t i = first; i < rows.size(); ++i) {
          rows[i].trueHingeMinDeg = lo / kDeg;
          rows[i].trueHingeMaxDeg = hi / kDeg;
        }
        if (progress) progress(++done, total);
      }
    }
  }
  if (setup.reachingRuns > 0) {
    BaselineStudyRow dh{"reaching, Table 5, IMUs only", std::nan(""), "DH filter", {}};
    BaselineStudyRow base{dh.recording, dh.zeroDeg, "baseline", {}};
    const auto pool = [](JointErrors& into, const JointErrors& from) {
      for (auto [a, b] :
           {std::pair{&into.hinge, &from.hinge}, std::pair{&into.pronation, &from.pronation},
            std::pair{&into.swing, &from.swing}}) {
        a->count += b->count;
        a->sumSq += b->sumSq;
        a->peak = std::max(a->peak, b->peak);
      }
    };
    for (int seed = 1; seed <= setup.reachingRuns; ++seed) {
      SimulationParams sim = defaultSimulation();
      sim.duration = setup.reachingSeconds;
      sim.seed = static_cast<std::uint64_t>(seed);
      sim.kinect.enabled = false;
      TrajectoryOptions traj;
      traj.seed = sim.seed;
      traj.duration = sim.duration;
      const auto trajectory = makeTrajectory("reaching", traj);
      const Recording rec = simulateRecording(*trajectory, sim);
      pool(dh.errors, runDhFilter(rec));
      pool(base.errors, runBaseline(rec, baselineParamsFor(rec.meta)).errors);
      if (progress) progress(++done, total);
    }
    rows.push_back(dh);
    rows.push_back(base);
  }
  return rows;
}

std::string formatBaselineStudy(const std::vector<BaselineStudyRow>& rows,
                                const BaselineStudySetup& setup) {
  std::string s =
      "The DH filter (EKF, default settings, IMUs only) and the complementary baseline on the same "
      "recordings: pendulum " +
      fixed(setup.pendulumSeconds, 0) + " s, reaching " + std::to_string(setup.reachingRuns) +
      " x " + fixed(setup.reachingSeconds, 0) +
      " s; the first second after a (re)start left out. Hinge = th4, swing = the humerus' "
      "elevation from the downward vertical; zero = the model's elbow flexion at the pendulum's "
      "straight hinge; pendulum A/B = released from the swing A and the hinge B (deg), held "
      "still 1 s first. Both methods are told where the forearm IMU sits on the rod, except in "
      "the rows \"model's mounting\". Errors in deg.\n\n"
      "| recording | zero (deg) | true th4 (deg) | method | hinge RMSE | hinge peak | pronation "
      "RMSE "
      "| pronation peak | swing RMSE | swing peak |\n"
      "|---|---:|---|---|---:|---:|---:|---:|---:|---:|\n";
  for (const BaselineStudyRow& r : rows) {
    const bool pendulum = !std::isnan(r.zeroDeg);
    s += "| " + r.recording + " | " + (pendulum ? fixed(r.zeroDeg, 0) : "-") + " | " +
         (pendulum ? fixed(r.trueHingeMinDeg, 0) + ".." + fixed(r.trueHingeMaxDeg, 0) : "-") +
         " | " + r.method;
    for (const AngleError* e : {&r.errors.hinge, &r.errors.pronation, &r.errors.swing})
      s += " | " + (e->count ? fixed(e->rmseDeg(), 2) + " | " + fixed(e->peakDeg(), 2)
                             : std::string("- | -"));
    s += " |\n";
  }
  return s;
}

}  // namespace armtrack
