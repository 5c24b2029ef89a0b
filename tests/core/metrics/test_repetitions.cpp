// Repetition detection and session metrics on a simulated exercise whose true angles are known
// (minimum-jerk moves between key postures, core/simulation), with noise, jittered time stamps,
// pauses, a gap, NaN rows and a partial repetition.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <string>

#include "core/kinematics/ClinicalAngles.h"
#include "core/metrics/ClinicalMetrics.h"
#include "core/metrics/NormativeRanges.h"
#include "core/metrics/Repetitions.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

struct Exercise {
  MinimumJerkPath path;
  std::vector<double> peakDeg;           ///< flexion reached by each repetition
  std::vector<double> onsetS, returnS;   ///< true movement start and end of each repetition
  std::vector<double> topFromS, topToS;  ///< when the arm holds at the top
  std::vector<double> riseS;             ///< duration of each rise
  ClinicalAngles rest, top;              ///< degrees
};

JointVector joints(const ClinicalAngles& c) {
  return fromClinical(c);
}

/// Shoulder flexion from 10 to `peak` deg and back, the other angles following in proportion;
/// pauses at rest and at the top of varying length.
Exercise makeExercise(const std::vector<double>& peaks) {
  Exercise e;
  e.rest = {10, 5, 0, 20, 0};
  e.top = {100, 15, 10, 35, 10};
  e.peakDeg = peaks;
  double t = 2.0;
  e.path.add(0.0, joints(e.rest));
  e.path.add(t, joints(e.rest));
  const double rises[] = {1.2, 1.5, 1.8, 1.0, 1.4, 1.6, 1.3};
  const double holds[] = {0.3, 1.0, 0.5, 0.2, 0.8, 0.4, 0.6};
  const double pauses[] = {0.5, 3.0, 1.0, 2.0, 0.3, 2.5, 1.5};
  for (std::size_t r = 0; r < peaks.size(); ++r) {
    const double f =
        (peaks[r] - e.rest.shoulderFlexion) / (e.top.shoulderFlexion - e.rest.shoulderFlexion);
    const auto a = asArray(e.rest), b = asArray(e.top);
    ClinicalAngles c;
    c.shoulderFlexion = a[0] + f * (b[0] - a[0]);
    c.shoulderAbduction = a[1] + f * (b[1] - a[1]);
    c.shoulderInternalRotation = a[2] + f * (b[2] - a[2]);
    c.elbowFlexion = a[3] + f * (b[3] - a[3]);
    c.forearmPronation = a[4] + f * (b[4] - a[4]);
    const double rise = rises[r % 7], hold = holds[r % 7], pause = pauses[r % 7];
    e.onsetS.push_back(t);
    e.riseS.push_back(rise);
    e.path.add(t + rise, joints(c));
    e.topFromS.push_back(t + rise);
    e.path.hold(hold);
    e.topToS.push_back(t + rise + hold);
    e.path.add(t + rise + hold + rise, joints(e.rest));
    e.returnS.push_back(t + 2 * rise + hold);
    e.path.hold(pause);
    t = e.path.endTime();
  }
  e.path.hold(2.0);
  return e;
}

struct Sampling {
  double rate = 100.0;
  double jitterS = 0.002;
  double noiseDeg = 0.5;
  bool gapAndNans = true;
  unsigned seed = 11;
};

/// Measured series (noisy) and the truth (noise-free, same time stamps).
void sampleExercise(const Exercise& e, const Sampling& s, AngleSeries& measured,
                    AngleSeries& truth) {
  std::mt19937 rng(s.seed);
  std::uniform_real_distribution<double> jitter(-s.jitterS, s.jitterS);
  std::normal_distribution<double> noise(0.0, s.noiseDeg * kDegToRad);
  std::vector<double> t;
  std::vector<JointVector> th;
  const int n = static_cast<int>(e.path.endTime() * s.rate);
  for (int k = 0; k <= n; ++k) {
    const double tk = k / s.rate + (k > 0 && k < n ? jitter(rng) : 0.0);
    // A 0.5 s gap in the pause after the second repetition.
    if (s.gapAndNans && tk > e.returnS[1] + 1.0 && tk < e.returnS[1] + 1.5) continue;
    t.push_back(tk);
    th.push_back(e.path.at(tk).th);
  }
  truth = angleSeriesFromJoints(t, th);
  measured = truth;
  for (ClinicalRow& row : measured.angle)
    for (double& a : row) a += noise(rng);
  if (s.gapAndNans) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    measured.angle[150][1] = nan;
    measured.angle[900][4] = nan;
  }
}

