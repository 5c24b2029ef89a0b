#include "core/session/EstimatorMessages.h"

#include <cstdio>

namespace armtrack::session {

namespace {

std::string at(double t) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3f s", t);
  return buf;
}

const char* kRecovered = "lost the arm and re-initialised from the recent data";
const char* kRecoveredTail = "; the angles may jump there without the arm having moved";
const char* kRestarted = "restarted after a gap in the data";

}  // namespace

EstimatorMessages::EstimatorMessages(std::array<std::string, kNumSensorBlocks> blockStreams,
                                     double quietSeconds, double summarySeconds)
    : m_blockStreams(std::move(blockStreams)), m_quiet(quietSeconds), m_every(summarySeconds) {}

std::string EstimatorMessages::streamsOf(const GateCounters& delta) const {
  std::string names;
  for (int b = 0; b < kNumSensorBlocks; ++b) {
    const std::string& name = m_blockStreams[static_cast<std::size_t>(b)];
    if (name.empty() || delta.byBlock(static_cast<SensorBlock>(b)) == 0) continue;
    if (names.find(name) != std::string::npos) continue;  // elbow and wrist share a stream
    names += (names.empty() ? "" : ", ") + name;
  }
  return names.empty() ? std::string() : " (" + names + ")";
}

void EstimatorMessages::summarise(const GateCounters& now, bool goingOn,
                                  std::vector<std::string>& out) {
  GateCounters d;
  for (int b = 0; b < kNumSensorBlocks; ++b)
    for (int w = 0; w < kNumImplausible; ++w)
      d.refused[b][w] = now.refused[b][w] - m_summarised.refused[b][w];
  d.samplesWithRefusal = now.samplesWithRefusal - m_summarised.samplesWithRefusal;
  d.firstT = m_sinceT;
  d.lastT = m_lastRefusalT;
  m_summarised = now;
  if (d.total() == 0) return;
  out.push_back("estimator" + streamsOf(d) + ": " + d.summary() +
                (goingOn ? "; still refusing" : "; refusals stopped"));
}

void EstimatorMessages::tell(Throttle& th, std::uint64_t count, double t, const std::string& event,
                             const std::string& tail, std::vector<std::string>& out, bool force) {
  if (count < th.latest) th = Throttle{};  // the estimator was reset
  if (count > th.latest) {
    if (th.latest == th.told) th.pendingT = t;
    th.latestT = t;
  }
  th.latest = count;
  if (th.latest == th.told) return;
  if (!force && t - th.lastT < 1.0) return;
  const std::uint64_t n = th.latest - th.told;
  std::string text = "estimator: " + event;
  if (n == 1)
    text += " at " + at(th.latestT);
  else
    text +=
        " " + std::to_string(n) + " times between " + at(th.pendingT) + " and " + at(th.latestT);
  text += " (" + std::to_string(count) + " in this session)" + tail;
  out.push_back(std::move(text));
  th.told = th.latest;
  th.lastT = t;
}

void EstimatorMessages::update(const EstimatorCounters& counters, double t,
                               std::vector<std::string>& out) {
  const GateCounters& g = counters.implausible;
  const std::uint64_t total = g.total();
  if (total < m_seen) {  // the estimator was reset: start the account again
    m_summarised = GateCounters{};
    m_seen = 0;
    m_refusing = false;
  }
  if (total > m_seen) {
    if (m_seen == m_summarised.total()) m_sinceT = g.lastT;  // first refusal not summed up
    if (!m_refusing) {
      m_refusing = true;
      m_summaryT = t;
      // What the new refusals are (everything before them has been summed up), by sensor.
      std::string what;
      for (int b = 0; b < kNumSensorBlocks; ++b) {
        std::string whys;
        for (int w = 0; w < kNumImplausible; ++w)
          if (g.refused[b][w] > m_summarised.refused[b][w])
            whys += (whys.empty() ? "" : ", ") +
                    std::string(implausibleName(static_cast<Implausible>(w)));
        if (whys.empty()) continue;
        const std::string& stream = m_blockStreams[static_cast<std::size_t>(b)];
        what += (what.empty() ? "" : "; ") +
                std::string(sensorBlockName(static_cast<SensorBlock>(b))) +
                (stream.empty() ? "" : " (" + stream + ")") + ": " + whys;
      }
      out.push_back("estimator: refusing implausible readings from the " + what + " at " +
                    at(g.lastT) + "; they are not used, counted and summed up when they stop");
    }
    m_lastRefusalT = g.lastT;
    m_seen = total;
    m_latest = g;
  }
  if (m_refusing) {
    if (t - m_lastRefusalT > m_quiet) {
      summarise(g, false, out);
      m_refusing = false;
    } else if (t - m_summaryT >= m_every) {
      summarise(g, true, out);
      m_summaryT = t;
    }
  }
  tell(m_recoveries, counters.recoveries, t, kRecovered, kRecoveredTail, out, false);
  tell(m_restarts, counters.restarts, t, kRestarted, "", out, false);
}

void EstimatorMessages::finish(std::vector<std::string>& out) {
  if (m_refusing) summarise(m_latest, false, out);
  m_refusing = false;
  tell(m_recoveries, m_recoveries.latest, m_recoveries.latestT, kRecovered, kRecoveredTail, out,
       true);
  tell(m_restarts, m_restarts.latest, m_restarts.latestT, kRestarted, "", out, true);
}

}  // namespace armtrack::session
