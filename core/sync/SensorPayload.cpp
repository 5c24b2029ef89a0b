#include "core/sync/SensorPayload.h"

namespace armtrack {

namespace {

bool finiteOpt(const std::optional<Eigen::Vector3d>& v) {
  return !v || v->allFinite();
}
bool finiteOpt(const std::optional<Eigen::Vector2d>& v) {
  return !v || v->allFinite();
}

}  // namespace

const char* toString(StreamRole role) {
  switch (role) {
    case StreamRole::UpperArmImu:
      return "upper-arm IMU";
    case StreamRole::ForearmImu:
      return "forearm IMU";
    case StreamRole::Optical:
      return "optical positions";
    case StreamRole::Camera:
      return "camera markers";
    case StreamRole::Truth:
      return "true angles";
    case StreamRole::TrunkImu:
      return "trunk IMU";
  }
  return "?";
}

bool validPayload(StreamRole role, const SensorPayload& p) {
  switch (role) {
    case StreamRole::UpperArmImu:
    case StreamRole::ForearmImu:
    case StreamRole::TrunkImu: {
      const auto* r = std::get_if<ImuReading>(&p);
      return r && r->gyr.allFinite() && r->acc.allFinite();
    }
    case StreamRole::Optical: {
      const auto* o = std::get_if<OpticalPositions>(&p);
      return o && finiteOpt(o->elbow) && finiteOpt(o->wrist) && finiteOpt(o->shoulder);
    }
    case StreamRole::Camera: {
      const auto* m = std::get_if<MarkerPixels>(&p);
      return m && finiteOpt(m->wrist) && finiteOpt(m->elbow);
    }
    case StreamRole::Truth: {
      const auto* t = std::get_if<TruthAngles>(&p);
      return t && t->th.allFinite() && finiteOpt(t->trunk);
    }
  }
  return false;
}

}  // namespace armtrack
