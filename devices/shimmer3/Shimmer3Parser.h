// Byte-level parser for the Shimmer3 Bluetooth streaming protocol (LogAndStream firmware).
// Pure C++20: the Qt device class feeds it the bytes read from the serial port.
// See docs/devices/shimmer3.md for the format and the sources of every constant.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "devices/common/ParseErrorLog.h"

namespace armtrack::devices::shimmer3 {

// Command bytes sent to the device, and packet types it sends back.
inline constexpr std::uint8_t kDataPacket = 0x00;
inline constexpr std::uint8_t kInquiryCommand = 0x01;
inline constexpr std::uint8_t kInquiryResponse = 0x02;
inline constexpr std::uint8_t kStartStreamingCommand = 0x07;
inline constexpr std::uint8_t kStopStreamingCommand = 0x20;
inline constexpr std::uint8_t kAck = 0xFF;

inline constexpr double kTickHz = 32768.0;                 ///< timestamp clock (Hz)
inline constexpr std::uint32_t kTimestampWrap = 1u << 24;  ///< the 3-byte timestamp wraps here

// Channel ids of the inquiry response that this parser converts.
inline constexpr std::uint8_t kLowNoiseAccelX = 0x00;   // 0x00-0x02, uint12 little-endian
inline constexpr std::uint8_t kWideRangeAccelX = 0x04;  // 0x04-0x06, int16 little-endian
inline constexpr std::uint8_t kGyroX = 0x0A;            // 0x0A-0x0C, int16 big-endian
inline constexpr std::uint8_t kMaxChannelId = 0x28;

/// Size in bytes of a channel in a data packet, or 0 for an unknown channel id.
std::size_t channelSize(std::uint8_t channelId);

/// Shimmer's kinematic calibration: value = A^-1 K^-1 (raw - b).
struct KinematicCalibration {
  std::array<double, 3> offset{};       ///< b (raw counts)
  std::array<double, 3> sensitivity{};  ///< diagonal of K (counts per output unit)
  std::array<double, 9> alignment{};    ///< A, row-major (unitless)
};

/// Default calibrations for Shimmer3 (output units: m/s^2 for accelerometers, deg/s for gyro).
KinematicCalibration defaultLowNoiseAccel();
/// `range`: 0..3 = +-2/4/8/16 g (LSM303DLHC).
KinematicCalibration defaultWideRangeAccel(int range);
/// `range`: 0..3 = +-250/500/1000/2000 deg/s (MPU9150).
KinematicCalibration defaultGyro(int range);

/// What the device streams, as told by its inquiry response.
struct Config {
  std::uint16_t samplingDivider = 0;          ///< sampling period in 32768 Hz ticks
  std::array<std::uint8_t, 4> configBytes{};  ///< config setup bytes 0-3
  std::uint8_t bufferSize = 1;
  std::vector<std::uint8_t> channels;  ///< channel ids in packet order

  double samplingRateHz() const { return samplingDivider ? kTickHz / samplingDivider : 0.0; }
  int gyroRange() const { return configBytes[2] & 0x03; }                   ///< byte 2, bits 1-0
  int wideRangeAccelRange() const { return (configBytes[0] >> 2) & 0x03; }  ///< byte 0, bits 3-2
  /// Bytes of one data packet: type byte, 3-byte timestamp and the channels.
  std::size_t packetSize() const;
};

/// Parses a complete inquiry response (starting with 0x02). Empty when it is malformed.
std::optional<Config> parseInquiryResponse(std::span<const std::uint8_t> bytes);

/// One data packet in SI units.
struct Sample {
  std::uint32_t rawTimestamp = 0;  ///< the packet's 24-bit timestamp (ticks)
  std::uint64_t ticks = 0;         ///< unwrapped timestamp, never decreasing (ticks)
  double t = 0.0;                  ///< ticks / 32768 (s)
  bool hasGyro = false;
  bool hasAcc = false;
  std::array<double, 3> gyr{};  ///< angular velocity (rad/s), sensor axes after alignment
  std::array<double, 3>
      acc{};  ///< specific force (m/s^2): low-noise accel if streamed, else wide-range
};

/// Incremental stream parser. Feed it bytes split anywhere; it emits every data packet it can
/// frame, resynchronises after garbage, and never throws. A packet is released once the first
/// bytes of the next packet (or an ACK) have arrived. Not thread-safe: one owner thread.
class Shimmer3Parser {
 public:
  struct Params {
    std::size_t maxBufferBytes = 4096;  ///< bytes held between feeds (bytes)
    /// A data packet is accepted only when an ACK or the next data packet follows it, and then
    /// the two timestamps must differ by 1..maxGapTicks.
    std::uint32_t maxGapTicks = 4 * 32768;  ///< (ticks, default 4 s)
  };

  Shimmer3Parser() : Shimmer3Parser(Params{}) {}
  explicit Shimmer3Parser(const Params& params);

  /// Uses a known configuration (e.g. from an inquiry answered before streaming). An inquiry
  /// response found in the stream replaces it. Calibration defaults follow the ranges.
  void setConfig(const Config& config);
  /// Overrides the default calibrations (e.g. with values read from the device).
  void setCalibration(const KinematicCalibration& lowNoiseAccel,
                      const KinematicCalibration& wideRangeAccel, const KinematicCalibration& gyro);
  const std::optional<Config>& config() const { return m_config; }

  /// Consumes `bytes`, appending each decoded packet to `out`.
  void feed(std::span<const std::uint8_t> bytes, std::vector<Sample>& out);
  /// Releases a complete packet still waiting for its successor (call when the stream ends),
  /// then drops the rest of the buffer.
  void flush(std::vector<Sample>& out);
  /// Forgets buffered bytes and the timestamp history (e.g. after a reconnect).
  void reset();

  std::uint64_t packets() const { return m_packets; }            ///< data packets decoded
  std::uint64_t droppedPackets() const { return m_dropped; }     ///< from timestamp gaps
  std::uint64_t acks() const { return m_acks; }                  ///< 0xFF acknowledgements seen
  std::uint64_t inquiries() const { return m_inquiries; }        ///< inquiry responses seen
  std::uint64_t garbageBytes() const { return m_garbageBytes; }  ///< bytes skipped
  const ParseErrorLog& errors() const { return m_errors; }

 private:
  enum class Step { Consumed, NeedMore, Garbage };
  Step tryDataPacket(std::size_t pos, std::vector<Sample>& out);
  Step tryInquiry(std::size_t pos);
  void decode(const std::uint8_t* packet, std::vector<Sample>& out);
  std::uint32_t timestampAt(std::size_t pos) const;
  bool plausible(const std::uint8_t* packet) const;
  void skipGarbage(std::size_t pos);
  void flushGarbage();

  Params m_params;
  std::optional<Config> m_config;
  std::size_t m_packetSize = 0;
  KinematicCalibration m_calLn, m_calWr, m_calGyro;
  std::array<double, 9> m_invLn{}, m_invWr{}, m_invGyro{};  // (A^-1) per sensor

  std::vector<std::uint8_t> m_buf;
  std::uint64_t m_bufOffset = 0;  // stream offset of m_buf[0]
  bool m_synced = false;
  std::uint64_t m_garbageStart = 0;
  std::uint64_t m_garbageRun = 0;

  bool m_haveTime = false;
  std::uint32_t m_lastRaw = 0;
  std::uint64_t m_ticks = 0;

  std::uint64_t m_dropped = 0;
  std::uint64_t m_packets = 0, m_acks = 0, m_inquiries = 0, m_garbageBytes = 0;
  ParseErrorLog m_errors;
};

}  // namespace armtrack::devices::shimmer3
