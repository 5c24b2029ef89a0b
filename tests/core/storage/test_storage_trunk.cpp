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

}  // namespace
}  // namespace armtrack::storage::test
