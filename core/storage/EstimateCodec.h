// A session's estimated joint angles as one compact blob (docs/storage.md, "Estimates"):
// codec "est-f64-zstd-v1".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/estimation/RecordingEstimator.h"
#include "core/kinematics/ArmModel.h"

namespace armtrack::storage {

/// The estimator's output rows as columns (the columns of kEstimateHeader, or of
/// kEstimateTrunkHeader when trunk and trunkSd are filled).
struct EstimateColumns {
  std::vector<double> t;        ///< s
  std::vector<JointVector> th;  ///< DH joint angles (rad)
  std::vector<JointVector> sd;  ///< their standard deviations (rad)
  std::vector<int> status;      ///< kStatus* of core/estimation/RecordingEstimator.h (0-4)
  /// The trunk's angles and their standard deviations (rad, flexion, lateral bending, axial
  /// rotation; NaN where not measured), one per row, for a recording with trunk output
  /// (hasTrunkOutput); both empty otherwise.
  std::vector<Eigen::Vector3d> trunk, trunkSd;
  std::size_t size() const { return t.size(); }
  bool hasTrunk() const { return !trunk.empty(); }
  /// Adds one output row of the estimator at the end of every column, with its trunk columns
  /// when withTrunk.
  void append(const EstimateRow& row, bool withTrunk = false) {
    t.push_back(row.t);
    th.push_back(row.th);
    sd.push_back(row.sd);
    status.push_back(row.status);
    if (!withTrunk) return;
    trunk.push_back(row.trunk);
    trunkSd.push_back(row.trunkSd);
  }
  void clear() {
    t.clear();
    th.clear();
    sd.clear();
    status.clear();
    trunk.clear();
    trunkSd.clear();
  }
};

/// Encodes and decodes estimate blobs. Every double is kept bit for bit. Before compression: a
/// 16-byte header (magic "ATE1", column count 12, or 18 with the trunk's columns, row count,
/// little-endian), then the 11 double columns (t, th0..th5, sd_th0..sd_th5), each value's 64-bit
/// pattern XORed with the previous row's and written as 8 byte planes (least significant first),
/// then one status byte per row, then (18 columns only) the 6 trunk columns (trunk_flex,
/// trunk_lat, trunk_rot and their sd) as the others; the whole compressed as one zstd frame with
/// its content checksum. A blob without the trunk is byte for byte what it was before the trunk
/// (schema version 9 marks databases that may hold the longer form). Stateless; any thread.
class EstimateCodec {
 public:
  static constexpr const char* kName = "est-f64-zstd-v1";
  /// A version stored as chunks (table estimate_chunks), each a blob of kName: an analysis
  /// writes its estimates as they come instead of holding them whole.
  static constexpr const char* kChunkedName = "est-f64-zstd-v1-chunks";

  /// The blob of columns (all of one length, the trunk's empty or of that length too; throws
  /// std::invalid_argument otherwise, or for a status outside 0-4).
  static std::string encode(const EstimateColumns& columns, int level = 3);

  /// The columns of a blob made by encode (trunk and trunkSd empty for a 12-column blob). Throws
  /// std::runtime_error saying what is wrong (not a zstd frame, damaged, wrong size, bad header,
  /// a row count other than expectedRows, a status outside 0-4, times that are not finite or
  /// decrease); the caller adds which session and version.
  static EstimateColumns decode(const std::string& blob, std::uint64_t expectedRows);
};

}  // namespace armtrack::storage
