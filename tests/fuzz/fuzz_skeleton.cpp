// libFuzzer target: one input = one UDP datagram into the skeleton JSON parser, and an accepted
// frame's shoulder into origin=start's world origin (StartOrigin).
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "devices/skeleton/SkeletonParser.h"
#include "devices/skeleton/StartOrigin.h"

using namespace armtrack::devices::skeleton;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  SkeletonParser parser;
  const auto frame = parser.parseDatagram(std::span(data, size));
  if (frame) {
    for (const auto* j : {&frame->shoulder, &frame->elbow, &frame->wrist})
      if (*j)
        for (double v : (*j)->position)
          if (!std::isfinite(v)) std::abort();
    // The first shoulder is the origin, exactly; a second one at the same time moves it to the
    // midpoint, which stays finite.
    if (frame->shoulder) {
      StartOrigin origin;
      origin.add(frame->t, frame->shoulder->position);
      const auto first = origin.origin();
      if (!first || *first != frame->shoulder->position) std::abort();
      origin.add(frame->t, {0.0, 0.0, 0.0});
      const auto both = origin.origin();
      if (!both) std::abort();
      for (double v : *both)
        if (!std::isfinite(v)) std::abort();
    }
    // What we accept, we can write back and read again.
    SkeletonParser again;
    if (!again.parseDatagram(encode(*frame))) std::abort();
  }
  return 0;
}
