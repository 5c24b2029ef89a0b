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

// The residuals of predictor P for every value: zigzag(s[i] - predict(s, i, P)), with the
// first values (which have fewer before them) through predict() and the rest by the predictor's
// own formula, so the loop has no branch to take per value.
template <int P>
void residuals(const std::uint64_t* s, std::size_t n, std::uint64_t* z) {
  constexpr std::size_t kWarm = P == 6 ? 4 : P;
  const std::size_t warm = std::min(kWarm, n);
  for (std::size_t i = 0; i < warm; ++i) z[i] = zigzag(s[i] - predict(s, i, P));
  for (std::size_t i = warm; i < n; ++i) {
    std::uint64_t p;
    if constexpr (P == 1) {
      p = s[i - 1];
    } else if constexpr (P == 2) {
      p = 2 * s[i - 1] - s[i - 2];
    } else if constexpr (P == 3) {
      p = 3 * s[i - 1] - 3 * s[i - 2] + s[i - 3];
    } else if constexpr (P == 4) {
      p = 4 * s[i - 1] - 6 * s[i - 2] + 4 * s[i - 3] - s[i - 4];
    } else if constexpr (P == 5) {
      p = 5 * s[i - 1] - 10 * s[i - 2] + 10 * s[i - 3] - 5 * s[i - 4] + s[i - 5];
    } else {
      __int128 sum = 0;
      for (int j = 1; j <= 4; ++j) sum += static_cast<std::int64_t>(s[i - j]);
      p = static_cast<std::uint64_t>(static_cast<std::int64_t>(sum / 4));
    }
    z[i] = zigzag(s[i] - p);
  }
}

void residualsOf(int predictor, const std::vector<std::uint64_t>& s,
                 std::vector<std::uint64_t>& z) {
  const std::size_t n = s.size();
  switch (predictor) {
    case 1:
      return residuals<1>(s.data(), n, z.data());
    case 2:
      return residuals<2>(s.data(), n, z.data());
    case 3:
      return residuals<3>(s.data(), n, z.data());
    case 4:
      return residuals<4>(s.data(), n, z.data());
    case 5:
      return residuals<5>(s.data(), n, z.data());
    default:
      return residuals<6>(s.data(), n, z.data());
  }
}

// The bit width of the median residual (the (n/2)-th smallest): bit_width grows with the value,
// so it is the smallest width that more than n/2 residuals do not exceed. No sort needed.
int medianWidth(const std::vector<std::uint64_t>& z) {
  std::array<std::uint32_t, 65> widths{};
  for (const std::uint64_t v : z) ++widths[static_cast<std::size_t>(std::bit_width(v))];
  std::size_t below = 0;
  for (int w = 0; w <= 64; ++w) {
    below += widths[static_cast<std::size_t>(w)];
    if (below > z.size() / 2) return w;
  }
  return 64;
}

// Bits needed by n residuals z split at k, for kCount (at most kCostKs) consecutive k from kFirst:
// Shannon estimate of the high bytes, k raw bits each, 64 per escaped residual. One pass: the
// high byte at k + j is the one at kFirst shifted by j, so one histogram of z >> kFirst over
// 256 << (kCostKs - 1) values (and one count of those beyond) gives all three exactly.
constexpr int kCostKs = 3;
void costBits(const std::vector<std::uint64_t>& z, int kFirst, int kCount,
              std::array<double, kCostKs>& out) {
  constexpr std::size_t kWide = std::size_t{256} << (kCostKs - 1);  // 1024
  // Kept zero between calls: only the bins a call used are cleared again.
  thread_local std::array<std::uint32_t, kWide> wide{};
  std::size_t beyond = 0, top = 0;
  for (const std::uint64_t v : z) {
    const std::uint64_t h = kFirst >= 64 ? 0 : v >> kFirst;
    if (h < kWide) {
      ++wide[static_cast<std::size_t>(h)];
      top = std::max(top, static_cast<std::size_t>(h));
    } else {
      ++beyond;
    }
  }
  const double n = static_cast<double>(z.size());
  for (int j = 0; j < kCount; ++j) {
    std::array<std::uint32_t, 256> histogram{};
    std::size_t escapes = beyond;
    for (std::size_t b = 0; b <= top; ++b) {
      const std::size_t h = b >> j;
      if (h >= kEscape)
        escapes += wide[b];
      else
        histogram[h] += wide[b];
    }
    histogram[kEscape] = static_cast<std::uint32_t>(escapes);
    double bits = static_cast<double>(z.size() - escapes) * (kFirst + j) +
                  64.0 * static_cast<double>(escapes);
    for (const std::uint32_t c : histogram)
      if (c) bits += c * std::log2(n / c);
    out[static_cast<std::size_t>(j)] = bits;
  }
  std::fill(wide.begin(), wide.begin() + static_cast<std::ptrdiff_t>(std::min(top + 1, kWide)), 0u);
}

}  // namespace

void BitWriter::put(std::uint64_t value, int bits) {
  // m_fill < 8 between calls: up to 56 bits go in at once, then the whole bytes out at once.
  while (bits > 0) {
    const int take = std::min(bits, 56 - m_fill);
    const std::uint64_t part = value & ((1ull << take) - 1);
    m_acc |= part << m_fill;
    m_fill += take;
    value = take == 64 ? 0 : value >> take;
    bits -= take;
    const int whole = m_fill / 8;
    if (whole > 0) {
      char out[8];
      for (int b = 0; b < whole; ++b) out[b] = static_cast<char>((m_acc >> (8 * b)) & 0xff);
      m_bytes.append(out, static_cast<std::size_t>(whole));
      m_acc >>= 8 * whole;
      m_fill -= 8 * whole;
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
  // Each predictor's residuals, and the split k around their median's width, are judged by the
  // estimated size; the best one's residuals are kept (swapped, not copied).
  std::vector<std::uint64_t> z(n), bestZ(n);
  for (int p = 1; p <= kPredictors && n > 0; ++p) {
    residualsOf(p, s, z);
    const int k0 = std::max(0, medianWidth(z) - 3);
    const int kFirst = std::max(0, k0 - 1), kLast = std::min(63, k0 + 1);
    std::array<double, kCostKs> costs{};
    costBits(z, kFirst, kLast - kFirst + 1, costs);
    bool better = false;
    for (int k = kFirst; k <= kLast; ++k) {
      const double c = costs[static_cast<std::size_t>(k - kFirst)];
      if (c < bestCost) {
        bestCost = c;
        bestPredictor = p;
        bestK = k;
        better = true;
      }
    }
    if (better) std::swap(z, bestZ);
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
