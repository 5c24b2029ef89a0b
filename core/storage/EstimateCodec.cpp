#include "core/storage/EstimateCodec.h"

#include <zstd.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

namespace armtrack::storage {

namespace {

constexpr std::uint32_t kMagic = 0x31455441;  // "ATE1" little-endian
constexpr std::uint32_t kColumns = 12;        // t, 5 angles, 5 standard deviations, status
constexpr std::size_t kDoubleColumns = 11;
// With the trunk: its 3 angles and 3 standard deviations after the status bytes.
constexpr std::uint32_t kTrunkColumns = 18;
constexpr std::size_t kTrunkDoubles = 6;
constexpr std::size_t kHeaderBytes = 16;
// kStatusFused .. kStatusTrunkMoved (4: the trunk moved with no trunk IMU to measure it).
constexpr int kMaxStatus = kStatusTrunkMoved;

void putU32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}
void putU64(std::string& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}
std::uint64_t getLe(const std::string& in, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i)
    v |= static_cast<std::uint64_t>(static_cast<unsigned char>(in[at + i])) << (8 * i);
  return v;
}

// Column c (0 = t, 1-5 angles, 6-10 standard deviations, 11-13 trunk angles, 14-16 their
// standard deviations) of row r; Columns is EstimateColumns, const or not.
template <class Columns>
auto& slotOf(Columns& e, std::size_t c, std::size_t r) {
  if (c == 0) return e.t[r];
  if (c <= 5) return e.th[r](static_cast<int>(c - 1));
  if (c <= 10) return e.sd[r](static_cast<int>(c - 6));
  if (c <= 13) return e.trunk[r](static_cast<int>(c - 11));
  return e.trunkSd[r](static_cast<int>(c - 14));
}

// The bytes before compression of n rows.
std::uint64_t contentBytes(std::uint64_t n, bool trunk) {
  return kHeaderBytes + n * (8 * kDoubleColumns + 1) + (trunk ? n * 8 * kTrunkDoubles : 0);
}

}  // namespace

namespace {

/// zstd's streaming compressor fed through a small buffer: the blob's bytes (which are as large
/// as the estimates themselves, about 89 per row) are never all in memory, only the compressed
/// frame is (docs/storage.md, "Memory of an analysis").
class FrameWriter {
 public:
  FrameWriter(int level, std::uint64_t contentBytes) : m_cctx(ZSTD_createCCtx(), &ZSTD_freeCCtx) {
    if (!m_cctx) throw std::runtime_error("zstd: out of memory");
    ZSTD_CCtx_setParameter(m_cctx.get(), ZSTD_c_compressionLevel, level);
    // With zstd's content checksum, so a damaged blob is refused rather than decoded to other
    // numbers; the size in the frame header as a one-shot compression would write it.
    ZSTD_CCtx_setParameter(m_cctx.get(), ZSTD_c_checksumFlag, 1);
    ZSTD_CCtx_setPledgedSrcSize(m_cctx.get(), contentBytes);
    m_in.reserve(kBuffer);
  }
  void put(char c) {
    m_in.push_back(c);
    if (m_in.size() == kBuffer) compress(ZSTD_e_continue);
  }
  void put(const std::string& bytes) {
    for (char c : bytes) put(c);
  }
  std::string finish() {
    compress(ZSTD_e_end);
    // The frame grew by doubling: up to twice its size is reserved, and an analysis holds it
    // while the metrics are computed.
    m_frame.shrink_to_fit();
    return std::move(m_frame);
  }

 private:
  static constexpr std::size_t kBuffer = 1 << 17;
  void compress(ZSTD_EndDirective mode) {
    ZSTD_inBuffer in{m_in.data(), m_in.size(), 0};
    std::size_t remaining = 0;
    do {
      const std::size_t at = m_frame.size();
      m_frame.resize(at + ZSTD_CStreamOutSize());
      ZSTD_outBuffer out{m_frame.data() + at, ZSTD_CStreamOutSize(), 0};
      remaining = ZSTD_compressStream2(m_cctx.get(), &out, &in, mode);
      if (ZSTD_isError(remaining))
        throw std::runtime_error(std::string("zstd compression failed: ") +
                                 ZSTD_getErrorName(remaining));
      m_frame.resize(at + out.pos);
    } while (in.pos < in.size || (mode == ZSTD_e_end && remaining != 0));
    m_in.clear();
  }
  std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)> m_cctx;
  std::string m_in;
  std::string m_frame;
};

}  // namespace

