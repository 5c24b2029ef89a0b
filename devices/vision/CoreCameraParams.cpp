#include "devices/vision/CoreCameraParams.h"

namespace armtrack::devices::webcam {

std::optional<CameraParams> toCameraParams(const CameraFile& file) {
  if (!file.extrinsics) return std::nullopt;
  CameraParams p;
  const Intrinsics& in = file.intrinsics;
  p.fx = in.fx;
  p.fy = in.fy;
  p.cx = in.cx;
  p.cy = in.cy;
  p.dist = in.dist;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) p.R(r, c) = file.extrinsics->R(r, c);
    p.t(r) = file.extrinsics->t[r];
  }
  return p;
}

}  // namespace armtrack::devices::webcam
