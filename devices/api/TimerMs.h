// A QTimer's interval from a setting in seconds, rounded to the millisecond.
#pragma once

#include <cmath>

namespace armtrack::devices {

inline int timerMs(double seconds) {
  return static_cast<int>(std::lround(seconds * 1000.0));
}

}  // namespace armtrack::devices
