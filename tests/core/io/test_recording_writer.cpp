// Tests for writing the recording format (docs/recording-format.md): the one-shot writer and the
// streaming RecordingWriter, under full disks, killed writers, two writers and bad rows; and the
// streaming reader far into a file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "core/io/Recording.h"
#include "tests/core/io/RecordingTestSupport.h"

#ifdef __linux__
#include <sys/resource.h>
#include <csignal>
#endif

namespace armtrack {
namespace {

using namespace armtrack::recording_test;

TEST_F(RecordingTest, WritingIntoMissingDirectoryThrowsAndLeavesNoFile) {
  const fs::path p = m_dir / "no_such_dir" / "rec.csv";
  const RecordingError e = errorOf([&] { writeRecording(p, mixedRecording()); });
  EXPECT_EQ(e.file(), p.string());
  EXPECT_NE(e.message().find(std::generic_category().message(ENOENT)), std::string::npos)
      << e.message();
  EXPECT_FALSE(fs::exists(p));
  EXPECT_FALSE(fs::exists(m_dir / "no_such_dir"));
  EXPECT_TRUE(dirEntries().empty());
}

TEST_F(RecordingTest, NonFiniteOrDecreasingDataIsNotWritten) {
  const fs::path p = m_dir / "rec.csv";
  Recording rec;
  rec.samples.resize(2);
  rec.samples[1].t = 1.0;
  rec.samples[1].wrist = Eigen::Vector3d(0, std::nan(""), 0);
  expectError(errorOf([&] { writeRecording(p, rec); }), p, 4, 3, "\"wrist_y\"");
  rec.samples[1].wrist.reset();
  rec.samples[1].t = -1.0;
  expectError(errorOf([&] { writeRecording(p, rec); }), p, 4, 1, "decreasing time");
  EXPECT_TRUE(dirEntries().empty());
}

#ifdef __linux__
// A write that fails half-way (here: the file size limit, standing in for a full disk) must throw
// and leave the previous file untouched, with no temporary file behind.
TEST_F(RecordingTest, FailedWriteKeepsTheOldFile) {
  const fs::path p = m_dir / "rec.csv";
  Recording small;
  small.samples.resize(1);
  writeRecording(p, small);
  const std::string before = readText(p);

  Recording big;
  for (int i = 0; i < 20000; ++i) {
    ArmSample s;
    s.t = i * 1e-3;
    s.upperArm = ImuReading{Eigen::Vector3d::Constant(0.123456789), Eigen::Vector3d::Constant(9.8)};
    big.samples.push_back(s);
  }

  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit limited = old;
  limited.rlim_cur = 100 * 1024;
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  const RecordingError e = errorOf([&] { writeRecording(p, big); });
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldHandler);

