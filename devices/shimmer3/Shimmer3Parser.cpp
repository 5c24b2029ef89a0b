#include "devices/shimmer3/Shimmer3Parser.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace armtrack::devices::shimmer3 {
namespace {

std::string hex(std::uint8_t b) {
  char s[8];
  std::snprintf(s, sizeof s, "0x%02X", b);
  return s;
}

// Inverse of a 3x3 row-major matrix; empty when it is (nearly) singular.
std::optional<std::array<double, 9>> inverse3(const std::array<double, 9>& m) {
  const double a = m[0], b = m[1], c = m[2], d = m[3], e = m[4], f = m[5], g = m[6], h = m[7],
               i = m[8];
  const double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  if (!std::isfinite(det) || std::abs(det) < 1e-12) return std::nullopt;
  const double s = 1.0 / det;
  return std::array<double, 9>{(e * i - f * h) * s, (c * h - b * i) * s, (b * f - c * e) * s,
                               (f * g - d * i) * s, (a * i - c * g) * s, (c * d - a * f) * s,
                               (d * h - e * g) * s, (b * g - a * h) * s, (a * e - b * d) * s};
}

bool usable(const KinematicCalibration& c) {
  for (double k : c.sensitivity)
    if (!std::isfinite(k) || k == 0.0) return false;
  for (double o : c.offset)
    if (!std::isfinite(o)) return false;
  return inverse3(c.alignment).has_value();
}

std::array<double, 3> apply(const KinematicCalibration& c, const std::array<double, 9>& inv,
                            const std::array<double, 3>& raw) {
  std::array<double, 3> v{};
  for (int k = 0; k < 3; ++k) v[k] = (raw[k] - c.offset[k]) / c.sensitivity[k];
  return {inv[0] * v[0] + inv[1] * v[1] + inv[2] * v[2],
          inv[3] * v[0] + inv[4] * v[1] + inv[5] * v[2],
          inv[6] * v[0] + inv[7] * v[1] + inv[8] * v[2]};
}

KinematicCalibration diagonal(double offset, double sensitivity,
                              const std::array<double, 9>& alignment) {
  return {{offset, offset, offset}, {sensitivity, sensitivity, sensitivity}, alignment};
}

constexpr std::array<double, 9> kAlignLowNoiseAndGyro{0, -1, 0, -1, 0, 0, 0, 0, -1};
constexpr std::array<double, 9> kAlignWideRange{-1, 0, 0, 0, 1, 0, 0, 0, -1};

}  // namespace

std::size_t channelSize(std::uint8_t id) {
  switch (id) {
    case 0x1B:  // pressure
    case 0x1E:
    case 0x1F:
    case 0x21:
    case 0x22:  // 24-bit ExG
      return 3;
    case 0x1D:
    case 0x20:  // ExG status
      return 1;
    default:
      return id <= kMaxChannelId ? 2 : 0;
  }
}

KinematicCalibration defaultLowNoiseAccel() {
  return diagonal(2047.0, 83.0, kAlignLowNoiseAndGyro);
}

KinematicCalibration defaultWideRangeAccel(int range) {
  static constexpr double kSens[4] = {1631.0, 815.0, 408.0, 135.0};
  return diagonal(0.0, kSens[std::clamp(range, 0, 3)], kAlignWideRange);
}

KinematicCalibration defaultGyro(int range) {
  static constexpr double kSens[4] = {131.0, 65.5, 32.8, 16.4};
  return diagonal(0.0, kSens[std::clamp(range, 0, 3)], kAlignLowNoiseAndGyro);
}

std::size_t Config::packetSize() const {
  std::size_t n = 4;
  for (std::uint8_t c : channels) n += channelSize(c);
  return n;
}

