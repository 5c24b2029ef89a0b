// The fixed world origin of the skeleton plugin's origin=start (docs/devices/skeleton-udp.md):
// where the tracked shoulder was while the trunk sat upright at the start. Plain C++20, no Qt.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace armtrack::devices::skeleton {

/// The origin is the per-axis median of the shoulder positions of the first `windowSeconds` of
/// tracker time (from the first frame with a shoulder), so one wild frame does not move it; it is
/// fixed after that window. Until then it is the median so far: the first frame's own shoulder at
/// first. Not thread-safe: one owner.
class StartOrigin {
 public:
  static constexpr std::size_t kMaxFrames = 1024;  ///< a faster tracker fixes the origin earlier

  explicit StartOrigin(double windowSeconds = 1.0) : m_window(windowSeconds) {}

  /// A shoulder position (m, any frame, as long as it is always the same) at tracker time t (s).
  /// A time after the window, or before its start (a restarted tracker clock), fixes the origin.
  void add(double t, const std::array<double, 3>& shoulder);
  /// The origin so far; empty before the first shoulder.
  std::optional<std::array<double, 3>> origin() const;
  /// True once the window is over and the origin no longer changes.
  bool fixed() const { return m_fixed; }
  /// Forgets everything (a new session).
  void reset();

 private:
  double m_window;
  std::optional<double> m_t0;
  std::vector<std::array<double, 3>> m_seen;
  std::array<double, 3> m_origin{};
  bool m_fixed = false;
};

}  // namespace armtrack::devices::skeleton
