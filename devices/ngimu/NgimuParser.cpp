#include "devices/ngimu/NgimuParser.h"

#include <cmath>
#include <numbers>
#include <string>

namespace armtrack::devices::ngimu {

void NgimuParser::parseDatagram(std::span<const std::uint8_t> datagram,
                                std::vector<SensorsSample>& out) {
  const std::string context = "datagram " + std::to_string(m_datagrams) + ": ";
  ++m_datagrams;
  m_messages.clear();
  osc::decodePacket(datagram, m_messages, m_errors, context);
  for (const osc::Message& m : m_messages) {
    if (m.address != "/sensors") {
      ++m_other;
      continue;
    }
    const std::string where = context + "/sensors at byte " + std::to_string(m.offset);
    if (m.args.size() != 10) {
      m_errors.report(m.offset, where + " has " + std::to_string(m.args.size()) +
                                    " arguments, expected 10 (gyroscope xyz, accelerometer xyz, "
                                    "magnetometer xyz, barometer)");
      continue;
    }
    bool ok = true;
    for (std::size_t k = 0; k < 10 && ok; ++k) {
      const char tag = m.args[k].tag;
      if (tag != 'f' && tag != 'i' && tag != 'd') {
        m_errors.report(m.offset, where + ": argument " + std::to_string(k) +
                                      " is not a number (type tag '" + std::string(1, tag) + "')");
        ok = false;
      } else if (!std::isfinite(m.args[k].number)) {
        m_errors.report(m.offset,
                        where + ": argument " + std::to_string(k) + " is NaN or infinite");
        ok = false;
      }
    }
    if (!ok) continue;
    SensorsSample s;
    for (int k = 0; k < 3; ++k) {
      s.gyr[k] = m.args[k].number * (std::numbers::pi / 180.0);  // deg/s
      s.acc[k] = m.args[3 + k].number * kStandardGravity;        // g
      s.mag[k] = m.args[6 + k].number * 1e-6;                    // uT
    }
    s.pressurePa = m.args[9].number * 100.0;  // hPa
    s.hasTimetag = m.timetag != osc::kImmediately;
    s.timetag = m.timetag;
    s.t = s.hasTimetag ? osc::timetagSeconds(m.timetag) : 0.0;
    ++m_sensors;
    out.push_back(s);
  }
}

}  // namespace armtrack::devices::ngimu
