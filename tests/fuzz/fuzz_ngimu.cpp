// libFuzzer target: one input = one UDP datagram into the NGIMU/OSC parser.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "devices/ngimu/NgimuParser.h"

using namespace armtrack::devices::ngimu;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  NgimuParser parser;
  std::vector<SensorsSample> out;
  parser.parseDatagram(std::span(data, size), out);
  for (const SensorsSample& s : out) {
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(s.gyr[i]) || !std::isfinite(s.acc[i]) || !std::isfinite(s.mag[i]))
        std::abort();
    if (!std::isfinite(s.pressurePa)) std::abort();
  }
  return 0;
}
