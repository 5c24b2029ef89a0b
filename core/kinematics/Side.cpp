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

ArmSample mirrorSample(const ArmSample& s) {
  ArmSample m = s;
  if (s.upperArm) m.upperArm = mirrorImu(*s.upperArm);
  if (s.forearm) m.forearm = mirrorImu(*s.forearm);
  if (s.elbow) m.elbow = mirrorPoint(*s.elbow);
  if (s.wrist) m.wrist = mirrorPoint(*s.wrist);
  return m;
}

}  // namespace armtrack
