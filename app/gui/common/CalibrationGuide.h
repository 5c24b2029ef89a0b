// The sensor-to-segment calibration protocol of docs/calibration.md as the screen guides it:
// what to do in each phase, for how long, and the pose to reach. The times are those of the
// simulated protocol (core/simulation CalibrationProtocolTrajectory, which the virtual arm plays
// with trajectory=calibration); test_calibration_pages holds the two together.
#pragma once

#include <QString>
#include <array>
#include <optional>
#include <vector>

namespace armtrack::app::gui {

struct CalibrationPhase {
  double startS = 0, endS = 0;  ///< protocol time (s)
  bool hold = false;            ///< keep still (true) or move
  QString title;                ///< short, the English source text: "Start pose"
  QString instruction;          ///< what the patient does, the English source text
  /// The pose to reach or hold, joint angles [th0 th1 th2 th4 th5] in degrees (the movements
  /// have none: they go back and forth).
  std::optional<std::array<double, 5>> poseDeg;

  /// title and instruction in the current language (made when asked, so a change of language
  /// shows at once).
  QString shownTitle() const;
  QString shownInstruction() const;
};

/// The phases in time order, from 0 to protocolSeconds().
const std::vector<CalibrationPhase>& calibrationPhases();
double protocolSeconds();
/// The phase at protocol time t (s); the last one after the end, the first before 0.
const CalibrationPhase& phaseAt(double t);

}  // namespace armtrack::app::gui
