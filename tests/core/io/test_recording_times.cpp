// Time stamps at the door of the recording reader (issue 24, items 3, 10 and 11): a recording
// spans at most 12 h, an absurd first time is refused, a jump forward is a gap that is counted,
// and a last line cut short is flagged. The recordings are simulated (5 s, two IMUs at 1 kHz and a
// Kinect at 30 Hz, as `armtrack-cli simulate --duration 5` makes them) and then broken.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/estimation/ArmFilter.h"
#include "core/io/Recording.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "tests/core/io/RecordingTestSupport.h"

namespace armtrack {
namespace {

using namespace armtrack::recording_test;

/// The shortest text that reads back as x, as the reader's messages write times.
std::string shortest(double x) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

Recording simulated5s() {
  SimulationParams sim = defaultSimulation();
  sim.duration = 5.0;
  const MultiJointTrajectory trajectory(7);
  return simulateRecording(trajectory, sim);
}

// writeRecording's layout: line 1 a comment, line 2 the header, row i (0-based) on line i + 3.
constexpr int kFirstRowLine = 3;

/// Offset just past line `line` (1-based) of text.
std::size_t endOfLine(const std::string& text, int line) {
  std::size_t at = 0;
  for (int l = 1; l <= line; ++l) at = text.find('\n', at) + 1;
  return at;
}

/// Writes rec to p as writeRecording does, but with the time cell of every row from index
/// `from` on printed as `times` gives it: a file no writer would make (the writers refuse a
/// recording longer than 12 h), as a broken clock or another program leaves it.
void writeWithTimes(const fs::path& p, const Recording& rec, std::size_t from,
                    const std::function<std::string(const ArmSample&)>& times) {
  writeRecording(p, rec);
  std::ifstream in(p, std::ios::binary);
  std::string line, out;
  for (int n = 1; std::getline(in, line); ++n) {
    const int row = n - kFirstRowLine;
    if (row >= 0 && static_cast<std::size_t>(row) >= from)
      line = times(rec.samples[static_cast<std::size_t>(row)]) + line.substr(line.find(','));
    out += line + '\n';
  }
  in.close();
  std::ofstream(p, std::ios::binary | std::ios::trunc) << out;
}

/// Reads every row; the error, or nothing when the file was accepted.
struct ReadOutcome {
  std::uint64_t rows = 0;
  std::uint64_t bytesRead = 0;
  std::optional<RecordingError> error;
};
ReadOutcome readAll(RecordingReader& reader) {
  ReadOutcome out;
  ArmSample s;
  try {
    while (reader.next(s)) ++out.rows;
  } catch (const RecordingError& e) {
    out.error = e;
  }
  out.bytesRead = reader.bytesRead();
  return out;
}

TEST(RecordingLimitsTest, TheGapIsTheStepAfterWhichTheEstimatorRestarts) {
  EXPECT_EQ(RecordingLimits::kGapSeconds, EstimatorParams{}.maxGap);
}

TEST_F(RecordingTest, OneDayJumpIsRefusedAtItsRowHavingReadOnlyUpToThere) {
  Recording rec = simulated5s();
  ASSERT_GT(rec.samples.size(), 5000u);
  // Row 2,500 (index 2499) and every row after it a day later: a clock that jumped.
  const fs::path p = m_dir / "rec.csv";
  writeWithTimes(p, rec, 2499, [](const ArmSample& s) { return shortest(s.t + 86400.0); });
  for (std::size_t i = 2499; i < rec.samples.size(); ++i) rec.samples[i].t += 86400.0;
  const std::string text = readText(p);

  RecordingReader reader(p);
  const ReadOutcome out = readAll(reader);
  ASSERT_TRUE(out.error.has_value()) << "the jump was accepted";
  const int line = 2499 + kFirstRowLine;
  expectError(*out.error, p, line, 1,
              "t jumps from " + shortest(rec.samples[2498].t) + " s to " +
                  shortest(rec.samples[2499].t) + " s");
  EXPECT_NE(out.error->message().find("a recording spans at most 12 h"), std::string::npos)
      << out.error->what();
  EXPECT_NE(out.error->message().find("is the clock right?"), std::string::npos);
  EXPECT_EQ(out.rows, 2499u);
  EXPECT_EQ(out.bytesRead, endOfLine(text, line));  // not a row further
  EXPECT_EQ(reader.gaps().count, 0u);               // a refused jump is not a gap
}

TEST_F(RecordingTest, TimeOf1e300IsRefusedInAnyRow) {
  const Recording rec = simulated5s();
  const fs::path p = m_dir / "rec.csv";
  writeRecording(p, rec);
  const std::string text = readText(p);
  auto withTime = [&](int row, const std::string& t) {  // row's time cell replaced by t
    const std::size_t start = endOfLine(text, row + kFirstRowLine - 1);
    std::string s = text;
    s.replace(start, s.find(',', start) - start, t);
    return writeText("rec.csv", s);
  };
  const int last = static_cast<int>(rec.samples.size()) - 1;
  for (const int row : {2499, last}) {
    const fs::path q = withTime(row, "1e300");
    expectError(readError(q), q, row + kFirstRowLine, 1,
                "t jumps from " + shortest(rec.samples[row - 1].t) + " s to 1e+300 s");
  }
  // In the first row it is no clock's reading.
  const fs::path q = withTime(0, "1e300");
  expectError(readError(q), q, kFirstRowLine, 1, "first time 1e+300 s");
}

TEST_F(RecordingTest, AbsurdFirstTimeIsRefusedAndUnixTimesAreNot) {
  const std::string header = "t,elbow_x,elbow_y,elbow_z\n";
  for (const char* t : {"1e11", "-2e10", "10000000001"}) {
    const fs::path p = writeCsv(header + t + ",0.1,0.2,0.3\n");
    expectError(readError(p), p, 2, 1, "|t| must be at most 1e+10 s");
  }
  // Unix times of today, in seconds with millisecond steps.
  const fs::path p = writeCsv(header + "1718000000.000,0.1,0.2,0.3\n1718000000.001,0.1,0.2,0.3\n" +
                              "-1e10,0.1,0.2,0.3\n");
  expectError(readError(p), p, 4, 1, "time goes backwards");  // -1e10 is allowed only first
  const fs::path q = writeCsv(header + "-1e10,0.1,0.2,0.3\n");
  EXPECT_EQ(readRecording(q).samples.size(), 1u);
}

TEST_F(RecordingTest, SpanOver12hIsRefusedEvenWithoutAJump) {
  // One row every 1,000 s from t = 5 s (each step a gap, accepted): t = 44,005 s is more than
  // 12 h after the first row.
  std::string text = "t,elbow_x,elbow_y,elbow_z\n";
  for (int i = 0; i <= 44; ++i) text += std::to_string(5 + 1000 * i) + ",0.1,0.2,0.3\n";
  const fs::path p = writeCsv(text);
  // Row 44 (t = 44,005) is on line 46.
  expectError(readError(p), p, 46, 1,
              "t jumps from 43005 s to 44005 s, more than 12 h after the first row (5 s)");
  // A row exactly 12 h after the first is accepted; one a step past it, within the gap limit, is
  // refused with the span it exceeds.
  const fs::path q = writeCsv("t\n5\n43205\n43205.05\n");
  expectError(readError(q), q, 4, 1,
              "t reaches 43205.05 s, more than 12 h after the first row (5 s)");
}

TEST_F(RecordingTest, OneHourJumpIsAcceptedAsAGapAndCounted) {
  Recording rec = simulated5s();
  for (std::size_t i = 2499; i < rec.samples.size(); ++i) rec.samples[i].t += 3600.0;
  // And a 0.25 s dropout of every sensor after row 4,000.
  for (std::size_t i = 4000; i < rec.samples.size(); ++i) rec.samples[i].t += 0.25;
  const fs::path p = m_dir / "rec.csv";
  writeRecording(p, rec);

  RecordingReader reader(p);
  const ReadOutcome out = readAll(reader);
  ASSERT_FALSE(out.error.has_value()) << out.error->what();
  EXPECT_EQ(out.rows, rec.samples.size());
  // Independent truth: every step of the written times longer than the limit.
  std::uint64_t count = 0;
  double total = 0.0;
  for (std::size_t i = 1; i < rec.samples.size(); ++i) {
    const double step = rec.samples[i].t - rec.samples[i - 1].t;
    if (step > RecordingLimits::kGapSeconds) {
      ++count;
      total += step;
    }
  }
  ASSERT_EQ(count, 2u);  // the test's own premise: no other step is a gap
  const TimeGaps& g = reader.gaps();
  EXPECT_EQ(g.count, 2u);
  EXPECT_EQ(g.totalSeconds, total);
  EXPECT_EQ(g.longestSeconds, rec.samples[2499].t - rec.samples[2498].t);
  EXPECT_GT(g.longestSeconds, 3600.0);
  EXPECT_LT(g.longestSeconds, 3600.1);
  EXPECT_EQ(g.longestFromT, rec.samples[2498].t);
  EXPECT_EQ(g.longestLine, 2499 + kFirstRowLine);
  EXPECT_FALSE(reader.cutShort());
}

TEST_F(RecordingTest, CutShortLastLineIsFlaggedAndWarned) {
  const Recording rec = simulated5s();
  const fs::path p = m_dir / "rec.csv";
  writeRecording(p, rec);
  {
    RecordingReader whole(p);
    EXPECT_EQ(readAll(whole).rows, rec.samples.size());
    EXPECT_FALSE(whole.cutShort());
  }
  // What a kill leaves: the file ends inside its last row.
  const std::string text = readText(p);
  writeText("rec.csv", text.substr(0, text.size() - 30));
  RecordingReader reader(p);
  const ReadOutcome out = readAll(reader);
  ASSERT_FALSE(out.error.has_value()) << out.error->what();
  EXPECT_EQ(out.rows, rec.samples.size() - 1);
  EXPECT_TRUE(reader.cutShort());
  const int line = static_cast<int>(rec.samples.size()) - 1 + kFirstRowLine;
  ASSERT_EQ(reader.warnings().size(), 1u);
  EXPECT_NE(reader.warnings()[0].find("line " + std::to_string(line) + " was cut short"),
            std::string::npos)
      << reader.warnings()[0];
}

}  // namespace
}  // namespace armtrack
