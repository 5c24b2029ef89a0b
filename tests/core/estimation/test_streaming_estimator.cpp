// StreamingEstimator: statistics summed as the samples go (with only the last 10 s of error
// samples held) equal the definitions in RecordingEstimator.h, computed here from the output rows
// and the true angles; stats() mid-stream equals a run over the samples so far.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/estimation/RecordingEstimator.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

// IMUs only (so the report has drift windows), 250 Hz to keep the test short.
Recording imuOnly(double duration) {
  const MultiJointTrajectory traj(2);
  SimulationParams sp = defaultSimulation();
  sp.duration = duration;
  sp.upperArm.rateHz = sp.forearm.rateHz = 250.0;
  sp.kinect.enabled = false;
  return simulateRecording(traj, sp);
}

EstimatorParams paramsFor(const Recording& rec) {
  EstimateOptions o;
  o.jointAccelStdDeg = 10.0;
  return estimatorParamsFor(rec.meta, o);
}

struct StreamRun {
  std::vector<EstimateRow> rows;
  std::vector<JointVector> truth;  // of each row's sample
  EstimateStats stats;
};

StreamRun stream(const std::vector<ArmSample>& samples, const EstimatorParams& p) {
  StreamRun run;
  StreamingEstimator est(p);
  EstimateRow row;
  for (const ArmSample& s : samples) {
    if (!est.push(s, row)) continue;
    run.rows.push_back(row);
    run.truth.push_back(*s.trueAngles);
  }
  run.stats = est.stats();
  return run;
}

// RMSE (deg) and count over the rows whose time passes inWindow, leaving out the second after
// each (re)start: the definition of EstimateStats, from scratch.
struct Window {
  std::size_t count = 0;
  JointVector rmseDeg = JointVector::Zero();
};
template <typename In>
Window windowOf(const StreamRun& run, In inWindow) {
  Window w;
  JointVector sum = JointVector::Zero();
  double tStart = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const EstimateRow& r = run.rows[i];
    if (r.status == kStatusRestarted) tStart = r.t;
    if (r.t < tStart + kStartupSeconds || !inWindow(r.t)) continue;
    ++w.count;
    for (int j = 0; j < kNumJoints; ++j) {
      const double e = wrapAngle(r.th(j) - run.truth[i](j));
      sum(j) += e * e;
    }
  }
  if (w.count > 0) w.rmseDeg = (sum / static_cast<double>(w.count)).cwiseSqrt() / kDeg;
  return w;
}

void expectWindow(const WindowError& got, const Window& want, const char* which) {
  EXPECT_EQ(got.count, want.count) << which;
  for (int j = 0; j < kNumJoints; ++j)
    EXPECT_NEAR(got.rmseDeg(j), want.rmseDeg(j), 1e-9) << which << " joint " << j;
}

// The windows of a run whose last IMU sample is at tEnd.
void expectWindows(const StreamRun& run, double tEnd) {
  const EstimateStats& st = run.stats;
  const double tFirst = run.rows.front().t;
  EXPECT_EQ(st.tFirst, tFirst);
  EXPECT_EQ(st.firstWindow.from, std::min(tFirst + 1.0, tEnd));
  EXPECT_EQ(st.firstWindow.to, std::min(st.firstWindow.from + 10.0, tEnd));
  EXPECT_EQ(st.lastWindow.to, tEnd);
  EXPECT_EQ(st.lastWindow.from, std::max(tEnd - 10.0, st.firstWindow.to));
  const WindowError f = st.firstWindow, l = st.lastWindow;
  expectWindow(f, windowOf(run, [&](double t) { return t >= f.from && t <= f.to; }), "first");
  expectWindow(l, windowOf(run, [&](double t) { return t > l.from && t <= l.to; }), "last");
  expectWindow(WindowError{0, 0, st.truthCount, st.rmseDeg},
               windowOf(run, [](double) { return true; }), "all");
}

TEST(StreamingEstimator, DriftWindowsFollowTheirDefinition) {
  for (const double duration : {25.0, 14.0, 6.0}) {  // apart, overlapping, the last one empty
    SCOPED_TRACE(duration);
    const Recording rec = imuOnly(duration);
    const StreamRun run = stream(rec.samples, paramsFor(rec));
    ASSERT_GT(run.rows.size(), 100u);
    EXPECT_GT(run.stats.firstWindow.count, 0u);
    if (duration > 21.0) {
      EXPECT_GT(run.stats.lastWindow.count, 2000u);
    }
    if (duration < 11.0) {
      EXPECT_EQ(run.stats.lastWindow.count, 0u);
    }
    expectWindows(run, rec.samples.back().t);
  }
}

