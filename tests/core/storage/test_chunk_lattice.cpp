// The lattice column mode of ATC3 chunks: real sensors' converted readings (a count times a step,
// rounded the way each plugin rounds) are stored as counts and come back bit for bit; values off
// any lattice fall back and stay exact; damaged or forged lattice chunks are refused.
#include <gtest/gtest.h>
#include <zstd.h>

#include <QSqlQuery>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>

#include "core/storage/ChunkCodec.h"
#include "core/storage/ChunkLattice.h"
#include "tests/core/storage/StorageTestSupport.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;
namespace lattice = armtrack::storage::detail;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// What devices/shimmer3 computes from a 16-bit gyroscope count at +-500 deg/s (65.5 counts per
// deg/s, offset 0, the default alignment's -1) and a 12-bit low-noise accelerometer count (83 per
// m/s^2 around 2047): (count - offset) / sensitivity, through the alignment, then deg to rad.
double shimmerGyro(double radPerS) {
  const double count = std::clamp(std::round(radPerS / kDeg * 65.5), -32768.0, 32767.0);
  const double v = (count - 0.0) / 65.5;
  return (-1.0 * v + 0.0 * 1.0 + 0.0 * 2.0) * (std::numbers::pi / 180.0);
}
double shimmerAcc(double mPerS2) {
  const double count = std::clamp(std::round(mPerS2 * 83.0 + 2047.0), 0.0, 4095.0);
  return (count - 2047.0) / 83.0;
}
// An NGIMU on a 16.4-counts-per-deg/s gyroscope: the float32 deg/s it sends, times pi/180.
double ngimuGyro(double radPerS) {
  const float degPerS = static_cast<float>(std::round(radPerS / kDeg * 16.4)) / 16.4f;
  return static_cast<double>(degPerS) * (std::numbers::pi / 180.0);
}

// n rows of both IMUs: a slow movement plus Table 5's noise, put through conv.
template <typename Gyro, typename Acc>
std::vector<ArmSample> imuRows(std::size_t n, Gyro gyro, Acc acc, unsigned seed = 3) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gNoise(0.0, std::sqrt(0.1) * kDeg), aNoise(0.0, 0.1);
  std::vector<ArmSample> rows(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 0.001 * static_cast<double>(i);
    rows[i].t = t;
    for (auto* imu : {&rows[i].upperArm, &rows[i].forearm}) {
      ImuReading r;
      for (int k = 0; k < 3; ++k) {
        r.gyr[k] = gyro(1.5 * std::sin(2.0 * t + k) + gNoise(rng));
        r.acc[k] = acc((k == 2 ? 9.81 : 2.0 * std::cos(1.3 * t + k)) + aNoise(rng));
      }
      *imu = r;
    }
  }
  return rows;
}

std::vector<ArmSample> roundTrip(const std::vector<ArmSample>& rows) {
  return ChunkCodec::decode(ChunkCodec::encode(rows), rows.size());
}

bool sameRows(const std::vector<ArmSample>& a, const std::vector<ArmSample>& b) {
  if (a.size() != b.size()) return false;
  auto same = [](const std::optional<ImuReading>& x, const std::optional<ImuReading>& y) {
    if (x.has_value() != y.has_value()) return false;
    for (int k = 0; x && k < 3; ++k)
      if (!sameBits(x->gyr[k], y->gyr[k]) || !sameBits(x->acc[k], y->acc[k])) return false;
    return true;
  };
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!sameBits(a[i].t, b[i].t) || !same(a[i].upperArm, b[i].upperArm) ||
        !same(a[i].forearm, b[i].forearm))
      return false;
  return true;
}

std::size_t atc2Size(const std::vector<ArmSample>& rows) {
  return ChunkCodec::encodeLegacy(rows, ChunkCodec::kAtc2Name).size();
}

std::vector<double> column(const std::vector<ArmSample>& rows, bool gyro, int axis) {
  std::vector<double> v;
  for (const ArmSample& s : rows) v.push_back(gyro ? s.upperArm->gyr[axis] : s.upperArm->acc[axis]);
  return v;
}

}  // namespace

