// The lattice column mode of ATC3 chunks (docs/storage.md, "Recording chunks"): a real sensor's
// values are integer counts times a step its plugin applies (a Shimmer3's (count - offset) /
// sensitivity in rad/s), so per column and chunk the step q is found, each value is stored as its
// count n = round(v / q), predicted like any other column, plus the distance in doubles between v
// and n * q (0 or a few units: the plugin's own operations round differently from n * q). Every
// value decodes bit for bit; one that is not on the lattice (NaN, a spike) is stored whole.
// Internal to ChunkCodec.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/storage/ChunkPredictive.h"

namespace armtrack::storage::detail {

/// The largest count a lattice column stores: beyond it the "lattice" is finer than a sensor's
/// and the values are better stored by the predictive mode.
inline constexpr double kMaxLatticeCount = 1099511627776.0;  // 2^40

/// The step the values lie on: the smallest difference between distinct finite values, refined
/// on ever larger values that lie on it (so q is known to about a double's precision), then the
/// neighbouring doubles of q that put the most values exactly on n * q. Nothing when the column
/// has fewer than two distinct finite values or most values are not on any step found.
std::optional<double> findLatticeStep(const std::vector<double>& values);

/// Appends the column on step q (finite, positive, normal): q's 8 bytes, the counts through the
/// predictive integer coder, then one byte per value of zig-zag distance (255: 8 bytes follow
/// after the column). Lossless for every bit pattern whatever q is.
void appendLatticeColumn(std::string& raw, BitWriter& bits, const std::vector<double>& values,
                         double q);

/// Reads count values written by appendLatticeColumn from raw at pos (advanced). Throws
/// std::runtime_error on a step that is not finite, positive and normal, a count beyond
/// kMaxLatticeCount, or content that ends early.
std::vector<double> readLatticeColumn(const std::string& raw, std::size_t& pos, BitReader& bits,
                                      std::size_t count);

}  // namespace armtrack::storage::detail