std::optional<Config> parseInquiryResponse(std::span<const std::uint8_t> b) {
  if (b.size() < 9 || b[0] != kInquiryResponse) return std::nullopt;
  const std::size_t n = b[7];
  if (n == 0 || n > kMaxChannelId + 1u || b.size() < 9 + n) return std::nullopt;
  Config c;
  c.samplingDivider = static_cast<std::uint16_t>(b[1] | (b[2] << 8));
  if (c.samplingDivider == 0) return std::nullopt;
  for (int k = 0; k < 4; ++k) c.configBytes[k] = b[3 + k];
  c.bufferSize = b[8];
  std::array<bool, kMaxChannelId + 1> seen{};
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint8_t id = b[9 + k];
    if (channelSize(id) == 0 || seen[id]) return std::nullopt;
    seen[id] = true;
    c.channels.push_back(id);
  }
  return c;
}

Shimmer3Parser::Shimmer3Parser(const Params& params) : m_params(params) {
  m_params.maxBufferBytes = std::max<std::size_t>(m_params.maxBufferBytes, 512);
  setCalibration(defaultLowNoiseAccel(), defaultWideRangeAccel(0), defaultGyro(0));
}

void Shimmer3Parser::setConfig(const Config& config) {
  m_config = config;
  m_packetSize = config.packetSize();
  setCalibration(defaultLowNoiseAccel(), defaultWideRangeAccel(config.wideRangeAccelRange()),
                 defaultGyro(config.gyroRange()));
  m_synced = false;
}

void Shimmer3Parser::setCalibration(const KinematicCalibration& ln, const KinematicCalibration& wr,
                                    const KinematicCalibration& gyro) {
  auto pick = [this](const KinematicCalibration& c, const KinematicCalibration& fallback,
                     const char* what) {
    if (usable(c)) return c;
    m_errors.report(m_bufOffset, std::string("unusable ") + what +
                                     " calibration (zero sensitivity, non-finite value or "
                                     "singular alignment); using the default");
    return fallback;
  };
  m_calLn = pick(ln, defaultLowNoiseAccel(), "low-noise accelerometer");
  m_calWr = pick(wr, defaultWideRangeAccel(m_config ? m_config->wideRangeAccelRange() : 0),
                 "wide-range accelerometer");
  m_calGyro = pick(gyro, defaultGyro(m_config ? m_config->gyroRange() : 0), "gyroscope");
  m_invLn = *inverse3(m_calLn.alignment);
  m_invWr = *inverse3(m_calWr.alignment);
  m_invGyro = *inverse3(m_calGyro.alignment);
}

void Shimmer3Parser::reset() {
  flushGarbage();
  m_bufOffset += m_buf.size();
  m_buf.clear();
  m_synced = false;
  m_haveTime = false;
  m_ticks = 0;
}

void Shimmer3Parser::feed(std::span<const std::uint8_t> bytes, std::vector<Sample>& out) {
  // Work in slices so that the retained buffer stays small whatever the chunk size.
  constexpr std::size_t kSlice = 256;
  for (std::size_t start = 0; start < bytes.size(); start += kSlice) {
    const auto slice = bytes.subspan(start, std::min(kSlice, bytes.size() - start));
    m_buf.insert(m_buf.end(), slice.begin(), slice.end());

    std::size_t pos = 0;
    while (pos < m_buf.size()) {
      const std::uint8_t b = m_buf[pos];
      Step step = Step::Garbage;
      std::size_t used = 1;
      if (b == kDataPacket && m_config) {
        step = tryDataPacket(pos, out);
        used = m_packetSize;
      } else if (b == kAck) {
        flushGarbage();
        ++m_acks;
        step = Step::Consumed;
      } else if (b == kInquiryResponse && !m_synced) {
        step = tryInquiry(pos);
        if (step == Step::Consumed) used = 9 + m_config->channels.size();
      }
      if (step == Step::NeedMore) break;
      if (step == Step::Garbage) {
        skipGarbage(pos);
        used = 1;
      }
      pos += used;
    }
    m_buf.erase(m_buf.begin(), m_buf.begin() + static_cast<std::ptrdiff_t>(pos));
    m_bufOffset += pos;

    if (m_buf.size() > m_params.maxBufferBytes) {  // cannot happen with sane sizes; stay bounded
      const std::size_t drop = m_buf.size() - m_params.maxBufferBytes;
      m_errors.report(m_bufOffset,
                      "buffer limit reached: dropped " + std::to_string(drop) + " bytes");
      m_garbageBytes += drop;
      m_buf.erase(m_buf.begin(), m_buf.begin() + static_cast<std::ptrdiff_t>(drop));
      m_bufOffset += drop;
    }
  }
}