// The step found is the converter's, to a few parts in 10^15, whether the smallest difference in
// the column is one count or several.
TEST(ChunkLattice, FindsTheConvertersStep) {
  const auto rows = imuRows(1000, shimmerGyro, shimmerAcc);
  const auto gyroStep = lattice::findLatticeStep(column(rows, true, 0));
  ASSERT_TRUE(gyroStep.has_value());
  EXPECT_NEAR(*gyroStep / (kDeg / 65.5), 1.0, 1e-13);
  const auto accStep = lattice::findLatticeStep(column(rows, false, 2));
  ASSERT_TRUE(accStep.has_value());
  EXPECT_NEAR(*accStep * 83.0, 1.0, 1e-13);
  // Counts 0, 3, 5, 8, ... never one apart: the step is the gap's fraction that fits them all.
  std::vector<double> sparse;
  for (int i = 0; i < 200; ++i) sparse.push_back((i * 5 / 2) / 83.0);  // gaps of 2 and 3
  const auto sparseStep = lattice::findLatticeStep(sparse);
  ASSERT_TRUE(sparseStep.has_value());
  EXPECT_NEAR(*sparseStep * 83.0, 1.0, 1e-13);
  // Full-precision noise lies on no lattice; neither does a column with one distinct value.
  const auto noisy = imuRows(
      1000, [](double v) { return v; }, [](double v) { return v; });
  EXPECT_FALSE(lattice::findLatticeStep(column(noisy, true, 1)).has_value());
  EXPECT_FALSE(lattice::findLatticeStep(std::vector<double>(50, 0.25)).has_value());
  EXPECT_FALSE(lattice::findLatticeStep({std::nan(""), INFINITY, -INFINITY}).has_value());
}

// A Shimmer3's readings come back bit for bit and take a fraction of what ATC2 needs for them.
TEST(ChunkLattice, Shimmer3ReadingsAreExactAndSmall) {
  const auto rows = imuRows(1000, shimmerGyro, shimmerAcc);
  EXPECT_TRUE(sameRows(roundTrip(rows), rows));
  const std::size_t atc3 = ChunkCodec::encode(rows).size(), atc2 = atc2Size(rows);
  std::printf("[ figures  ] Shimmer3 1000 rows, 2 IMUs: ATC2 %zu bytes, ATC3 %zu bytes\n", atc2,
              atc3);
  // Gyroscope counts need ~6.4 bits, accelerometer ~5.1 at this noise; ATC2 spends ~6 bytes a
  // value on them. 12 values a row and the time: at most 3 bytes a value.
  EXPECT_LT(atc3, atc2 / 2);
  EXPECT_LT(atc3, 1000u * 12u * 3u);
}

// NGIMU's float32 deg/s times pi/180: the float32 rounding puts the values off a uniform lattice
// by up to 2^29 doubles, so the lattice is not smaller and the column falls back; still exact.
TEST(ChunkLattice, NgimuFloat32ReadingsAreExact) {
  const auto rows = imuRows(1000, ngimuGyro, [](double a) {
    return static_cast<double>(static_cast<float>(a / 9.80665)) * 9.80665;
  });
  EXPECT_TRUE(sameRows(roundTrip(rows), rows));
  EXPECT_LE(ChunkCodec::encode(rows).size(), atc2Size(rows) + 64);
}

// Values on no lattice (the simulator's full precision) fall back to the predictive mode: no gain
// on the IMU values, never a loss (only the time column, 0.001 i, may take the lattice).
TEST(ChunkLattice, ValuesOffAnyLatticeFallBack) {
  const auto rows = imuRows(
      1000, [](double v) { return v; }, [](double v) { return v; });
  EXPECT_TRUE(sameRows(roundTrip(rows), rows));
  const std::size_t atc3 = ChunkCodec::encode(rows).size(), atc2 = atc2Size(rows);
  EXPECT_LE(atc3, atc2);
  EXPECT_GT(atc3, atc2 * 95 / 100);
}

