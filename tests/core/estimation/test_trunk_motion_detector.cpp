// TrunkMotionDetector on synthetic tracks: a trunk turning about a hip point (s_W = h - R h,
// core/kinematics/Trunk.h), Kinect-like noise (1 cm per axis at 30 Hz, seeded) and IMU-only
// samples at 200 Hz in between, against the known trunk angles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>

#include "core/estimation/TrunkMotionDetector.h"
#include "core/kinematics/Trunk.h"

using namespace armtrack;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kImuRate = 200.0;
constexpr double kFrameRate = 30.0;

/// A lean that follows reaches: rest, ramp up (raised cosine), hold, ramp down, rest; repeated.
struct LeanProfile {
  double peakDeg = 10;      // forward flexion at the top
  double sideFraction = 0;  // lateral bending and axial rotation as fractions of the flexion
  double startS = 2.0;      // still before the first lean
  double rampS = 1.0;       // each ramp
  double holdS = 1.5;       // at the top
  double restS = 1.5;       // upright between leans
  int leans = 8;

  double cycle() const { return 2 * rampS + holdS + restS; }
  double duration() const { return startS + leans * cycle() + 1.0; }
  /// 0..1 of the peak at time t.
  double level(double t) const {
    const double u = t - startS;
    if (u < 0 || u >= leans * cycle()) return 0;
    const double c = std::fmod(u, cycle());
    if (c < rampS) return 0.5 * (1 - std::cos(std::numbers::pi * c / rampS));
    if (c < rampS + holdS) return 1;
    if (c < 2 * rampS + holdS)
      return 0.5 * (1 + std::cos(std::numbers::pi * (c - rampS - holdS) / rampS));
    return 0;
  }
  TrunkAngles angles(double t) const {
    const double f = peakDeg * kDeg * level(t);
    return {f, sideFraction * f, sideFraction * f};
  }
};

struct World {
  Eigen::Vector3d hip{0.47, 0.0, 0.0};  // frame-0 coordinates of a right arm: x0 down
  Eigen::Vector3d skeletonOffset{0.02, -0.03, 0.015};  // the Kinect's shoulder joint vs the centre
  double noiseM = 0.01;
  Eigen::Vector3d shoulderAt(const TrunkAngles& a) const { return hip - trunkRotation(a) * hip; }
};

struct Trace {
  std::vector<double> t;
  std::vector<TrunkAngles> truth;
  std::vector<TrunkMotionStatus> status;
  TrunkMotionDetector detector;
  explicit Trace(const TrunkMotionParams& p = {}) : detector(p) {}

  /// Fraction of the samples whose true total rotation exceeds `deg` that were reported moving.
  double detectedFraction(double deg) const {
    std::size_t over = 0, flagged = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (Eigen::AngleAxisd(trunkRotation(truth[i])).angle() <= deg * kDeg) continue;
      ++over;
      flagged += status[i].moving ? 1 : 0;
    }
    return over ? static_cast<double>(flagged) / static_cast<double>(over) : -1.0;
  }
  std::size_t flaggedCount() const {
    std::size_t n = 0;
    for (const auto& s : status) n += s.moving ? 1 : 0;
    return n;
  }
};

/// Drives a detector at 200 Hz with a shoulder frame every 1/30 s. `frame` may change or drop
/// a frame (return false to leave the shoulder out).
using FrameHook = std::function<bool(int frame, double t, Eigen::Vector3d& shoulder)>;

void runShoulder(Trace& run, const LeanProfile& lean, const World& world, std::uint64_t seed,
                 const FrameHook& hook = {}) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, world.noiseM);
  const int n = static_cast<int>(lean.duration() * kImuRate);
  int frame = 0;
  for (int i = 0; i < n; ++i) {
    const double t = i / kImuRate;
    TrunkMotionInput in;
    in.t = t;
    const TrunkAngles a = lean.angles(t);
    if (t + 1e-9 >= frame / kFrameRate) {
      Eigen::Vector3d s = world.shoulderAt(a) + world.skeletonOffset +
                          Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
      if (!hook || hook(frame, t, s)) in.shoulder = s;
      ++frame;
    }
    run.t.push_back(t);
    run.truth.push_back(a);
    run.status.push_back(run.detector.update(in));
  }
}
}  // namespace

