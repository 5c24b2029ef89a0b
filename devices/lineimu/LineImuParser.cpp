#include "devices/lineimu/LineImuParser.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace armtrack::devices::lineimu {
namespace {

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t k = s.find(sep, start);
    parts.push_back(s.substr(start, k == std::string_view::npos ? k : k - start));
    if (k == std::string_view::npos) return parts;
    start = k + 1;
  }
}

// A finite decimal number taking the whole field (no NaN, inf, hex or '+').
std::optional<double> toDouble(std::string_view f) {
  if (f.empty()) return std::nullopt;
  for (char c : f)
    if (!((c >= '0' && c <= '9') || c == '-' || c == '.' || c == 'e' || c == 'E' || c == '+'))
      return std::nullopt;
  if (f.front() == '+') return std::nullopt;
  double v = 0.0;
  const auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc() || p != f.data() + f.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<std::uint32_t> toU32(std::string_view f) {
  if (f.empty() || f.size() > 10) return std::nullopt;
  std::uint64_t v = 0;
  for (char c : f) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + static_cast<std::uint64_t>(c - '0');
  }
  if (v > 0xFFFFFFFFull) return std::nullopt;
  return static_cast<std::uint32_t>(v);
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

std::string printable(std::string_view s) {
  std::string r;
  for (char c : s.substr(0, 40)) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7F) {
      r += c;
    } else {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02X", u);
      r += b;
    }
  }
  if (s.size() > 40) r += "...";
  return r;
}

}  // namespace

std::uint8_t checksum(std::string_view body) {
  std::uint8_t x = 0;
  for (char c : body) x ^= static_cast<std::uint8_t>(c);
  return x;
}

std::string makeSentence(std::string_view body) {
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X\n", checksum(body));
  return "$" + std::string(body) + tail;
}

void LineImuParser::feed(std::string_view text, std::vector<Sample>& out) {
  for (char c : text) handleByte(c, out);
}

void LineImuParser::feed(std::span<const std::uint8_t> bytes, std::vector<Sample>& out) {
  for (std::uint8_t b : bytes) handleByte(static_cast<char>(b), out);
}

void LineImuParser::handleByte(char c, std::vector<Sample>& out) {
  const std::uint64_t at = m_offset++;
  if (c == '$') {
    if (m_inLine)
      m_errors.report(m_lineStart, "truncated sentence at byte " + std::to_string(m_lineStart) +
                                       " (a new '$' came before its end of line): \"$" +
                                       printable(m_line) + "\"");
    flushGarbage();
    m_inLine = true;
    m_overflow = false;
    m_line.clear();
    m_lineStart = at;
    return;
  }
  if (!m_inLine) {
    if (c == '\n' || c == '\r') return;  // blank lines are fine
    if (m_garbageRun == 0) m_garbageStart = at;
    ++m_garbageRun;
    ++m_garbageBytes;
    return;
  }
  if (c == '\n') {
    finishLine(out);
    return;
  }
  if (m_overflow) return;
  if (m_line.size() + 1 >= kMaxLineBytes) {
    m_overflow = true;
    m_errors.report(m_lineStart, "sentence at byte " + std::to_string(m_lineStart) +
                                     " is longer than " + std::to_string(kMaxLineBytes) +
                                     " bytes; skipped to its end");
    m_line.clear();
    return;
  }
  m_line += c;
}

void LineImuParser::endOfDatagram() {
  if (m_inLine && !m_overflow)
    m_errors.report(m_lineStart, "datagram ended inside the sentence at byte " +
                                     std::to_string(m_lineStart) + ": \"$" + printable(m_line) +
                                     "\"");
  m_inLine = false;
  m_line.clear();
  flushGarbage();
}

void LineImuParser::reset() {
  m_inLine = false;
  m_overflow = false;
  m_line.clear();
  flushGarbage();
  m_haveTime = false;
}

void LineImuParser::flushGarbage() {
  if (m_garbageRun == 0) return;
  m_errors.report(m_garbageStart, "skipped " + std::to_string(m_garbageRun) +
                                      " bytes outside any sentence starting at byte " +
                                      std::to_string(m_garbageStart));
  m_garbageRun = 0;
}