// NaN, infinities, -0, subnormals and huge values among a lattice column's values: each stored
// whole, the rest still as counts, every bit back.
TEST(ChunkLattice, AwkwardValuesAmongLatticeValues) {
  auto rows = imuRows(1000, shimmerGyro, shimmerAcc);
  const double awkward[] = {std::numeric_limits<double>::quiet_NaN(),
                            -std::numeric_limits<double>::signaling_NaN(),
                            std::bit_cast<double>(0x7ff8dead0000beefull),
                            INFINITY,
                            -INFINITY,
                            -0.0,
                            0.0,
                            5e-324,
                            -2.2250738585072e-308,
                            1e300,
                            -std::numeric_limits<double>::max(),
                            1e6};
  for (std::size_t j = 0; j < std::size(awkward); ++j) {
    rows[37 * j + 5].upperArm->gyr[0] = awkward[j];
    rows[41 * j + 3].upperArm->acc[2] = awkward[j];
    rows[43 * j + 1].forearm->gyr[j % 3] = awkward[j];
  }
  EXPECT_TRUE(sameRows(roundTrip(rows), rows));
  EXPECT_LT(ChunkCodec::encode(rows).size(), atc2Size(rows) / 2);  // still on the lattice
  // A column of nothing but awkward values, and one of zeros of both signs.
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].upperArm->gyr[1] = awkward[i % std::size(awkward)];
    rows[i].upperArm->gyr[2] = i % 3 ? 0.0 : -0.0;
  }
  EXPECT_TRUE(sameRows(roundTrip(rows), rows));
}

// Degenerate chunks: one row, two rows, one distinct value, counts at the largest a column
// takes and beyond it.
TEST(ChunkLattice, DegenerateColumns) {
  const auto rows = imuRows(300, shimmerGyro, shimmerAcc);
  for (std::size_t n : {std::size_t{1}, std::size_t{2}, std::size_t{3}}) {
    const std::vector<ArmSample> head(rows.begin(), rows.begin() + static_cast<std::ptrdiff_t>(n));
    EXPECT_TRUE(sameRows(roundTrip(head), head)) << n << " rows";
  }
  auto flat = rows;
  for (ArmSample& s : flat) s.upperArm->acc.setConstant(shimmerAcc(9.81));
  EXPECT_TRUE(sameRows(roundTrip(flat), flat));
  // Counts of 2^40 and 2^40 + 1 steps (beyond it a value is stored whole).
  auto far = rows;
  const double q = 1.0 / 83.0;
  far[10].upperArm->acc[0] = lattice::kMaxLatticeCount * q;
  far[11].upperArm->acc[0] = (lattice::kMaxLatticeCount + 1.0) * q;
  far[12].upperArm->acc[0] = -lattice::kMaxLatticeCount * q;
  EXPECT_TRUE(sameRows(roundTrip(far), far));
  EXPECT_TRUE(ChunkCodec::decode(ChunkCodec::encode({}), 0).empty());
}

// Random lattices of every scale (steps from 1e-300 to 1e300, with each plugin-like rounding
// order) round-trip bit for bit.
TEST(ChunkLattice, RandomLatticesRoundTrip) {
  std::mt19937_64 rng(17);
  for (int trial = 0; trial < 60; ++trial) {
    const double step = std::pow(10.0, std::uniform_real_distribution<double>(-300, 300)(rng));
    const double divisor = std::uniform_real_distribution<double>(1.0, 1000.0)(rng);
    std::normal_distribution<double> counts(0.0, std::pow(2.0, trial % 30));
    std::vector<ArmSample> rows(257);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      rows[i].t = static_cast<double>(i);
      ImuReading r;
      for (int k = 0; k < 3; ++k) {
        const double n = std::round(counts(rng));
        r.gyr[k] = n / divisor * step;    // divide, then scale (Shimmer3)
        r.acc[k] = n * (step / divisor);  // one product
      }
      rows[i].upperArm = r;
    }
    ASSERT_TRUE(sameRows(roundTrip(rows), rows)) << "trial " << trial << " step " << step;
  }
}