TEST(TrunkMotionDetector, StillTrunkIsNeverFlaggedOverManySeeds) {
  LeanProfile still;
  still.peakDeg = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    Trace run;
    runShoulder(run, still, World{}, seed);
    EXPECT_EQ(run.flaggedCount(), 0u) << "seed " << seed;
    EXPECT_TRUE(run.detector.spans().empty()) << "seed " << seed;
    // The displacement it reports for a still trunk is noise only: typically well under a
    // centimetre (the norm of 3.8 mm per axis), never the enter threshold.
    std::vector<double> d;
    for (const auto& s : run.status) {
      if (s.cue == TrunkCue::Shoulder) d.push_back(s.displacementM);
    }
    ASSERT_FALSE(d.empty());
    std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
    EXPECT_LT(d[d.size() / 2], 0.01) << "seed " << seed;
    EXPECT_LT(*std::max_element(d.begin(), d.end()), TrunkMotionParams{}.enterM);
    EXPECT_EQ(run.status.back().cue, TrunkCue::Shoulder);
  }
}

TEST(TrunkMotionDetector, ForwardLeansAreFlaggedWhileBeyondFiveDegrees) {
  for (double peak : {6.0, 10.0, 20.0}) {
    for (std::uint64_t seed = 100; seed < 110; ++seed) {
      LeanProfile lean;
      lean.peakDeg = peak;
      Trace run;
      runShoulder(run, lean, World{}, seed);
      EXPECT_GE(run.detectedFraction(5.0), 0.9) << peak << " deg, seed " << seed;
      // Nothing is flagged before the first lean starts.
      for (std::size_t i = 0; run.t[i] < lean.startS; ++i) ASSERT_FALSE(run.status[i].moving);
      // One span per lean, each holding the lean's top, its largest displacement near the truth.
      const auto spans = run.detector.spans();
      ASSERT_EQ(spans.size(), static_cast<std::size_t>(lean.leans)) << peak << " deg";
      const double trueMax = World{}.shoulderAt(TrunkAngles(peak * kDeg, 0, 0)).norm();
      for (int k = 0; k < lean.leans; ++k) {
        const double top = lean.startS + k * lean.cycle() + lean.rampS;
        EXPECT_LT(spans[k].startS, top);
        EXPECT_GT(spans[k].endS, top + lean.holdS);
        // The largest of a noisy average over the hold lies a little above the truth.
        EXPECT_GT(spans[k].maxDisplacementM, trueMax - 0.005) << peak << " deg, lean " << k;
        EXPECT_LT(spans[k].maxDisplacementM, trueMax + 0.015) << peak << " deg, lean " << k;
        EXPECT_EQ(spans[k].cue, TrunkCue::Shoulder);
        EXPECT_FALSE(spans[k].open);
      }
    }
  }
}

TEST(TrunkMotionDetector, FastLeansWithSidewaysAndAxialTurnAboutAMedialHip) {
  // Lateral bending and axial rotation half the flexion; hip below and 12 cm medial; quick
  // 0.5 s ramps. "Leaning more than 5 deg" is the trunk's whole rotation here.
  World world;
  world.hip = {0.47, 0.0, -0.12};
  for (double peak : {5.0, 10.0, 20.0}) {
    for (std::uint64_t seed = 200; seed < 210; ++seed) {
      LeanProfile lean;
      lean.peakDeg = peak;
      lean.sideFraction = 0.5;
      lean.rampS = 0.5;
      Trace run;
      runShoulder(run, lean, world, seed);
      EXPECT_GE(run.detectedFraction(5.0), 0.9) << peak << " deg, seed " << seed;
    }
  }
}