  EXPECT_EQ(e.file(), p.string());
  EXPECT_NE(e.message().find("write failed"), std::string::npos) << e.message();
  EXPECT_EQ(readText(p), before);
  EXPECT_EQ(dirEntries(), (std::set<std::string>{"rec.csv", "rec.json"}));
}
#endif

// ---------------------------------------------------------------------------------------------
// RecordingWriter (live sessions)

namespace {
ArmSample liveRow(int i) {
  ArmSample s;
  s.t = 0.001 * i + 1e-7 / 3.0;  // not a short decimal: the round trip must be exact
  s.upperArm =
      ImuReading{Eigen::Vector3d(0.1 / 3, -0.2, 0.3 * i), Eigen::Vector3d(9.81, 0.1, -0.2)};
  if (i % 3 == 0) s.wrist = Eigen::Vector3d(0.2, 0.3 / 7, -0.1);
  JointVector th;
  th << 0.1, -0.2 / 3, 0.3, 1.0 / 7, -0.5;
  s.trueAngles = th;
  if (i > 0) s.estimate = th * 1.0001;
  return s;
}
RecordingColumns liveColumns() {
  RecordingColumns c;
  c.upperArm = c.wrist = c.truth = c.estimate = true;
  return c;
}
}  // namespace

TEST_F(RecordingTest, WriterRowsReadBackBitExactWithEstimates) {
  const fs::path p = m_dir / "live.csv";
  RecordingMeta meta;
  meta.g = 9.80665;
  {
    RecordingWriter w(p, meta, liveColumns());
    for (int i = 0; i < 500; ++i) w.append(liveRow(i));
    w.close();
    EXPECT_EQ(w.rows(), 500u);
  }
  const Recording rec = readRecording(p);
  EXPECT_TRUE(rec.warnings.empty());
  EXPECT_EQ(rec.meta.g, 9.80665);
  ASSERT_EQ(rec.samples.size(), 500u);
  for (int i = 0; i < 500; ++i) {
    const ArmSample want = liveRow(i);
    const ArmSample& got = rec.samples[static_cast<std::size_t>(i)];
    EXPECT_EQ(got.t, want.t);
    EXPECT_EQ(got.upperArm->gyr, want.upperArm->gyr);
    EXPECT_EQ(got.wrist.has_value(), want.wrist.has_value());
    EXPECT_EQ(*got.trueAngles, *want.trueAngles);
    ASSERT_EQ(got.estimate.has_value(), i > 0);
    if (i > 0) {
      EXPECT_EQ(*got.estimate, *want.estimate);
    }
    EXPECT_FALSE(got.forearm.has_value());
  }
}

TEST_F(RecordingTest, WriterRefusesBadRowsAndStaysUsable) {
  const fs::path p = m_dir / "live.csv";
  RecordingWriter w(p, RecordingMeta{}, liveColumns());
  w.append(liveRow(1));
  ArmSample extra = liveRow(2);
  extra.forearm = ImuReading{};  // no forearm columns
  EXPECT_NE(errorOf([&] { w.append(extra); }).message().find("forearm"), std::string::npos);
  ArmSample nan = liveRow(2);
  nan.upperArm->acc.x() = std::nan("");
  EXPECT_NE(errorOf([&] { w.append(nan); }).message().find("non-finite"), std::string::npos);
  EXPECT_NE(errorOf([&] { w.append(liveRow(0)); }).message().find("decreasing"), std::string::npos);
  // What the reader would refuse is not written either (issue 24, item 11): a time beyond any
  // clock, or more than 12 h after the first row (a session left running).
  ArmSample absurd = liveRow(2);
  absurd.t = 1e300;
  EXPECT_NE(errorOf([&] { w.append(absurd); }).message().find("beyond any clock"),
            std::string::npos);
  ArmSample late = liveRow(2);
  late.t = liveRow(1).t + RecordingLimits::kMaxRecordingSeconds + 1.0;
  EXPECT_NE(errorOf([&] { w.append(late); }).message().find("more than 12 h after the first row"),
            std::string::npos);
  w.append(liveRow(2));
  w.close();
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 2u);
  EXPECT_EQ(rec.samples[1].t, liveRow(2).t);
}

TEST_F(RecordingTest, InterruptedRecordingReadsUpToTheCutLine) {
  // What a killed session leaves: flushed rows, then part of a row and no final newline.
  const fs::path p = m_dir / "live.csv";
  {
    RecordingWriter w(p, RecordingMeta{}, liveColumns());
    for (int i = 0; i < 10; ++i) w.append(liveRow(i));
    w.close();
  }
  std::string text = readText(p);
  text.resize(text.size() - 20);  // cut into the last row
  writeText(p, text);
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 9u);
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_NE(rec.warnings[0].find("line 12 was cut short"), std::string::npos) << rec.warnings[0];
  // A bad row that is not the cut-short last line is still an error.
  writeText(p, text + "\n");
  EXPECT_THROW(readRecording(p), RecordingError);
}

#ifdef __linux__
TEST_F(RecordingTest, WriterFullDiskKeepsWrittenRowsAndRetries) {
  const fs::path p = m_dir / "live.csv";
  RecordingWriter w(p, RecordingMeta{}, liveColumns());
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit limited = old;
  limited.rlim_cur = 64 * 1024;
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  int i = 0;
  std::string message;
  for (; i < 5000 && message.empty(); ++i) {
    w.append(liveRow(i));
    if (i % 100 == 99) {
      try {
        w.flush();
      } catch (const RecordingError& e) {
        message = e.message();
      }
    }
  }
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldHandler);
  ASSERT_FALSE(message.empty()) << "the size limit never hit";
  EXPECT_NE(message.find("free some disk space"), std::string::npos) << message;
  // Space is back: the next flush completes the file, nothing lost or doubled.
  w.close();
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), static_cast<std::size_t>(i));
  for (int k = 0; k < i; ++k) EXPECT_EQ(rec.samples[static_cast<std::size_t>(k)].t, liveRow(k).t);
}
#endif

