#include "core/storage/ChunkCodec.h"

#include "core/storage/ChunkLattice.h"
#include "core/storage/ChunkPredictive.h"

#include <zstd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>

namespace armtrack::storage {

namespace {

constexpr std::uint32_t kMagic = 0x31435441;   // "ATC1" little-endian
constexpr std::uint32_t kMagic2 = 0x32435441;  // "ATC2" little-endian
constexpr std::uint32_t kMagic3 = 0x33435441;  // "ATC3" little-endian
constexpr std::uint32_t kMaxRows = 1u << 24;   // a chunk holds about a second; this is far beyond
constexpr int kGroups = 11;
// Groups 0-7 are in every chunk (their columns, possibly empty, always follow the time); the
// trunk's groups (8: sternum IMU, 9: optical shoulder, 10: true trunk angles, issue 26) have
// columns only in a chunk with a row that has them. A chunk without them is therefore the same
// bytes as before they existed (an older version reads it), and a chunk written before them
// decodes unchanged; an older version refuses a chunk with them ("unknown sensor group").
constexpr int kAlwaysGroups = 8;

// The sensor groups of an ArmSample in a fixed order, and their number of doubles.
constexpr std::array<int, kGroups> kGroupSize{6, 6, 3, 3, 2, 2, 5, 5, 6, 3, 3};

std::uint16_t presenceOf(const ArmSample& s) {
  std::uint16_t m = 0;
  if (s.upperArm) m |= 1u << 0;
  if (s.forearm) m |= 1u << 1;
  if (s.elbow) m |= 1u << 2;
  if (s.wrist) m |= 1u << 3;
  if (s.camWrist) m |= 1u << 4;
  if (s.camElbow) m |= 1u << 5;
  if (s.trueAngles) m |= 1u << 6;
  if (s.estimate) m |= 1u << 7;
  if (s.trunk) m |= 1u << 8;
  if (s.shoulder) m |= 1u << 9;
  if (s.trueTrunk) m |= 1u << 10;
  return m;
}

// The doubles of group g of s, in the order of the recording format's columns.
void valuesOf(const ArmSample& s, int g, double* v) {
  auto put = [&](const auto& vec, int offset) {
    for (int i = 0; i < vec.size(); ++i) v[offset + i] = vec[i];
  };
  switch (g) {
    case 0:
      put(s.upperArm->gyr, 0);
      put(s.upperArm->acc, 3);
      break;
    case 1:
      put(s.forearm->gyr, 0);
      put(s.forearm->acc, 3);
      break;
    case 2:
      put(*s.elbow, 0);
      break;
    case 3:
      put(*s.wrist, 0);
      break;
    case 4:
      put(*s.camWrist, 0);
      break;
    case 5:
      put(*s.camElbow, 0);
      break;
    case 6:
      put(*s.trueAngles, 0);
      break;
    case 7:
      put(*s.estimate, 0);
      break;
    case 8:
      put(s.trunk->gyr, 0);
      put(s.trunk->acc, 3);
      break;
    case 9:
      put(*s.shoulder, 0);
      break;
    default:
      put(*s.trueTrunk, 0);
      break;
  }
}

void setValues(ArmSample& s, int g, const double* v) {
  auto get = [&](auto& vec, int offset) {
    for (int i = 0; i < vec.size(); ++i) vec[i] = v[offset + i];
  };
  switch (g) {
    case 0:
      s.upperArm.emplace();
      get(s.upperArm->gyr, 0);
      get(s.upperArm->acc, 3);
      break;
    case 1:
      s.forearm.emplace();
      get(s.forearm->gyr, 0);
      get(s.forearm->acc, 3);
      break;
    case 2:
      s.elbow.emplace();
      get(*s.elbow, 0);
      break;
    case 3:
      s.wrist.emplace();
      get(*s.wrist, 0);
      break;
    case 4:
      s.camWrist.emplace();
      get(*s.camWrist, 0);
      break;
    case 5:
      s.camElbow.emplace();
      get(*s.camElbow, 0);
      break;
    case 6:
      s.trueAngles.emplace();
      get(*s.trueAngles, 0);
      break;
    case 7:
      s.estimate.emplace();
      get(*s.estimate, 0);
      break;
    case 8:
      s.trunk.emplace();
      get(s.trunk->gyr, 0);
      get(s.trunk->acc, 3);
      break;
    case 9:
      s.shoulder.emplace();
      get(*s.shoulder, 0);
      break;
    default:
      s.trueTrunk.emplace();
      get(*s.trueTrunk, 0);
      break;
  }
}

// Whether group g has columns in a chunk whose rows have these presence masks (kAlwaysGroups).
bool hasColumns(int g, std::uint16_t anyPresence) {
  return g < kAlwaysGroups || ((anyPresence >> g) & 1u);
}

// Appends words as byte planes: every word's byte 0, then every byte 1, ...
template <typename Word>
void appendPlanes(std::string& out, const std::vector<Word>& words) {
  const std::size_t n = words.size(), base = out.size();
  out.resize(base + n * sizeof(Word));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t b = 0; b < sizeof(Word); ++b)
      out[base + b * n + i] = static_cast<char>((words[i] >> (8 * b)) & 0xff);
}

class Reader {
 public:
  explicit Reader(const std::string& data) : m_data(data) {}
  template <typename Word>
  std::vector<Word> planes(std::size_t n) {
    need(n * sizeof(Word));
    std::vector<Word> words(n, 0);
    for (std::size_t b = 0; b < sizeof(Word); ++b)
      for (std::size_t i = 0; i < n; ++i)
        words[i] |= static_cast<Word>(static_cast<unsigned char>(m_data[m_pos + b * n + i]))
                    << (8 * b);
    m_pos += n * sizeof(Word);
    return words;
  }
  std::uint32_t u32() { return planes<std::uint32_t>(1)[0]; }
  std::uint8_t u8() { return planes<std::uint8_t>(1)[0]; }
  bool atEnd() const { return m_pos == m_data.size(); }
  const std::string& data() const { return m_data; }
  std::size_t& position() { return m_pos; }