TEST(TrunkMotionDetector, SidewaysLeanAloneIsFlagged) {
  LeanProfile lean;
  lean.peakDeg = 0;
  Trace run;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  const World world;
  for (int i = 0; i < static_cast<int>(lean.duration() * kFrameRate); ++i) {
    const double t = i / kFrameRate;
    const TrunkAngles a(0, 10 * kDeg * LeanProfile{}.level(t), 0);
    TrunkMotionInput in;
    in.t = t;
    in.shoulder = world.shoulderAt(a) + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    run.t.push_back(t);
    run.truth.push_back(a);
    run.status.push_back(run.detector.update(in));
  }
  EXPECT_GE(run.detectedFraction(5.0), 0.9);
  EXPECT_EQ(run.detector.spans().size(), 8u);
}

TEST(TrunkMotionDetector, SingleWildFramesAreOutliersNotMotion) {
  LeanProfile still;
  still.peakDeg = 0;
  for (std::uint64_t seed = 300; seed < 320; ++seed) {
    Trace run;
    int injected = 0;
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> axis(0, 2);
    runShoulder(run, still, World{}, seed, [&](int frame, double, Eigen::Vector3d& s) {
      // One frame 30 cm off every second, and twice a run of two and of three.
      const bool wild = (frame > 40 && frame % 30 == 0) || frame == 301 || frame == 302 ||
                        (frame >= 451 && frame <= 453);
      if (wild) {
        s(axis(rng)) += (frame % 2 ? 0.3 : -0.3);
        ++injected;
      }
      return true;
    });
    EXPECT_EQ(run.flaggedCount(), 0u) << "seed " << seed;
    EXPECT_EQ(run.detector.counters().outlierShoulder, static_cast<std::uint64_t>(injected))
        << "seed " << seed;
  }
}

TEST(TrunkMotionDetector, WildFramesDuringALeanDoNotHideIt) {
  LeanProfile lean;
  lean.peakDeg = 12;
  Trace run;
  runShoulder(run, lean, World{}, 11, [](int frame, double, Eigen::Vector3d& s) {
    if (frame > 40 && frame % 15 == 0) s.x() += 0.3;
    return true;
  });
  EXPECT_GE(run.detectedFraction(5.0), 0.9);
  EXPECT_EQ(run.detector.spans().size(), 8u);
}

TEST(TrunkMotionDetector, APointThatStaysElsewhereIsFollowed) {
  // A shoulder that really moves 20 cm in one step (a tracking switch, or a sudden lurch) and
  // stays there is not an outlier for ever: after relockSamples frames it is the position.
  LeanProfile still;
  still.peakDeg = 0;
  Trace run;
  runShoulder(run, still, World{}, 5, [](int frame, double, Eigen::Vector3d& s) {
    if (frame >= 200) s.y() += 0.2;
    return true;
  });
  const double jumpT = 200 / kFrameRate;
  for (std::size_t i = 0; i < run.t.size(); ++i) {
    if (run.t[i] < jumpT) {
      ASSERT_FALSE(run.status[i].moving);
    }
    if (run.t[i] > jumpT + 0.5) {
      ASSERT_TRUE(run.status[i].moving) << run.t[i];
      ASSERT_NEAR(run.status[i].displacementM, 0.2, 0.015);
    }
  }
}

TEST(TrunkMotionDetector, GapsLeaveNothingKnownAndRecover) {
  LeanProfile lean;
  lean.peakDeg = 12;
  lean.holdS = 3.0;  // a long top, with a 1.5 s dropout in it
  Trace run;
  const double top = lean.startS + lean.rampS;  // first lean reaches its top here
  runShoulder(run, lean, World{}, 21,
              [&](int, double t, Eigen::Vector3d&) { return !(t > top + 0.5 && t < top + 2.0); });
  TrunkMotionParams p;
  for (std::size_t i = 0; i < run.t.size(); ++i) {
    const double t = run.t[i];
    if (t > top + 0.1 && t < top + 0.5 + p.holdSeconds - 0.05) {
      EXPECT_TRUE(run.status[i].moving) << t;  // held across the first part of the dropout
    }
    if (t > top + 0.5 + p.holdSeconds + 0.05 && t < top + 2.0) {
      EXPECT_FALSE(run.status[i].moving) << t;  // then nothing is known
      EXPECT_EQ(run.status[i].cue, TrunkCue::None) << t;
    }
    if (t > top + 2.0 + 0.3 && t < top + lean.holdS) {
      EXPECT_TRUE(run.status[i].moving) << t;
    }
  }
  // The dropout splits the first lean's span in two.
  EXPECT_EQ(run.detector.spans().size(), 9u);
}

