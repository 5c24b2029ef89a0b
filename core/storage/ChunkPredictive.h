// The predictive column coding of ATC2 chunks (docs/storage.md, "Recording chunks"): each double
// mapped to an integer that orders as the double does, predicted from the previous values of its
// column, and the residual split into a high byte (compressed by zstd with the rest of the chunk)
// and k low bits (stored raw: they are noise). Internal to ChunkCodec.
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

/// Appends the column (predictor byte, k, high bytes, escaped residuals) to raw and its low bits to
/// bits. Lossless for every bit pattern (NaN, -0, subnormals included).
void appendPredictiveColumn(std::string& raw, BitWriter& bits, const std::vector<double>& values);

/// Reads count values written by appendPredictiveColumn from raw at pos (advanced). Throws
/// std::runtime_error on content that encode cannot have written.
std::vector<double> readPredictiveColumn(const std::string& raw, std::size_t& pos, BitReader& bits,
                                         std::size_t count);

}  // namespace armtrack::storage::detail
