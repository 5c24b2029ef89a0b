#include "devices/replay/ReplayDevice.h"

namespace armtrack::devices::replay {

std::vector<StreamInfo> ReplayDevice::describe(const Recording& rec) {
  bool up = false, fa = false, opt = false, cam = false, truth = false;
  for (const ArmSample& s : rec.samples) {
    up |= s.upperArm.has_value();
    fa |= s.forearm.has_value();
    opt |= s.elbow.has_value() || s.wrist.has_value();
    cam |= s.camWrist.has_value() || s.camElbow.has_value();
    truth |= s.trueAngles.has_value();
  }
  std::vector<StreamInfo> out;
  const double duration = rec.samples.empty() ? 0.0 : rec.samples.back().t - rec.samples.front().t;
  auto rate = [&](auto has) {
    std::size_t n = 0;
    for (const ArmSample& s : rec.samples) n += has(s);
    return duration > 0.0 ? static_cast<double>(n - 1) / duration : 0.0;
  };
  if (up) out.push_back({"upper", StreamRole::UpperArmImu, rate([](const ArmSample& s) { return s.upperArm.has_value(); }), 0.0, {}});
  if (fa) out.push_back({"forearm", StreamRole::ForearmImu, rate([](const ArmSample& s) { return s.forearm.has_value(); }), 0.0, {}});
  if (opt) out.push_back({"optical", StreamRole::Optical, rate([](const ArmSample& s) { return s.elbow || s.wrist; }), 0.0, {}});
  if (cam) out.push_back({"camera", StreamRole::Camera, rate([](const ArmSample& s) { return s.camWrist || s.camElbow; }), 0.0, rec.meta.camera});
  if (truth) out.push_back({"truth", StreamRole::Truth, rate([](const ArmSample& s) { return s.trueAngles.has_value(); }), 0.0, {}});
  return out;
}

ReplayDevice::ReplayDevice(Recording recording, double speed, bool loop)
    : Device(describe(recording)), m_rec(std::move(recording)), m_speed(speed), m_loop(loop) {
  m_streamOf.assign(5, -1);
  for (std::size_t i = 0; i < streams().size(); ++i)
    m_streamOf[static_cast<std::size_t>(streams()[i].role)] = static_cast<int>(i);
}

void ReplayDevice::start() {
  if (m_timer) return;
  m_next = 0;
  m_timeOffset = 0.0;
  m_startHost = hostNow();
  m_timer = new QTimer(this);
  m_timer->setTimerType(Qt::PreciseTimer);
  m_timer->setInterval(2);
  connect(m_timer, &QTimer::timeout, this, &ReplayDevice::tick);
  m_timer->start();
  setState(DeviceState::Streaming, QStringLiteral("replaying %1 rows at %2x")
                                       .arg(m_rec.samples.size())
                                       .arg(m_speed));
}

void ReplayDevice::stop() {
  delete m_timer;
  m_timer = nullptr;
  setState(DeviceState::Disconnected, QStringLiteral("stopped"));
}

void ReplayDevice::tick() {
  if (m_rec.samples.empty()) {
    stop();
    return;
  }
  const double t0 = m_rec.samples.front().t;
  const double due = t0 + (hostNow() - m_startHost) * m_speed;
  const double arrival = hostNow();
  SampleBatch batch;
  auto add = [&](StreamRole role, double t, SensorPayload p) {
    const int k = m_streamOf[static_cast<std::size_t>(role)];
    if (k >= 0) batch.push_back({k, t + m_timeOffset, arrival, std::move(p)});
  };
  while (m_next < m_rec.samples.size() && m_rec.samples[m_next].t <= due) {
    const ArmSample& s = m_rec.samples[m_next++];
    if (s.upperArm) add(StreamRole::UpperArmImu, s.t, *s.upperArm);
    if (s.forearm) add(StreamRole::ForearmImu, s.t, *s.forearm);
    if (s.elbow || s.wrist) add(StreamRole::Optical, s.t, OpticalPositions{s.elbow, s.wrist});
    if (s.camWrist || s.camElbow) add(StreamRole::Camera, s.t, MarkerPixels{s.camWrist, s.camElbow});
    if (s.trueAngles) add(StreamRole::Truth, s.t, TruthAngles{*s.trueAngles});
  }
  publish(batch);
  if (m_next < m_rec.samples.size()) return;
  if (m_loop) {
    // Device time continues past the end, one mean sample step after the last row.
    const double span = m_rec.samples.back().t - t0;
    const double step = m_rec.samples.size() > 1 ? span / static_cast<double>(m_rec.samples.size() - 1) : 0.001;
    m_timeOffset += span + step;
    m_startHost += (span + step) / m_speed;
    m_next = 0;
    return;
  }
  m_timer->stop();
  setState(DeviceState::Disconnected, QStringLiteral("end of the recording"));
}

}  // namespace armtrack::devices::replay