TEST(TrunkMotionDetector, StillTrunkWithGapsAndALateOrWildFirstFrame) {
  LeanProfile still;
  still.peakDeg = 0;
  for (std::uint64_t seed = 400; seed < 420; ++seed) {
    Trace run;
    runShoulder(run, still, World{}, seed, [&](int frame, double t, Eigen::Vector3d& s) {
      if (frame < 20) return false;               // the first 0.67 s have no shoulder
      if (frame == 20) s.setConstant(1e38);       // absurd
      if (frame == 21) s(1) = std::nan("");       // not a number
      if (frame == 22) s.x() += 0.3;              // the first usable frame is 30 cm off
      if (std::fmod(t, 7.0) > 5.5) return false;  // 1.5 s dropouts
      if (frame % 97 == 0) s.z() -= 0.3;          // and the odd wild frame
      return true;
    });
    EXPECT_EQ(run.flaggedCount(), 0u) << "seed " << seed;
    EXPECT_EQ(run.detector.counters().refusedShoulder, 2u);
    EXPECT_GE(run.detector.counters().outlierShoulder, 1u);
  }
}

TEST(TrunkMotionDetector, LateStartStillDetectsTheLeans) {
  LeanProfile lean;
  lean.peakDeg = 10;
  Trace run;
  runShoulder(run, lean, World{}, 31, [](int frame, double, Eigen::Vector3d& s) {
    if (frame == 15) s.setConstant(std::numeric_limits<double>::infinity());
    return frame >= 15;
  });
  EXPECT_GE(run.detectedFraction(5.0), 0.9);
}

TEST(TrunkMotionDetector, RefusesBadTimesAndKeepsItsDecision) {
  TrunkMotionDetector d;
  TrunkMotionInput in;
  in.shoulder = Eigen::Vector3d::Zero();
  for (int i = 0; i < 60; ++i) {
    in.t = i / 30.0;
    d.update(in);
  }
  in.shoulder = Eigen::Vector3d(0, 0.1, 0);
  for (int i = 60; i < 90; ++i) {
    in.t = i / 30.0;
    d.update(in);
  }
  const TrunkMotionStatus before = d.update(in);
  ASSERT_TRUE(before.moving);
  in.shoulder = Eigen::Vector3d::Zero();
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity(), 1.0, -1e300}) {
    in.t = bad;
    const TrunkMotionStatus s = d.update(in);
    EXPECT_EQ(s.moving, before.moving);
    EXPECT_EQ(s.displacementM, before.displacementM);
  }
  EXPECT_EQ(d.counters().refusedTime, 4u);
  const auto spans = d.spans();
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_TRUE(spans[0].open);
  EXPECT_NEAR(spans[0].maxDisplacementM, 0.1, 1e-9);
  d.reset();
  EXPECT_TRUE(d.spans().empty());
  EXPECT_EQ(d.counters().refusedTime, 0u);
}

TEST(TrunkMotionDetector, NothingIsDecidedBeforeTheStartPoseIsKnown) {
  // The trunk leans from the very first frame: the detector takes that as the start pose and says
  // nothing during its first second (documented limit).
  TrunkMotionDetector d;
  TrunkMotionInput in;
  for (int i = 0; i < 25; ++i) {
    in.t = i / 30.0;
    in.shoulder = Eigen::Vector3d(0, 0.001 * i, 0);
    const TrunkMotionStatus s = d.update(in);
    EXPECT_FALSE(s.moving);
    EXPECT_EQ(s.cue, TrunkCue::None);
  }
}

// --- the arm cue: optical elbow and wrist against the filter's prediction
// ---------------------------

