// One time base for a stored session wherever a therapist reads times (docs/metrics.md, "Times
// of a session"): recording time, the seconds since the recording's first stored row, which the
// review's slider shows from 0:00. The samples, estimates and metrics keep the session clock (the
// devices' time since the session started); the review's table, plots and slider, the PDF report
// and the event markers convert with recordingTime(). Plain C++, no Qt.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace armtrack {

/// A time on the session clock (s) as recording time: since the first recorded row.
inline double recordingTime(double sessionClockS, double recordingStartS) {
  return sessionClockS - recordingStartS;
}

/// The first time the review opens on (session clock, s): the first estimate after the filter's
/// start-up second (kStartupSeconds after the first estimate), whose angles have converged; the
/// first estimate itself when the estimates end sooner. times: ascending; 0 when empty.
double firstConvergedTime(const std::vector<double>& times, double startupSeconds);

/// An event the therapist marked during a session: its recording time and label.
struct EventMark {
  double recordingS = 0;  ///< s since the first recorded row (negative: before recording began)
  std::string label;
};

/// The event as a line of the session's notes: "[m:ss.s] label", in recording time, e.g.
/// "[0:15.4] Pain"; "[-0:02.0] Rest" for one marked before the recording began.
std::string eventLine(const EventMark& event);

/// The events in a session's notes: each "[m:ss.s] label" line (eventLine), and the items of an
/// older notes line "Events: 28.4 s: Pain; 30.0 s: Rest" (any first word), whose times are on the
/// session clock and become recording time with recordingStartS. In the order found.
std::vector<EventMark> parseEventMarks(std::string_view notes, double recordingStartS);

/// The notes without the lines parseEventMarks reads as events, for printing them beside a list
/// of the events in recording time.
std::string notesWithoutEvents(std::string_view notes);

}  // namespace armtrack
