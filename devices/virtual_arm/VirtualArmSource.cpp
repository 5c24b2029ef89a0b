#include "devices/virtual_arm/VirtualArmSource.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <variant>

namespace armtrack::devices::virtualarm {
namespace {

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::string cur;
  std::istringstream in(text);
  while (std::getline(in, cur, sep))
    if (!cur.empty()) parts.push_back(cur);
  return parts;
}

double number(const std::string& s, const std::string& what) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != s.size() || !std::isfinite(v))
    throw std::invalid_argument("'" + what + "' is not a valid fault: '" + s + "' is not a number");
  return v;
}

Window window(const std::string& text) {
  const auto plus = text.find('+', 1);
  if (plus == std::string::npos)
    throw std::invalid_argument("'" + text + "' is not a valid time window: write START+SECONDS");
  Window w{number(text.substr(0, plus), text), number(text.substr(plus + 1), text)};
  if (w.start < 0.0 || w.duration <= 0.0)
    throw std::invalid_argument("'" + text + "': the start must be >= 0 and the length > 0");
  return w;
}

std::string seconds(double s) {
  std::ostringstream o;
  o << s << " s";
  return o.str();
}

}  // namespace

ImuResolution ImuResolution::shimmer3() {
  return {65.5, 83.0, 32767.0, 2047.0};
}

void ImuResolution::apply(ImuReading& reading) const {
  constexpr double kDeg = std::numbers::pi / 180.0;
  auto count = [](double v, double max) { return std::clamp(std::round(v), -max - 1.0, max); };
  for (int k = 0; k < 3; ++k) {
    double& g = reading.gyr[k];
    double& a = reading.acc[k];
    if (gyroCountsPerDegS > 0.0 && std::isfinite(g))
      g = count(g / kDeg * gyroCountsPerDegS, gyroMaxCount) / gyroCountsPerDegS * kDeg;
    if (accCountsPerMS2 > 0.0 && std::isfinite(a))
      a = count(a * accCountsPerMS2, accMaxCount) / accCountsPerMS2;
  }
}

ImuResolution parseResolution(const std::string& text) {
  if (text.empty() || text == "full") return {};
  if (text == "shimmer3") return ImuResolution::shimmer3();
  const auto colon = text.find(':');
  const std::string what = "resolution=" + text;
  if (colon == std::string::npos)
    throw std::invalid_argument(
        what + ": use full, shimmer3 or GYRO:ACC (counts per deg/s and per m/s^2)");
  auto perUnit = [&](const std::string& part) {
    try {
      std::size_t used = 0;
      const double v = std::stod(part, &used);
      if (used == part.size()) return v;
    } catch (const std::exception&) {
    }
    throw std::invalid_argument(what + ": '" + part + "' is not a number");
  };
  ImuResolution r;
  r.gyroCountsPerDegS = perUnit(text.substr(0, colon));
  r.accCountsPerMS2 = perUnit(text.substr(colon + 1));
  if (!(r.gyroCountsPerDegS > 0.0 && r.accCountsPerMS2 > 0.0) || r.gyroCountsPerDegS > 1e6 ||
      r.accCountsPerMS2 <= 0.0 || r.gyroCountsPerDegS > 1e6 || r.accCountsPerMS2 > 1e6)
    throw std::invalid_argument(what + ": counts per unit must be above 0 and at most 1e6");
  return r;
}

bool Faults::any() const {
  return !dropouts.empty() || !spikes.empty() || !saturations.empty() || !zeros.empty() ||
         !disappear.empty() || !stalls.empty() || !jumps.empty() || corruptProbability > 0.0 ||
         driftPpm != 0.0;
}

std::vector<Window> parseWindows(const std::string& text) {
  std::vector<Window> out;
  for (const std::string& part : split(text, '|')) out.push_back(window(part));
  return out;
}

std::vector<StreamWindow> parseStreamWindows(const std::string& text, const std::string& what) {
  std::vector<StreamWindow> out;
  for (const std::string& part : split(text, '|')) {
    const auto at = part.find('@');
    if (at == std::string::npos)
      throw std::invalid_argument("'" + part + "' is not a valid " + what +
                                  ": write STREAM@START+SECONDS");
    out.push_back({part.substr(0, at), window(part.substr(at + 1))});
  }
  return out;
}

std::vector<Dropout> parseDropouts(const std::string& text) {
  return parseStreamWindows(text, "dropout");
}