std::uint32_t Shimmer3Parser::timestampAt(std::size_t pos) const {
  return static_cast<std::uint32_t>(m_buf[pos + 1]) |
         (static_cast<std::uint32_t>(m_buf[pos + 2]) << 8) |
         (static_cast<std::uint32_t>(m_buf[pos + 3]) << 16);
}

bool Shimmer3Parser::plausible(const std::uint8_t* p) const {
  std::size_t off = 4;
  for (std::uint8_t id : m_config->channels) {
    // The low-noise accelerometer is a 12-bit ADC: its high nibble is always zero.
    if (id <= kLowNoiseAccelX + 2 && (p[off + 1] & 0xF0) != 0) return false;
    off += channelSize(id);
  }
  return true;
}

Shimmer3Parser::Step Shimmer3Parser::tryDataPacket(std::size_t pos, std::vector<Sample>& out) {
  // Packets carry no length or checksum, so a packet is framed by what follows it: the next data
  // packet with a timestamp 1..maxGapTicks later, or (when in step) an ACK.
  const std::size_t avail = m_buf.size() - pos;
  if (avail < m_packetSize + 1) return Step::NeedMore;
  const std::uint8_t next = m_buf[pos + m_packetSize];
  if (next == kDataPacket) {
    if (avail < m_packetSize + 4) return Step::NeedMore;
    const std::uint32_t gap =
        (timestampAt(pos + m_packetSize) - timestampAt(pos)) & (kTimestampWrap - 1);
    if (gap == 0 || gap > m_params.maxGapTicks) return Step::Garbage;
    if (!m_synced) {
      // Hunting after garbage: the gap must also be close to a whole number of sampling periods.
      const std::uint32_t period = m_config->samplingDivider;
      const std::uint32_t rest = gap % period;
      if (std::min(rest, period - rest) > 2) return Step::Garbage;
    }
  } else if (next != kAck || !m_synced) {  // after garbage, only a data packet confirms
    return Step::Garbage;
  }
  if (!plausible(m_buf.data() + pos)) return Step::Garbage;
  if (!m_synced && m_haveTime) {
    const std::uint32_t sinceLast = (timestampAt(pos) - m_lastRaw) & (kTimestampWrap - 1);
    if (sinceLast == 0 || sinceLast > m_params.maxGapTicks) return Step::Garbage;
  }
  m_synced = true;
  flushGarbage();
  decode(m_buf.data() + pos, out);
  return Step::Consumed;
}

void Shimmer3Parser::flush(std::vector<Sample>& out) {
  if (m_config && m_buf.size() >= m_packetSize && m_buf[0] == kDataPacket &&
      plausible(m_buf.data())) {
    flushGarbage();
    decode(m_buf.data(), out);
    m_buf.erase(m_buf.begin(), m_buf.begin() + static_cast<std::ptrdiff_t>(m_packetSize));
    m_bufOffset += m_packetSize;
  }
  for (std::size_t k = 0; k < m_buf.size(); ++k) skipGarbage(k);
  flushGarbage();
  m_bufOffset += m_buf.size();
  m_buf.clear();
  m_synced = false;
}

Shimmer3Parser::Step Shimmer3Parser::tryInquiry(std::size_t pos) {
  const std::size_t avail = m_buf.size() - pos;
  if (avail < 9) return Step::NeedMore;
  const std::size_t n = m_buf[pos + 7];
  if (n == 0 || n > kMaxChannelId + 1u) return Step::Garbage;
  if (avail < 9 + n) return Step::NeedMore;
  const auto config = parseInquiryResponse(std::span(m_buf.data() + pos, 9 + n));
  if (!config) return Step::Garbage;
  flushGarbage();
  setConfig(*config);
  m_synced = true;  // a well-formed inquiry response puts the stream in step
  ++m_inquiries;
  return Step::Consumed;
}

