// The predictive column coding of ATC2/ATC3 chunks (docs/storage.md, "Recording chunks"): each
// double mapped to an integer that orders as the double does, predicted from the previous values
// of its column, and the residual split into a high byte (compressed by zstd with the rest of the
// chunk) and k low bits (stored raw: they are noise). The integer coder underneath also stores
// the lattice mode's counts (ChunkLattice.h). Internal to ChunkCodec.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace armtrack::storage::detail {

/// Low bits, packed least significant bit first.
class BitWriter {
 public:
  void put(std::uint64_t value, int bits);
  /// The bytes written so far (the last one padded with zero bits).
  std::string finish();
  /// How many bytes finish() gives.
  std::size_t bytes() const { return m_bytes.size() + (m_fill > 0 ? 1 : 0); }
  /// Appends the bits another writer holds, as if they had been put here.
  void append(const BitWriter& other);

 private:
  std::string m_bytes;
  std::uint64_t m_acc = 0;
  int m_fill = 0;
};

class BitReader {
 public:
  BitReader(const char* data, std::size_t size) : m_data(data), m_size(size) {}
  /// Throws std::runtime_error when the stream ends early.
  std::uint64_t get(int bits);
  /// Throws unless every byte was used (only the last byte's padding may remain).
  void expectEnd() const;

 private:
  const char* m_data;
  std::size_t m_size;
  std::size_t m_bit = 0;
};

/// A high byte of 255 marks a value stored whole (8 bytes after the column's high bytes).
inline constexpr unsigned kEscape = 255;

/// A double's 64 bits as an integer that orders as the double does (a bijection on all 2^64
/// patterns), and back.
std::uint64_t orderedBits(double v);
double fromOrderedBits(std::uint64_t u);
/// Zig-zag of a wrapping 64-bit difference (small magnitudes of either sign -> small codes).
std::uint64_t zigzagWord(std::uint64_t r);
std::uint64_t unzigzagWord(std::uint64_t z);

/// The escaped words of a column, 8 little-endian bytes each.
struct EscapedWords {
  const char* data = nullptr;
  std::size_t count = 0;
  std::uint64_t word(std::size_t i) const;
};
/// Appends words as 8 little-endian bytes each.
void appendEscaped(std::string& raw, const std::vector<std::uint64_t>& words);
/// The words that follow at pos for the marks (one byte per value, kEscape for an escaped one);
/// advances pos past them. Throws when raw is too short for them.
EscapedWords readEscaped(const std::string& raw, std::size_t& pos, const char* marks,
                         std::size_t count);

/// Appends integers (wrapping 64-bit, signed values as two's complement) as the predictive coder
/// stores them: predictor byte, k, high bytes, escaped residuals; the k low bits to bits.
void appendPredictiveIntegers(std::string& raw, BitWriter& bits,
                              const std::vector<std::uint64_t>& s);
/// Reads count integers written by appendPredictiveIntegers. Throws std::runtime_error on content
/// that encode cannot have written.
std::vector<std::uint64_t> readPredictiveIntegers(const std::string& raw, std::size_t& pos,
                                                  BitReader& bits, std::size_t count);

/// Appends the column (predictor byte, k, high bytes, escaped residuals) to raw and its low bits to
/// bits. Lossless for every bit pattern (NaN, -0, subnormals included).
void appendPredictiveColumn(std::string& raw, BitWriter& bits, const std::vector<double>& values);

/// Reads count values written by appendPredictiveColumn from raw at pos (advanced). Throws
/// std::runtime_error on content that encode cannot have written.
std::vector<double> readPredictiveColumn(const std::string& raw, std::size_t& pos, BitReader& bits,
                                         std::size_t count);

}  // namespace armtrack::storage::detail