const std::vector<double> kPeaks{100, 100, 100, 50, 100, 100, 100};  // the fourth is partial

TEST(Repetitions, CountsAndMeasuresASimulatedExercise) {
  const Exercise e = makeExercise(kPeaks);
  AngleSeries measured, truth;
  sampleExercise(e, {}, measured, truth);
  const PreparedSeries p = prepareSeries(measured);
  EXPECT_EQ(p.rejectedNonFinite, 2u);
  EXPECT_EQ(p.segments.size(), 2u);
  const RepetitionResult r = detectRepetitions(p);

  EXPECT_EQ(r.primaryAngle, 0);  // shoulder flexion moves most
  EXPECT_FALSE(r.negativeDirection);
  ASSERT_EQ(r.repetitions.size(), kPeaks.size());
  EXPECT_EQ(r.fullCount, 6u);
  EXPECT_EQ(r.partialCount, 1u);
  EXPECT_EQ(r.truncated, 0u);
  double worstRom = 0, worstOnset = 0, worstReturn = 0, worstPeak = 0;
  for (std::size_t i = 0; i < kPeaks.size(); ++i) {
    SCOPED_TRACE(i);
    const Repetition& rep = r.repetitions[i];
    EXPECT_EQ(rep.partial, i == 3);
    const double trueRom = kPeaks[i] - e.rest.shoulderFlexion;
    const double romErr = rep.excursionRad * kRadToDeg - trueRom;
    EXPECT_LT(std::abs(romErr), 1.0);
    EXPECT_GE(rep.peakS, e.topFromS[i] - 0.15);
    EXPECT_LE(rep.peakS, e.topToS[i] + 0.15);
    EXPECT_NEAR(rep.startS, e.onsetS[i], 0.25);
    EXPECT_NEAR(rep.endS, e.returnS[i], 0.25);
    // Minimum jerk: peak rate 1.875 x amplitude / duration. The peak of a noisy rate is biased
    // up by the noise (0.5 deg of angle noise: about 2.5 deg/s rms on the rate).
    const double truePeak = 1.875 * trueRom / e.riseS[i];
    EXPECT_NEAR(rep.metrics.angle[0].peakVelocityRadPerS * kRadToDeg, truePeak,
                0.02 * truePeak + 6.0);
    worstPeak = std::max(worstPeak,
                         std::abs(rep.metrics.angle[0].peakVelocityRadPerS * kRadToDeg - truePeak));
    worstRom = std::max(worstRom, std::abs(romErr));
    worstOnset = std::max(worstOnset, std::abs(rep.startS - e.onsetS[i]));
    worstReturn = std::max(worstReturn, std::abs(rep.endS - e.returnS[i]));
  }
  std::printf(
      "7 repetitions (1 partial), 0.5 deg noise: worst repetition ROM error %.3f deg, "
      "worst start %.3f s, worst end %.3f s, worst peak rate %.2f deg/s\n",
      worstRom, worstOnset, worstReturn, worstPeak);
}

TEST(Repetitions, NoiseFreePeakRateMatchesMinimumJerk) {
  const Exercise e = makeExercise(kPeaks);
  AngleSeries measured, truth;
  sampleExercise(e, {}, measured, truth);
  const RepetitionResult r = detectRepetitions(prepareSeries(truth));
  ASSERT_EQ(r.repetitions.size(), kPeaks.size());
  for (std::size_t i = 0; i < kPeaks.size(); ++i) {
    const double trueRom = kPeaks[i] - e.rest.shoulderFlexion;
    const double truePeak = 1.875 * trueRom / e.riseS[i];
    EXPECT_NEAR(r.repetitions[i].metrics.angle[0].peakVelocityRadPerS * kRadToDeg, truePeak,
                0.01 * truePeak)
        << i;
    EXPECT_NEAR(r.repetitions[i].excursionRad * kRadToDeg, trueRom, 0.3) << i;
  }
  const PreparedSeries p = prepareSeries(truth);
  const IntervalMetrics m = intervalMetrics(p, 0, p.size());
  const auto rest = asArray(e.rest), top = asArray(e.top);
  for (int a = 0; a < kNumClinicalAngles; ++a)
    EXPECT_NEAR(m.angle[a].romRad * kRadToDeg, std::abs(top[a] - rest[a]), 0.3) << a;
}

