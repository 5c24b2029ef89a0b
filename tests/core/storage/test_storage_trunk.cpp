// The sternum IMU, the optical shoulder and the true trunk angles in the clinical records
// (issue 26): chunks keep them bit for bit, sessions recorded or imported with them give them
// back, and chunks written before them decode exactly as before (golden chunks of main's codec in
// tests/data/recording).
#include <QSqlQuery>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "core/io/Recording.h"
#include "core/storage/ChunkCodec.h"
#include "core/storage/DatabaseRecordingSink.h"
#include "tests/core/storage/StorageTestSupport.h"

namespace armtrack::storage::test {
namespace {

namespace fs = std::filesystem;

const fs::path kDataDir = fs::path(ARMTRACK_SOURCE_DIR) / "tests/data/recording";

std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The golden recording's samples (every group the format had before the trunk).
std::vector<ArmSample> oldSamples() {
  return readRecording(kDataDir / "no_trunk_v1.csv").samples;
}

// Chunks of each codec written by main's ChunkCodec before the trunk's groups existed: today's
// decoder gives back the same samples, and today's encoder writes the same bytes for them.
TEST(TrunkChunks, ChunksWrittenBeforeTheTrunkDecodeAndEncodeAsBefore) {
  const std::vector<ArmSample> samples = oldSamples();
  ASSERT_EQ(samples.size(), 200u);
  for (const char* codec : {ChunkCodec::kName, ChunkCodec::kAtc2Name, ChunkCodec::kLegacyName}) {
    const fs::path golden = kDataDir / ("chunk_" + std::string(codec) + "_no_trunk.bin");
    const std::string now = codec == std::string(ChunkCodec::kName)
                                ? ChunkCodec::encode(samples)
                                : ChunkCodec::encodeLegacy(samples, codec);
    if (std::getenv("ARMTRACK_WRITE_GOLDEN")) {
      std::ofstream(golden, std::ios::binary) << now;
    }
    const std::string old = readBytes(golden);
    ASSERT_GT(old.size(), 1000u) << codec;
    EXPECT_EQ(now, old) << codec;
    const std::vector<ArmSample> back = ChunkCodec::decode(old, samples.size(), codec);
    ASSERT_EQ(back.size(), samples.size());
    for (std::size_t i = 0; i < back.size(); ++i) {
      EXPECT_TRUE(sameBits(back[i].t, samples[i].t)) << i;
      EXPECT_EQ(back[i].upperArm.has_value(), samples[i].upperArm.has_value()) << i;
      EXPECT_EQ(back[i].estimate.has_value(), samples[i].estimate.has_value()) << i;
      EXPECT_FALSE(back[i].trunk || back[i].shoulder || back[i].trueTrunk) << i;
    }
  }
}

/// A simulated session (two IMUs at 200 Hz, Kinect, true angles) with a sternum IMU on every IMU
/// row, an optical shoulder on every Kinect row and true trunk angles with the true arm angles;
/// awkward values (subnormals, -0) among them. Written to csv and read back.
Recording trunkSession(const fs::path& csv) {
  Recording rec = simulateTo(csv, 2.5, 200.0);
  std::size_t k = 0;
  for (ArmSample& s : rec.samples) {
    const double x = 0.37 * static_cast<double>(k++);
    if (s.upperArm) {
      s.trunk = ImuReading{Eigen::Vector3d(0.01 * std::sin(x), -0.0, 5e-324),
                           Eigen::Vector3d(9.81 + 0.1 * std::cos(x), 0.2 * std::sin(x), -0.3)};
    }
    if (s.elbow) s.shoulder = Eigen::Vector3d(0.001 * std::sin(x), 0.02 * x, -1e-300);
    if (s.trueAngles) s.trueTrunk = Eigen::Vector3d(0.2 * std::sin(x), 0.1, -0.05 * x);
  }
  TrunkMount m;
  m.imuPosition = Eigen::Vector3d(0.1, 0.07, -0.19);
  m.imuRotation = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  rec.meta.trunk = m;
  writeRecording(csv, rec);
  return readRecording(csv);
}

void expectSameTrunk(const std::vector<ArmSample>& a, const std::vector<ArmSample>& b) {
  ASSERT_EQ(a.size(), b.size());
  std::size_t trunk = 0, shoulder = 0, trueTrunk = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(sameBits(a[i].t, b[i].t)) << i;
    ASSERT_EQ(a[i].trunk.has_value(), b[i].trunk.has_value()) << i;
    ASSERT_EQ(a[i].shoulder.has_value(), b[i].shoulder.has_value()) << i;
    ASSERT_EQ(a[i].trueTrunk.has_value(), b[i].trueTrunk.has_value()) << i;
    ASSERT_EQ(a[i].upperArm.has_value(), b[i].upperArm.has_value()) << i;
    ASSERT_EQ(a[i].elbow.has_value(), b[i].elbow.has_value()) << i;
    for (int j = 0; j < 3; ++j) {
      if (a[i].trunk) {
        ASSERT_TRUE(sameBits(a[i].trunk->gyr(j), b[i].trunk->gyr(j))) << i;
        ASSERT_TRUE(sameBits(a[i].trunk->acc(j), b[i].trunk->acc(j))) << i;
      }
      const auto same = [&](const auto& x, const auto& y) {
        if (x) {
          ASSERT_TRUE(sameBits((*x)(j), (*y)(j))) << i;
        }
      };
      same(a[i].shoulder, b[i].shoulder);
      same(a[i].trueTrunk, b[i].trueTrunk);
      same(a[i].elbow, b[i].elbow);
      if (a[i].upperArm) {
        ASSERT_TRUE(sameBits(a[i].upperArm->acc(j), b[i].upperArm->acc(j))) << i;
      }
    }
    trunk += a[i].trunk.has_value();
    shoulder += a[i].shoulder.has_value();
    trueTrunk += a[i].trueTrunk.has_value();
  }
  EXPECT_GT(trunk, 100u);
  EXPECT_GT(shoulder, 10u);
  EXPECT_GT(trueTrunk, 10u);
}

// Every codec keeps the trunk's groups bit for bit, alone or with the arm's, in chunks that have
// them on some rows only.
TEST(TrunkChunks, EveryCodecKeepsTheTrunkBitForBit) {
  QTemporaryDir dir;
  const Recording rec = trunkSession(dir.filePath("t.csv").toStdString());
  for (const char* codec : {ChunkCodec::kName, ChunkCodec::kAtc2Name, ChunkCodec::kLegacyName}) {
    const std::string frame = codec == std::string(ChunkCodec::kName)
                                  ? ChunkCodec::encode(rec.samples)
                                  : ChunkCodec::encodeLegacy(rec.samples, codec);
    expectSameTrunk(ChunkCodec::decode(frame, rec.samples.size(), codec), rec.samples);
  }
  // Only the trunk's groups on a row, and NaN payloads and infinities (the codec is not the
  // place that refuses them).
  std::vector<ArmSample> odd(50);
  for (std::size_t i = 0; i < odd.size(); ++i) {
    odd[i].t = 1e-3 * static_cast<double>(i);
    if (i % 2)
      odd[i].trunk = ImuReading{Eigen::Vector3d::Constant(-std::nan("7")),
                                Eigen::Vector3d(1e308, -1e-308, 0.0)};
    if (i % 3)
      odd[i].trueTrunk = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  }
  for (const char* codec : {ChunkCodec::kName, ChunkCodec::kAtc2Name, ChunkCodec::kLegacyName}) {
    const std::string frame = codec == std::string(ChunkCodec::kName)
                                  ? ChunkCodec::encode(odd)
                                  : ChunkCodec::encodeLegacy(odd, codec);
    const auto back = ChunkCodec::decode(frame, odd.size(), codec);
    ASSERT_EQ(back.size(), odd.size());
    for (std::size_t i = 0; i < odd.size(); ++i) {
      ASSERT_EQ(back[i].trunk.has_value(), odd[i].trunk.has_value());
      ASSERT_EQ(back[i].trueTrunk.has_value(), odd[i].trueTrunk.has_value());
      EXPECT_FALSE(back[i].shoulder || back[i].upperArm);
      if (odd[i].trunk)
        for (int j = 0; j < 3; ++j) {
          EXPECT_TRUE(sameBits(back[i].trunk->gyr(j), odd[i].trunk->gyr(j)));
          EXPECT_TRUE(sameBits(back[i].trunk->acc(j), odd[i].trunk->acc(j)));
        }
      if (odd[i].trueTrunk) {
        EXPECT_TRUE(std::isinf(back[i].trueTrunk->x()));
      }
    }
  }
}

// A damaged trunk chunk is refused, never read as something else.
TEST(TrunkChunks, DamagedTrunkChunksAreRefused) {
  QTemporaryDir dir;
  const Recording rec = trunkSession(dir.filePath("t.csv").toStdString());
  const std::vector<ArmSample> head(rec.samples.begin(), rec.samples.begin() + 300);
  const std::string frame = ChunkCodec::encode(head);
  if (std::getenv("ARMTRACK_WRITE_GOLDEN")) {  // the fuzz_chunk seed with the trunk's groups
    const std::vector<ArmSample> few(rec.samples.begin(), rec.samples.begin() + 24);
    const std::string seed = ChunkCodec::encode(few);
    std::ofstream(fs::path(ARMTRACK_SOURCE_DIR) / "tests/fuzz/corpus/fuzz_chunk/atc3-trunk",
                  std::ios::binary)
        << '\x02' << static_cast<char>(few.size()) << '\x00' << seed;
  }
  // Cut short, anywhere.
  for (std::size_t cut : {std::size_t{0}, std::size_t{10}, frame.size() / 2, frame.size() - 1})
    EXPECT_THROW(ChunkCodec::decode(frame.substr(0, cut), head.size()), std::runtime_error) << cut;
  // A changed byte.
  std::string flipped = frame;
  flipped[frame.size() / 3] ^= 0x20;
  EXPECT_THROW(ChunkCodec::decode(flipped, head.size()), std::runtime_error);
  // Garbage, and the wrong row count.
  EXPECT_THROW(ChunkCodec::decode(std::string(400, '\x5a'), head.size()), std::runtime_error);
  EXPECT_THROW(ChunkCodec::decode(frame, head.size() + 1), std::runtime_error);
  // ATC1 (no checksum): cut short or read with another row count, refused.
  const std::string legacy = ChunkCodec::encodeLegacy(head);
  EXPECT_THROW(
      ChunkCodec::decode(legacy.substr(0, legacy.size() - 3), head.size(), ChunkCodec::kLegacyName),
      std::runtime_error);
  EXPECT_THROW(ChunkCodec::decode(legacy, head.size() - 1, ChunkCodec::kLegacyName),
               std::runtime_error);
}

class TrunkSessions : public Engines {};

// A session imported with a trunk IMU, an optical shoulder and true trunk angles keeps them, and
// its mounting; its export is the same recording.
TEST_P(TrunkSessions, ImportedSessionKeepsTheTrunk) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const auto csv = f.file("rec.csv");
  const Recording original = trunkSession(csv);
  const qint64 id = f.store->importRecording(csv, "P1");
  expectSameTrunk(f.store->readRecording(id).samples, original.samples);
  const RecordingMeta meta = f.store->recordingMeta(id);
  ASSERT_TRUE(meta.trunk.has_value());
  EXPECT_EQ(meta.trunk->imuPosition, original.meta.trunk->imuPosition);
  EXPECT_EQ(meta.trunk->imuRotation, original.meta.trunk->imuRotation);
  const auto out = f.file("out.csv");
  f.store->exportRecording(id, out);
  std::ifstream a(csv, std::ios::binary), b(out, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}),
            std::string(std::istreambuf_iterator<char>(b), {}));
}

