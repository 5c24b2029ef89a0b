// A recording without the trunk's columns is written byte for byte as before issue 26: the golden
// files in tests/data/recording were written by writeRecording at main's head before the trunk
// columns existed (tests/data/recording/README.md), and are compared with today's writer.
#include <cstdlib>

#include "tests/core/io/RecordingTestSupport.h"

namespace armtrack::recording_test {
namespace {

const fs::path kGoldenDir = fs::path(ARMTRACK_SOURCE_DIR) / "tests/data/recording";

/// mixedRecording() with estimated angles on some rows and a left arm: every group the format had
/// before the trunk, and every sidecar key.
Recording goldenRecording() {
  Recording rec = mixedRecording();
  rec.meta.side = Side::Left;
  for (std::size_t i = 0; i < rec.samples.size(); i += 7) {
    JointVector th;
    th << 0.1 * static_cast<double>(i), -0.25, 1.0 / 3.0, 1e-300, -7.5;
    rec.samples[i].estimate = th;
  }
  return rec;
}

using RecordingGolden = RecordingTest;

TEST_F(RecordingGolden, WithoutTrunkWrittenAsBeforeByteForByte) {
  const fs::path csv = m_dir / "golden.csv";
  writeRecording(csv, goldenRecording());
  if (std::getenv("ARMTRACK_WRITE_GOLDEN")) {  // how the files were made (README.md)
    fs::copy_file(csv, kGoldenDir / "no_trunk_v1.csv", fs::copy_options::overwrite_existing);
    fs::copy_file(sidecarPath(csv), kGoldenDir / "no_trunk_v1.json",
                  fs::copy_options::overwrite_existing);
  }
  const std::string golden = readText(kGoldenDir / "no_trunk_v1.csv");
  ASSERT_GT(golden.size(), 1000u);
  EXPECT_EQ(readText(csv), golden);
  EXPECT_EQ(readText(sidecarPath(csv)), readText(kGoldenDir / "no_trunk_v1.json"));
}

TEST_F(RecordingGolden, GoldenFileReadsAndWritesBackIdentically) {
  const Recording rec = readRecording(kGoldenDir / "no_trunk_v1.csv");
  for (const ArmSample& s : rec.samples) {
    EXPECT_FALSE(s.trunk || s.shoulder || s.trueTrunk);
  }
  EXPECT_FALSE(rec.meta.trunk.has_value());
  expectSameSamples(rec.samples, goldenRecording().samples);
  const fs::path again = m_dir / "again.csv";
  writeRecording(again, rec);
  EXPECT_EQ(readText(again), readText(kGoldenDir / "no_trunk_v1.csv"));
  EXPECT_EQ(readText(sidecarPath(again)), readText(kGoldenDir / "no_trunk_v1.json"));
  // Row by row as a live session writes.
  const fs::path live = m_dir / "live.csv";
  RecordingReader reader(kGoldenDir / "no_trunk_v1.csv");
  {
    RecordingWriter w(live, reader.meta(), reader.columns());
    ArmSample s;
    while (reader.next(s)) w.append(s);
    w.close();
  }
  EXPECT_EQ(readText(live), readText(kGoldenDir / "no_trunk_v1.csv"));
}

}  // namespace
}  // namespace armtrack::recording_test