 private:
  void need(std::size_t bytes) const {
    if (m_data.size() - m_pos < bytes) throw std::runtime_error("chunk content ends early");
  }
  const std::string& m_data;
  std::size_t m_pos = 0;
};

// A column is stored in one of two modes, whichever suits its values:
//  - kBinary: each 64-bit pattern XORed with the previous one, as byte planes. Always exact.
//  - kDecimal: every value as its shortest decimal k * 10^e (k at most 13 digits, |e| <= 127),
//    stored as byte planes of e and of k (see decimalColumn). Chosen when every value of the
//    column is such a short decimal (a 16-bit sensor, a file written with 7 digits), where it
//    takes a few bytes a value instead of the ~6.5 of a double's noisy mantissa. Exact because
//    the shortest decimal reads back to the same double.
//  - kPredictive (ATC2 on): see ChunkPredictive.h. Always exact.
//  - kLattice (ATC3 on): counts on a step, see ChunkLattice.h. Always exact.
enum ColumnMode : std::uint8_t { kBinary = 0, kDecimal = 1, kPredictive = 2, kLattice = 3 };
constexpr int kNoExponent = 1000;
constexpr std::int64_t kLongDigits = 10'000'000'000'000;  // 14 significant digits

std::uint64_t zigzag(std::int64_t d) {
  return (static_cast<std::uint64_t>(d) << 1) ^ static_cast<std::uint64_t>(d >> 63);
}
std::int64_t unzigzag(std::uint64_t z) {
  return static_cast<std::int64_t>(z >> 1) ^ -static_cast<std::int64_t>(z & 1);
}

// v as (integer significand, decimal exponent) from its shortest round-trip form.
bool shortestDecimal(double v, std::int64_t& digits, int& exponent) {
  if (v == 0.0 && std::signbit(v)) return false;  // -0 has no integer significand
  if (!std::isfinite(v)) return false;            // "inf" and "nan" have no digits
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
  if (r.ec != std::errc()) return false;
  // "-d.ddddde-xx": collect the digits, then the exponent.
  std::int64_t k = 0;
  int fraction = 0;
  bool inFraction = false;
  const char* p = buf;
  const bool negative = *p == '-';
  if (negative) ++p;
  for (; p < r.ptr && *p != 'e'; ++p) {
    if (*p == '.') {
      inFraction = true;
      continue;
    }
    k = k * 10 + (*p - '0');  // at most 17 digits: fits
    if (inFraction) ++fraction;
  }
  int e = 0;
  if (p < r.ptr) std::from_chars(p + 1 + (p[1] == '+' ? 1 : 0), r.ptr, e);
  digits = negative ? -k : k;
  exponent = e - fraction;
  return true;
}

// Per value: its decimal exponent (a byte), and its significand as the zig-zag difference from
// the previous value's when both have the same exponent (a slowly changing signal), else whole.
bool decimalColumn(const std::vector<double>& values, std::vector<std::uint8_t>& exponents,
                   std::vector<std::uint64_t>& steps) {
  exponents.resize(values.size());
  steps.resize(values.size());
  std::int64_t prevDigits = 0;
  int prevExp = kNoExponent;
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::int64_t digits = 0;
    int exp = 0;
    if (!shortestDecimal(values[i], digits, exp)) return false;
    if (digits >= kLongDigits || digits <= -kLongDigits) return false;  // full precision
    if (exp < -127 || exp > 127) return false;
    exponents[i] = static_cast<std::uint8_t>(static_cast<std::int8_t>(exp));
    steps[i] = zigzag(exp == prevExp ? digits - prevDigits : digits);
    prevDigits = digits;
    prevExp = exp;
  }
  return true;
}