// A live session recording straight into the records (DatabaseRecordingSink) with the trunk's
// columns keeps them; a sink without them refuses a trunk row and stays usable.
TEST_P(TrunkSessions, LiveSessionKeepsTheTrunk) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const Recording original = trunkSession(f.file("rec.csv"));
  RecordingColumns columns;
  columns.upperArm = columns.forearm = columns.elbow = columns.wrist = columns.truth = true;
  columns.trunk = columns.shoulder = columns.trueTrunk = true;
  const qint64 id = f.store->beginRecording("P1", "", original.meta, columns);
  {
    DatabaseRecordingSink sink(DatabaseUrl::parse(f.path), id, columns, 0.5);
    for (const ArmSample& s : original.samples) sink.append(s);
    sink.close();
  }
  f.store->finishSession(id);
  expectSameTrunk(f.store->readRecording(id).samples, original.samples);
  ASSERT_TRUE(f.store->recordingMeta(id).trunk.has_value());
  // Exported, the trunk's columns are there (the stored column mask keeps them).
  const auto out = f.file("out.csv");
  f.store->exportRecording(id, out);
  RecordingReader reader(out);
  EXPECT_TRUE(reader.columns().trunk);
  EXPECT_TRUE(reader.columns().shoulder);
  EXPECT_TRUE(reader.columns().trueTrunk);

  RecordingColumns armOnly;
  armOnly.upperArm = true;
  const qint64 other = f.store->beginRecording("P1", "", RecordingMeta{}, armOnly);
  DatabaseRecordingSink sink(DatabaseUrl::parse(f.path), other, armOnly);
  ArmSample s;
  s.upperArm = ImuReading{};
  s.trunk = ImuReading{};
  try {
    sink.append(s);
    ADD_FAILURE() << "a trunk row was taken without trunk columns";
  } catch (const RecordingError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write the trunk (sternum) gyroscope"),
              std::string::npos)
        << e.what();
  }
  s.trunk.reset();
  sink.append(s);
  sink.close();
  EXPECT_EQ(f.store->readRecording(other).samples.size(), 1u);
}

