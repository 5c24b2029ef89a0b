#include "core/storage/ChunkPredictive.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace armtrack::storage::detail {

namespace {

constexpr std::uint64_t kTop = 1ull << 63;
constexpr int kPredictors = 6;  // 1..5: polynomial extrapolation of that order; 6: mean of 4

// A double as an integer that orders as the double does (for non-NaN), so that the difference
// of two close values counts the doubles between them. A bijection on all 2^64 patterns.
std::uint64_t ordered(double v) {
  const auto b = std::bit_cast<std::uint64_t>(v);
  return (b & kTop) ? ~b : (b | kTop);
}
double unordered(std::uint64_t u) {
  return std::bit_cast<double>((u & kTop) ? (u & ~kTop) : ~u);
}

std::uint64_t zigzag(std::uint64_t r) {
  return (r << 1) ^ (0 - (r >> 63));
}
std::uint64_t unzigzag(std::uint64_t z) {
  return (z >> 1) ^ (0 - (z & 1));
}

// The prediction of s[i] from the values before it (wrapping arithmetic: any input is defined
// and the decoder computes the very same number). s holds ordered values minus 2^63.
std::uint64_t predict(const std::uint64_t* s, std::size_t i, int predictor) {
  if (i == 0) return 0;
  const int order =
      predictor == 6 ? (i >= 4 ? 6 : 1) : std::min<int>(predictor, static_cast<int>(i));
  const std::uint64_t a = s[i - 1];
  switch (order) {
    case 1:
      return a;
    case 2:
      return 2 * a - s[i - 2];
    case 3:
      return 3 * a - 3 * s[i - 2] + s[i - 3];
    case 4:
      return 4 * a - 6 * s[i - 2] + 4 * s[i - 3] - s[i - 4];
    case 5:
      return 5 * a - 10 * s[i - 2] + 10 * s[i - 3] - 5 * s[i - 4] + s[i - 5];
    default: {  // the mean of the last four, for noise around a slowly moving value
      __int128 sum = 0;
      for (int j = 1; j <= 4; ++j) sum += static_cast<std::int64_t>(s[i - j]);
      return static_cast<std::uint64_t>(static_cast<std::int64_t>(sum / 4));
    }
  }
}

// Bits needed by n residuals z split at k: Shannon estimate of the high bytes, k raw bits each,
// 64 per escaped residual.
double costBits(const std::vector<std::uint64_t>& z, int k) {
  std::array<std::uint32_t, 256> histogram{};
  std::size_t escapes = 0;
  for (const std::uint64_t v : z) {
    const std::uint64_t h = k >= 64 ? 0 : v >> k;
    if (h >= kEscape) {
      ++histogram[kEscape];
      ++escapes;
    } else {
      ++histogram[h];
    }
  }
  const double n = static_cast<double>(z.size());
  double bits = static_cast<double>(z.size() - escapes) * k + 64.0 * static_cast<double>(escapes);
  for (const std::uint32_t c : histogram)
    if (c) bits += c * std::log2(n / c);
  return bits;
}

}  // namespace

void BitWriter::put(std::uint64_t value, int bits) {
  while (bits > 0) {
    const int take = std::min(bits, 56 - m_fill);
    const std::uint64_t part = take == 64 ? value : value & ((1ull << take) - 1);
    m_acc |= part << m_fill;
    m_fill += take;
    value = take == 64 ? 0 : value >> take;
    bits -= take;
    while (m_fill >= 8) {
      m_bytes.push_back(static_cast<char>(m_acc & 0xff));
      m_acc >>= 8;
      m_fill -= 8;
    }
  }
}

void BitWriter::append(const BitWriter& other) {
  if (m_fill == 0)
    m_bytes += other.m_bytes;  // byte-aligned: the bytes as they are
  else
    for (const char c : other.m_bytes) put(static_cast<unsigned char>(c), 8);
  put(other.m_acc, other.m_fill);
}

std::string BitWriter::finish() {
  std::string out = m_bytes;
  if (m_fill > 0) out.push_back(static_cast<char>(m_acc & 0xff));
  return out;
}

std::uint64_t BitReader::get(int bits) {
  if (bits == 0) return 0;
  if (m_bit + static_cast<std::size_t>(bits) > m_size * 8)
    throw std::runtime_error("low-bit stream ends early");
  std::uint64_t v = 0;
  for (int done = 0; done < bits;) {
    const std::size_t byte = m_bit / 8;
    const int offset = static_cast<int>(m_bit % 8);
    const int take = std::min(8 - offset, bits - done);
    const std::uint64_t part =
        (static_cast<unsigned char>(m_data[byte]) >> offset) & ((1u << take) - 1);
    v |= part << done;
    done += take;
    m_bit += static_cast<std::size_t>(take);
  }
  return v;
}