void appendColumn(std::string& raw, const std::vector<double>& values) {
  std::vector<std::uint8_t> exponents;
  std::vector<std::uint64_t> words;
  if (!values.empty() && decimalColumn(values, exponents, words)) {
    raw.push_back(static_cast<char>(kDecimal));
    appendPlanes(raw, exponents);
    appendPlanes(raw, words);
    return;
  }
  raw.push_back(static_cast<char>(kBinary));
  words.resize(values.size());
  std::uint64_t prev = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto bits = std::bit_cast<std::uint64_t>(values[i]);
    words[i] = bits ^ prev;
    prev = bits;
  }
  appendPlanes(raw, words);
}

std::size_t zstdSize(const std::string& raw) {
  std::string out(ZSTD_compressBound(raw.size()), '\0');
  const std::size_t size = ZSTD_compress(out.data(), out.size(), raw.data(), raw.size(), 1);
  return ZSTD_isError(size) ? raw.size() : size;
}

// ATC2 and ATC3: whichever of the modes the values allow takes the fewest bytes (the zstd size of
// its part plus its raw low bits); predictive always can. ATC3 adds the lattice mode.
void appendColumn2(std::string& raw, detail::BitWriter& bits, const std::vector<double>& values,
                   int version) {
  // The predictive part, and the lattice part when the values lie on a step, are written once
  // (their raw bytes and low bits) and the smaller one is appended as it is.
  std::string part;
  detail::BitWriter partBits;
  detail::appendPredictiveColumn(part, partBits, values);
  ColumnMode mode = kPredictive;
  std::vector<std::uint8_t> exponents;
  std::vector<std::uint64_t> words;
  const bool decimal = !values.empty() && decimalColumn(values, exponents, words);
  const std::optional<double> step =
      version >= 3 && !values.empty() ? detail::findLatticeStep(values) : std::nullopt;
  if (decimal || step) {
    std::size_t best = zstdSize(part) + partBits.bytes();
    if (step) {
      std::string lattice;
      detail::BitWriter latticeBits;
      detail::appendLatticeColumn(lattice, latticeBits, values, *step);
      const std::size_t size = zstdSize(lattice) + latticeBits.bytes();
      if (size < best) {
        best = size;
        mode = kLattice;
        part = std::move(lattice);
        partBits = std::move(latticeBits);
      }
    }
    if (decimal) {
      std::string text;
      appendPlanes(text, exponents);
      appendPlanes(text, words);
      if (zstdSize(text) <= best) {
        mode = kDecimal;
        part = std::move(text);
        partBits = {};
      }
    }
  }
  raw.push_back(static_cast<char>(mode));
  raw += part;
  bits.append(partBits);
}