std::vector<Spike> parseSpikes(const std::string& text) {
  std::vector<Spike> out;
  for (const std::string& part : split(text, '|')) {
    const auto at = part.find('@');
    if (at == std::string::npos || at == 0)
      throw std::invalid_argument("'" + part + "' is not a valid spike: write STREAM@TIME or " +
                                  "STREAM@TIME:VALUE");
    const auto colon = part.find(':', at + 1);
    Spike s;
    s.stream = part.substr(0, at);
    s.at = number(
        part.substr(at + 1, colon == std::string::npos ? std::string::npos : colon - at - 1), part);
    if (colon != std::string::npos) s.value = number(part.substr(colon + 1), part);
    if (s.at < 0.0) throw std::invalid_argument("'" + part + "': the time must be >= 0");
    out.push_back(s);
  }
  return out;
}

std::vector<ClockJump> parseJumps(const std::string& text) {
  std::vector<ClockJump> out;
  for (const std::string& part : split(text, '|')) {
    const auto colon = part.find(':');
    if (colon == std::string::npos)
      throw std::invalid_argument("'" + part + "' is not a valid clock jump: write AT:SECONDS");
    ClockJump j{number(part.substr(0, colon), part), number(part.substr(colon + 1), part)};
    if (j.at < 0.0 || j.delta == 0.0)
      throw std::invalid_argument("'" + part + "': the time must be >= 0 and the step not 0");
    out.push_back(j);
  }
  return out;
}

VirtualArmSource::VirtualArmSource(const VirtualArmParams& params)
    : m_p(params), m_rng(params.sim.seed ^ 0x5eedf417ULL) {
  m_trajectory = makeTrajectory(m_p.trajectory, m_p.trajectoryOptions);
  const SimulationParams& s = m_p.sim;
  if (!(m_p.faults.corruptProbability >= 0.0 && m_p.faults.corruptProbability <= 1.0))
    throw std::invalid_argument("the corrupt-sample probability must be in [0, 1]");
  if (!std::isfinite(m_p.faults.driftPpm) || std::abs(m_p.faults.driftPpm) > 1000.0)
    throw std::invalid_argument("the clock drift must be within +-1000 ppm");
  SimulationParams sim = s;
  sim.includeTruth = m_p.truth;
  m_stream = std::make_unique<SensorStream>(*m_trajectory, sim);
  if (s.upperArm.enabled)
    m_streams.push_back({"upper", StreamRole::UpperArmImu, s.upperArm.rateHz});
  if (s.forearm.enabled) m_streams.push_back({"forearm", StreamRole::ForearmImu, s.forearm.rateHz});
  if (s.trunkImu.enabled) m_streams.push_back({"trunk", StreamRole::TrunkImu, s.trunkImu.rateHz});
  if (s.kinect.enabled)
    m_streams.push_back({"kinect", StreamRole::Optical, s.kinect.rateHz,
                         s.kinect.shoulder.value_or(s.trunk.enabled)});
  if (s.webcam.enabled) m_streams.push_back({"webcam", StreamRole::Camera, s.webcam.rateHz});
  // The simulator gives the truth on every IMU row, the trunk's with a moving trunk or a sternum
  // IMU (SensorSimulator.h).
  if (m_p.truth && (s.upperArm.enabled || s.forearm.enabled || s.trunkImu.enabled))
    m_streams.push_back({"truth", StreamRole::Truth,
                         std::max({s.upperArm.enabled ? s.upperArm.rateHz : 0.0,
                                   s.forearm.enabled ? s.forearm.rateHz : 0.0,
                                   s.trunkImu.enabled ? s.trunkImu.rateHz : 0.0}),
                         false, s.trunk.enabled || s.trunkImu.enabled});
  if (m_streams.empty()) throw std::invalid_argument("the virtual arm needs at least one sensor");
  // Every fault names a stream this arm has (and saturation one of its IMUs).
  auto checkStream = [&](const std::string& stream, const std::string& what, bool imuOnly) {
    std::string names;
    for (const VirtualStream& v : m_streams) {
      const bool imu = v.role == StreamRole::UpperArmImu || v.role == StreamRole::ForearmImu ||
                       v.role == StreamRole::TrunkImu;
      if (v.role == StreamRole::Truth && what != "dropout") continue;
      if (imuOnly && !imu) continue;
      if (v.name == stream) return;
      names += (names.empty() ? "" : ", ") + v.name;
    }
    throw std::invalid_argument(
        what + " of '" + stream + "', which this virtual arm does not have " +
        (names.empty() ? std::string("(it has no stream for it)") : "(it has " + names + ")"));
  };
  for (const Dropout& d : m_p.faults.dropouts) checkStream(d.stream, "dropout", false);
  for (const Spike& s : m_p.faults.spikes) checkStream(s.stream, "spike", false);
  for (const StreamWindow& w : m_p.faults.saturations) checkStream(w.stream, "saturation", true);
  for (const StreamWindow& w : m_p.faults.zeros) checkStream(w.stream, "zeros", false);
  m_dropped.assign(m_streams.size(), 0);
  m_corrupted.assign(m_streams.size(), 0);
  m_injected.assign(m_streams.size(), 0);
  m_inDropout.assign(m_streams.size(), false);
  m_inSaturation.assign(m_streams.size(), false);
  m_inZeros.assign(m_streams.size(), false);
  m_spikeDone.assign(m_p.faults.spikes.size(), false);
}