TEST(Repetitions, SessionRangeIsWithinOneDegreeOfTheTrueAngles) {
  const Exercise e = makeExercise(kPeaks);
  AngleSeries measured, truth;
  sampleExercise(e, {}, measured, truth);
  const PreparedSeries p = prepareSeries(measured);
  const IntervalMetrics m = intervalMetrics(p, 0, p.size());
  const auto rest = asArray(e.rest), top = asArray(e.top);
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    const double trueRom = std::abs(top[a] - rest[a]);
    const double err = m.angle[a].romRad * kRadToDeg - trueRom;
    EXPECT_LT(std::abs(err), 1.0) << a;
    std::printf("session ROM angle %d: %.3f deg, true %.3f deg, error %.3f deg\n", a,
                m.angle[a].romRad * kRadToDeg, trueRom, err);
  }
}

TEST(Repetitions, TargetRangeDecidesWhatIsPartial) {
  const Exercise e = makeExercise(kPeaks);
  AngleSeries measured, truth;
  sampleExercise(e, {}, measured, truth);
  const PreparedSeries p = prepareSeries(measured);
  RepetitionParams params;
  params.primaryAngle = 0;
  params.target = TargetRange{10 * kDegToRad, 100 * kDegToRad};
  RepetitionResult r = detectRepetitions(p, params);
  EXPECT_EQ(r.fullCount, 6u);
  EXPECT_EQ(r.partialCount, 1u);
  EXPECT_NEAR(r.referenceRad, 90 * kDegToRad, 1e-12);
  // A target the patient never reaches: every repetition is partial, none is lost.
  params.target = TargetRange{0.0, 170 * kDegToRad};
  r = detectRepetitions(p, params);
  EXPECT_EQ(r.fullCount, 0u);
  EXPECT_EQ(r.partialCount, 7u);
}

TEST(Repetitions, CountIsRobustToHeavierNoiseAndSeeds) {
  const Exercise e = makeExercise(kPeaks);
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    Sampling s;
    s.noiseDeg = 1.5;
    s.seed = seed;
    AngleSeries measured, truth;
    sampleExercise(e, s, measured, truth);
    const RepetitionResult r = detectRepetitions(prepareSeries(measured));
    EXPECT_EQ(r.repetitions.size(), 7u) << seed;
    EXPECT_EQ(r.partialCount, 1u) << seed;
  }
}

TEST(Repetitions, NegativeExcursionsAreFoundAutomatically) {
  // Elbow extension from a flexed rest: elbow flexion 120 -> 30 deg and back, four times.
  MinimumJerkPath path;
  ClinicalAngles rest{20, 0, 0, 120, 0}, out{20, 0, 0, 30, 0};
  path.add(0, joints(rest));
  path.hold(1.5);
  for (int i = 0; i < 4; ++i) {
    path.add(path.endTime() + 1.0, joints(out));
    path.hold(0.3);
    path.add(path.endTime() + 1.0, joints(rest));
    path.hold(1.2);
  }
  std::vector<double> t;
  std::vector<JointVector> th;
  for (double x = 0; x <= path.endTime(); x += 0.01) {
    t.push_back(x);
    th.push_back(path.at(x).th);
  }
  const RepetitionResult r = detectRepetitions(prepareSeries(angleSeriesFromJoints(t, th)));
  EXPECT_EQ(r.primaryAngle, 3);
  EXPECT_TRUE(r.negativeDirection);
  ASSERT_EQ(r.repetitions.size(), 4u);
  for (const Repetition& rep : r.repetitions) {
    EXPECT_NEAR(rep.excursionRad * kRadToDeg, 90.0, 0.5);
    EXPECT_FALSE(rep.partial);
  }
}

TEST(Repetitions, RecordingCutInsideARepetitionIsNotCounted) {
  const Exercise e = makeExercise({100, 100, 100});
  Sampling s;
  s.gapAndNans = false;
  AngleSeries measured, truth;
  sampleExercise(e, s, measured, truth);
  // Keep from the top of the first repetition to the top of the third.
  AngleSeries cut;
  for (std::size_t i = 0; i < measured.t.size(); ++i) {
    if (measured.t[i] < e.topFromS[0] || measured.t[i] > e.topFromS[2]) continue;
    cut.t.push_back(measured.t[i]);
    cut.angle.push_back(measured.angle[i]);
  }
  const RepetitionResult r = detectRepetitions(prepareSeries(cut));
  EXPECT_EQ(r.repetitions.size(), 1u);
  EXPECT_EQ(r.truncated, 2u);
}