namespace {
/// An arm reaching forward and back in the trunk frame (shoulder at the origin), and what a filter
/// that follows the arm's orientation (from the IMUs) but keeps the shoulder at the origin
/// predicts: R p_T, plus `absorbed` of the shoulder's displacement when its optical update pulls
/// the arm towards the optical points, plus a few millimetres of its own error.
struct ArmScene {
  double upperArmM = 0.30, forearmM = 0.27;
  double absorbed = 0.0;
  double filterErrorM = 0.003;
  /// Adds to the prediction: an error of the filter's own (world frame), by time.
  std::function<void(double t, Eigen::Vector3d& elbow, Eigen::Vector3d& wrist)> filterFault;

  void arm(double t, Eigen::Vector3d& e, Eigen::Vector3d& w) const {
    const double reach = 0.5 * (1 - std::cos(2 * std::numbers::pi * t / 4.5));
    const double a = (20 + 60 * reach) * kDeg, b = 15 * kDeg * std::sin(0.7 * t);
    const double g = (80 - 60 * reach) * kDeg;
    const Eigen::Vector3d u(std::cos(a), std::sin(a) * std::cos(b), std::sin(a) * std::sin(b));
    const Eigen::Vector3d v(std::cos(a + g), std::sin(a + g) * std::cos(b),
                            std::sin(a + g) * std::sin(b));
    e = upperArmM * u;
    w = e + forearmM * v;
  }
};

void runArm(Trace& run, const LeanProfile& lean, const World& world, const ArmScene& scene,
            std::uint64_t seed, bool withShoulder = false) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, world.noiseM), small(0.0, scene.filterErrorM);
  const auto n3 = [&](std::normal_distribution<double>& d) {
    return Eigen::Vector3d(d(rng), d(rng), d(rng));
  };
  const int n = static_cast<int>(lean.duration() * kImuRate);
  int frame = 0;
  for (int i = 0; i < n; ++i) {
    const double t = i / kImuRate;
    TrunkMotionInput in;
    in.t = t;
    const TrunkAngles a = lean.angles(t);
    if (t + 1e-9 >= frame / kFrameRate) {
      const Eigen::Matrix3d r = trunkRotation(a);
      const Eigen::Vector3d s = world.shoulderAt(a);
      Eigen::Vector3d e, w;
      scene.arm(t, e, w);
      in.elbow = s + r * e + n3(noise);
      in.wrist = s + r * w + n3(noise);
      Eigen::Vector3d pe = r * e + scene.absorbed * s + n3(small);
      Eigen::Vector3d pw = r * w + scene.absorbed * s + n3(small);
      if (scene.filterFault) scene.filterFault(t, pe, pw);
      in.predictedElbow = pe;
      in.predictedWrist = pw;
      if (withShoulder) in.shoulder = s + world.skeletonOffset + n3(noise);
      ++frame;
    }
    run.t.push_back(t);
    run.truth.push_back(a);
    run.status.push_back(run.detector.update(in));
  }
}
}  // namespace

TEST(TrunkMotionDetector, ArmCueStillTrunkIsNeverFlagged) {
  LeanProfile still;
  still.peakDeg = 0;
  for (std::uint64_t seed = 500; seed < 540; ++seed) {
    Trace run;
    runArm(run, still, World{}, ArmScene{}, seed);
    EXPECT_EQ(run.flaggedCount(), 0u) << "seed " << seed;
    EXPECT_EQ(run.status.back().cue, TrunkCue::Arm);
  }
}

TEST(TrunkMotionDetector, ArmCueFlagsLeansThatMoveTheShoulder) {
  World world;
  world.hip = {0.47, 0.0, -0.12};
  for (double peak : {10.0, 20.0}) {
    for (std::uint64_t seed = 600; seed < 610; ++seed) {
      LeanProfile lean;
      lean.peakDeg = peak;
      lean.sideFraction = 0.5;
      Trace run;
      runArm(run, lean, world, ArmScene{}, seed);
      EXPECT_GE(run.detectedFraction(5.0), 0.9) << peak << " deg, seed " << seed;
      EXPECT_EQ(run.detector.spans().size(), static_cast<std::size_t>(lean.leans));
      for (const auto& span : run.detector.spans()) EXPECT_EQ(span.cue, TrunkCue::Arm);
    }
  }
}