// ---------------------------------------------------------------------------------------------
// Hostile sidecars (issue 9, item 7): impossible geometry and camera blocks are refused naming the
// file and the key; every JSON error names the file.

TEST_F(RecordingTest, SidecarRefusesImpossibleGeometryNamingFileAndKey) {
  const fs::path j = m_dir / "m.json";
  auto geometryError = [&](const std::string& geometry) {
    writeText("m.json",
              R"({"format": "armtrack-recording", "version": 1, "geometry": )" + geometry + "}");
    return errorOf([&] { readSidecar(j); });
  };
  // Each of these was accepted before and gave 14-172 deg errors (or no estimates at all).
  const std::pair<std::string, std::string> cases[] = {
      {R"({"l3": 0})", "geometry.l3"},         {R"({"l3": -0.3})", "geometry.l3"},
      {R"({"l3": 1e300})", "geometry.l3"},     {R"({"l3": 0.05})", "geometry.l3"},
      {R"({"l3": 0.61})", "geometry.l3"},      {R"({"l6": 0})", "geometry.l6"},
      {R"({"l6": -0.2})", "geometry.l6"},      {R"({"l6": 2.5})", "geometry.l6"},
      {R"({"lu3": -0.01})", "geometry.lu3"},   {R"({"l3": 0.22, "lu3": 0.33})", "geometry.lu3"},
      {R"({"lf6": -0.05})", "geometry.lf6"},   {R"({"l6": 0.2, "lf6": 0.31})", "geometry.lf6"},
      {R"({"lu5": 0.2})", "geometry.lu5"},     {R"({"lf8": -1e6})", "geometry.lf8"},
      {R"({"thu4": 1e300})", "geometry.thu4"}, {R"({"thf7": -7})", "geometry.thf7"}};
  for (const auto& [geometry, key] : cases) {
    SCOPED_TRACE(geometry);
    expectError(geometryError(geometry), j, 0, 0, "\"" + key + "\"");
  }
  // The limits themselves, and the paper's strap at the shoulder (lu3 = lu5 = 0), are possible.
  for (const std::string ok :
       {R"({"l3": 0.1, "l6": 0.6})", R"({"l3": 0.6, "l6": 0.1, "lu3": 0.7, "lf6": 0.2})",
        R"({"lu3": 0, "lu5": 0, "lf6": 0, "lf8": 0})", R"({"lu5": -0.15, "thu4": -6.28})"}) {
    writeText("m.json",
              R"({"format": "armtrack-recording", "version": 1, "geometry": )" + ok + "}");
    EXPECT_NO_THROW(readSidecar(j)) << ok;
  }
  writeText("m.json", R"({"format": "armtrack-recording", "version": 1, "g": 1e300})");
  expectError(errorOf([&] { readSidecar(j); }), j, 0, 0, "\"g\"");
  writeText("m.json", R"({"format": "armtrack-recording", "version": 1, "g": 1})");
  expectError(errorOf([&] { readSidecar(j); }), j, 0, 0, "\"g\"");
}

TEST_F(RecordingTest, SidecarWithAHugeNumberNamesFileLineAndColumn) {
  const fs::path j = writeText("m.json",
                               "{\"format\": \"armtrack-recording\", \"version\": 1,\n"
                               "  \"geometry\": {\"l3\": 1e999}}\n");
  // Before: nlohmann's out_of_range escaped with "number overflow parsing '1e999'" and no file.
  const RecordingError e = errorOf([&] { readSidecar(j); });
  expectError(e, j, 2, 22, "1e999");
  // Through the CSV reader too.
  writeText("rec.csv", kImuHeader + "0,0,0,0,0,0,9.81\n");
  writeText("rec.json", "{\"format\": \"armtrack-recording\", \"version\": 1, \"g\": -1e999}");
  expectError(readError(m_dir / "rec.csv"), m_dir / "rec.json", 1, 53, "-1e999");
}