// A column of a chunk of the given version (1: ATC1, without bits; 2: ATC2; 3: ATC3).
std::vector<double> readColumn(Reader& in, std::size_t count, detail::BitReader* bits,
                               int version) {
  const std::uint8_t mode = in.u8();
  if (mode == kPredictive && bits)
    return detail::readPredictiveColumn(in.data(), in.position(), *bits, count);
  if (mode == kLattice && bits && version >= 3)
    return detail::readLatticeColumn(in.data(), in.position(), *bits, count);
  std::vector<double> values(count);
  if (mode == kBinary && !bits) {
    std::uint64_t prev = 0;
    const auto words = in.planes<std::uint64_t>(count);
    for (std::size_t i = 0; i < count; ++i) {
      prev ^= words[i];
      values[i] = std::bit_cast<double>(prev);
    }
    return values;
  }
  if (mode != kDecimal) throw std::runtime_error("unknown column mode " + std::to_string(mode));
  const auto exponents = in.planes<std::uint8_t>(count);
  const auto words = in.planes<std::uint64_t>(count);
  std::int64_t k = 0;
  int prevExp = kNoExponent;
  char buf[48];
  for (std::size_t i = 0; i < count; ++i) {
    const int exponent = static_cast<std::int8_t>(exponents[i]);
    const std::int64_t step = unzigzag(words[i]);
    // Wrapping addition: a forged step must not be undefined behaviour (from_chars then refuses
    // or yields some double; the row count and sizes were already checked).
    k = exponent == prevExp ? static_cast<std::int64_t>(static_cast<std::uint64_t>(k) +
                                                        static_cast<std::uint64_t>(step))
                            : step;
    prevExp = exponent;
    auto r = std::to_chars(buf, buf + 24, k);
    *r.ptr++ = 'e';
    r = std::to_chars(r.ptr, buf + sizeof buf, exponent);
    const auto parsed = std::from_chars(buf, r.ptr, values[i]);
    if (parsed.ec != std::errc()) throw std::runtime_error("decimal value out of range");
  }
  return values;
}

// The uncompressed content both versions share: magic, row count, presence masks, the time
// column, then every group's columns (column is ATC1's or ATC2's writer).
template <typename AppendColumn>
std::string content(std::span<const ArmSample> samples, std::uint32_t magic,
                    AppendColumn&& column) {
  const std::size_t n = samples.size();
  if (n > kMaxRows) throw std::runtime_error("too many rows for one chunk");
  std::string raw;
  appendPlanes(raw, std::vector<std::uint32_t>{magic});
  appendPlanes(raw, std::vector<std::uint32_t>{static_cast<std::uint32_t>(n)});
  std::vector<std::uint16_t> presence(n);
  std::vector<double> times(n);
  std::uint16_t any = 0;
  for (std::size_t i = 0; i < n; ++i) {
    presence[i] = presenceOf(samples[i]);
    any |= presence[i];
    times[i] = samples[i].t;
  }
  appendPlanes(raw, presence);
  column(raw, times);
  std::vector<double> values;
  double v[6];
  for (int g = 0; g < kGroups; ++g) {
    if (!hasColumns(g, any)) continue;
    for (int c = 0; c < kGroupSize[g]; ++c) {
      values.clear();
      for (std::size_t i = 0; i < n; ++i) {
        if (!(presence[i] & (1u << g))) continue;
        valuesOf(samples[i], g, v);
        values.push_back(v[c]);
      }
      column(raw, values);
    }
  }
  return raw;
}

std::string compress(const std::string& raw, int level) {
  std::string frame(ZSTD_compressBound(raw.size()), '\0');
  const std::size_t size = ZSTD_compress(frame.data(), frame.size(), raw.data(), raw.size(), level);
  if (ZSTD_isError(size))
    throw std::runtime_error(std::string("zstd compression failed: ") + ZSTD_getErrorName(size));
  frame.resize(size);
  return frame;
}

