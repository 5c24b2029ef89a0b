// libFuzzer target: one input = one UDP datagram into the skeleton JSON parser.
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "devices/skeleton/SkeletonParser.h"

using namespace armtrack::devices::skeleton;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  SkeletonParser parser;
  const auto frame = parser.parseDatagram(std::span(data, size));
  if (frame) {
    for (const auto* j : {&frame->shoulder, &frame->elbow, &frame->wrist})
      if (*j)
        for (double v : (*j)->position)
          if (!std::isfinite(v)) std::abort();
    // What we accept, we can write back and read again.
    SkeletonParser again;
    if (!again.parseDatagram(encode(*frame))) std::abort();
  }
  return 0;
}