void Shimmer3Parser::decode(const std::uint8_t* p, std::vector<Sample>& out) {
  Sample s;
  s.rawTimestamp = static_cast<std::uint32_t>(p[1]) | (static_cast<std::uint32_t>(p[2]) << 8) |
                   (static_cast<std::uint32_t>(p[3]) << 16);
  if (m_haveTime) {
    const std::uint32_t gap = (s.rawTimestamp - m_lastRaw) & (kTimestampWrap - 1);
    m_ticks += gap;
    const std::uint32_t period = m_config->samplingDivider;
    if (gap > period + period / 2) m_dropped += (gap + period / 2) / period - 1;
  } else
    m_ticks = s.rawTimestamp;
  m_haveTime = true;
  m_lastRaw = s.rawTimestamp;
  s.ticks = m_ticks;
  s.t = static_cast<double>(m_ticks) / kTickHz;

  std::array<double, 3> ln{}, wr{}, gyro{};
  int nLn = 0, nWr = 0, nGyro = 0;
  std::size_t off = 4;
  for (std::uint8_t id : m_config->channels) {
    // Only the two-byte channels below are decoded; ExG status is a single byte and may end
    // the packet, so its neighbour must not be read.
    if (channelSize(id) != 2) {
      off += channelSize(id);
      continue;
    }
    const std::uint8_t lo = p[off], hi = p[off + 1];
    if (id <= 0x02) {
      ln[id] = static_cast<double>(lo | (hi << 8));
      ++nLn;
    } else if (id >= kWideRangeAccelX && id <= kWideRangeAccelX + 2) {
      wr[id - kWideRangeAccelX] = static_cast<std::int16_t>(lo | (hi << 8));
      ++nWr;
    } else if (id >= kGyroX && id <= kGyroX + 2) {
      gyro[id - kGyroX] = static_cast<std::int16_t>((lo << 8) | hi);  // big-endian
      ++nGyro;
    }
    off += channelSize(id);
  }
  if (nLn == 3) {
    s.acc = apply(m_calLn, m_invLn, ln);
    s.hasAcc = true;
  } else if (nWr == 3) {
    s.acc = apply(m_calWr, m_invWr, wr);
    s.hasAcc = true;
  }
  if (nGyro == 3) {
    s.gyr = apply(m_calGyro, m_invGyro, gyro);
    for (double& g : s.gyr) g *= std::numbers::pi / 180.0;
    s.hasGyro = true;
  }
  ++m_packets;
  out.push_back(s);
}

void Shimmer3Parser::skipGarbage(std::size_t pos) {
  if (m_garbageRun == 0) {
    m_garbageStart = m_bufOffset + pos;
    if (m_synced)
      m_errors.report(m_garbageStart,
                      "expected a packet type (0x00 data, 0x02 inquiry "
                      "response, 0xFF ack) at byte " +
                          std::to_string(m_garbageStart) + ", got " + hex(m_buf[pos]) +
                          "; resynchronising");
    else if (!m_config && m_buf[pos] == kDataPacket)
      m_errors.report(m_garbageStart, "data packet at byte " + std::to_string(m_garbageStart) +
                                          " before any inquiry response: channel layout unknown");
  }
  m_synced = false;
  ++m_garbageRun;
  ++m_garbageBytes;
  if (m_garbageRun >= 4096) flushGarbage();  // endless noise is still reported
}

void Shimmer3Parser::flushGarbage() {
  if (m_garbageRun == 0) return;
  m_errors.report(m_garbageStart, "skipped " + std::to_string(m_garbageRun) +
                                      " unframed bytes starting at byte " +
                                      std::to_string(m_garbageStart));
  m_garbageRun = 0;
}

}  // namespace armtrack::devices::shimmer3
