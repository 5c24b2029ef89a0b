// Lossless, compact storage of recorded samples: a run of ArmSamples <-> one zstd frame.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/ArmSample.h"

namespace armtrack::storage {

/// Encodes and decodes one recording chunk (docs/storage.md, "Recording chunks"). Every double is
/// kept bit for bit: the decoded samples equal the encoded ones exactly. The layout is columnar
/// (time, then each sensor value across the rows that have it; the trunk's groups only in a chunk
/// that has them, so a chunk without them is the bytes of before); a column of short decimals is
/// kept as decimal exponents and significand steps, a column of counts times a step (a real
/// sensor's converted readings, ATC3) as predicted counts plus each value's distance in doubles
/// from count x step, any other (ATC2 on) as the residuals of a per-column predictor on the
/// doubles' ordered bit patterns, split into a zstd-compressed high byte and raw low bits. ATC2
/// and ATC1 chunks (64-bit patterns XORed with the previous one, as byte planes) are still read.
/// Stateless; any thread.
class ChunkCodec {
 public:
  /// The codec names of the recording_chunks.codec column: kName is written, all three are read.
  static constexpr const char* kName = "atc3-zstd";
  static constexpr const char* kAtc2Name = "atc2-zstd";
  static constexpr const char* kLegacyName = "atc1-zstd";
  /// zstd level of the structured part (the low noise bits are stored raw beside it).
  static constexpr int kDefaultLevel = 3;

  /// Whether decode reads chunks of this codec name.
  static bool knows(std::string_view codec);

  /// The chunk for samples in the current format (kName): times must not decrease (not checked
  /// here).
  static std::string encode(std::span<const ArmSample> samples, int level = kDefaultLevel);
  /// A format written before (kLegacyName or kAtc2Name), kept so tests can make the chunks old
  /// databases hold. Throws std::runtime_error for another codec name.
  static std::string encodeLegacy(std::span<const ArmSample> samples,
                                  std::string_view codec = kLegacyName, int level = kDefaultLevel);

  /// The samples of a chunk of the given codec. Throws std::runtime_error naming what is wrong
  /// (unknown codec, not a zstd frame, truncated, wrong size, bad header, row count other than
  /// expectedRows); the caller adds which session and chunk.
  static std::vector<ArmSample> decode(const std::string& frame, std::uint64_t expectedRows,
                                       std::string_view codec = kName);
  /// Checks a chunk without decoding it where its format allows (reading a session's chunks so
  /// took a fourth to a third of the time decoding them did): ATC2 and ATC3 the header (magic,
  /// frame length) and the checksum of everything after it, which any changed byte fails; ATC1,
  /// which has no checksum, is decoded. Throws std::runtime_error as decode (the row count is
  /// checked only where it decodes).
  static void verify(std::string_view frame, std::uint64_t expectedRows,
                     std::string_view codec = kName);
};

}  // namespace armtrack::storage