TEST(RepetitionsHostile, NoMovementNoRepetitions) {
  AngleSeries still;
  std::mt19937 rng(2);
  std::normal_distribution<double> noise(0.0, 1.0 * kDegToRad);
  for (int i = 0; i < 3000; ++i) {
    still.t.push_back(i * 0.01);
    still.angle.push_back({0.3 + noise(rng), 0.1, 0, 0.5, 0});
  }
  EXPECT_TRUE(detectRepetitions(prepareSeries(still)).repetitions.empty());
  AngleSeries one;
  one.t = {0.0};
  one.angle = {{0, 0, 0, 0, 0}};
  EXPECT_TRUE(detectRepetitions(prepareSeries(one)).repetitions.empty());
}

TEST(RepetitionsHostile, BadParametersAreRejected) {
  AngleSeries s;
  s.t = {0.0, 0.01};
  s.angle = {{0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}};
  const PreparedSeries p = prepareSeries(s);
  RepetitionParams bad;
  bad.primaryAngle = 5;
  EXPECT_THROW(detectRepetitions(p, bad), std::invalid_argument);
  bad = {};
  bad.exitFraction = 0.5;  // above enter
  EXPECT_THROW(detectRepetitions(p, bad), std::invalid_argument);
  bad = {};
  bad.partialFraction = 0;
  EXPECT_THROW(detectRepetitions(p, bad), std::invalid_argument);
  bad = {};
  bad.target = TargetRange{1.0, 1.0};
  EXPECT_THROW(detectRepetitions(p, bad), std::invalid_argument);
  bad = {};
  bad.minExcursionRad = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(detectRepetitions(p, bad), std::invalid_argument);
}

// ---- The whole session ------------------------------------------------------------------------

TEST(SessionMetrics, OneCallGivesEverything) {
  const Exercise e = makeExercise(kPeaks);
  AngleSeries measured, truth;
  sampleExercise(e, {}, measured, truth);
  const SessionMetrics m = computeSessionMetrics(measured);
  EXPECT_EQ(m.samples + m.rejectedNonFinite, measured.t.size());
  EXPECT_EQ(m.gaps, 1u);
  EXPECT_NEAR(m.durationS, e.path.endTime(), 0.01);
  EXPECT_EQ(m.repetitions.repetitions.size(), 7u);
  ASSERT_EQ(m.repetitionSmoothness.size(), 7u);
  for (const RepetitionSmoothness& s : m.repetitionSmoothness) {
    EXPECT_TRUE(s.sparc.ok());
    EXPECT_TRUE(s.ldlj.ok());
  }
  ASSERT_TRUE(m.sparc.ok());
  ASSERT_TRUE(m.ldlj.ok());
  // Out, hold, back: two minimum-jerk strokes, less smooth than one (-1.41) but not erratic.
  EXPECT_LT(m.sparc.value, -1.41);
  EXPECT_GT(m.sparc.value, -4.0);
  std::printf("session: SPARC %.3f, LDLJ %.3f (median over repetitions)\n", m.sparc.value,
              m.ldlj.value);

  // The same session without noise: the smoothness barely moves.
  const SessionMetrics clean = computeSessionMetrics(truth);
  ASSERT_TRUE(clean.sparc.ok() && clean.ldlj.ok());
  std::printf("noise-free session: SPARC %.3f, LDLJ %.3f\n", clean.sparc.value, clean.ldlj.value);
  EXPECT_NEAR(m.sparc.value, clean.sparc.value, 0.1);
  EXPECT_NEAR(m.ldlj.value, clean.ldlj.value, 1.0);  // LDLJ is the noise-sensitive one

  ClinicalMetricsParams noWrist;
  noWrist.geometry.reset();
  const SessionMetrics n = computeSessionMetrics(measured, noWrist);
  EXPECT_TRUE(n.repetitionSmoothness.empty());
  EXPECT_FALSE(n.sparc.ok());
}

