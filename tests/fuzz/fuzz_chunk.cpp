// libFuzzer target: the recording chunk codec (core/storage/ChunkCodec). The first byte says what
// the rest is: a stored chunk to decode (0, 1, 2: codec atc1, atc2, atc3; the row count in the
// next two bytes), which must be refused with std::runtime_error or decode to samples that
// survive an ATC3 round trip; or values to store (3: any doubles; 4: 16-bit counts on a step
// taken from the input, converted as a plugin does), which must come back bit for bit.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/storage/ChunkCodec.h"

using armtrack::ArmSample;
using armtrack::ImuReading;
using armtrack::storage::ChunkCodec;

namespace {

bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool sameImu(const std::optional<ImuReading>& a, const std::optional<ImuReading>& b) {
  if (a.has_value() != b.has_value()) return false;
  for (int k = 0; a && k < 3; ++k)
    if (!same(a->gyr[k], b->gyr[k]) || !same(a->acc[k], b->acc[k])) return false;
  return true;
}

template <typename V>
bool sameOpt(const std::optional<V>& a, const std::optional<V>& b) {
  if (a.has_value() != b.has_value()) return false;
  for (int i = 0; a && i < a->size(); ++i)
    if (!same((*a)[i], (*b)[i])) return false;
  return true;
}

void expectRoundTrip(const std::vector<ArmSample>& rows) {
  const std::vector<ArmSample> back = ChunkCodec::decode(ChunkCodec::encode(rows), rows.size());
  if (back.size() != rows.size()) std::abort();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ArmSample &a = rows[i], &b = back[i];
    if (!same(a.t, b.t) || !sameImu(a.upperArm, b.upperArm) || !sameImu(a.forearm, b.forearm) ||
        !sameOpt(a.elbow, b.elbow) || !sameOpt(a.wrist, b.wrist) ||
        !sameOpt(a.camWrist, b.camWrist) || !sameOpt(a.camElbow, b.camElbow) ||
        !sameOpt(a.trueAngles, b.trueAngles) || !sameOpt(a.estimate, b.estimate) ||
        !sameImu(a.trunk, b.trunk) || !sameOpt(a.shoulder, b.shoulder) ||
        !sameOpt(a.trueTrunk, b.trueTrunk))
      std::abort();
  }
}

// Rows of one IMU from 48-byte records (6 doubles), or from 12-byte records of 16-bit counts
// put on a step: count / divisor * scale, as the Shimmer3 plugin converts.
std::vector<ArmSample> rowsOf(const std::uint8_t* data, std::size_t size, bool counts) {
  std::vector<ArmSample> rows;
  double divisor = 65.5, scale = 0.017453292519943295;
  if (counts && size >= 16) {
    std::memcpy(&divisor, data, 8);
    std::memcpy(&scale, data + 8, 8);
    data += 16;
    size -= 16;
    if (!std::isnormal(divisor) || !std::isnormal(scale)) return rows;
  }
  const std::size_t record = counts ? 12 : 48;
  for (std::size_t off = 0; off + record <= size; off += record) {
    ArmSample s;
    s.t = static_cast<double>(rows.size()) * 1e-3;
    ImuReading r;
    for (int k = 0; k < 6; ++k) {
      double v = 0.0;
      if (counts) {
        std::int16_t c = 0;
        std::memcpy(&c, data + off + 2 * k, 2);
        v = static_cast<double>(c) / divisor * scale;
      } else {
        std::memcpy(&v, data + off + 8 * k, 8);
      }
      (k < 3 ? r.gyr : r.acc)[k % 3] = v;
    }
    // Every third record goes to the trunk IMU (and its gyroscope to the true trunk angles), so
    // chunks with the trunk's groups on some rows are stored too.
    if (rows.size() % 3 == 2) {
      s.trunk = r;
      s.trueTrunk = r.gyr;
    } else {
      s.upperArm = r;
    }
    rows.push_back(s);
  }
  return rows;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  const int what = data[0] % 5;
  if (what >= 3) {
    expectRoundTrip(rowsOf(data + 1, size - 1, what == 4));
    return 0;
  }
  const char* codecs[] = {ChunkCodec::kLegacyName, ChunkCodec::kAtc2Name, ChunkCodec::kName};
  const std::uint64_t rows = data[1] | (data[2] << 8);
  std::vector<ArmSample> decoded;
  try {
    decoded = ChunkCodec::decode(std::string(reinterpret_cast<const char*>(data + 3), size - 3),
                                 rows, codecs[what]);
  } catch (const std::runtime_error&) {
    return 0;  // refused, as a damaged chunk must be
  }
  if (decoded.size() != rows) std::abort();
  expectRoundTrip(decoded);
  return 0;
}