// The lattice decoder refuses what the encoder cannot have written: a step that is not a
// positive normal number, a count beyond 2^40, content that ends anywhere early.
TEST(ChunkLattice, ForgedLatticeColumnsAreRefused) {
  auto column = [](double q, const std::vector<std::uint64_t>& counts) {
    std::string raw;
    const auto bits = std::bit_cast<std::uint64_t>(q);
    for (int b = 0; b < 8; ++b) raw.push_back(static_cast<char>((bits >> (8 * b)) & 0xff));
    lattice::BitWriter low;
    lattice::appendPredictiveIntegers(raw, low, counts);
    raw += std::string(counts.size(), '\0');
    return std::make_pair(raw, low.finish());
  };
  auto read = [](const std::pair<std::string, std::string>& c, std::size_t n) {
    std::size_t pos = 0;
    lattice::BitReader bits(c.second.data(), c.second.size());
    return lattice::readLatticeColumn(c.first, pos, bits, n);
  };
  const std::vector<std::uint64_t> counts{3, 4, 2, 7};
  EXPECT_EQ(read(column(0.5, counts), 4), (std::vector<double>{1.5, 2.0, 1.0, 3.5}));
  for (const double q :
       {0.0, -0.5, -0.0, 5e-324, std::nan(""), double(INFINITY), -double(INFINITY)}) {
    try {
      read(column(q, counts), 4);
      ADD_FAILURE() << "step " << q << " accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("lattice step"), std::string::npos) << e.what();
    }
  }
  for (const std::uint64_t n : {(1ull << 40) + 1, ~0ull - (1ull << 41), 1ull << 63}) {
    try {
      read(column(0.5, {1, n, 2}), 3);
      ADD_FAILURE() << "count " << n << " accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
    }
  }
  const auto good = column(0.5, counts);
  for (std::size_t cut = 0; cut < good.first.size(); ++cut)
    EXPECT_THROW(read({good.first.substr(0, cut), good.second}, 4), std::runtime_error) << cut;
  EXPECT_THROW(read(good, 5), std::runtime_error);
}

namespace {

// An ATC3 chunk around content, as ChunkCodec::encode wraps it: magic, zstd frame length,
// FNV-1a-64 of the rest (written here independently of the codec), the frame, the low bits.
std::string wrap(const std::string& content, const std::string& low) {
  std::string frame(ZSTD_compressBound(content.size()), '\0');
  frame.resize(ZSTD_compress(frame.data(), frame.size(), content.data(), content.size(), 3));
  const std::string body = frame + low;
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : body) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  std::string out = "ATC3";
  for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((frame.size() >> (8 * b)) & 0xff));
  for (int b = 0; b < 8; ++b) out.push_back(static_cast<char>((h >> (8 * b)) & 0xff));
  return out + body;
}

std::string unwrap(const std::string& chunk, std::string& low) {
  std::uint32_t frameBytes = 0;
  std::memcpy(&frameBytes, chunk.data() + 4, 4);
  const char* frame = chunk.data() + 16;
  std::string content(ZSTD_getFrameContentSize(frame, frameBytes), '\0');
  content.resize(ZSTD_decompress(content.data(), content.size(), frame, frameBytes));
  low = chunk.substr(16 + frameBytes);
  return content;
}

}  // namespace

