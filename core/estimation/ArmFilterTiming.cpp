// Readings of sensors slower than the logger's rows (a 50 Hz gyroscope and a 25 Hz accelerometer
// on a 90 Hz clock, issue 27): the logger repeats the last sample until a new one comes, and the
// SampleGate marks the repeats as held, so the filter fuses each sample once, on the first row
// that carries it. That row's time is not the sample's: the sample was taken at some moment
// since the previous row, up to one row step earlier, uniformly. Fused at the row's time, every
// reading is late by half a row on average, which on a fast swing is far beyond the sensors'
// noise (a forearm accelerometer changes by 100 m/s^2 per second and more): on the double
// pendulum it doubled the hinge's error and made it worse than with the same readings at 25 Hz
// unheld (docs/baseline.md). So a row whose new readings all come from slow channels is fused at
// the middle of the row step (sampleDelay; the state is then predicted on to the row's time), and
// each slow block's variance grows by the delay's remaining spread, d^2 / 12 for a row step d,
// times the channel's squared rate of change (from its last two new samples). Channels with a new
// value on every row (every simulation at 1 kHz, every study of the paper) are never held and are
// fused exactly as before.
#include <cmath>

#include "core/estimation/ArmFilterImpl.h"

namespace armtrack::detail {

namespace {
// A channel counts as slow this long (s) after its last held value.
constexpr double kSlowMemory = 1.0;
// The delay is uniform over the row step d: mean d / 2, which sampleDelay takes out, and
// variance d^2 / 12 about it.
constexpr double kDelaySpread = 12.0;
template <typename C>
bool slow(const C& c) {
  return c.lastT - c.heldT <= kSlowMemory;
}
}  // namespace

template <int N>
void ArmFilter<N>::trackSampleTiming(const ArmSample& clean, double rowStep) {
  m_rowStep = std::isfinite(rowStep) && rowStep > 0.0 ? rowStep : 0.0;
  const std::optional<ImuReading>* imus[2] = {&clean.upperArm, &clean.forearm};
  for (int i = 0; i < 2; ++i) {
    if (!*imus[i]) continue;
    const ImuReading& r = **imus[i];
    for (int k = 0; k < 2; ++k) {
      ChannelTiming& c = m_timing[2 * i + k];
      const bool held = k == 0 ? r.gyrHeld : r.accHeld;
      const Eigen::Vector3d& v = k == 0 ? r.gyr : r.acc;
      if (held) {
        c.heldT = clean.t;
        continue;
      }
      const double dt = clean.t - c.lastT;
      c.changeSquared =
          dt > 0.0 && dt <= kSlowMemory ? (v - c.last).squaredNorm() / (dt * dt) : 0.0;
      c.last = v;
      c.lastT = clean.t;
    }
  }
}

template <int N>
double ArmFilter<N>::timingVariance(int block) const {
  if (block < kUaGyr || block > kFaAcc) return 0.0;
  const ChannelTiming& c = m_timing[block];
  if (!slow(c)) return 0.0;
  return c.changeSquared * m_rowStep * m_rowStep / kDelaySpread;
}

// How long before the row its new IMU readings were taken, on average: half a row step when
// every new reading in the row comes from a slow channel (and no optical data, which keep the
// row's time), else 0.
template <int N>
double ArmFilter<N>::sampleDelay(const ArmSample& clean) const {
  if (clean.elbow || clean.wrist || clean.camWrist || clean.camElbow) return 0.0;
  const std::optional<ImuReading>* imus[2] = {&clean.upperArm, &clean.forearm};
  bool any = false;
  for (int i = 0; i < 2; ++i) {
    if (!*imus[i]) continue;
    const ImuReading& r = **imus[i];
    for (int k = 0; k < 2; ++k) {
      if (k == 0 ? r.gyrHeld : r.accHeld) continue;
      if (!slow(m_timing[2 * i + k])) return 0.0;
      any = true;
    }
  }
  return any ? 0.5 * m_rowStep : 0.0;
}

template void ArmFilter<kBase>::trackSampleTiming(const ArmSample&, double);
template double ArmFilter<kBase>::timingVariance(int) const;
template double ArmFilter<kBase>::sampleDelay(const ArmSample&) const;
template void ArmFilter<kBase + 6>::trackSampleTiming(const ArmSample&, double);
template double ArmFilter<kBase + 6>::timingVariance(int) const;
template double ArmFilter<kBase + 6>::sampleDelay(const ArmSample&) const;

}  // namespace armtrack::detail