// The last IMU rows get no estimate (every reading refused for longer than the filter coasts):
// the windows still end at the last IMU row, and the estimates of the last 10 s before it count.
TEST(StreamingEstimator, WindowsEndAtTheLastImuRowEvenWithoutItsEstimate) {
  Recording rec = imuOnly(24.0);
  const double tCut = 21.5;
  for (ArmSample& s : rec.samples) {
    if (s.t < tCut || !s.hasImu()) continue;
    if (s.upperArm) s.upperArm->acc.setZero();  // "all zero": refused
    if (s.forearm) s.forearm->acc.setZero();
  }
  const StreamRun run = stream(rec.samples, paramsFor(rec));
  ASSERT_LT(run.stats.tLast, rec.samples.back().t - 1.0) << "the tail should get no estimate";
  EXPECT_LT(run.stats.estimates, run.stats.imuRows);
  expectWindows(run, rec.samples.back().t);
  EXPECT_GT(run.stats.lastWindow.count, 1000u);
}

// stats() may be asked at any time: it equals a run over the samples pushed so far, and pushing
// on afterwards is unaffected (the rows equal those of one run over everything).
TEST(StreamingEstimator, StatsMidStreamEqualARunOverThePrefix) {
  const Recording rec = imuOnly(16.0);
  const EstimatorParams p = paramsFor(rec);
  const std::size_t half = rec.samples.size() * 6 / 10;
  Recording prefix = rec;
  prefix.samples.resize(half);
  const EstimateStats want = estimateRecording(prefix, p);

  StreamingEstimator est(p);
  EstimateRow row;
  std::vector<EstimateRow> rows;
  for (std::size_t i = 0; i < rec.samples.size(); ++i) {
    if (i == half) {
      const EstimateStats got = est.stats();
      EXPECT_EQ(got.rows, want.rows);
      EXPECT_EQ(got.estimates, want.estimates);
      EXPECT_EQ(got.truthCount, want.truthCount);
      EXPECT_EQ(got.tLast, want.tLast);
      EXPECT_EQ(got.lastWindow.count, want.lastWindow.count);
      EXPECT_EQ(got.lastWindow.from, want.lastWindow.from);
      for (int j = 0; j < kNumJoints; ++j) {
        EXPECT_EQ(got.rmseDeg(j), want.rmseDeg(j));
        EXPECT_EQ(got.firstWindow.rmseDeg(j), want.firstWindow.rmseDeg(j));
        EXPECT_EQ(got.lastWindow.rmseDeg(j), want.lastWindow.rmseDeg(j));
      }
    }
    if (est.push(rec.samples[i], row)) rows.push_back(row);
  }
  std::vector<EstimateRow> whole;
  EstimateCallbacks cb;
  cb.row = [&](const EstimateRow& r) { whole.push_back(r); };
  estimateRecording(rec, p, cb);
  ASSERT_EQ(rows.size(), whole.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].t, whole[i].t);
    ASSERT_EQ(rows[i].status, whole[i].status);
    for (int j = 0; j < kNumJoints; ++j) {
      ASSERT_EQ(rows[i].th(j), whole[i].th(j)) << i;
      ASSERT_EQ(rows[i].sd(j), whole[i].sd(j)) << i;
    }
  }
}

// Rows without IMU data (optics alone) give no output row but count as rows; a sample before the
// previous one is refused and counted.
TEST(StreamingEstimator, CountsRowsItGivesNoEstimateFor) {
  const Recording rec = imuOnly(3.0);
  StreamingEstimator est(paramsFor(rec));
  EstimateRow row;
  std::size_t out = 0;
  for (const ArmSample& s : rec.samples) out += est.push(s, row);
  ArmSample optical;
  optical.t = rec.samples.back().t + 0.001;
  optical.elbow = Eigen::Vector3d(0.22, 0.0, 0.0);
  EXPECT_FALSE(est.push(optical, row));
  ArmSample late = rec.samples[rec.samples.size() / 2];  // earlier than the last one
  EXPECT_FALSE(est.push(late, row));
  const EstimateStats st = est.stats();
  EXPECT_EQ(st.rows, rec.samples.size() + 2);
  EXPECT_EQ(st.imuRows, rec.samples.size() + 1);
  EXPECT_EQ(st.estimates, out);
  EXPECT_EQ(st.counters.rejectedTime, 1u);
}

}  // namespace
}  // namespace armtrack
