#include "core/metrics/SessionTime.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <regex>

namespace armtrack {

namespace {
// Not std::stod: the C library's number format follows the user's locale (a comma in German).
double number(const std::string& text) {
  double v = 0;
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}
}  // namespace

double firstConvergedTime(const std::vector<double>& times, double startupSeconds) {
  if (times.empty()) return 0;
  const double settled = times.front() + startupSeconds;
  const auto it = std::lower_bound(times.begin(), times.end(), settled);
  return it == times.end() ? times.front() : *it;
}

std::string eventLine(const EventMark& event) {
  const double s = std::isfinite(event.recordingS) ? event.recordingS : 0.0;
  const long tenths = std::lround(std::abs(s) * 10);
  char time[32];
  std::snprintf(time, sizeof time, "%s%ld:%02ld.%ld", s < 0 && tenths > 0 ? "-" : "", tenths / 600,
                (tenths / 10) % 60, tenths % 10);
  std::string label = event.label;
  std::replace(label.begin(), label.end(), '\n', ' ');
  return "[" + std::string(time) + "] " + label;
}

std::vector<EventMark> parseEventMarks(std::string_view notes, double recordingStartS) {
  std::vector<EventMark> out;
  static const std::regex line(R"(^\s*\[(-?)(\d+):(\d{1,2}(?:\.\d+)?)\]\s*(.*?)\s*$)");
  static const std::regex legacyItem(R"((?:^|;)\s*(\d+(?:\.\d+)?) s: ([^;]*))");
  std::size_t from = 0;
  while (from <= notes.size()) {
    std::size_t to = notes.find('\n', from);
    if (to == std::string_view::npos) to = notes.size();
    const std::string text(notes.substr(from, to - from));
    from = to + 1;
    std::smatch m;
    if (std::regex_match(text, m, line)) {
      const double s = number(m[2].str()) * 60 + number(m[3].str());
      out.push_back({m[1].length() > 0 ? -s : s, m[4].str()});
      continue;
    }
    // The older form: one line "<word>: 28.4 s: Pain; 30.0 s: Rest" on the session clock.
    const std::size_t colon = text.find(": ");
    if (colon == std::string::npos || text.find(' ') < colon) continue;
    const std::string items = text.substr(colon + 1);
    for (auto it = std::sregex_iterator(items.begin(), items.end(), legacyItem);
         it != std::sregex_iterator(); ++it) {
      std::string label = (*it)[2].str();
      while (!label.empty() && label.back() == ' ') label.pop_back();
      out.push_back({recordingTime(number((*it)[1].str()), recordingStartS), label});
    }
  }
  return out;
}

std::string notesWithoutEvents(std::string_view notes) {
  std::string out;
  std::size_t from = 0;
  while (from <= notes.size()) {
    std::size_t to = notes.find('\n', from);
    if (to == std::string_view::npos) to = notes.size();
    const std::string_view line = notes.substr(from, to - from);
    from = to + 1;
    if (!parseEventMarks(line, 0).empty()) continue;
    if (!out.empty()) out += '\n';
    out += line;
  }
  return out;
}

}  // namespace armtrack
