// Default settings on movement the tuning never saw (issue 9, acceptance 1 and 3), against
// simulated truth with Table 5 IMU noise:
// - fast, smooth five-joint reaching at 420 and 600 deg/s (4,000 and 8,160 deg/s^2 on the joint
//   that moves most), two IMUs at 500 Hz with a Kinect (30 Hz) or a webcam (30 Hz, 1 px): every
//   joint under 1 deg RMSE from the first second;
// - honest uncertainty: on five-joint movement with IMUs only, IMUs + Kinect and IMUs + webcam,
//   the share of estimates whose error lies inside two reported standard deviations, pooled
//   over seeds and noise draws: between 90 % and 99 % for every joint with IMUs only, with a
//   Kinect and with a webcam, and on the fast reaching above pooled over ten movements; and the
//   heading's assumed random walk against the one the filter makes without optics.
// The defaults were chosen on reaching seeds 11-12 and multi-joint seeds 1-3; these use others.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "core/estimation/ArmFilter.h"
#include "core/estimation/Heading.h"
#include "core/metrics/Accuracy.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

enum class Optics { None, Kinect, Webcam };

const char* opticsName(Optics o) {
  return o == Optics::Kinect ? "Kinect" : o == Optics::Webcam ? "webcam" : "IMUs only";
}

SimulationParams simulation(double duration, std::uint64_t seed, double imuRate, Optics optics) {
  SimulationParams sp = defaultSimulation();
  sp.duration = duration;
  sp.seed = seed;
  sp.upperArm.rateHz = sp.forearm.rateHz = imuRate;
  sp.kinect.enabled = optics == Optics::Kinect;
  sp.webcam.enabled = optics == Optics::Webcam;
  return sp;
}

struct Tally {
  ErrorAccumulator errors;
  JointVector inside = JointVector::Zero();  // estimates within two reported sd
  double count = 0;
  std::size_t imuRows = 0, estimated = 0;

  JointVector coverage() const { return inside / std::max(count, 1.0); }
};

// Runs the default filter over rec, tallying estimates from `from` seconds on. A non-zero
// headingTurn turns the true arm about the vertical by that angle (rad) before comparing: the
// IMUs read the same for the turned arm, so without optics it is an equally true arm.
void run(const Recording& rec, FilterKind kind, double from, Tally& tally, double headingTurn = 0) {
  EstimatorParams p = recordingParams(rec.meta);
  p.filter = kind;
  const Eigen::Vector3d up = p.gUp.normalized();
  auto f = makeEstimator(p);
  for (const ArmSample& s : rec.samples) {
    const UpdateResult r = f->update(s);
    if (s.hasImu()) {
      ++tally.imuRows;
      if (hasEstimate(r)) ++tally.estimated;
    }
    if (!s.trueAngles || s.t < from || !f->initialised()) continue;
    const JointEstimate e = f->estimate();
    const JointVector truth =
        headingTurn != 0.0 ? turnAboutVertical(*s.trueAngles, headingTurn, up) : *s.trueAngles;
    tally.errors.add(e.th, truth);
    for (int j = 0; j < kNumJoints; ++j)
      if (std::abs(wrapAngle(e.th(j) - truth(j))) <= 2.0 * e.thStd(j)) tally.inside(j) += 1;
    tally.count += 1;
  }
}

std::string row(const JointVector& v, double scale = 1.0) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3f %.3f %.3f %.3f %.3f", v(0) * scale, v(1) * scale,
                v(2) * scale, v(3) * scale, v(4) * scale);
  return buf;
}

struct ReachCase {
  FilterKind kind;
  Optics optics;
  double peakRateDeg;
};

// Both reaching tests run these: the EKF with each optical sensor at 420 and 600 deg/s, the UKF
// at 600.
const ReachCase kReachCases[] = {
    {FilterKind::Ekf, Optics::Kinect, 420.0}, {FilterKind::Ekf, Optics::Kinect, 600.0},
    {FilterKind::Ekf, Optics::Webcam, 420.0}, {FilterKind::Ekf, Optics::Webcam, 600.0},
    {FilterKind::Ukf, Optics::Kinect, 600.0}, {FilterKind::Ukf, Optics::Webcam, 600.0}};

// 20 s of reaching at the case's peak rate, IMUs at 500 Hz and the case's optical sensor. Minimum
// jerk's peak acceleration scales with the square of its peak rate at fixed amplitude.
Recording reachingRecording(const ReachCase& c, std::uint64_t seed) {
  const double scale = c.peakRateDeg / 420.0;
  const ReachingTrajectory traj(seed, c.peakRateDeg * kDeg, 4000.0 * scale * scale * kDeg, 20.0);
  return simulateRecording(traj, simulation(20.0, seed, 500.0, c.optics));
}

