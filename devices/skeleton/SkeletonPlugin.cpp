#include "devices/skeleton/SkeletonPlugin.h"

#include "devices/skeleton/SkeletonDevice.h"

namespace armtrack::devices::skeleton {

QString SkeletonPlugin::name() const {
  return QStringLiteral("skeleton-udp");
}

QString SkeletonPlugin::description() const {
  // Word for word as in ui/DeviceWords.cpp, which translates it (the shoulder comes too).
  return QStringLiteral(
      "elbow and wrist positions from an external body tracker (Kinect SDK, "
      "pose estimator), JSON over UDP");
}

QString SkeletonPlugin::optionsHelp() const {
  return QStringLiteral(
      "port=9870        local UDP port the tracker sends to\n"
      "origin=start     start: the world frame, relative to where the tracked shoulder was in\n"
      "                 the first second, shoulder included (a lean moves it; needed with a\n"
      "                 trunk sensor); shoulder: elbow and wrist relative to the moving shoulder\n"
      "                 (the trunk's motion is lost); camera: relative to the registration's\n"
      "                 origin (as sent with axes=)\n"
      "timeout=3        seconds without a frame before the state goes back to connecting\n"
      "camera=FILE      the tracker camera's file with its pose (camera-register): turns the\n"
      "                 tracker's axes into the shoulder frame's\n"
      "axes=shoulder    instead of camera=: the tracker already sends shoulder-frame axes");
}

std::unique_ptr<Device> SkeletonPlugin::create(const QVariantMap& options, QString* error) {
  const auto settings = readSkeletonSettings(options, error);
  if (!settings) return nullptr;
  return std::make_unique<SkeletonDevice>(*settings);
}

}  // namespace armtrack::devices::skeleton
