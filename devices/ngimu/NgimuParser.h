// x-io NGIMU over UDP: decodes OSC datagrams and turns "/sensors" messages into SI samples.
// See docs/devices/ngimu.md.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "devices/common/ParseErrorLog.h"
#include "devices/ngimu/Osc.h"

namespace armtrack::devices::ngimu {

inline constexpr double kStandardGravity = 9.80665;  ///< g used to convert "g" to m/s^2

/// One "/sensors" message in SI units.
struct SensorsSample {
  bool hasTimetag = false;      ///< false when the message came without a bundle time tag
  std::uint64_t timetag = 0;    ///< NTP time tag of the enclosing bundle
  double t = 0.0;               ///< time tag as seconds since 1900-01-01 (s)
  std::array<double, 3> gyr{};  ///< angular velocity (rad/s)
  std::array<double, 3> acc{};  ///< specific force (m/s^2)
  std::array<double, 3> mag{};  ///< magnetic flux density (T)
  double pressurePa = 0.0;      ///< barometric pressure (Pa)
};

/// Datagram parser. UDP keeps message boundaries, so it takes one whole datagram per call (a
/// datagram split in two is two malformed datagrams). Never throws; no state between datagrams
/// except counters. Not thread-safe: one owner thread.
class NgimuParser {
 public:
  /// Decodes one datagram, appending each valid "/sensors" message to `out`. Other NGIMU
  /// messages ("/quaternion", "/battery", ...) are counted and ignored.
  void parseDatagram(std::span<const std::uint8_t> datagram, std::vector<SensorsSample>& out);

  std::uint64_t datagrams() const { return m_datagrams; }
  std::uint64_t sensorMessages() const { return m_sensors; }
  std::uint64_t otherMessages() const { return m_other; }
  const ParseErrorLog& errors() const { return m_errors; }

 private:
  std::vector<osc::Message> m_messages;  // reused between datagrams
  std::uint64_t m_datagrams = 0, m_sensors = 0, m_other = 0;
  ParseErrorLog m_errors;
};

}  // namespace armtrack::devices::ngimu
