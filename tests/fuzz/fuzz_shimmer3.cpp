// libFuzzer target: arbitrary bytes, split into arbitrary chunks, into the Shimmer3 parser.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "devices/shimmer3/Shimmer3Parser.h"

using namespace armtrack::devices::shimmer3;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t control = data[0];
  Shimmer3Parser parser;
  if (control & 0x80) {  // start configured, as after an inquiry answered before streaming
    const std::uint8_t inquiry[] = {0x02, 0x40, 0x00, 0x00, 0x00, 0x00, 0x00, 0x07,
                                    0x01, 0x00, 0x01, 0x02, 0x0A, 0x0B, 0x0C, 0x04};
    parser.setConfig(*parseInquiryResponse(inquiry));
  }
  const std::size_t chunk = (control & 0x3F) + 1;
  std::vector<Sample> out;
  std::uint64_t lastTicks = 0;
  for (std::size_t k = 1; k < size; k += chunk) {
    const std::size_t n = std::min(chunk, size - k);
    parser.feed(std::span(data + k, n), out);
  }
  parser.flush(out);
  for (const Sample& s : out) {
    if (s.ticks < lastTicks) std::abort();  // time must never go back
    lastTicks = s.ticks;
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(s.gyr[i]) || !std::isfinite(s.acc[i])) std::abort();
  }
  return 0;
}
