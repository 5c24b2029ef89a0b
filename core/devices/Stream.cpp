#include "core/devices/Stream.h"

#include <chrono>

namespace armtrack {

double hostNow() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

const char* toString(DeviceState state) {
  switch (state) {
    case DeviceState::Disconnected:
      return "disconnected";
    case DeviceState::Connecting:
      return "connecting";
    case DeviceState::Streaming:
      return "streaming";
    case DeviceState::Error:
      return "error";
  }
  return "?";
}

}  // namespace armtrack
