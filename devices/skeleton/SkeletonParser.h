// Arm joints from an external body tracker (a Kinect SDK, Azure Kinect body tracking or a pose
// estimator on another machine) as JSON over UDP. Format: docs/devices/skeleton-udp.md.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "core/sync/SequenceTracker.h"
#include "devices/common/ParseErrorLog.h"

namespace armtrack::devices::skeleton {

inline constexpr int kFormatVersion = 1;
inline constexpr std::size_t kMaxDatagramBytes = 8192;
inline constexpr double kMaxCoordinate = 20.0;  ///< larger |x|, |y| or |z| is rejected (m)

enum class Side { Right, Left };

/// One joint in the camera frame.
struct Joint {
  std::array<double, 3> position{};  ///< (m), camera frame
  std::optional<double> confidence;  ///< 0..1 when the tracker sent one
};

/// One datagram.
struct Frame {
  double t = 0.0;           ///< tracker time (s)
  std::uint64_t frame = 0;  ///< tracker frame counter
  Side side = Side::Right;
  std::optional<Joint> shoulder, elbow, wrist;  ///< absent when not tracked
};

/// Encodes a frame as the documented JSON (for tests, fakes and the docs).
std::string encode(const Frame& frame);

/// Datagram parser: one whole datagram per call. Never throws. Not thread-safe: one owner.
class SkeletonParser {
 public:
  /// The frame, or empty when the datagram is invalid (the reason is in errors()), older than the
  /// newest frame (counted in reorderedFrames()) or a duplicate (duplicateFrames()).
  std::optional<Frame> parseDatagram(std::string_view datagram);
  std::optional<Frame> parseDatagram(std::span<const std::uint8_t> datagram);

  std::uint64_t datagrams() const { return m_datagrams; }
  std::uint64_t frames() const { return m_frames; }
  /// Frames missing from the counter when a later one arrived (gaps), whether or not they came
  /// later; droppedFrames() - reorderedFrames() were lost.
  std::uint64_t droppedFrames() const { return m_seq.missing(); }
  /// Frames that arrived after a newer one (UDP reorders): not returned (time never goes back),
  /// not lost on the link either.
  std::uint64_t reorderedFrames() const { return m_seq.reordered(); }
  /// Frames whose number had arrived before: not returned (a duplicated datagram).
  std::uint64_t duplicateFrames() const { return m_seq.duplicates() + m_seq.tooLate(); }
  const ParseErrorLog& errors() const { return m_errors; }

 private:
  std::uint64_t m_datagrams = 0, m_frames = 0;
  std::uint64_t m_lastFrame = 0;  // newest frame number
  SequenceTracker m_seq;
  ParseErrorLog m_errors;
};

}  // namespace armtrack::devices::skeleton