TEST(SessionMetrics, HostileSeriesGiveClearErrors) {
  EXPECT_THROW(computeSessionMetrics({}), std::invalid_argument);
  AngleSeries one;
  one.t = {0.0};
  one.angle = {{0.1, 0, 0, 0, 0}};
  const SessionMetrics m = computeSessionMetrics(one);
  EXPECT_EQ(m.samples, 1u);
  EXPECT_EQ(m.session.angle[0].romRad, 0.0);
  EXPECT_EQ(m.sparc.status, SmoothnessStatus::TooShort);

  AngleSeries back;
  back.t = {0.0, 0.02, 0.01};
  back.angle.assign(3, ClinicalRow{0, 0, 0, 0, 0});
  EXPECT_THROW(computeSessionMetrics(back), std::invalid_argument);

  // Constant angles with a NaN row: defined zeros, the row counted, smoothness "no movement".
  AngleSeries still;
  for (int i = 0; i < 300; ++i) {
    still.t.push_back(i * 0.01);
    still.angle.push_back({0.2, 0.1, 0.0, 0.5, 0.0});
  }
  still.angle[10][3] = std::numeric_limits<double>::quiet_NaN();
  const SessionMetrics c = computeSessionMetrics(still);
  EXPECT_EQ(c.rejectedNonFinite, 1u);
  EXPECT_TRUE(c.repetitions.repetitions.empty());
  EXPECT_NEAR(c.session.angle[3].romRad, 0.0, 1e-12);
  EXPECT_EQ(c.sparc.status, SmoothnessStatus::NoMovement);
  EXPECT_EQ(c.ldlj.status, SmoothnessStatus::NoMovement);
}

TEST(NormativeRanges, AaosValuesAndSpans) {
  const auto& n = aaosNormativeRanges();
  EXPECT_NEAR(n[0].maxRad * kRadToDeg, 180, 1e-9);
  EXPECT_NEAR(*n[0].minRad * kRadToDeg, -60, 1e-9);
  EXPECT_FALSE(n[1].minRad.has_value());
  EXPECT_NEAR(normativeSpanRad(n[1]) * kRadToDeg, 180, 1e-9);
  EXPECT_NEAR(normativeSpanRad(n[2]) * kRadToDeg, 160, 1e-9);
  EXPECT_NEAR(normativeSpanRad(n[3]) * kRadToDeg, 150, 1e-9);
  EXPECT_NEAR(normativeSpanRad(n[4]) * kRadToDeg, 160, 1e-9);
  EXPECT_NEAR(fractionOfNormativeSpan(n[3], 75 * kDegToRad), 0.5, 1e-12);
  // The named motion alone, from the neutral position (Norkin & White, Table A.1).
  const double named[] = {180, 180, 70, 150, 80};
  for (int a = 0; a < kNumClinicalAngles; ++a)
    EXPECT_NEAR(namedMotionNormalRad(n[a]) * kRadToDeg, named[a], 1e-9) << a;
  EXPECT_NEAR(fractionOfNamedMotionNormal(n[0], 90 * kDegToRad), 0.5, 1e-12);
  // Eight directions: each angle's named one, and extension, external rotation and supination,
  // with their own limits (60, 90, 80 deg); abduction and elbow flexion have no opposite one.
  const std::vector<MotionDirection> dirs = motionDirections(n);
  ASSERT_EQ(dirs.size(), 8u);
  const int angles[] = {0, 0, 1, 2, 2, 3, 4, 4};
  const bool opposite[] = {false, true, false, false, true, false, false, true};
  const double normal[] = {180, 60, 180, 70, 90, 150, 80, 80};
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    EXPECT_EQ(dirs[i].angle, angles[i]) << i;
    EXPECT_EQ(dirs[i].opposite, opposite[i]) << i;
    EXPECT_NEAR(
        motionNormalRad(n[static_cast<std::size_t>(dirs[i].angle)], dirs[i].opposite) * kRadToDeg,
        normal[i], 1e-9)
        << i;
  }
  EXPECT_EQ(largestInDirection(-0.2, 1.1, false), std::optional<double>(1.1));
  EXPECT_EQ(largestInDirection(-0.2, 1.1, true), std::optional<double>(0.2));
  EXPECT_EQ(largestInDirection(std::nullopt, 1.1, true), std::nullopt);
  EXPECT_NE(normSourceCitation(NormSource::Aaos).find("AAOS 1965"), std::string_view::npos);
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    EXPECT_EQ(n[a].angle, a);
    EXPECT_EQ(n[a].maxSource, NormSource::Aaos);
    EXPECT_EQ(n[a].minSource, NormSource::Aaos);
  }
}

