// Lossless, compact storage of recorded samples: a run of ArmSamples <-> one zstd frame.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/ArmSample.h"

namespace armtrack::storage {

/// Encodes and decodes one recording chunk (docs/storage.md, "Recording chunks"). Every double is
/// kept bit for bit: the decoded samples equal the encoded ones exactly. The layout before
/// compression is columnar (time, then each sensor value across the rows that have it); a column
/// of short decimals is kept as decimal exponents and significand steps, any other as 64-bit
/// patterns XORed with the previous one; all as byte planes, which is what lets zstd find the
/// repeated bytes. Stateless; any thread.
class ChunkCodec {
 public:
  /// zstd level: 3 compresses as well as 12 on these data (the noise in the low mantissa bits is
  /// what remains) and imports 60 s at 1 kHz in ~0.2 s.
  static constexpr int kDefaultLevel = 3;

  /// The compressed frame for samples (times must not decrease; not checked here).
  static std::string encode(std::span<const ArmSample> samples, int level = kDefaultLevel);

  /// The samples of a frame made by encode. Throws std::runtime_error naming what is wrong (not a
  /// zstd frame, truncated, wrong size, bad header, row count other than expectedRows); the caller
  /// adds which session and chunk.
  static std::vector<ArmSample> decode(const std::string& frame, std::uint64_t expectedRows);
};

}  // namespace armtrack::storage