TEST_F(RecordingTest, SidecarCameraWithZeroFocalOrBadRotationNamesFileAndKey) {
  const fs::path j = m_dir / "m.json";
  auto cameraError = [&](const std::string& camera) {
    writeText("m.json",
              R"({"format": "armtrack-recording", "version": 1, "camera": )" + camera + "}");
    return errorOf([&] { readSidecar(j); });
  };
  expectError(cameraError(R"({"fx": 0, "fy": 600, "cx": 320, "cy": 240})"), j, 0, 0,
              "\"camera.fx\"");
  expectError(cameraError(R"({"fx": 600, "fy": -600, "cx": 320, "cy": 240})"), j, 0, 0,
              "\"camera.fy\"");
  expectError(cameraError(R"({"fx": 600, "fy": 600, "cx": 1e300, "cy": 240})"), j, 0, 0,
              "\"camera.cx\"");
  // Scaled, sheared and mirrored matrices are not rotations.
  for (const std::string r : {"[2, 0, 0, 0, 2, 0, 0, 0, 2]", "[1, 0, 0, 0, 1, 0, 0, 0, -1]",
                              "[1, 0.1, 0, 0, 1, 0, 0, 0, 1]", "[0, 0, 0, 0, 0, 0, 0, 0, 0]"}) {
    expectError(cameraError(R"({"fx": 600, "fy": 600, "cx": 320, "cy": 240, "R": )" + r + "}"), j,
                0, 0, "\"camera.R\" is not a rotation");
  }
  expectError(cameraError(R"({"fx": 600, "fy": 600, "cx": 320, "cy": 240, "t": [0, 0, 1e9]})"), j,
              0, 0, "\"camera.t\"");
}

TEST_F(RecordingTest, SidecarWithAnInvalidUtf8StringNamesTheFile) {
  const fs::path j = writeText("m.json", "{\"format\": \"\xff\xfe\", \"version\": 1}");
  const RecordingError e = errorOf([&] { readSidecar(j); });
  EXPECT_EQ(e.file(), j.string()) << e.what();
}

TEST_F(RecordingTest, ImpossibleMetaIsNeverWritten) {
  Recording rec = mixedRecording();
  rec.meta.geometry.l3 = 0.0;
  const RecordingError e = errorOf([&] { writeRecording(m_dir / "r.csv", rec); });
  EXPECT_EQ(e.file(), (m_dir / "r.json").string());
  EXPECT_NE(e.message().find("\"geometry.l3\""), std::string::npos) << e.message();
  rec = mixedRecording();
  rec.meta.camera->fx = 0.0;
  EXPECT_THROW(writeRecording(m_dir / "r.csv", rec), RecordingError);
  EXPECT_THROW(RecordingWriter(m_dir / "live.csv", rec.meta, liveColumns()), RecordingError);
  EXPECT_TRUE(dirEntries().empty());
}

// ---------------------------------------------------------------------------------------------
// Item 12: a byte outside printable ASCII in a cell is shown escaped (a NUL would cut the message
// short; NUL and the other control bytes are now refused as binary content before any cell is
// parsed, test_recording_door.cpp, so bytes above 0x7f stand in for them here).

TEST_F(RecordingTest, NonPrintableBytesInACellAreShownEscaped) {
  const fs::path p = writeCsv(kImuHeader + "0,0,0,0,0,0,9.81\n" + std::string("0.1,1\xffx\x80", 8) +
                              ",0,0,0,0,9.81\n");
  const RecordingError e = readError(p);
  expectError(e, p, 3, 2, "bad number \"1\\xffx\\x80\" in column \"ua_gx\"");
  const std::string what = e.what();
  EXPECT_EQ(what.find('\0'), std::string::npos);
  EXPECT_EQ(std::strlen(e.what()), what.size());  // what a C string consumer sees is all of it
  // A long cell is shown in part.
  const fs::path q = writeCsv(kImuHeader + "0," + std::string(5000, '7') + "z,0,0,0,0,9.81\n");
  const RecordingError l = readError(q);
  EXPECT_LT(l.message().size(), 200u) << l.message();
  EXPECT_NE(l.message().find("5001 bytes, first 40 shown"), std::string::npos) << l.message();
}

// ---------------------------------------------------------------------------------------------
// Item 8: one writer per file, nothing created for an unusable path.