std::string reachCaseName(const testing::TestParamInfo<ReachCase>& i) {
  return std::string(i.param.kind == FilterKind::Ekf ? "Ekf" : "Ukf") +
         (i.param.optics == Optics::Kinect ? "Kinect" : "Webcam") +
         std::to_string(static_cast<int>(i.param.peakRateDeg));
}

class FastReaching : public testing::TestWithParam<ReachCase> {};

TEST_P(FastReaching, EveryJointWithinOneDegree) {
  const ReachCase c = GetParam();
  for (std::uint64_t seed : {21u, 22u}) {
    const Recording rec = reachingRecording(c, seed);
    Tally t;
    run(rec, c.kind, 1.0, t);
    const JointVector rmse = t.errors.rmse() / kDeg;
    std::printf(
        "[ measured ] %s reaching %.0f deg/s, %s, seed %lu: RMSE (deg) %s, peak %.2f, inside 2 "
        "sd (%%) %s\n",
        c.kind == FilterKind::Ekf ? "EKF" : "UKF", c.peakRateDeg, opticsName(c.optics),
        static_cast<unsigned long>(seed), row(rmse).c_str(), t.errors.peak().maxCoeff() / kDeg,
        row(t.coverage(), 100.0).c_str());
    EXPECT_EQ(t.estimated, t.imuRows) << "every IMU row gets an estimate";
    for (int j = 0; j < kNumJoints; ++j)
      EXPECT_LT(rmse(j), 1.0) << "joint " << j << ", seed " << seed;
  }
}

INSTANTIATE_TEST_SUITE_P(Defaults, FastReaching, testing::ValuesIn(kReachCases), reachCaseName);

// Honest uncertainty on fast reaching: the share of errors inside two reported sd, pooled over
// ten reaching movements (seeds 101-110, 19 s each) that neither the defaults nor the
// accelerometers' jerk term and the shoulder's lag walk (accelJerkVariance,
// shoulderPathVarianceRate: measured and chosen on seeds 31-34 and 51-64) were chosen on.
// Without the jerk term the elbow's two joints fall to 72-78 % at 420 deg/s and 52-54 % at
// 600 deg/s, without the lag walk the shoulder's three to 85-89 % at 600 deg/s.
class FastReachingCoverage : public testing::TestWithParam<ReachCase> {};

TEST_P(FastReachingCoverage, TwoSigmaHoldsNinetyToNinetyNinePercent) {
  const ReachCase c = GetParam();
  Tally t;
  for (std::uint64_t seed = 101; seed <= 110; ++seed)
    run(reachingRecording(c, seed), c.kind, 1.0, t);
  const JointVector cover = t.coverage();
  std::printf(
      "[ measured ] %s reaching %.0f deg/s, %s, seeds 101-110: inside 2 sd (%%) %s; RMSE "
      "(deg) %s\n",
      c.kind == FilterKind::Ekf ? "EKF" : "UKF", c.peakRateDeg, opticsName(c.optics),
      row(cover, 100.0).c_str(), row(t.errors.rmse() / kDeg).c_str());
  for (int j = 0; j < kNumJoints; ++j) {
    EXPECT_GE(cover(j), 0.90) << "joint " << j << ": the reported sd is too small";
    EXPECT_LE(cover(j), 0.99) << "joint " << j << ": the reported sd is too large";
  }
}

INSTANTIATE_TEST_SUITE_P(Defaults, FastReachingCoverage, testing::ValuesIn(kReachCases),
                         reachCaseName);

// The heading's random walk the filter assumes (the gyroscopes' own plus the motion walk, which
// grows with the path the shoulder joints travel) against the walk it makes: a Kinect fix up to
// 2 s, then IMUs alone (Table 5 noise), on movements the rate was not measured on. The truth's
// turn about the vertical relative to the estimate, changed over 1 s windows, has a mean square
// that the model must match within a factor of two. The gyroscopes' walk alone is five times too
// small (docs/estimator.md, "Uncertainty").
TEST(HeadingWalk, MatchesTheMotionModelWithoutOptics) {
  const EstimatorParams defaults;
  double measured = 0.0, modelled = 0.0;
  for (std::uint64_t seed = 91; seed <= 98; ++seed) {
    const Recording rec = simulateRecording(MultiJointTrajectory(seed),
                                            simulation(20.0, seed, 1000.0, Optics::Kinect));
    EstimatorParams p = recordingParams(rec.meta);
    const Eigen::Vector3d up = p.gUp.normalized();
    auto f = makeEstimator(p);
    double windowStart = 3.0, turnAtStart = NAN, path = 0.0, lastT = NAN;
    for (ArmSample s : rec.samples) {
      if (s.t > 2.0) {  // the Kinect's fix ends
        s.elbow.reset();
        s.wrist.reset();
      }
      f->update(s);
      if (!s.trueAngles || s.t < windowStart || !f->initialised()) continue;
      const JointEstimate e = f->estimate();
      JointVector d;
      for (int j = 0; j < kNumJoints; ++j) d(j) = wrapAngle(e.th(j) - (*s.trueAngles)(j));
      const double turn = headingCovector(*s.trueAngles, up).dot(d);
      if (std::isnan(turnAtStart)) turnAtStart = turn;
      if (!std::isnan(lastT)) path += e.thd.head<3>().norm() * (s.t - lastT);
      lastT = s.t;
      if (s.t >= windowStart + 1.0) {
        measured += (turn - turnAtStart) * (turn - turnAtStart);
        modelled += defaults.headingVarianceRate * 1.0 + defaults.headingPathVarianceRate * path;
        windowStart += 1.0;
        turnAtStart = turn;
        path = 0.0;
      }
    }
  }
  std::printf("[ measured ] heading walk without optics, measured / modelled: %.2f\n",
              measured / modelled);
  EXPECT_GT(measured / modelled, 0.5) << "the heading's assumed walk is too large";
  EXPECT_LT(measured / modelled, 2.0) << "the heading's assumed walk is too small";
}