// A recording without the trunk goes through the records unchanged: its chunk is main's bytes
// (the golden chunk) and its export is the golden file byte for byte.
TEST_P(TrunkSessions, SessionWithoutTrunkIsStoredAndExportedAsBefore) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const auto csv = f.file("old.csv");
  fs::copy_file(kDataDir / "no_trunk_v1.csv", csv);
  fs::copy_file(kDataDir / "no_trunk_v1.json", f.file("old.json"));
  const qint64 id = f.store->importRecording(csv, "P1");
  QSqlQuery q = f.db->exec(
      "SELECT codec, data FROM recording_chunks WHERE session_id = ? ORDER BY seq", {id});
  ASSERT_TRUE(q.next());
  EXPECT_EQ(q.value(0).toString(), QString(ChunkCodec::kName));
  const QByteArray data = q.value(1).toByteArray();
  EXPECT_EQ(std::string(data.constData(), static_cast<std::size_t>(data.size())),
            readBytes(kDataDir / "chunk_atc3-zstd_no_trunk.bin"));
  EXPECT_FALSE(q.next());
  q.finish();
  const auto out = f.file("out.csv");
  f.store->exportRecording(id, out);
  EXPECT_EQ(readBytes(out), readBytes(kDataDir / "no_trunk_v1.csv"));
  EXPECT_FALSE(f.store->recordingMeta(id).trunk.has_value());
}

INSTANTIATE_TEST_SUITE_P(Engines, TrunkSessions, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);

}  // namespace
}  // namespace armtrack::storage::test