VirtualArmSource::~VirtualArmSource() = default;

int VirtualArmSource::streamIndex(StreamRole role) const {
  for (std::size_t i = 0; i < m_streams.size(); ++i)
    if (m_streams[i].role == role) return static_cast<int>(i);
  return -1;
}

double VirtualArmSource::imuClock(double t) const {
  return (t - m_clockBase) * (1.0 + m_p.faults.driftPpm * 1e-6) + m_jumpOffset;
}

void VirtualArmSource::skipTo(double t) {
  m_stream->skipTo(t);
}

void VirtualArmSource::emitRow(const ArmSample& row, std::vector<VirtualSample>& out,
                               std::vector<SourceEvent>& events) {
  const double t = row.t;
  // Link state.
  bool gone = false;
  for (const Window& w : m_p.faults.disappear) gone = gone || w.contains(t);
  if (gone && m_linkUp) {
    m_linkUp = false;
    events.push_back({SourceEventKind::LinkLost, t, -1,
                      "virtual arm: link lost at " + seconds(t) + " (injected)"});
  } else if (!gone && !m_linkUp) {
    m_linkUp = true;
    if (m_p.faults.restartClock) {
      m_clockBase = t;
      m_jumpOffset = 0.0;
    }
    events.push_back({SourceEventKind::LinkBack, t, -1,
                      std::string("virtual arm: link back at ") + seconds(t) +
                          (m_p.faults.restartClock ? ", its clock restarted from 0" : "")});
  }
  while (m_nextJump < m_p.faults.jumps.size() && m_p.faults.jumps[m_nextJump].at <= t) {
    m_jumpOffset += m_p.faults.jumps[m_nextJump].delta;
    events.push_back({SourceEventKind::ClockJump, t, -1,
                      "virtual arm: IMU clock stepped by " +
                          seconds(m_p.faults.jumps[m_nextJump].delta) + " (injected)"});
    ++m_nextJump;
  }
  bool stalled = false;
  for (const Window& w : m_p.faults.stalls) stalled = stalled || w.contains(t);
  if (stalled && !m_stalled)
    events.push_back({SourceEventKind::StallStart, t, -1,
                      "virtual arm: link stalled at " + seconds(t) + " (injected)"});
  m_stalled = stalled;

  auto deliver = [&](StreamRole role, double deviceTime, SensorPayload payload) {
    const int k = streamIndex(role);
    if (k < 0) return;
    const auto i = static_cast<std::size_t>(k);
    bool dropping = false;
    for (const Dropout& d : m_p.faults.dropouts)
      dropping = dropping || (d.stream == m_streams[i].name && d.window.contains(t));
    if (dropping != m_inDropout[i]) {
      m_inDropout[i] = dropping;
      events.push_back(
          {dropping ? SourceEventKind::DropoutStart : SourceEventKind::DropoutEnd, t, k,
           "virtual arm: " + m_streams[i].name + (dropping ? " dropped out at " : " back at ") +
               seconds(t) + (dropping ? " (injected)" : "")});
    }
    if (gone || dropping) {
      if (role != StreamRole::Truth) ++m_dropped[i];
      return;
    }
    injectValues(i, t, payload, events);
    if (auto* imu = std::get_if<ImuReading>(&payload)) m_p.resolution.apply(*imu);
    if (auto* imu = std::get_if<ImuReading>(&payload); imu && m_p.faults.corruptProbability > 0.0) {
      if (std::uniform_real_distribution<double>(0.0, 1.0)(m_rng) < m_p.faults.corruptProbability) {
        imu->acc.x() = std::numeric_limits<double>::quiet_NaN();
        ++m_corrupted[i];
      }
    }
    VirtualSample s{k, deviceTime, std::move(payload)};
    if (stalled)
      m_held.push_back(std::move(s));
    else
      out.push_back(std::move(s));
  };

  const double imuT = imuClock(t);
  const std::optional<ImuReading>& upper = m_p.swapImus ? row.forearm : row.upperArm;
  const std::optional<ImuReading>& forearm = m_p.swapImus ? row.upperArm : row.forearm;
  if (upper) deliver(StreamRole::UpperArmImu, imuT, *upper);
  if (forearm) deliver(StreamRole::ForearmImu, imuT, *forearm);
  if (row.trunk) deliver(StreamRole::TrunkImu, imuT, *row.trunk);
  if (row.elbow || row.wrist || row.shoulder)
    deliver(StreamRole::Optical, t, OpticalPositions{row.elbow, row.wrist, row.shoulder});
  if (row.camWrist || row.camElbow)
    deliver(StreamRole::Camera, t, MarkerPixels{row.camWrist, row.camElbow});
  if (row.trueAngles) deliver(StreamRole::Truth, imuT, TruthAngles{*row.trueAngles, row.trueTrunk});
}

