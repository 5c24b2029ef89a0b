// The live session's word when the trunk moves and no trunk IMU measures it (docs/session.md,
// "Messages"): the shoulder angles then include the patient's lean. Fed the trunk motion
// detector's decision row by row (core/estimation/TrunkMotionDetector.h); plain C++, no Qt.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/estimation/TrunkMotionDetector.h"

namespace armtrack::session {

/// Says when the trunk has left its start pose, naming the time and how far the shoulder went,
/// and when it is back. A patient who leans on every reach would hear it every few seconds: a
/// departure is told at most once per everySeconds, with the ones in between counted in the next
/// message (their returns are not told). Never says anything while the detector reports a still
/// trunk. Not thread-safe: the worker thread owns it.
class TrunkMessages {
 public:
  explicit TrunkMessages(double everySeconds = 10.0);

  /// After the detector's decision for the row at time t (s, session time): appends what is new.
  void update(const TrunkMotionStatus& status, double t, std::vector<std::string>& out);
  /// At the end of the session: the departures not told yet.
  void finish(std::vector<std::string>& out);

 private:
  double m_every;
  bool m_away = false;       // the trunk is away now
  bool m_told = false;       // the current departure was told
  double m_awaySince = 0.0;  // time the current departure began
  double m_farthest = 0.0;   // the shoulder's largest displacement in it (m)
  double m_lastTold = -std::numeric_limits<double>::infinity();  // time of the last departure told
  std::uint64_t m_untold = 0;   // departures not told since the last one that was
  double m_untoldSince = 0.0;   // the first of them
  double m_untoldLatest = 0.0;  // the latest row away among them
  double m_untoldFarthest = 0.0;
};

}  // namespace armtrack::session