// The content of one zstd frame, its claimed size bounded before anything is allocated.
std::string decompress(const char* data, std::size_t bytes, std::uint64_t bound,
                       std::uint64_t rows) {
  const unsigned long long size = ZSTD_getFrameContentSize(data, bytes);
  if (size == ZSTD_CONTENTSIZE_ERROR) throw std::runtime_error("not a zstd frame");
  if (size == ZSTD_CONTENTSIZE_UNKNOWN) throw std::runtime_error("zstd frame without its size");
  if (size > bound)
    throw std::runtime_error("zstd frame claims " + std::to_string(size) + " bytes for " +
                             std::to_string(rows) + " rows");
  std::string raw(size, '\0');
  const std::size_t got = ZSTD_decompress(raw.data(), raw.size(), data, bytes);
  if (ZSTD_isError(got))
    throw std::runtime_error(std::string("damaged zstd frame: ") + ZSTD_getErrorName(got));
  if (got != size) throw std::runtime_error("zstd frame shorter than it claims");
  return raw;
}

std::vector<ArmSample> parse(const std::string& raw, std::uint32_t magic,
                             std::uint64_t expectedRows, detail::BitReader* bits, int version) {
  Reader in(raw);
  if (in.u32() != magic) throw std::runtime_error("not an ArmTrack chunk (bad magic number)");
  const std::uint32_t n = in.u32();
  if (n != expectedRows)
    throw std::runtime_error("holds " + std::to_string(n) + " rows, the index says " +
                             std::to_string(expectedRows));
  const auto presence = in.planes<std::uint16_t>(n);
  const auto times = readColumn(in, n, bits, version);
  std::vector<ArmSample> samples(n);
  std::uint16_t any = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (presence[i] >> kGroups) throw std::runtime_error("unknown sensor group in a row");
    samples[i].t = times[i];
    any |= presence[i];
  }
  for (int g = 0; g < kGroups; ++g) {
    if (!hasColumns(g, any)) continue;
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) count += (presence[i] >> g) & 1u;
    std::vector<std::vector<double>> cols;
    for (int c = 0; c < kGroupSize[g]; ++c) cols.push_back(readColumn(in, count, bits, version));
    std::size_t k = 0;
    double v[6];
    for (std::size_t i = 0; i < n; ++i) {
      if (!((presence[i] >> g) & 1u)) continue;
      for (int c = 0; c < kGroupSize[g]; ++c) v[c] = cols[c][k];
      setValues(samples[i], g, v);
      ++k;
    }
  }
  if (!in.atEnd()) throw std::runtime_error("chunk content longer than its rows");
  if (bits) bits->expectEnd();
  return samples;
}

std::uint32_t le32(const char* p) {
  std::uint32_t v = 0;
  for (int b = 0; b < 4; ++b)
    v |= static_cast<std::uint32_t>(static_cast<unsigned char>(p[b])) << (8 * b);
  return v;
}

// FNV-1a, 64 bits: any flipped bit of an ATC2 chunk's body shows (its low bits are raw, so zstd
// alone would not notice).
std::uint64_t fnv1a(const char* data, std::size_t size) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i < size; ++i) {
    h ^= static_cast<unsigned char>(data[i]);
    h *= 0x100000001b3ull;
  }
  return h;
}

constexpr std::size_t kHeader2 = 16;  // magic, frame length, checksum of the rest

}  // namespace

