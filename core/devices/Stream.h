// What a sensor source delivers, in plain C++20: its streams, their timestamped samples, and
// counts of how they fare. Devices (devices/) produce these; the session (core/session) consumes
// them through the SampleSource interface (core/devices/SampleSource.h). No Qt here.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/CameraParams.h"
#include "core/io/Recording.h"
#include "core/sync/SensorPayload.h"

namespace armtrack {

/// Seconds on the host's monotonic clock (std::chrono::steady_clock), shared by every device and
/// the session. Any thread.
double hostNow();

enum class DeviceState {
  Disconnected,  ///< not started, or stopped
  Connecting,    ///< opening, or waiting for a device that went away to come back
  Streaming,     ///< samples are flowing
  Error,         ///< cannot go on without the user (bad port, bad file); see the reason
};
/// "disconnected", "connecting", "streaming", "error".
const char* toString(DeviceState state);

/// A stream: one clock, one kind of payload.
struct StreamInfo {
  std::string name;  ///< e.g. "upper-arm IMU"
  StreamRole role = StreamRole::UpperArmImu;
  double nominalRateHz = 0.0;  ///< Hz, 0 when unknown
  double wrapPeriod = 0.0;     ///< s after which the device timestamp wraps; 0 = never
  /// The camera model of a Camera stream (intrinsics and pose in the shoulder frame), when the
  /// device knows it (a calibration file, a simulation). The estimator needs it for pixels.
  std::optional<CameraParams> camera;
  /// The sternum sensor's mounting of a TrunkImu stream (the recording's "trunk" block), when the
  /// device knows it (a simulation, a recording, a calibration). Without one the session assumes
  /// defaultTrunkMount(side) and says so.
  std::optional<TrunkMount> trunkMount = std::nullopt;
  /// Optional groups the stream's samples fill, which the recording then gets columns for: an
  /// Optical stream's shoulder (OpticalPositions::shoulder, shoulder_*), a Truth stream's trunk
  /// angles (TruthAngles::trunk, true_trunk_*). Values of a group a stream does not declare are
  /// estimated with but not recorded.
  bool shoulder = false;
  bool trueTrunk = false;
};

/// One timestamped sample in SI units.
struct DeviceSample {
  int stream = 0;            ///< index into the source's streams
  double deviceTime = 0.0;   ///< s on the device's own clock (may wrap, see StreamInfo)
  double arrivalTime = 0.0;  ///< s on hostNow() when the bytes arrived
  SensorPayload payload;     ///< must match the stream's role
};
using SampleBatch = std::vector<DeviceSample>;

/// Health of one stream, counted since the source started.
struct StreamHealth {
  double rateHz = 0.0;        ///< samples per second over the last second
  std::uint64_t samples = 0;  ///< samples published
  std::uint64_t dropped = 0;  ///< samples the device says it lost (sequence gaps, dropouts)
  std::uint64_t corrupt = 0;  ///< packets or frames rejected as malformed
  /// Samples that arrived after a newer one (UDP reorders): not published, since device time
  /// must not go back, and not counted as dropped either: they were not lost on the link.
  std::uint64_t reordered = 0;
};

struct DeviceHealth {
  std::vector<StreamHealth> streams;     ///< one per stream of the source
  std::optional<double> batteryPercent;  ///< 0-100 where the device tells
  std::uint64_t reconnects = 0;          ///< times the device came back after going away
  std::string lastProblem;               ///< newest reported problem, empty if none
};

}  // namespace armtrack