TEST_F(RecordingTest, SecondWriterOnTheSameFileIsRefusedAndTheFirstRecordingSurvives) {
  const fs::path p = m_dir / "live.csv";
  RecordingMeta meta;
  meta.g = 9.80665;
  RecordingWriter first(p, meta, liveColumns());
  for (int i = 0; i < 100; ++i) first.append(liveRow(i));
  first.flush();
  RecordingMeta other;
  other.geometry.l3 = 0.3;
  RecordingColumns otherColumns;
  otherColumns.forearm = true;
  const RecordingError e = errorOf([&] { RecordingWriter second(p, other, otherColumns); });
  EXPECT_EQ(e.file(), p.string());
  EXPECT_NE(e.message().find("another recording is being written to this file"), std::string::npos)
      << e.message();
  for (int i = 100; i < 200; ++i) first.append(liveRow(i));
  first.close();
  const Recording rec = readRecording(p);
  EXPECT_TRUE(rec.warnings.empty());
  EXPECT_EQ(rec.meta.g, 9.80665);  // the sidecar is the first writer's
  EXPECT_EQ(rec.meta.geometry.l3, ArmGeometry{}.l3);
  ASSERT_EQ(rec.samples.size(), 200u);
  for (int i = 0; i < 200; ++i) EXPECT_EQ(rec.samples[static_cast<std::size_t>(i)].t, liveRow(i).t);
  // Once the first is closed, the file can be written again (the caller decides on replacing).
  RecordingWriter third(p, other, otherColumns);
  third.close();
  EXPECT_EQ(readRecording(p).samples.size(), 0u);
}

TEST_F(RecordingTest, WriterOnADirectoryOrJsonNameCreatesNothing) {
  fs::create_directory(m_dir / "d");
  RecordingError e =
      errorOf([&] { RecordingWriter w(m_dir / "d", RecordingMeta{}, liveColumns()); });
  EXPECT_EQ(e.file(), (m_dir / "d").string());
  EXPECT_NE(e.message().find("directory"), std::string::npos) << e.message();
  fs::create_directory(m_dir / "s.json");
  e = errorOf([&] { RecordingWriter w(m_dir / "s.csv", RecordingMeta{}, liveColumns()); });
  EXPECT_EQ(e.file(), (m_dir / "s.json").string());
  e = errorOf([&] { RecordingWriter w(m_dir / "x.json", RecordingMeta{}, liveColumns()); });
  EXPECT_NE(e.message().find(".json"), std::string::npos) << e.message();
  EXPECT_EQ(dirEntries(), (std::set<std::string>{"d", "s.json"}));  // no d.json, s.csv, x.json
  EXPECT_TRUE(fs::is_empty(m_dir / "d"));
}

#ifdef __linux__
// Item 9: the writer's own account of what reached the file.
TEST_F(RecordingTest, WriterCountsTheRowsThatReachedTheFile) {
  const fs::path p = m_dir / "live.csv";
  RecordingWriter w(p, RecordingMeta{}, liveColumns());
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit limited = old;
  limited.rlim_cur = 32 * 1024;
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  bool failed = false;
  for (int i = 0; i < 3000; ++i) {
    w.append(liveRow(i));
    if (i % 100 == 99) {
      try {
        w.flush();
      } catch (const RecordingError&) {
        failed = true;
      }
    }
  }
  std::uint64_t writtenWhileFull = w.rowsWritten();
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldHandler);
  ASSERT_TRUE(failed) << "the size limit never hit";
  EXPECT_EQ(w.rows(), 3000u);
  // Independent truth: the complete lines in the file, less the comment and the header.
  std::string text = readText(p);
  const auto lines = static_cast<std::uint64_t>(std::count(text.begin(), text.end(), '\n'));
  EXPECT_EQ(writtenWhileFull, lines - 2);
  EXPECT_LT(writtenWhileFull, 3000u);
  w.close();
  EXPECT_EQ(w.rowsWritten(), 3000u);
  EXPECT_EQ(readRecording(p).samples.size(), 3000u);
}
#endif

// ---------------------------------------------------------------------------------------------
// Timing (run by hand: --gtest_also_run_disabled_tests --gtest_filter=*Timing*)