namespace {

// ATC2 and ATC3 chunks: header (magic, frame length, checksum), zstd frame, raw low bits.
std::string encodeWithBits(std::span<const ArmSample> samples, std::uint32_t magic, int version,
                           int level) {
  detail::BitWriter bits;
  const std::string raw = content(samples, magic, [&](std::string& out, const auto& values) {
    appendColumn2(out, bits, values, version);
  });
  const std::string frame = compress(raw, level);
  const std::string body = frame + bits.finish();
  std::string blob;
  blob.reserve(kHeader2 + body.size());
  appendPlanes(blob, std::vector<std::uint32_t>{magic});
  appendPlanes(blob, std::vector<std::uint32_t>{static_cast<std::uint32_t>(frame.size())});
  const std::uint64_t sum = fnv1a(body.data(), body.size());
  for (int b = 0; b < 8; ++b) blob.push_back(static_cast<char>((sum >> (8 * b)) & 0xff));
  return blob + body;
}

// The header of an ATC2 or ATC3 chunk checked (magic, frame length) and its checksum against
// everything after it; returns the length of the zstd frame.
std::uint32_t checkHeaderAndSum(std::string_view frame, std::uint32_t magic) {
  if (frame.size() < kHeader2 || le32(frame.data()) != magic)
    throw std::runtime_error("not an ArmTrack chunk (bad magic number)");
  const std::uint32_t frameBytes = le32(frame.data() + 4);
  if (frameBytes > frame.size() - kHeader2)
    throw std::runtime_error("chunk shorter than its header says");
  const std::uint64_t sum = static_cast<std::uint64_t>(le32(frame.data() + 8)) |
                            (static_cast<std::uint64_t>(le32(frame.data() + 12)) << 32);
  if (sum != fnv1a(frame.data() + kHeader2, frame.size() - kHeader2))
    throw std::runtime_error("checksum mismatch: the chunk was damaged");
  return frameBytes;
}

std::vector<ArmSample> decodeWithBits(const std::string& frame, std::uint64_t expectedRows,
                                      std::uint32_t magic, int version, std::uint64_t bound) {
  const std::uint32_t frameBytes = checkHeaderAndSum(frame, magic);
  const std::string raw = decompress(frame.data() + kHeader2, frameBytes, bound, expectedRows);
  detail::BitReader bits(frame.data() + kHeader2 + frameBytes,
                         frame.size() - kHeader2 - frameBytes);
  return parse(raw, magic, expectedRows, &bits, version);
}

}  // namespace

bool ChunkCodec::knows(std::string_view codec) {
  return codec == kName || codec == kAtc2Name || codec == kLegacyName;
}

std::string ChunkCodec::encode(std::span<const ArmSample> samples, int level) {
  return encodeWithBits(samples, kMagic3, 3, level);
}

std::string ChunkCodec::encodeLegacy(std::span<const ArmSample> samples, std::string_view codec,
                                     int level) {
  if (codec == kAtc2Name) return encodeWithBits(samples, kMagic2, 2, level);
  if (codec != kLegacyName) throw std::runtime_error("unknown codec '" + std::string(codec) + "'");
  return compress(content(samples, kMagic, appendColumn), level);
}

std::vector<ArmSample> ChunkCodec::decode(const std::string& frame, std::uint64_t expectedRows,
                                          std::string_view codec) {
  // Header + presence + time + at most every value of every row (9 bytes each at most, plus a
  // few per column): a bound that a forged size field cannot push past. A lattice column may
  // take 18 bytes a value (count and distance, each stored whole) and 11 of its own. 46 columns:
  // the time and 45 values a row (33 before the trunk's groups).
  const std::uint64_t bound = 8 + 46 * 3 + expectedRows * (2 + 9 * 45);
  const std::uint64_t bound3 = 8 + 46 * 11 + expectedRows * (2 + 18 * 46);
  if (codec == kLegacyName)
    return parse(decompress(frame.data(), frame.size(), bound, expectedRows), kMagic, expectedRows,
                 nullptr, 1);
  if (codec == kAtc2Name) return decodeWithBits(frame, expectedRows, kMagic2, 2, bound);
  if (codec != kName) throw std::runtime_error("unknown codec '" + std::string(codec) + "'");
  return decodeWithBits(frame, expectedRows, kMagic3, 3, bound3);
}

void ChunkCodec::verify(std::string_view frame, std::uint64_t expectedRows,
                        std::string_view codec) {
  if (codec == kLegacyName) {  // no checksum: only decoding tells
    decode(std::string(frame), expectedRows, codec);
    return;
  }
  if (codec != kName && codec != kAtc2Name)
    throw std::runtime_error("unknown codec '" + std::string(codec) + "'");
  checkHeaderAndSum(frame, codec == kName ? kMagic3 : kMagic2);
}

}  // namespace armtrack::storage
