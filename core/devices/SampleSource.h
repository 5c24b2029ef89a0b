// The session's side of the device contract, without Qt: a SampleSource is a running sensor
// source as the session drives it, and SampleInput is the port through which a source hands the
// session its samples, state changes and problems. devices/api adapts its Qt plugin devices to
// SampleSource (devices/api/DeviceThread.h); tests may implement it directly.
#pragma once

#include <string>
#include <vector>

#include "core/devices/Stream.h"

namespace armtrack {

/// Where a started source delivers. The session gives each source its own input. The calls come
/// from the source's thread(s), so an implementation must be thread-safe; they must not block for
/// long (the session only queues samples here).
class SampleInput {
 public:
  virtual ~SampleInput() = default;
  /// Samples in arrival order; DeviceSample::stream indexes the source's streams().
  virtual void samplesArrived(const SampleBatch& batch) = 0;
  /// The source's state changed, or it has a new reason for it (empty when none).
  virtual void stateChanged(DeviceState state, const std::string& reason) = 0;
  /// A problem worth telling the user that does not stop the source (a corrupt packet, a gap).
  virtual void problemReported(const std::string& message) = 0;
};

/// A sensor source as the session sees it. streams(), timeScale(), state() and health() may be
/// called from any thread; start() and stop() from the thread that owns the source.
class SampleSource {
 public:
  virtual ~SampleSource() = default;

  /// The streams, fixed for the source's life.
  virtual const std::vector<StreamInfo>& streams() const = 0;
  /// Device seconds per host second: 1 for live devices; a replay at 4x returns 4.
  virtual double timeScale() const = 0;
  virtual DeviceState state() const = 0;
  /// Counts since start(): one StreamHealth per stream.
  virtual DeviceHealth health() const = 0;

  /// Starts the source; it delivers into input until stop() returns. input must outlive that.
  virtual void start(SampleInput& input) = 0;
  /// Stops the source: nothing reaches the input after it returns. Returns an empty string, or
  /// what went wrong while stopping (for the session's log). Calling it again does nothing.
  virtual std::string stop() = 0;
};

}  // namespace armtrack
