#include "devices/skeleton/StartOrigin.h"

#include <algorithm>

namespace armtrack::devices::skeleton {

void StartOrigin::add(double t, const std::array<double, 3>& shoulder) {
  if (m_fixed) return;
  if (!m_t0) m_t0 = t;
  if (!(t >= *m_t0) || t - *m_t0 > m_window || m_seen.size() >= kMaxFrames) {
    // Nothing seen yet cannot happen here: the first frame always opens the window.
    m_fixed = true;
    return;
  }
  m_seen.push_back(shoulder);
  std::vector<double> axis(m_seen.size());
  for (int k = 0; k < 3; ++k) {
    for (std::size_t i = 0; i < m_seen.size(); ++i)
      axis[i] = m_seen[i][static_cast<std::size_t>(k)];
    std::sort(axis.begin(), axis.end());
    const std::size_t n = axis.size();
    m_origin[static_cast<std::size_t>(k)] =
        n % 2 ? axis[n / 2] : 0.5 * (axis[n / 2 - 1] + axis[n / 2]);
  }
}

std::optional<std::array<double, 3>> StartOrigin::origin() const {
  if (m_seen.empty()) return std::nullopt;
  return m_origin;
}

void StartOrigin::reset() {
  m_t0.reset();
  m_seen.clear();
  m_origin = {};
  m_fixed = false;
}

}  // namespace armtrack::devices::skeleton
