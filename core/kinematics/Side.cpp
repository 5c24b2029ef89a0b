#include "core/kinematics/Side.h"

#include <stdexcept>

#include "core/Strings.h"

namespace armtrack {

Side parseSide(const std::string& name) {
  const std::string s = asciiLower(name);
  if (s == "right") return Side::Right;
  if (s == "left") return Side::Left;
  throw std::invalid_argument("unknown side \"" + name + "\": expected \"left\" or \"right\"");
}

std::string sideName(Side side) {
  return side == Side::Left ? "left" : "right";
}

}  // namespace armtrack
