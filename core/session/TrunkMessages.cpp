#include "core/session/TrunkMessages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace armtrack::session {

namespace {

std::string seconds(double t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", t);
  return buf;
}

std::string centimetres(double m) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f cm", std::max(1.0, std::round(m * 100.0)));
  return buf;
}

const char* kWhatItMeans =
    ": the shoulder angles include the patient's lean. Ask the patient to sit back, or add a "
    "sternum sensor.";

}  // namespace

TrunkMessages::TrunkMessages(double everySeconds) : m_every(everySeconds) {}

void TrunkMessages::update(const TrunkMotionStatus& status, double t,
                           std::vector<std::string>& out) {
  if (status.moving) {
    if (!m_away) {
      m_away = true;
      m_awaySince = t;
      m_farthest = 0.0;
      m_told = t - m_lastTold >= m_every;
      if (m_told) {
        std::string text = "The trunk moved from its start pose at " + seconds(t) + " (shoulder " +
                           centimetres(status.displacementM) + " away";
        if (m_untold > 0)
          text += "; it also moved " + std::to_string(m_untold) +
                  (m_untold == 1 ? " time" : " times") + " between " + seconds(m_untoldSince) +
                  " and " + seconds(m_untoldLatest) + ", the shoulder up to " +
                  centimetres(m_untoldFarthest) + " away";
        out.push_back(text + ")" + kWhatItMeans);
        m_lastTold = t;
        m_untold = 0;
        m_untoldFarthest = 0.0;
      } else if (m_untold++ == 0) {
        m_untoldSince = t;
      }
    }
    m_farthest = std::max(m_farthest, status.displacementM);
    if (!m_told) {
      m_untoldLatest = t;
      m_untoldFarthest = std::max(m_untoldFarthest, status.displacementM);
    }
    return;
  }
  if (!m_away) return;
  m_away = false;
  if (m_told)
    out.push_back("The trunk is back at its start pose at " + seconds(t) + " (it was away " +
                  seconds(t - m_awaySince) + ", the shoulder up to " + centimetres(m_farthest) +
                  " away).");
}

void TrunkMessages::finish(std::vector<std::string>& out) {
  if (m_untold == 0) return;
  out.push_back("The trunk moved from its start pose " + std::to_string(m_untold) +
                (m_untold == 1 ? " more time" : " more times") + " between " +
                seconds(m_untoldSince) + " and " + seconds(m_untoldLatest) +
                " (the shoulder up to " + centimetres(m_untoldFarthest) + " away)" + kWhatItMeans);
  m_untold = 0;
}

}  // namespace armtrack::session