TEST_F(RecordingTest, DISABLED_Timing600kRows) {
  Recording rec;
  std::mt19937_64 rng(1);
  std::normal_distribution<double> n(0.0, 1.0);
  rec.samples.reserve(600000);
  for (int i = 0; i < 600000; ++i) {
    ArmSample s;
    s.t = i * 1e-3;
    s.upperArm = ImuReading{Eigen::Vector3d(n(rng), n(rng), n(rng)),
                            Eigen::Vector3d(n(rng), n(rng), 9.81 + n(rng))};
    s.forearm = ImuReading{Eigen::Vector3d(n(rng), n(rng), n(rng)),
                           Eigen::Vector3d(n(rng), n(rng), 9.81 + n(rng))};
    rec.samples.push_back(s);
  }
  const fs::path p = m_dir / "big.csv";
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  writeRecording(p, rec);
  const auto t1 = Clock::now();
  const Recording back = readRecording(p);
  const auto t2 = Clock::now();
  const double ws = std::chrono::duration<double>(t1 - t0).count();
  const double rs = std::chrono::duration<double>(t2 - t1).count();
  std::cout << "600k rows, " << fs::file_size(p) / 1e6 << " MB: write " << ws << " s, read " << rs
            << " s\n";
  ASSERT_EQ(back.samples.size(), rec.samples.size());
  EXPECT_EQ(bits(back.samples.back().forearm->acc.z()), bits(rec.samples.back().forearm->acc.z()));
  EXPECT_LT(rs, 3.0);
}

// ---------------------------------------------------------------------------------------------
// RecordingReader (row by row, for replays of long recordings)

TEST_F(RecordingTest, ReaderStreamsRowsAcrossChunkBoundariesBitExact) {
  // 40,000 rows (about 9 MB, several of the reader's 1 MiB chunks): rows cross chunk edges.
  const fs::path p = m_dir / "long.csv";
  constexpr int kRows = 40000;
  std::vector<ArmSample> written;
  written.reserve(kRows);
  {
    RecordingWriter w(p, RecordingMeta{}, liveColumns());
    for (int i = 0; i < kRows; ++i) {
      written.push_back(liveRow(i));
      w.append(written.back());
    }
    w.close();
  }
  const auto size = fs::file_size(p);
  ASSERT_GT(size, 4u << 20);

  RecordingReader reader(p);
  EXPECT_TRUE(reader.warnings().empty());
  const RecordingColumns& c = reader.columns();
  EXPECT_TRUE(c.upperArm && c.wrist && c.truth && c.estimate);
  EXPECT_FALSE(c.forearm || c.elbow || c.camWrist || c.camElbow);
  EXPECT_EQ(reader.fileSize(), size);
  std::vector<ArmSample> read;
  ArmSample s;
  std::uint64_t lastBytes = reader.bytesRead();
  while (reader.next(s)) {
    read.push_back(s);
    EXPECT_GE(reader.bytesRead(), lastBytes);
    lastBytes = reader.bytesRead();
  }
  EXPECT_FALSE(reader.next(s));  // stays at the end
  EXPECT_EQ(reader.rows(), static_cast<std::uint64_t>(kRows));
  EXPECT_EQ(reader.bytesRead(), size);
  expectSameSamples(read, written);
  for (std::size_t i = 0; i < read.size(); i += 997)
    EXPECT_EQ(read[i].estimate.has_value(), written[i].estimate.has_value()) << i;
}

TEST_F(RecordingTest, ReaderReportsTheRightLineFarIntoAFileAndCutShortLastLine) {
  const fs::path p = m_dir / "long.csv";
  {
    RecordingWriter w(p, RecordingMeta{}, liveColumns());
    for (int i = 0; i < 20000; ++i) w.append(liveRow(i));
    w.close();
  }
  std::string text = readText(p);
  // Lines: 1 comment, 2 header, 3.. rows. Break row 15000 (line 15002) with a letter.
  std::size_t at = 0;
  for (int line = 1; line < 15002; ++line) at = text.find('\n', at) + 1;
  std::string broken = text;
  broken.insert(at, "x");
  writeText(p, broken);
  {
    RecordingReader reader(p);
    ArmSample s;
    int rows = 0;
    try {
      while (reader.next(s)) ++rows;
      ADD_FAILURE() << "no error";
    } catch (const RecordingError& e) {
      EXPECT_EQ(e.line(), 15002) << e.what();
      EXPECT_EQ(e.column(), 1) << e.what();
    }
    EXPECT_EQ(rows, 14999);
  }
  // Killed mid-row: the rows before the cut line are read, then a warning, no error.
  writeText(p, text.substr(0, text.size() - 25));
  RecordingReader reader(p);
  ArmSample s;
  int rows = 0;
  while (reader.next(s)) ++rows;
  EXPECT_EQ(rows, 19999);
  ASSERT_EQ(reader.warnings().size(), 1u);
  EXPECT_NE(reader.warnings()[0].find("line 20002 was cut short"), std::string::npos)
      << reader.warnings()[0];
}

}  // namespace
}  // namespace armtrack