class Coverage : public testing::TestWithParam<Optics> {};

TEST_P(Coverage, TwoSigmaHoldsNinetyToNinetyNinePercent) {
  // Without optics the start heading is a guess whose stated uncertainty (initialHeadingStd) is
  // only tested fairly if the true arm's heading is drawn from it: each run turns the truth by
  // a draw of N(0, initialHeadingStd). The shoulder's error is then one draw per run, so IMU-only
  // coverage needs many short runs (320 of 2 s: about 1 % sampling error).
  // With optics the heading error wanders over seconds, so four runs of 19 s hold about a dozen
  // independent heading errors and their share moves by several points with the noise draw
  // alone (84-98 % on the same four movements). The test therefore pools 88 runs: movements
  // 31-34 with ten noise draws each, and 91-98, on which nothing was measured or tuned, with
  // six. Pools of half that size with other draws spread over 93.5-98.3 % on the shoulder.
  struct Pool {
    std::uint64_t firstSeed;
    int movements, draws;
  };
  const bool imusOnly = GetParam() == Optics::None;
  const std::vector<Pool> pools =
      imusOnly ? std::vector<Pool>{{4001, 320, 1}} : std::vector<Pool>{{31, 4, 10}, {91, 8, 6}};
  std::mt19937_64 rng(7);
  std::normal_distribution<double> heading(0.0, EstimatorParams{}.initialHeadingStd);
  Tally t;
  for (const Pool& pool : pools) {
    const JointVector insideBefore = t.inside;
    const double countBefore = t.count;
    for (int d = 0; d < pool.draws; ++d)
      for (int k = 0; k < pool.movements; ++k) {
        const std::uint64_t seed = pool.firstSeed + k;
        const double turn = imusOnly ? heading(rng) : 0.0;
        // The movement comes from `seed`, the sensor noise from seed + 1000 d.
        const Recording rec = simulateRecording(
            MultiJointTrajectory(seed),
            simulation(imusOnly ? 2.0 : 20.0, seed + 1000 * d, 1000.0, GetParam()));
        run(rec, FilterKind::Ekf, 1.0, t, turn);
      }
    if (!imusOnly)
      std::printf("[ measured ] %s, movements %lu-%lu, %d noise draws: inside 2 sd (%%) %s\n",
                  opticsName(GetParam()), static_cast<unsigned long>(pool.firstSeed),
                  static_cast<unsigned long>(pool.firstSeed + pool.movements - 1), pool.draws,
                  row((t.inside - insideBefore) / (t.count - countBefore), 100.0).c_str());
  }
  const JointVector cover = t.coverage();
  std::printf("[ measured ] %s: inside 2 sd (%%) %s; RMSE (deg) %s\n", opticsName(GetParam()),
              row(cover, 100.0).c_str(), row(t.errors.rmse() / kDeg).c_str());
  for (int j = 0; j < kNumJoints; ++j) {
    EXPECT_GE(cover(j), 0.90) << "joint " << j << ": the reported sd is too small";
    EXPECT_LE(cover(j), 0.99) << "joint " << j << ": the reported sd is too large";
  }
}

INSTANTIATE_TEST_SUITE_P(Defaults, Coverage,
                         testing::Values(Optics::None, Optics::Kinect, Optics::Webcam),
                         [](const testing::TestParamInfo<Optics>& i) {
                           return std::string(i.param == Optics::Kinect   ? "Kinect"
                                              : i.param == Optics::Webcam ? "Webcam"
                                                                          : "ImusOnly");
                         });

}  // namespace
}  // namespace armtrack