// In the records: a lattice chunk truncated, with a flipped bit, or re-wrapped with a valid
// checksum around a forged step is refused as Corrupt naming the session and the chunk; the other
// sessions still read. On both engines (PostgreSQL reads the chunks through libpq).
using DamagedLatticeChunk = Engines;
TEST_P(DamagedLatticeChunk, NamesTheSessionAndChunk) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const auto rows = imuRows(3000, shimmerGyro, shimmerAcc);
  auto store = [&] {
    RecordingColumns columns;
    columns.upperArm = columns.forearm = true;
    const qint64 id = f.store->beginRecording("P1", "", RecordingMeta{}, columns);
    for (std::size_t begin = 0; begin < rows.size(); begin += 1000)
      f.store->appendChunk(id, std::span<const ArmSample>(rows.data() + begin, 1000));
    f.store->finishSession(id);
    return id;
  };
  const qint64 intact = store();
  ASSERT_TRUE(sameRows(f.store->readRecording(intact).samples, rows));
  QSqlQuery q = f.db->exec(
      "SELECT codec, data FROM recording_chunks WHERE session_id = ? AND seq = 1", {intact});
  ASSERT_TRUE(q.next());
  EXPECT_EQ(q.value(0).toString(), QString(ChunkCodec::kName));
  const QByteArray blob = q.value(1).toByteArray();
  q.finish();
  const std::string chunk(blob.constData(), static_cast<std::size_t>(blob.size()));

  // The step of the first lattice column, found in the content by its bytes.
  std::string low;
  const std::string content = unwrap(chunk, low);
  const std::vector<ArmSample> second(rows.begin() + 1000, rows.begin() + 2000);
  const double step = *lattice::findLatticeStep(column(second, true, 0));
  std::string stepBytes(8, '\0');
  std::memcpy(stepBytes.data(), &step, 8);
  const std::size_t at = content.find(stepBytes);
  ASSERT_NE(at, std::string::npos);

  std::vector<std::pair<std::string, std::string>> damaged{
      {"truncated", chunk.substr(0, chunk.size() - 7)},
      {"flipped", chunk},
      {"step 0", {}},
      {"step NaN", {}},
      {"step -q", {}},
      {"counts bit stream short", wrap(content, low.substr(0, low.size() / 2))}};
  damaged[1].second[chunk.size() / 2] ^= 0x10;
  for (const auto& [name, value] : {std::pair<const char*, double>{"step 0", 0.0},
                                    {"step NaN", std::nan("")},
                                    {"step -q", -step}}) {
    std::string forged = content;
    std::memcpy(forged.data() + at, &value, 8);
    for (auto& d : damaged)
      if (d.first == name) d.second = wrap(forged, low);
  }
  for (const auto& [name, data] : damaged) {
    const qint64 id = store();
    f.db->exec("UPDATE recording_chunks SET data = ? WHERE session_id = ? AND seq = 1",
               {QByteArray(data.data(), static_cast<qsizetype>(data.size())), id});
    try {
      f.store->readRecording(id);
      ADD_FAILURE() << name << " accepted";
    } catch (const StorageError& e) {
      EXPECT_EQ(e.kind(), Kind::Corrupt) << name;
      EXPECT_NE(std::string(e.what()).find("session " + std::to_string(id) + ", chunk 1"),
                std::string::npos)
          << name << ": " << e.what();
      if (std::string(name).starts_with("step")) {
        EXPECT_NE(std::string(e.what()).find("lattice step"), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_TRUE(sameRows(f.store->readRecording(intact).samples, rows));
}

INSTANTIATE_TEST_SUITE_P(Engines, DamagedLatticeChunk,
                         testing::Values(Engine::Sqlite, Engine::Postgres), engineName);

// ATC2 chunks written before stay readable beside ATC3 ones, and each name reads only its format.
TEST(ChunkLattice, Atc2ChunksStayReadable) {
  const auto rows = imuRows(500, shimmerGyro, shimmerAcc);
  const std::string atc2 = ChunkCodec::encodeLegacy(rows, ChunkCodec::kAtc2Name);
  EXPECT_TRUE(sameRows(ChunkCodec::decode(atc2, rows.size(), ChunkCodec::kAtc2Name), rows));
  EXPECT_THROW(ChunkCodec::decode(atc2, rows.size(), ChunkCodec::kName), std::runtime_error);
  EXPECT_THROW(ChunkCodec::decode(ChunkCodec::encode(rows), rows.size(), ChunkCodec::kAtc2Name),
               std::runtime_error);
  EXPECT_TRUE(ChunkCodec::knows(ChunkCodec::kAtc2Name));
  EXPECT_THROW(ChunkCodec::encodeLegacy(rows, "atc9-zstd"), std::runtime_error);
  // An ATC2 content holding a lattice column (mode 3), which ATC2 never had, is refused.
  std::string low;
  std::string content = unwrap(ChunkCodec::encode(rows), low);
  content.replace(0, 4, "ATC2");
  std::string atc2Forged = wrap(content, low);
  atc2Forged.replace(0, 4, "ATC2");
  EXPECT_THROW(ChunkCodec::decode(atc2Forged, rows.size(), ChunkCodec::kAtc2Name),
               std::runtime_error);
}
