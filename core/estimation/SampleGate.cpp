#include "core/estimation/SampleGate.h"

#include <cmath>
#include <cstdio>

namespace armtrack {

PlausibilityLimits PlausibilityLimits::forGeometry(double upperArmLength, double forearmLength) {
  PlausibilityLimits l;
  l.maxReach = 1.5 * (upperArmLength + forearmLength) + 0.2;
  return l;
}

const char* sensorBlockName(SensorBlock b) {
  switch (b) {
    case SensorBlock::UpperArm:
      return "upper-arm IMU";
    case SensorBlock::Forearm:
      return "forearm IMU";
    case SensorBlock::Elbow:
      return "optical elbow";
    case SensorBlock::Wrist:
      return "optical wrist";
    case SensorBlock::CamWrist:
      return "wrist marker pixel";
    case SensorBlock::CamElbow:
      return "elbow marker pixel";
  }
  return "?";
}

const char* implausibleName(Implausible why) {
  switch (why) {
    case Implausible::NonFinite:
      return "not a number";
    case Implausible::BeyondRange:
      return "beyond the sensor's range";
    case Implausible::Saturated:
      return "saturated";
    case Implausible::AllZero:
      return "all zero";
    case Implausible::Stuck:
      return "stuck";
  }
  return "?";
}

std::uint64_t GateCounters::total() const {
  std::uint64_t n = 0;
  for (const auto& row : refused)
    for (std::uint64_t c : row) n += c;
  return n;
}

std::uint64_t GateCounters::byReason(Implausible why) const {
  std::uint64_t n = 0;
  for (const auto& row : refused) n += row[static_cast<int>(why)];
  return n;
}

std::uint64_t GateCounters::byBlock(SensorBlock b) const {
  std::uint64_t n = 0;
  for (std::uint64_t c : refused[static_cast<int>(b)]) n += c;
  return n;
}

std::string GateCounters::summary() const {
  const std::uint64_t n = total();
  if (n == 0) return {};
  std::string s =
      "refused " + std::to_string(n) + " implausible reading" + (n == 1 ? "" : "s") + " (";
  bool firstReason = true;
  for (int w = 0; w < kNumImplausible; ++w) {
    const auto why = static_cast<Implausible>(w);
    const std::uint64_t nw = byReason(why);
    if (nw == 0) continue;
    if (!firstReason) s += "; ";
    firstReason = false;
    s += std::string(implausibleName(why)) + " " + std::to_string(nw) + ":";
    bool firstBlock = true;
    for (int b = 0; b < kNumSensorBlocks; ++b) {
      const std::uint64_t c = refused[b][w];
      if (c == 0) continue;
      s += std::string(firstBlock ? " " : ", ") + sensorBlockName(static_cast<SensorBlock>(b)) +
           " " + std::to_string(c);
      firstBlock = false;
    }
  }
  char when[96];
  if (firstT == lastT)
    std::snprintf(when, sizeof when, ") at %.3f s", firstT);
  else
    std::snprintf(when, sizeof when, ") between %.3f s and %.3f s", firstT, lastT);
  return s + when;
}

std::uint64_t GateCounters::totalHeld() const {
  std::uint64_t n = 0;
  for (std::uint64_t c : held) n += c;
  return n;
}

std::string GateCounters::heldSummary() const {
  const std::uint64_t n = totalHeld();
  if (n == 0) return {};
  static const char* kNames[4] = {"upper-arm gyroscope", "upper-arm accelerometer",
                                  "forearm gyroscope", "forearm accelerometer"};
  std::string s = "took " + std::to_string(n) + " repeated (held) reading" + (n == 1 ? "" : "s") +
                  " as absent:";
  bool first = true;
  for (int i = 0; i < 4; ++i) {
    if (held[i] == 0) continue;
    s += std::string(first ? " " : ", ") + kNames[i] + " " + std::to_string(held[i]);
    first = false;
  }
  return s;
}

SampleGate::SampleGate(const PlausibilityLimits& limits) : m_limits(limits) {}

void SampleGate::reset() {
  m_counters = {};
  m_havePrevious = {false, false};
  m_repeats = {0, 0};
  m_last = {};
  m_lastRefused = false;
}

void SampleGate::count(SensorBlock b, Implausible why, double t) {
  if (m_counters.total() == 0) {
    m_counters.firstT = t;
    m_counters.firstBlock = b;
    m_counters.firstWhy = why;
  }
  m_counters.lastT = t;
  ++m_counters.refused[static_cast<int>(b)][static_cast<int>(why)];
  m_lastRefused = true;
}

std::optional<Implausible> SampleGate::checkImu(int slot, const ImuReading& r) {
  if (!r.gyr.allFinite() || !r.acc.allFinite()) return Implausible::NonFinite;
  // Stuck is judged on what the link delivered, before any other verdict, so a frozen sensor
  // is recognised whatever value it froze at.
  bool stuck = false;
  if (m_limits.stuckSamples > 0) {
    if (m_havePrevious[slot] && r.gyr == m_previous[slot].gyr && r.acc == m_previous[slot].acc)
      stuck = ++m_repeats[slot] + 1 >= m_limits.stuckSamples;
    else
      m_repeats[slot] = 0;
    m_previous[slot] = r;
    m_havePrevious[slot] = true;
  }
  const double g = r.gyr.cwiseAbs().maxCoeff(), a = r.acc.cwiseAbs().maxCoeff();
  // A full-scale reading converted to SI units may land an ulp or two beyond the range: that is
  // saturation, not a value from beyond it.
  constexpr double kRounding = 1.0 + 1e-9;
  if (g > kRounding * m_limits.gyroRange || a > kRounding * m_limits.accelRange)
    return Implausible::BeyondRange;
  const double f = m_limits.saturationFraction;
  if (g >= f * m_limits.gyroRange || a >= f * m_limits.accelRange) return Implausible::Saturated;
  if (r.acc.isZero(0.0)) return Implausible::AllZero;
  if (stuck) return Implausible::Stuck;
  return std::nullopt;
}

// A value equal to the sensor's previous one within heldSeconds of its last change is a repeat
// of an old sample. Judged on every block that passed the other checks.
void SampleGate::markHeld(int slot, double t, ImuReading& r) {
  if (m_limits.heldSeconds <= 0.0) return;
  auto mark = [&](Last& last, const Eigen::Vector3d& v, bool& held, std::uint64_t& count) {
    if (last.have && v == last.value && t - last.changedT <= m_limits.heldSeconds) {
      held = true;
      ++count;
      return;
    }
    if (!last.have || v != last.value) last.changedT = t;
    last.value = v;
    last.have = true;
  };
  mark(m_last[slot][0], r.gyr, r.gyrHeld, m_counters.held[2 * slot]);
  mark(m_last[slot][1], r.acc, r.accHeld, m_counters.held[2 * slot + 1]);
}

ArmSample SampleGate::check(const ArmSample& s) {
  m_lastRefused = false;
  ArmSample out = s;
  auto imu = [&](std::optional<ImuReading>& r, int slot, SensorBlock b) {
    if (!r) return;
    if (const auto why = checkImu(slot, *r)) {
      count(b, *why, s.t);
      r.reset();
      return;
    }
    markHeld(slot, s.t, *r);
  };
  imu(out.upperArm, 0, SensorBlock::UpperArm);
  imu(out.forearm, 1, SensorBlock::Forearm);
  auto point = [&](std::optional<Eigen::Vector3d>& p, SensorBlock b) {
    if (!p) return;
    if (!p->allFinite())
      count(b, Implausible::NonFinite, s.t);
    else if (p->isZero(0.0))  // the shoulder itself: a link that sends zeros
      count(b, Implausible::AllZero, s.t);
    else if (p->norm() > m_limits.maxReach)
      count(b, Implausible::BeyondRange, s.t);
    else
      return;
    p.reset();
  };
  point(out.elbow, SensorBlock::Elbow);
  point(out.wrist, SensorBlock::Wrist);
  auto pixel = [&](std::optional<Eigen::Vector2d>& px, SensorBlock b) {
    if (!px) return;
    if (!px->allFinite())
      count(b, Implausible::NonFinite, s.t);
    else if (px->isZero(0.0))
      count(b, Implausible::AllZero, s.t);
    else if (px->cwiseAbs().maxCoeff() > m_limits.maxPixel)
      count(b, Implausible::BeyondRange, s.t);
    else
      return;
    px.reset();
  };
  pixel(out.camWrist, SensorBlock::CamWrist);
  pixel(out.camElbow, SensorBlock::CamElbow);
  if (m_lastRefused) ++m_counters.samplesWithRefusal;
  return out;
}

}  // namespace armtrack