std::string EstimateCodec::encode(const EstimateColumns& e, int level) {
  const std::size_t n = e.t.size();
  const bool trunk = e.hasTrunk();
  if (e.th.size() != n || e.sd.size() != n || e.status.size() != n ||
      (trunk && (e.trunk.size() != n || e.trunkSd.size() != n)) || (!trunk && !e.trunkSd.empty()))
    throw std::invalid_argument("estimate columns of different lengths");
  for (int s : e.status)
    if (s < 0 || s > kMaxStatus)
      throw std::invalid_argument("estimate status " + std::to_string(s) + " outside 0-4");
  FrameWriter frame(level, contentBytes(n, trunk));
  std::string header;
  putU32(header, kMagic);
  putU32(header, trunk ? kTrunkColumns : kColumns);
  putU64(header, n);
  frame.put(header);
  std::vector<std::uint64_t> bits(n);
  const auto putColumns = [&](std::size_t from, std::size_t to) {
    for (std::size_t c = from; c < to; ++c) {
      std::uint64_t previous = 0;
      for (std::size_t r = 0; r < n; ++r) {
        const std::uint64_t b = std::bit_cast<std::uint64_t>(slotOf(e, c, r));
        bits[r] = b ^ previous;
        previous = b;
      }
      for (int plane = 0; plane < 8; ++plane)
        for (std::size_t r = 0; r < n; ++r)
          frame.put(static_cast<char>((bits[r] >> (8 * plane)) & 0xff));
    }
  };
  putColumns(0, kDoubleColumns);
  for (int s : e.status) frame.put(static_cast<char>(s));
  if (trunk) putColumns(kDoubleColumns, kDoubleColumns + kTrunkDoubles);
  return frame.finish();
}

EstimateColumns EstimateCodec::decode(const std::string& blob, std::uint64_t expectedRows) {
  const unsigned long long size = ZSTD_getFrameContentSize(blob.data(), blob.size());
  if (size == ZSTD_CONTENTSIZE_ERROR) throw std::runtime_error("not a zstd frame");
  if (size == ZSTD_CONTENTSIZE_UNKNOWN) throw std::runtime_error("zstd frame without its size");
  const std::uint64_t expectedSize = contentBytes(expectedRows, false);
  const std::uint64_t withTrunk = contentBytes(expectedRows, true);
  if (size != expectedSize && size != withTrunk)
    throw std::runtime_error("zstd frame holds " + std::to_string(size) + " bytes, " +
                             std::to_string(expectedRows) + " rows need " +
                             std::to_string(expectedSize) + " (" + std::to_string(withTrunk) +
                             " with the trunk)");
  const bool trunk = size == withTrunk && withTrunk != expectedSize;
  std::string raw(size, '\0');
  const std::size_t got = ZSTD_decompress(raw.data(), raw.size(), blob.data(), blob.size());
  if (ZSTD_isError(got))
    throw std::runtime_error(std::string("damaged zstd frame: ") + ZSTD_getErrorName(got));
  if (got != size) throw std::runtime_error("zstd frame shorter than it claims");
  if (getLe(raw, 0, 4) != kMagic)
    throw std::runtime_error("not an ArmTrack estimate blob (bad magic number)");
  if (getLe(raw, 4, 4) != (trunk ? kTrunkColumns : kColumns))
    throw std::runtime_error("estimate blob with " + std::to_string(getLe(raw, 4, 4)) +
                             " columns, expected " + (trunk ? "18" : "12"));
  const std::uint64_t n = getLe(raw, 8, 8);
  if (n != expectedRows)
    throw std::runtime_error("estimate blob holds " + std::to_string(n) + " rows, expected " +
                             std::to_string(expectedRows));

  EstimateColumns e;
  e.t.resize(n);
  e.th.assign(n, JointVector::Zero());
  e.sd.assign(n, JointVector::Zero());
  e.status.resize(n);
  if (trunk) {
    e.trunk.assign(n, Eigen::Vector3d::Zero());
    e.trunkSd.assign(n, Eigen::Vector3d::Zero());
  }
  const unsigned char* p = reinterpret_cast<const unsigned char*>(raw.data()) + kHeaderBytes;
  const auto getColumns = [&](std::size_t from, std::size_t to) {
    for (std::size_t c = from; c < to; ++c) {
      std::uint64_t previous = 0;
      for (std::size_t r = 0; r < n; ++r) {
        std::uint64_t b = 0;
        for (int plane = 0; plane < 8; ++plane)
          b |= static_cast<std::uint64_t>(p[plane * n + r]) << (8 * plane);
        previous ^= b;
        slotOf(e, c, r) = std::bit_cast<double>(previous);
      }
      p += 8 * n;
    }
  };
  getColumns(0, kDoubleColumns);
  for (std::size_t r = 0; r < n; ++r) {
    if (p[r] > kMaxStatus)
      throw std::runtime_error("row " + std::to_string(r) + ": status " + std::to_string(p[r]) +
                               " outside 0-4");
    e.status[r] = p[r];
  }
  p += n;
  if (trunk) getColumns(kDoubleColumns, kDoubleColumns + kTrunkDoubles);
  for (std::size_t r = 0; r < n; ++r) {
    if (!std::isfinite(e.t[r]) || (r > 0 && e.t[r] < e.t[r - 1]))
      throw std::runtime_error("row " + std::to_string(r) + ": time not finite or decreasing");
  }
  return e;
}

}  // namespace armtrack::storage