void BitReader::expectEnd() const {
  if ((m_bit + 7) / 8 != m_size) throw std::runtime_error("low-bit stream longer than its values");
}

void appendPredictiveIntegers(std::string& raw, BitWriter& bits,
                              const std::vector<std::uint64_t>& s) {
  const std::size_t n = s.size();
  int bestPredictor = 1, bestK = 0;
  double bestCost = INFINITY;
  std::vector<std::uint64_t> z(n), bestZ, sorted;
  for (int p = 1; p <= kPredictors && n > 0; ++p) {
    for (std::size_t i = 0; i < n; ++i) z[i] = zigzag(s[i] - predict(s.data(), i, p));
    sorted = z;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(n / 2),
                     sorted.end());
    const int k0 = std::max(0, static_cast<int>(std::bit_width(sorted[n / 2])) - 3);
    for (int k = std::max(0, k0 - 1); k <= std::min(63, k0 + 1); ++k) {
      const double c = costBits(z, k);
      if (c < bestCost) {
        bestCost = c;
        bestPredictor = p;
        bestK = k;
        bestZ = z;
      }
    }
  }
  raw.push_back(static_cast<char>(bestPredictor));
  raw.push_back(static_cast<char>(bestK));
  std::vector<std::uint64_t> escaped;
  const std::uint64_t mask = bestK == 0 ? 0 : (~0ull >> (64 - bestK));
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t h = bestZ[i] >> bestK;
    if (h >= kEscape) {
      raw.push_back(static_cast<char>(kEscape));
      escaped.push_back(bestZ[i]);
    } else {
      raw.push_back(static_cast<char>(h));
      bits.put(bestZ[i] & mask, bestK);
    }
  }
  appendEscaped(raw, escaped);
}

std::vector<std::uint64_t> readPredictiveIntegers(const std::string& raw, std::size_t& pos,
                                                  BitReader& bits, std::size_t count) {
  if (raw.size() - pos < 2 + count) throw std::runtime_error("chunk content ends early");
  const int predictor = static_cast<unsigned char>(raw[pos]);
  const int k = static_cast<unsigned char>(raw[pos + 1]);
  if (predictor < 1 || predictor > kPredictors)
    throw std::runtime_error("unknown predictor " + std::to_string(predictor));
  if (k > 63) throw std::runtime_error("low-bit count " + std::to_string(k) + " out of range");
  const char* high = raw.data() + pos + 2;
  pos += 2 + count;
  const EscapedWords escaped = readEscaped(raw, pos, high, count);

  std::vector<std::uint64_t> s(count);
  std::size_t e = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const unsigned h = static_cast<unsigned char>(high[i]);
    const std::uint64_t z =
        h == kEscape ? escaped.word(e++) : (static_cast<std::uint64_t>(h) << k) | bits.get(k);
    s[i] = predict(s.data(), i, predictor) + unzigzag(z);
  }
  return s;
}

void appendPredictiveColumn(std::string& raw, BitWriter& bits, const std::vector<double>& values) {
  std::vector<std::uint64_t> s(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) s[i] = ordered(values[i]) ^ kTop;
  appendPredictiveIntegers(raw, bits, s);
}

std::vector<double> readPredictiveColumn(const std::string& raw, std::size_t& pos, BitReader& bits,
                                         std::size_t count) {
  const std::vector<std::uint64_t> s = readPredictiveIntegers(raw, pos, bits, count);
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = unordered(s[i] ^ kTop);
  return values;
}

void appendEscaped(std::string& raw, const std::vector<std::uint64_t>& words) {
  for (const std::uint64_t e : words)
    for (int b = 0; b < 8; ++b) raw.push_back(static_cast<char>((e >> (8 * b)) & 0xff));
}

EscapedWords readEscaped(const std::string& raw, std::size_t& pos, const char* marks,
                         std::size_t count) {
  std::size_t escapes = 0;
  for (std::size_t i = 0; i < count; ++i)
    escapes += static_cast<unsigned char>(marks[i]) == kEscape ? 1 : 0;
  if ((raw.size() - pos) / 8 < escapes) throw std::runtime_error("chunk content ends early");
  EscapedWords words{raw.data() + pos, escapes};
  pos += escapes * 8;
  return words;
}

std::uint64_t EscapedWords::word(std::size_t i) const {
  std::uint64_t z = 0;
  for (int b = 0; b < 8; ++b)
    z |= static_cast<std::uint64_t>(static_cast<unsigned char>(data[8 * i + b])) << (8 * b);
  return z;
}

std::uint64_t orderedBits(double v) {
  return ordered(v);
}
double fromOrderedBits(std::uint64_t u) {
  return unordered(u);
}
std::uint64_t zigzagWord(std::uint64_t r) {
  return zigzag(r);
}
std::uint64_t unzigzagWord(std::uint64_t z) {
  return unzigzag(z);
}

}  // namespace armtrack::storage::detail