void LineImuParser::finishLine(std::vector<Sample>& out) {
  m_inLine = false;
  if (m_overflow) {
    m_overflow = false;
    return;
  }
  std::string_view line = m_line;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  const std::string where = "sentence at byte " + std::to_string(m_lineStart);
  const std::size_t star = line.rfind('*');
  if (star == std::string_view::npos || star + 3 != line.size()) {
    m_errors.report(m_lineStart,
                    where + " has no '*HH' checksum at its end: \"$" + printable(line) + "\"");
    return;
  }
  const int hi = hexDigit(line[star + 1]), lo = hexDigit(line[star + 2]);
  const std::string_view body = line.substr(0, star);
  if (hi < 0 || lo < 0) {
    m_errors.report(m_lineStart, where + ": checksum '" + printable(line.substr(star + 1)) +
                                     "' is not two hex digits");
    return;
  }
  const std::uint8_t want = static_cast<std::uint8_t>(hi * 16 + lo), got = checksum(body);
  if (want != got) {
    char msg[96];
    std::snprintf(msg, sizeof msg, ": bad checksum, sentence says %02X, its bytes give %02X", want,
                  got);
    m_errors.report(m_lineStart, where + msg);
    return;
  }
  parseBody(body, out);
}

void LineImuParser::parseBody(std::string_view body, std::vector<Sample>& out) {
  const std::string where = "sentence at byte " + std::to_string(m_lineStart);
  const auto f = split(body, ',');
  if (f[0] == "IMU") {
    if (f.size() != 9) {
      m_errors.report(m_lineStart,
                      where + ": $IMU needs 8 fields, got " + std::to_string(f.size() - 1));
      return;
    }
    const auto seq = toU32(f[1]);
    const auto us = toU32(f[2]);
    if (!seq || !us) {
      m_errors.report(m_lineStart, where + ": seq and time must be unsigned 32-bit integers");
      return;
    }
    Sample s;
    for (int k = 0; k < 6; ++k) {
      const auto v = toDouble(f[3 + k]);
      if (!v) {
        m_errors.report(m_lineStart, where + ": field " + std::to_string(3 + k) + " \"" +
                                         printable(f[3 + k]) + "\" is not a finite decimal number");
        return;
      }
      (k < 3 ? s.gyr[k] : s.acc[k - 3]) = *v;
    }
    s.seq = *seq;
    s.rawTimeUs = *us;
    s.epoch = m_epoch;
    // The sequence number says whether this sentence is newer than every one before it (the
    // usual case), overtaken by a newer one on the way (UDP reorders), or seen before.
    const std::uint32_t ahead = s.seq - m_lastSeq;  // modulo 2^32
    if (!m_haveTime) {
      m_seq.restart();  // a new epoch or a reconnect: the counter is followed anew
      m_seq.add(m_seqUnwrapped);
      m_timeUs = s.rawTimeUs;
    } else if (ahead != 0 && ahead < 0x80000000u) {
      m_seqUnwrapped += ahead;
      m_seq.add(m_seqUnwrapped);
      m_timeUs += static_cast<std::uint32_t>(s.rawTimeUs - m_lastRawUs);
    } else {
      // Older than the newest sentence: overtaken on the way (counted reordered) or a duplicate.
      // Either way it is not returned: device time never decreases within an epoch.
      m_seq.add(m_seqUnwrapped - (m_lastSeq - s.seq));
      return;
    }
    m_haveTime = true;
    m_lastSeq = s.seq;
    m_lastRawUs = s.rawTimeUs;
    s.deviceTimeUs = m_timeUs;
    s.t = static_cast<double>(m_timeUs) * 1e-6;
    ++m_samples;
    out.push_back(s);
  } else if (f[0] == "HELLO") {
    if (f.size() != 4) {
      m_errors.report(m_lineStart,
                      where + ": $HELLO needs 3 fields, got " + std::to_string(f.size() - 1));
      return;
    }
    const auto version = toU32(f[1]);
    const auto rate = toDouble(f[3]);
    if (!version || *version != static_cast<std::uint32_t>(kProtocolVersion)) {
      m_errors.report(m_lineStart, where + ": unsupported protocol version \"" + printable(f[1]) +
                                       "\" (this reader speaks 1)");
      return;
    }
    if (!rate || *rate <= 0.0) {
      m_errors.report(m_lineStart,
                      where + ": rate \"" + printable(f[3]) + "\" is not a positive number");
      return;
    }
    m_hello = Hello{kProtocolVersion, std::string(f[2]), *rate};
    m_haveTime = false;  // a (re)started device starts its clock anew: a new epoch
    ++m_epoch;
  } else {
    m_errors.report(m_lineStart, where + ": unknown sentence type \"" + printable(f[0]) + "\"");
  }
}

}  // namespace armtrack::devices::lineimu
