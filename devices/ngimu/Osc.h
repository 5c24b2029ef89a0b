// Open Sound Control 1.0 packet decoding (messages and bundles), as used by x-io's NGIMU over UDP.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "devices/common/ParseErrorLog.h"

namespace armtrack::devices::osc {

/// OSC time tag 1 means "immediately" (no time).
inline constexpr std::uint64_t kImmediately = 1;

/// One argument. Numbers (f, i, h, d, c, r, m, t) go to `number`; strings and blobs to `text`;
/// T, F, N and I carry no data (T gives number 1).
struct Value {
  char tag = 0;
  double number = 0.0;
  std::string text;
};

struct Message {
  std::string address;  ///< e.g. "/sensors"
  std::string tags;     ///< type tags without the leading ','
  std::vector<Value> args;
  std::uint64_t timetag = kImmediately;  ///< of the enclosing bundle, NTP format
  std::size_t offset = 0;                ///< byte offset of the message in its datagram
};

/// NTP time tag to seconds since 1900-01-01 (s).
double timetagSeconds(std::uint64_t timetag);

/// Decodes one UDP datagram (a message or a bundle, bundles nested up to 8 deep). Appends the
/// messages it can decode to `out` and reports each problem to `errors` with its byte offset in
/// the datagram, prefixed by `context`. Returns false when anything was wrong. Never throws.
bool decodePacket(std::span<const std::uint8_t> datagram, std::vector<Message>& out,
                  ParseErrorLog& errors, const std::string& context = "");

/// Encoders, for tests and fakes.
void appendString(std::vector<std::uint8_t>& b, const std::string& s);
void appendInt32(std::vector<std::uint8_t>& b, std::int32_t v);
void appendFloat32(std::vector<std::uint8_t>& b, float v);
std::vector<std::uint8_t> encodeMessage(const std::string& address, const std::vector<float>& args);
std::vector<std::uint8_t> encodeBundle(std::uint64_t timetag,
                                       const std::vector<std::vector<std::uint8_t>>& elements);

}  // namespace armtrack::devices::osc