void VirtualArmSource::injectValues(std::size_t i, double t, SensorPayload& payload,
                                    std::vector<SourceEvent>& events) {
  const std::string& name = m_streams[i].name;
  const int k = static_cast<int>(i);
  auto fill = [&payload](double v) {
    std::visit(
        [v](auto& p) {
          using P = std::decay_t<decltype(p)>;
          if constexpr (std::is_same_v<P, ImuReading>) {
            p.gyr.setConstant(v);
            p.acc.setConstant(v);
          } else if constexpr (std::is_same_v<P, OpticalPositions>) {
            if (p.elbow) p.elbow->setConstant(v);
            if (p.wrist) p.wrist->setConstant(v);
            if (p.shoulder) p.shoulder->setConstant(v);
          } else if constexpr (std::is_same_v<P, MarkerPixels>) {
            if (p.wrist) p.wrist->setConstant(v);
            if (p.elbow) p.elbow->setConstant(v);
          }
        },
        payload);
  };
  auto during = [&](const std::vector<StreamWindow>& windows) {
    for (const StreamWindow& w : windows)
      if (w.stream == name && w.window.contains(t)) return true;
    return false;
  };
  auto edge = [&](bool now, std::vector<bool>& state, const std::string& from,
                  const std::string& until) {
    if (now == state[i]) return;
    state[i] = now;
    events.push_back(
        {SourceEventKind::Injected, t, k,
         "virtual arm: " + name + (now ? from : until) + seconds(t) + (now ? " (injected)" : "")});
  };
  bool replaced = false;
  const bool zeros = during(m_p.faults.zeros);
  edge(zeros, m_inZeros, " reads all zeros from ", " reads again after zeros at ");
  if (zeros) {
    fill(0.0);
    replaced = true;
  }
  const bool saturated = during(m_p.faults.saturations);
  edge(saturated, m_inSaturation, " saturated at full scale from ", " no longer saturated at ");
  if (auto* imu = std::get_if<ImuReading>(&payload); imu && saturated) {
    imu->gyr.setConstant(kGyroFullScale);
    imu->acc.setConstant(kAccelFullScale);
    replaced = true;
  }
  for (std::size_t s = 0; s < m_p.faults.spikes.size(); ++s) {
    const Spike& spike = m_p.faults.spikes[s];
    if (m_spikeDone[s] || spike.stream != name || t < spike.at) continue;
    m_spikeDone[s] = true;
    fill(spike.value);
    replaced = true;
    std::ostringstream text;
    text << "virtual arm: " << name << " spike of " << spike.value << " at " << seconds(t)
         << " (injected)";
    events.push_back({SourceEventKind::Injected, t, k, text.str()});
  }
  if (replaced) ++m_injected[i];
}

void VirtualArmSource::advance(double t, std::vector<VirtualSample>& out,
                               std::vector<SourceEvent>& events) {
  if (m_finished) return;
  while (m_stream->nextTime() <= t) {
    const std::optional<ArmSample> row = m_stream->next();
    if (!row) break;
    const bool wasStalled = m_stalled;
    std::vector<VirtualSample> now;
    emitRow(*row, now, events);
    if (wasStalled && !m_stalled) {
      events.push_back({SourceEventKind::StallEnd, row->t, -1,
                        "virtual arm: link delivered " + std::to_string(m_held.size()) +
                            " held samples at " + seconds(row->t)});
      for (VirtualSample& s : m_held) out.push_back(std::move(s));
      m_held.clear();
    }
    for (VirtualSample& s : now) out.push_back(std::move(s));
  }
  if (!std::isfinite(m_stream->nextTime())) {
    for (VirtualSample& s : m_held) out.push_back(std::move(s));
    m_held.clear();
    m_finished = true;
    events.push_back({SourceEventKind::Finished, t, -1, "virtual arm: simulation finished"});
  }
}

}  // namespace armtrack::devices::virtualarm
