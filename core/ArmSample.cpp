#include "core/ArmSample.h"

namespace armtrack {

ArmSample mirrorSample(const ArmSample& s) {
  ArmSample m = s;
  if (s.upperArm) m.upperArm = mirrorImu(*s.upperArm);
  if (s.forearm) m.forearm = mirrorImu(*s.forearm);
  if (s.elbow) m.elbow = mirrorPoint(*s.elbow);
  if (s.wrist) m.wrist = mirrorPoint(*s.wrist);
  if (s.trunk) m.trunk = mirrorImu(*s.trunk);
  if (s.shoulder) m.shoulder = mirrorPoint(*s.shoulder);
  return m;
}

}  // namespace armtrack
