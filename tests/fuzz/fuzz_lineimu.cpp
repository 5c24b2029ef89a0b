// libFuzzer target: arbitrary bytes, split into arbitrary chunks, into the line-protocol parser.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "devices/lineimu/LineImuParser.h"

using namespace armtrack::devices::lineimu;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t control = data[0];
  const std::size_t chunk = (control & 0x3F) + 1;
  LineImuParser parser;
  std::vector<Sample> out;
  for (std::size_t k = 1; k < size; k += chunk) {
    parser.feed(std::span(data + k, std::min(chunk, size - k)), out);
    if (control & 0x80) parser.endOfDatagram();  // UDP: each chunk a datagram
  }
  std::uint64_t last = 0;
  std::uint32_t epoch = 0;
  for (const Sample& s : out) {
    if (s.epoch < epoch) std::abort();
    if (s.epoch != epoch) last = 0;  // a $HELLO starts the device clock anew
    epoch = s.epoch;
    if (s.deviceTimeUs < last) std::abort();
    last = s.deviceTimeUs;
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(s.gyr[i]) || !std::isfinite(s.acc[i])) std::abort();
  }
  return 0;
}