TEST(TrunkMotionDetector, ArmCueSeesLessWhenTheFilterFollowsTheOpticalPoints) {
  // A filter that explains 30 % of the shoulder's displacement by turning the arm leaves 70 % as
  // the common residual: a 10 deg lean is still seen beyond 7 deg, and the displacement it reports
  // is about 70 % of the truth (a documented limit).
  LeanProfile lean;
  lean.peakDeg = 10;
  ArmScene scene;
  scene.absorbed = 0.3;
  Trace run;
  runArm(run, lean, World{}, scene, 77);
  EXPECT_GE(run.detectedFraction(7.0), 0.9);
  const double trueMax = World{}.shoulderAt(TrunkAngles(10 * kDeg, 0, 0)).norm();
  for (const auto& span : run.detector.spans()) {
    EXPECT_NEAR(span.maxDisplacementM, 0.7 * trueMax, 0.015);
  }
}

TEST(TrunkMotionDetector, ArmCueIgnoresTheFiltersOwnErrors) {
  LeanProfile still;
  still.peakDeg = 0;
  // A shoulder-angle error of 2 deg (three times the worst the filter shows on a still trunk)
  // for 3 s of every 12, then an 8 cm wrist error alone (an elbow-angle error): a common
  // residual of 4 cm that a moving shoulder does not explain, since the elbow does not share it.
  ArmScene scene;
  scene.filterFault = [](double t, Eigen::Vector3d& e, Eigen::Vector3d& w) {
    const double c = std::fmod(t, 12.0);
    if (c > 3 && c < 6) {
      const Eigen::Matrix3d r =
          Eigen::AngleAxisd(2 * kDeg, Eigen::Vector3d(0.3, 0.2, 1.0).normalized()).matrix();
      e = r * e;
      w = r * w;
    } else if (c > 9 && c < 12) {
      w += Eigen::Vector3d(0, 0.08, 0);
    }
  };
  for (std::uint64_t seed = 700; seed < 720; ++seed) {
    Trace run;
    runArm(run, still, World{}, scene, seed);
    EXPECT_EQ(run.flaggedCount(), 0u) << "seed " << seed;
    // The common residual was there; it was refused for not being common to both points.
    double largest = 0;
    for (const auto& s : run.status) largest = std::max(largest, s.displacementM);
    EXPECT_GT(largest, TrunkMotionParams{}.armEnterM) << "seed " << seed;
  }
}

TEST(TrunkMotionDetector, TheShoulderCueWinsAndOnePointIsNotEnough) {
  LeanProfile lean;
  lean.peakDeg = 10;
  Trace both;
  runArm(both, lean, World{}, ArmScene{}, 81, /*withShoulder=*/true);
  EXPECT_GE(both.detectedFraction(5.0), 0.9);
  for (const auto& span : both.detector.spans()) EXPECT_EQ(span.cue, TrunkCue::Shoulder);

  // An elbow and its prediction without the wrist: no arm cue at all.
  TrunkMotionDetector d;
  for (int i = 0; i < 300; ++i) {
    TrunkMotionInput in;
    in.t = i / 30.0;
    in.elbow = Eigen::Vector3d(0.3, 0.1 * (i > 60), 0);
    in.predictedElbow = Eigen::Vector3d(0.3, 0, 0);
    const TrunkMotionStatus s = d.update(in);
    EXPECT_FALSE(s.moving);
    EXPECT_EQ(s.cue, TrunkCue::None);
  }
  // Absurd arm points are refused and counted.
  TrunkMotionInput in;
  in.t = 20;
  in.elbow = Eigen::Vector3d(0.3, 0, 0);
  in.wrist = Eigen::Vector3d(std::nan(""), 0, 0);
  in.predictedElbow = in.elbow;
  in.predictedWrist = Eigen::Vector3d(0.5, 0, 0);
  d.update(in);
  in.wrist = Eigen::Vector3d(1e6, 0, 0);
  d.update(in);
  EXPECT_EQ(d.counters().refusedArm, 2u);
}
