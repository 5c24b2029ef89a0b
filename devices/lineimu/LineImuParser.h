// Parser for ArmTrack's text line protocol for do-it-yourself IMUs (ESP32/Arduino + MPU-6050 or
// BNO055) over a serial port or UDP. The format is specified in docs/devices/line-protocol.md.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/sync/SequenceTracker.h"
#include "devices/common/ParseErrorLog.h"

namespace armtrack::devices::lineimu {

inline constexpr int kProtocolVersion = 1;
inline constexpr std::size_t kMaxLineBytes = 200;  ///< longest accepted sentence, '$' to '\n'

/// One `$IMU` sentence in SI units.
struct Sample {
  std::uint32_t seq = 0;           ///< sentence counter as sent (wraps at 2^32)
  std::uint32_t rawTimeUs = 0;     ///< device time as sent (us, wraps at 2^32)
  std::uint32_t epoch = 0;         ///< number of $HELLO seen before this sample (restarts)
  std::uint64_t deviceTimeUs = 0;  ///< unwrapped device time, never decreasing within an epoch (us)
  double t = 0.0;                  ///< deviceTimeUs * 1e-6 (s)
  std::array<double, 3> gyr{};     ///< angular velocity (rad/s)
  std::array<double, 3> acc{};     ///< specific force (m/s^2)
};

/// What the device said about itself in its `$HELLO` sentence.
struct Hello {
  int version = 0;
  std::string device;   ///< free text without ',' or '*'
  double rateHz = 0.0;  ///< nominal sample rate (Hz)
};

/// XOR of the bytes between '$' and '*' (NMEA style).
std::uint8_t checksum(std::string_view body);
/// Builds a complete sentence "$<body>*HH\n" (used by tests, the fake device and the docs).
std::string makeSentence(std::string_view body);

/// Incremental parser: feed bytes split anywhere. Never throws; every problem is counted in
/// errors(). A '$' always starts a new sentence, so a good sentence after garbage is never lost.
/// Not thread-safe: one owner thread.
class LineImuParser {
 public:
  void feed(std::span<const std::uint8_t> bytes, std::vector<Sample>& out);
  void feed(std::string_view text, std::vector<Sample>& out);
  /// Ends a UDP datagram: an unfinished sentence is reported as truncated and dropped.
  void endOfDatagram();
  /// Forgets the partial sentence and the time history (e.g. after a reconnect).
  void reset();

  const std::optional<Hello>& hello() const { return m_hello; }
  std::uint64_t samples() const { return m_samples; }
  /// Sentences missing from `seq` when a later one arrived (gaps), whether or not they came later.
  std::uint64_t droppedSamples() const { return m_seq.missing(); }
  /// Of those, sentences that arrived after a newer one (UDP reorders), within 64 sentences. They
  /// are not returned either (device time never decreases within an epoch), but they were not
  /// lost on the link: droppedSamples() - reorderedSamples() were.
  std::uint64_t reorderedSamples() const { return m_seq.reordered(); }
  /// Sentences dropped because their `seq` had arrived before, or came more than 64 late.
  std::uint64_t duplicateSamples() const { return m_seq.duplicates() + m_seq.tooLate(); }
  std::uint64_t garbageBytes() const { return m_garbageBytes; }
  const ParseErrorLog& errors() const { return m_errors; }

 private:
  void handleByte(char c, std::vector<Sample>& out);
  void finishLine(std::vector<Sample>& out);
  void parseBody(std::string_view body, std::vector<Sample>& out);
  void flushGarbage();

  std::string m_line;  // bytes after '$', bounded by kMaxLineBytes
  bool m_inLine = false;
  bool m_overflow = false;
  std::uint64_t m_offset = 0;     // stream offset of the next byte
  std::uint64_t m_lineStart = 0;  // stream offset of the current '$'
  std::uint64_t m_garbageStart = 0, m_garbageRun = 0;

  std::optional<Hello> m_hello;
  bool m_haveTime = false;
  std::uint32_t m_lastRawUs = 0, m_lastSeq = 0;
  std::uint64_t m_timeUs = 0;
  std::uint32_t m_epoch = 0;
  // m_lastSeq without its wraps; starts high so that a sentence behind it never goes below 0.
  std::uint64_t m_seqUnwrapped = std::uint64_t{1} << 40;
  SequenceTracker m_seq;

  std::uint64_t m_samples = 0, m_garbageBytes = 0;
  ParseErrorLog m_errors;
};

}  // namespace armtrack::devices::lineimu
