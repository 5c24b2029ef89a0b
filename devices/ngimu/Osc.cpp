#include "devices/ngimu/Osc.h"

#include <bit>
#include <cstring>
#include <optional>

namespace armtrack::devices::osc {
namespace {

constexpr int kMaxDepth = 8;
constexpr char kBundleTag[8] = {'#', 'b', 'u', 'n', 'd', 'l', 'e', '\0'};

struct Reader {
  std::span<const std::uint8_t> data;
  std::size_t base;  // offset of data[0] in the datagram
  std::size_t pos = 0;
  ParseErrorLog& errors;
  const std::string& context;
  bool ok = true;

  std::size_t left() const { return data.size() - pos; }
  std::size_t at() const { return base + pos; }
  void fail(const std::string& what) {
    if (ok) errors.report(at(), context + what + " at byte " + std::to_string(at()));
    ok = false;
  }
  std::optional<std::uint32_t> u32() {
    if (left() < 4) {
      fail("truncated: a 4-byte value needs " + std::to_string(4 - left()) + " more bytes");
      return std::nullopt;
    }
    const std::uint8_t* p = data.data() + pos;
    pos += 4;
    return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
           std::uint32_t{p[3]};
  }
  std::optional<std::uint64_t> u64() {
    const auto hi = u32();
    if (!hi) return std::nullopt;
    const auto lo = u32();
    if (!lo) return std::nullopt;
    return (std::uint64_t{*hi} << 32) | *lo;
  }
  // Null-terminated, zero-padded to a multiple of 4 bytes.
  std::optional<std::string> str() {
    const std::size_t start = pos;
    std::size_t end = start;
    while (end < data.size() && data[end] != 0) ++end;
    if (end == data.size()) {
      fail("string without its terminating zero byte");
      return std::nullopt;
    }
    const std::size_t padded = (end - start + 4) & ~std::size_t{3};
    if (start + padded > data.size()) {
      fail("string padding runs past the end");
      return std::nullopt;
    }
    for (std::size_t k = end; k < start + padded; ++k)
      if (data[k] != 0) {
        pos = k;
        fail("non-zero padding byte after a string");
        return std::nullopt;
      }
    pos = start + padded;
    return std::string(reinterpret_cast<const char*>(data.data() + start), end - start);
  }
};

bool decodeMessage(Reader& r, std::uint64_t timetag, std::vector<Message>& out) {
  Message m;
  m.offset = r.at();
  m.timetag = timetag;
  auto address = r.str();
  if (!address) return false;
  if (address->empty() || address->front() != '/') {
    r.pos = m.offset - r.base;
    r.fail("message address \"" + address->substr(0, 40) + "\" does not start with '/'");
    return false;
  }
  m.address = *address;
  auto tags = r.str();
  if (!tags) return false;
  if (tags->empty() || tags->front() != ',') {
    r.fail("type tag string missing (must start with ',') in " + m.address);
    return false;
  }
  m.tags = tags->substr(1);
  for (char tag : m.tags) {
    Value v;
    v.tag = tag;
    switch (tag) {
      case 'i':
      case 'c':
      case 'r':
      case 'm': {
        const auto x = r.u32();
        if (!x) return false;
        v.number = tag == 'i' ? static_cast<double>(static_cast<std::int32_t>(*x))
                              : static_cast<double>(*x);
        break;
      }
      case 'f': {
        const auto x = r.u32();
        if (!x) return false;
        v.number = std::bit_cast<float>(*x);
        break;
      }
      case 'h':
      case 't': {
        const auto x = r.u64();
        if (!x) return false;
        v.number =
            tag == 'h' ? static_cast<double>(static_cast<std::int64_t>(*x)) : timetagSeconds(*x);
        break;
      }
      case 'd': {
        const auto x = r.u64();
        if (!x) return false;
        v.number = std::bit_cast<double>(*x);
        break;
      }
      case 's':
      case 'S': {
        auto s = r.str();
        if (!s) return false;
        v.text = std::move(*s);
        break;
      }
      case 'b': {
        const auto n = r.u32();
        if (!n) return false;
        const std::size_t padded = (std::size_t{*n} + 3) & ~std::size_t{3};
        if (*n > r.left() || padded > r.left()) {
          r.fail("blob of " + std::to_string(*n) + " bytes runs past the end");
          return false;
        }
        v.text.assign(reinterpret_cast<const char*>(r.data.data() + r.pos), *n);
        r.pos += padded;
        break;
      }
      case 'T':
        v.number = 1.0;
        break;
      case 'F':
      case 'N':
      case 'I':
        break;
      default:
        r.fail(std::string("unknown type tag '") +
               (tag >= 0x20 && tag < 0x7F ? std::string(1, tag) : std::string("?")) + "' in " +
               m.address);
        return false;
    }
    m.args.push_back(std::move(v));
  }
  if (r.left() != 0) {
    r.fail(std::to_string(r.left()) + " stray bytes after the arguments of " + m.address);
    return false;
  }
  out.push_back(std::move(m));
  return true;
}

bool decodeAny(std::span<const std::uint8_t> data, std::size_t base, std::uint64_t timetag,
               int depth, std::vector<Message>& out, ParseErrorLog& errors,
               const std::string& context) {
  Reader r{data, base, 0, errors, context};
  if (data.size() % 4 != 0) {
    r.fail("OSC packet size " + std::to_string(data.size()) + " is not a multiple of 4");
    return false;
  }
  if (data.empty()) {
    r.fail("empty OSC packet");
    return false;
  }
  if (data[0] != '#') return decodeMessage(r, timetag, out);
  if (data.size() < 16 || std::memcmp(data.data(), kBundleTag, 8) != 0) {
    r.fail("packet starts with '#' but is not a \"#bundle\" with a time tag");
    return false;
  }
  if (depth >= kMaxDepth) {
    r.fail("bundles nested deeper than " + std::to_string(kMaxDepth));
    return false;
  }
  r.pos = 8;
  const std::uint64_t tag = *r.u64();
  bool ok = true;
  while (r.left() > 0) {
    const auto size = r.u32();
    if (!size) return false;
    if (*size == 0 || *size % 4 != 0 || *size > r.left()) {
      r.fail("bundle element declares " + std::to_string(*size) + " bytes but " +
             std::to_string(r.left()) + " remain (size must be a positive multiple of 4)");
      return false;
    }
    ok =
        decodeAny(data.subspan(r.pos, *size), base + r.pos, tag, depth + 1, out, errors, context) &&
        ok;
    r.pos += *size;
  }
  return ok;
}

}  // namespace

double timetagSeconds(std::uint64_t t) {
  return static_cast<double>(t >> 32) + static_cast<double>(t & 0xFFFFFFFFu) / 4294967296.0;
}

bool decodePacket(std::span<const std::uint8_t> datagram, std::vector<Message>& out,
                  ParseErrorLog& errors, const std::string& context) {
  return decodeAny(datagram, 0, kImmediately, 0, out, errors, context);
}

void appendString(std::vector<std::uint8_t>& b, const std::string& s) {
  b.insert(b.end(), s.begin(), s.end());
  const std::size_t pad = 4 - s.size() % 4;
  b.insert(b.end(), pad, 0);
}

void appendInt32(std::vector<std::uint8_t>& b, std::int32_t v) {
  const auto u = static_cast<std::uint32_t>(v);
  for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<std::uint8_t>(u >> s));
}

void appendFloat32(std::vector<std::uint8_t>& b, float v) {
  appendInt32(b, std::bit_cast<std::int32_t>(v));
}

std::vector<std::uint8_t> encodeMessage(const std::string& address,
                                        const std::vector<float>& args) {
  std::vector<std::uint8_t> b;
  appendString(b, address);
  appendString(b, "," + std::string(args.size(), 'f'));
  for (float a : args) appendFloat32(b, a);
  return b;
}

std::vector<std::uint8_t> encodeBundle(std::uint64_t timetag,
                                       const std::vector<std::vector<std::uint8_t>>& elements) {
  std::vector<std::uint8_t> b(kBundleTag, kBundleTag + 8);
  appendInt32(b, static_cast<std::int32_t>(timetag >> 32));
  appendInt32(b, static_cast<std::int32_t>(timetag & 0xFFFFFFFFu));
  for (const auto& e : elements) {
    appendInt32(b, static_cast<std::int32_t>(e.size()));
    b.insert(b.end(), e.begin(), e.end());
  }
  return b;
}

}  // namespace armtrack::devices::osc