// The typical ranges the kinematics layer gives with each angle's name (for a GUI's scales and
// gauges) are the cited AAOS ones, not figures of their own; adduction, which that source does
// not give, starts at the side (0).
TEST(NormativeRanges, ClinicalAngleInfoCarriesTheCitedRanges) {
  const auto& n = aaosNormativeRanges();
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    SCOPED_TRACE(clinicalAngleInfo()[a].key);
    EXPECT_NEAR(clinicalAngleInfo()[a].normalMax, n[a].maxRad * kRadToDeg, 1e-9);
    EXPECT_NEAR(clinicalAngleInfo()[a].normalMin, n[a].minRad.value_or(0.0) * kRadToDeg, 1e-9);
  }
}

}  // namespace

namespace {

/// Runs fn in a child process whose address space may grow by at most extraBytes beyond the
/// parent's; true when fn returned normally (false on std::bad_alloc, any exception, or a crash).
bool runsWithinMemory(std::size_t extraBytes, const std::function<void()>& fn) {
  std::ifstream status("/proc/self/status");
  std::string line;
  std::size_t vmKb = 0;
  while (std::getline(status, line))
    if (line.rfind("VmSize:", 0) == 0) vmKb = std::stoul(line.substr(7));
  const pid_t child = ::fork();
  if (child == 0) {
    const rlimit limit{vmKb * 1024 + extraBytes, vmKb * 1024 + extraBytes};
    ::setrlimit(RLIMIT_AS, &limit);
    try {
      fn();
    } catch (...) {
      ::_exit(1);
    }
    ::_exit(0);
  }
  int result = 0;
  ::waitpid(child, &result, 0);
  return WIFEXITED(result) && WEXITSTATUS(result) == 0;
}

}  // namespace

// A clock that jumps by a day between two stretches of an exercise: the metrics cost what the
// movements cost, not what the time between them would. Before, the wrist velocity was resampled
// over the whole span (8.6 million rows for a day at 100 Hz) and, with no repetition, one spectrum
// taken of all of it: gigabytes, and a SPARC of -16,961.
TEST(SessionMetricsHostile, ADayLongGapCostsNoMemory) {
  const Exercise e = makeExercise({100, 100});
  AngleSeries measured, truth;
  Sampling s;
  s.gapAndNans = false;
  sampleExercise(e, s, measured, truth);
  AngleSeries jumped = measured;
  const std::size_t n = measured.t.size();
  for (std::size_t i = 0; i < n; ++i) {
    jumped.t.push_back(measured.t[i] + 86400.0 + measured.t.back());
    jumped.angle.push_back(measured.angle[i]);
  }
  // Each stretch alone, and both: the day between them changes nothing but the gap count.
  const SessionMetrics one = computeSessionMetrics(measured);
  SessionMetrics both;
  EXPECT_TRUE(
      runsWithinMemory(std::size_t{64} << 20, [&] { both = computeSessionMetrics(jumped); }));
  both = computeSessionMetrics(jumped);
  EXPECT_EQ(both.gaps, one.gaps + 1);
  EXPECT_EQ(both.repetitions.repetitions.size(), 2 * one.repetitions.repetitions.size());
  ASSERT_TRUE(both.sparc.ok() && one.sparc.ok());
  EXPECT_NEAR(both.sparc.value, one.sparc.value, 0.05);

  // Without repetitions (the primary angle still), the smoothness is the median over the gap-free
  // stretches: about that of one, never the spectrum of a day of zeros.
  ClinicalMetricsParams p;
  p.repetitions.minExcursionRad = 10.0;  // no excursion counts: no repetition
  SessionMetrics free;
  EXPECT_TRUE(
      runsWithinMemory(std::size_t{64} << 20, [&] { free = computeSessionMetrics(jumped, p); }));
  free = computeSessionMetrics(jumped, p);
  EXPECT_TRUE(free.repetitions.repetitions.empty());
  ASSERT_TRUE(free.sparc.ok());
  EXPECT_GT(free.sparc.value, -10.0);
  EXPECT_LT(free.sparc.value, -1.0);
}

}  // namespace armtrack
