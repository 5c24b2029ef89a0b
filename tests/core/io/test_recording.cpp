// Tests for reading the recording format (docs/recording-format.md): round trips, tolerant
// parsing, the sidecar, and every documented error with its line and column. Writing is tested in
// test_recording_writer.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/io/Recording.h"
#include "tests/core/io/RecordingTestSupport.h"

namespace armtrack {
namespace {

using namespace armtrack::recording_test;

// ---------------------------------------------------------------------------------------------

TEST(RecordingErrorTest, WhatHasFileLineColumnAndMessage) {
  const RecordingError e("dir/rec.csv", 12, 3, "bad number \"x\" in column \"ua_gz\"");
  EXPECT_STREQ(e.what(), "dir/rec.csv:12:3: bad number \"x\" in column \"ua_gz\"");
  EXPECT_EQ(e.file(), "dir/rec.csv");
  EXPECT_EQ(e.line(), 12);
  EXPECT_EQ(e.column(), 3);
  EXPECT_EQ(e.message(), "bad number \"x\" in column \"ua_gz\"");
}

TEST(SidecarPathTest, ReplacesTheExtension) {
  EXPECT_EQ(sidecarPath("a/b/session.csv"), fs::path("a/b/session.json"));
  EXPECT_EQ(sidecarPath("session"), fs::path("session.json"));
  EXPECT_EQ(sidecarPath("x.y.csv"), fs::path("x.y.json"));
}

// ---------------------------------------------------------------------------------------------
// Round trips

TEST_F(RecordingTest, RoundTripIsBitExact) {
  const Recording rec = mixedRecording();
  const fs::path p = m_dir / "session.csv";
  writeRecording(p, rec);
  ASSERT_TRUE(fs::exists(m_dir / "session.json"));
  const Recording back = readRecording(p);
  EXPECT_TRUE(back.warnings.empty());
  expectSameMeta(rec.meta, back.meta);
  expectSameSamples(rec.samples, back.samples);
  // Only the final files remain: no temporary files left behind.
  EXPECT_EQ(dirEntries(), (std::set<std::string>{"session.csv", "session.json"}));
}

TEST_F(RecordingTest, RoundTripWithoutCameraAndWithDefaults) {
  Recording rec;
  rec.samples.resize(3);
  rec.samples[0].t = 0.0;
  rec.samples[1].t = 0.0;  // equal times are allowed
  rec.samples[2].t = 1.5;
  rec.samples[1].elbow = Eigen::Vector3d(0.1, 0.2, 0.3);
  const fs::path p = m_dir / "r.csv";
  writeRecording(p, rec);
  const Recording back = readRecording(p);
  expectSameMeta(rec.meta, back.meta);
  expectSameSamples(rec.samples, back.samples);
}

TEST_F(RecordingTest, WrittenTextHasCommentHeaderInFixedOrderAndEmptyCells) {
  Recording rec;
  ArmSample a;
  a.t = 0;
  a.forearm = ImuReading{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6.5)};
  ArmSample b;
  b.t = 0.5;
  JointVector th;
  th << 0.1, 0.2, 0.3, 0.4, -0.5;
  b.trueAngles = th;
  b.camElbow = Eigen::Vector2d(320, 240.25);
  rec.samples = {a, b};
  const fs::path p = m_dir / "r.csv";
  writeRecording(p, rec);
  EXPECT_EQ(readText(p),
            "# ArmTrack recording, format version 1\n"
            "t,fa_gx,fa_gy,fa_gz,fa_ax,fa_ay,fa_az,cam_elbow_u,cam_elbow_v,"
            "true_th0,true_th1,true_th2,true_th4,true_th5\n"
            "0,1,2,3,4,5,6.5,,,,,,,\n"
            "0.5,,,,,,,320,240.25,0.1,0.2,0.3,0.4,-0.5\n");
  const std::string json = readText(m_dir / "r.json");
  EXPECT_NE(json.find("\"format\": \"armtrack-recording\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"version\": 1"), std::string::npos) << json;
  EXPECT_NE(json.find("\n  \"geometry\": {"), std::string::npos) << "pretty-printed: " << json;
}

TEST_F(RecordingTest, EmptyRecordingHasOnlyTimeColumn) {
  const fs::path p = m_dir / "r.csv";
  writeRecording(p, Recording{});
  EXPECT_EQ(readText(p), "# ArmTrack recording, format version 1\nt\n");
  EXPECT_TRUE(readRecording(p).samples.empty());
}

TEST_F(RecordingTest, OverwritesAnExistingRecording) {
  const fs::path p = m_dir / "r.csv";
  writeRecording(p, mixedRecording());
  Recording second;
  second.samples.resize(1);
  second.samples[0].t = 7.0;
  writeRecording(p, second);
  const Recording back = readRecording(p);
  expectSameSamples(second.samples, back.samples);
  EXPECT_FALSE(back.meta.camera.has_value());
  EXPECT_EQ(dirEntries(), (std::set<std::string>{"r.csv", "r.json"}));
}

// ---------------------------------------------------------------------------------------------
// Tolerant reading

TEST_F(RecordingTest, ColumnsInAnyOrderAndUnknownColumnsIgnored) {
  const fs::path p = writeCsv(
      "note,wrist_z,ua_az,ua_gx,t,wrist_x,ua_ay,ua_gz,wrist_y,ua_gy,ua_ax,extra\n"
      "hello,0.3,9.81,0.5,0.25,0.1,0.02,-1.5,0.2,2,0.01,\n"
      "any text,,,,0.5,,,,,,,42\n");
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 2u);
  const ArmSample& s = rec.samples[0];
  EXPECT_EQ(s.t, 0.25);
  ASSERT_TRUE(s.upperArm.has_value());
  EXPECT_EQ(s.upperArm->gyr, Eigen::Vector3d(0.5, 2, -1.5));
  EXPECT_EQ(s.upperArm->acc, Eigen::Vector3d(0.01, 0.02, 9.81));
  ASSERT_TRUE(s.wrist.has_value());
  EXPECT_EQ(*s.wrist, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_FALSE(s.forearm || s.elbow || s.camWrist || s.camElbow || s.trueAngles);
  const ArmSample& s2 = rec.samples[1];
  EXPECT_EQ(s2.t, 0.5);
  EXPECT_FALSE(s2.upperArm || s2.forearm || s2.elbow || s2.wrist || s2.camWrist || s2.camElbow ||
               s2.trueAngles);
}

TEST_F(RecordingTest, CommentsBlankLinesCrlfAndBomAccepted) {
  const fs::path p = writeCsv(
      "\xEF\xBB\xBF# exported by hand\r\n"
      "\r\n"
      "#another comment\r\n"
      "t,elbow_x,elbow_y,elbow_z,true_th0,true_th1,true_th2,true_th4,true_th5\r\n"
      "0,1,2,3,,,,,\r\n"
      "# a comment between rows\r\n"
      "   \r\n"
      "\r\n"
      "0.01,,,,0.1,0.2,0.3,0.4,0.5\r\n"
      "0.02,4,5,6,,,,,");  // last line without newline
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 3u);
  EXPECT_EQ(rec.samples[0].t, 0.0);
  ASSERT_TRUE(rec.samples[0].elbow.has_value());
  EXPECT_EQ(*rec.samples[0].elbow, Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(rec.samples[0].trueAngles.has_value());
  ASSERT_TRUE(rec.samples[1].trueAngles.has_value());
  JointVector th;
  th << 0.1, 0.2, 0.3, 0.4, 0.5;
  EXPECT_EQ(*rec.samples[1].trueAngles, th);
  EXPECT_FALSE(rec.samples[1].elbow.has_value());
  EXPECT_EQ(rec.samples[2].t, 0.02);
  EXPECT_EQ(*rec.samples[2].elbow, Eigen::Vector3d(4, 5, 6));
}

TEST_F(RecordingTest, SensorsAtDifferentRates) {
  const fs::path p = writeCsv(
      "t,ua_gx,ua_gy,ua_gz,ua_ax,ua_ay,ua_az,fa_gx,fa_gy,fa_gz,fa_ax,fa_ay,fa_az,"
      "cam_wrist_u,cam_wrist_v,cam_elbow_u,cam_elbow_v\n"
      "0.000,1,1,1,0,0,9.8,2,2,2,0,0,9.8,100,200,,\n"
      "0.001,1,1,1,0,0,9.8,,,,,,,,,300,400\n"
      "0.002,,,,,,,2,2,2,0,0,9.8,,,,\n");
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 3u);
  EXPECT_TRUE(rec.samples[0].upperArm && rec.samples[0].forearm);
  EXPECT_EQ(*rec.samples[0].camWrist, Eigen::Vector2d(100, 200));
  EXPECT_FALSE(rec.samples[0].camElbow);
  EXPECT_TRUE(rec.samples[1].upperArm && !rec.samples[1].forearm);
  EXPECT_EQ(*rec.samples[1].camElbow, Eigen::Vector2d(300, 400));
  EXPECT_FALSE(rec.samples[1].camWrist);
  EXPECT_TRUE(!rec.samples[2].upperArm && rec.samples[2].forearm);
  EXPECT_EQ(rec.samples[2].forearm->gyr, Eigen::Vector3d(2, 2, 2));
  EXPECT_EQ(rec.samples[2].forearm->acc, Eigen::Vector3d(0, 0, 9.8));
}

TEST_F(RecordingTest, SpacesAroundCellsAndLeadingPlusAccepted) {
  const fs::path p = writeCsv(" t , elbow_x,elbow_y ,elbow_z\n 1.5 ,+2, 3e-1 ,\t-4\n2,  , ,\n");
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 2u);
  EXPECT_EQ(rec.samples[0].t, 1.5);
  EXPECT_EQ(*rec.samples[0].elbow, Eigen::Vector3d(2, 0.3, -4));
  EXPECT_FALSE(rec.samples[1].elbow.has_value());
}

// ---------------------------------------------------------------------------------------------
// CSV errors: message, line and column

TEST_F(RecordingTest, BadNumber) {
  const fs::path p = writeCsv("# comment\n" + kImuHeader + "0,1,2,3,4,5,6\n0.1,1.2.3,2,3,4,5,6\n");
  const RecordingError e = readError(p);
  expectError(e, p, 4, 2, "bad number \"1.2.3\" in column \"ua_gx\"");
  EXPECT_EQ(std::string(e.what()), p.string() + ":4:2: " + e.message());

  for (const std::string bad : {"abc", "1e", "0x10", "1;5", "--1", "+-1", "\"1\"", "1 2"}) {
    const fs::path q = writeCsv(kImuHeader + "0,1,2,3,4,5," + bad + "\n");
    expectError(readError(q), q, 2, 7, "bad number \"" + bad + "\" in column \"ua_az\"");
  }
}

TEST_F(RecordingTest, NumberOutOfRange) {
  const fs::path p = writeCsv(kImuHeader + "0,1,2,1e999,4,5,6\n");
  expectError(readError(p), p, 2, 4, "out of range \"1e999\" in column \"ua_gz\"");
}

TEST_F(RecordingTest, NanAndInfinityInAnySpellingAreErrors) {
  for (const std::string v :
       {"nan", "NaN", "-nan", "NAN", "nan(0x1)", "inf", "-Inf", "INF", "infinity", "-Infinity"}) {
    const fs::path p =
        writeCsv("t,fa_gx,fa_gy,fa_gz,fa_ax,fa_ay,fa_az\n0,0,0,0,0,0,9.8\n1,0,0,0,0,0," + v + "\n");
    expectError(readError(p), p, 3, 7, "not a finite number \"" + v + "\" in column \"fa_az\"");
  }
  const fs::path p = writeCsv("t,elbow_x,elbow_y,elbow_z\nnan,1,2,3\n");
  expectError(readError(p), p, 2, 1, "not a finite number \"nan\" in column \"t\"");
}

TEST_F(RecordingTest, MissingHeaderInEmptyFile) {
  const fs::path p = writeCsv("");
  expectError(readError(p), p, 0, 0, "missing header");
}

TEST_F(RecordingTest, MissingHeaderInCommentOnlyFile) {
  const fs::path p = writeCsv("\xEF\xBB\xBF# just a comment\r\n\r\n  \n# another\n");
  expectError(readError(p), p, 0, 0, "missing header");
}

TEST_F(RecordingTest, TimeGoingBackwards) {
  const fs::path p = writeCsv(
      "elbow_x,elbow_y,t,elbow_z\n"
      "1,2,0.5,3\n"
      "# comment\n"
      "1,2,0.6,3\n"
      "1,2,0.6,3\n"
      "\n"
      "1,2,0.5,3\n");
  expectError(readError(p), p, 7, 3, "time goes backwards: 0.5 after 0.6");
}

TEST_F(RecordingTest, EmptyTimeCell) {
  const fs::path p = writeCsv("t,elbow_x,elbow_y,elbow_z\n0,1,2,3\n,1,2,3\n");
  expectError(readError(p), p, 3, 1, "\"t\"");
}

TEST_F(RecordingTest, WrongFieldCount) {
  const fs::path few = writeCsv(kImuHeader + "0,1,2,3,4,5,6\n0.1,1,2,3,4\n");
  expectError(readError(few), few, 3, 6, "row has 5 fields, header has 7");
  const fs::path many = writeCsv(kImuHeader + "0,1,2,3,4,5,6,7\n");
  expectError(readError(many), many, 2, 8, "row has 8 fields, header has 7");
}

TEST_F(RecordingTest, PartiallyFilledGroup) {
  const fs::path p = writeCsv(kImuHeader + "0,1,,3,4,5,6\n");
  expectError(readError(p), p, 2, 3, "\"ua_gy\"");
  const fs::path q = writeCsv("t,cam_wrist_v,cam_wrist_u\n0,,5\n");
  expectError(readError(q), q, 2, 2, "\"cam_wrist_v\"");
}

TEST_F(RecordingTest, ImuNeedsBothGyroAndAccel) {
  const fs::path p = writeCsv(kImuHeader + "0,1,2,3,,,\n");
  expectError(readError(p), p, 2, 5, "no upper-arm accelerometer values");
  const fs::path q = writeCsv(kImuHeader + "0,,,,4,5,6\n");
  expectError(readError(q), q, 2, 2, "no upper-arm gyroscope values");
  // Gyroscope columns without accelerometer columns in the header: rows with gyro data fail.
  const fs::path r = writeCsv("t,fa_gx,fa_gy,fa_gz\n0,,,\n1,1,2,3\n");
  expectError(readError(r), r, 3, 2, "no forearm accelerometer values");
}

TEST_F(RecordingTest, GroupPartlyInHeader) {
  const fs::path p = writeCsv("# c\nt,elbow_x,elbow_y\n0,1,2\n");
  expectError(readError(p), p, 2, 2, "\"elbow_z\"");
}

TEST_F(RecordingTest, MissingTimeColumn) {
  const fs::path p = writeCsv("# c\n\nelbow_x,elbow_y,elbow_z\n1,2,3\n");
  expectError(readError(p), p, 3, 0, "no \"t\" column in header");
}

TEST_F(RecordingTest, DuplicateColumn) {
  const fs::path p = writeCsv("t,elbow_x,elbow_y,elbow_z,t\n0,1,2,3,0\n");
  expectError(readError(p), p, 1, 5, "duplicate column \"t\"");
}

TEST_F(RecordingTest, UnopenableFile) {
  const fs::path p = m_dir / "does_not_exist.csv";
  expectError(readError(p), p, 0, 0,
              "cannot open file: " + std::generic_category().message(ENOENT));
  const fs::path d = m_dir / "a_directory.csv";
  fs::create_directory(d);
  expectError(readError(d), d, 0, 0, "cannot open file");
}

// ---------------------------------------------------------------------------------------------
// Sidecar

TEST_F(RecordingTest, MissingSidecarGivesWarningAndDefaults) {
  const fs::path p = writeText("rec.csv", "t\n0\n");
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_NE(rec.warnings[0].find((m_dir / "rec.json").string()), std::string::npos)
      << rec.warnings[0];
  EXPECT_EQ(rec.meta.geometry.l3, 0.22);
  EXPECT_EQ(rec.meta.geometry.lf8, 0.01);
  EXPECT_EQ(rec.meta.up, Eigen::Vector3d(-1, 0, 0));
  EXPECT_EQ(rec.meta.g, 9.81);
  EXPECT_FALSE(rec.meta.camera.has_value());
  EXPECT_EQ(rec.samples.size(), 1u);
}

TEST_F(RecordingTest, CorruptSidecarJsonIsAnError) {
  writeText("rec.csv", "t\n0\n");
  const std::string text = "{\"format\": \"armtrack-recording\",\n  \"version\": 1,,\n}\n";
  const fs::path j = writeText("rec.json", text);
  const std::size_t byte = text.find(",,") + 2;  // 1-based position of the second comma
  const RecordingError e = readError(m_dir / "rec.csv");
  expectError(e, j, 2, 16, "bad JSON at byte " + std::to_string(byte));
}

TEST_F(RecordingTest, TruncatedSidecarJsonIsAnError) {
  const fs::path j = writeText("rec.json", "{\"format\": \"armtrack-re");
  expectError(errorOf([&] { readSidecar(j); }), j, 1, 24, "bad JSON at byte");
}

TEST_F(RecordingTest, WrongVersionOrFormatIsAnError) {
  const fs::path j = m_dir / "m.json";
  auto sidecarError = [&](const std::string& text) {
    writeText("m.json", text);
    return errorOf([&] { readSidecar(j); });
  };
  expectError(sidecarError(R"({"format": "armtrack-recording", "version": 2})"), j, 0, 0,
              "\"version\" 2");
  expectError(sidecarError(R"({"format": "armtrack-recording", "version": "1"})"), j, 0, 0,
              "\"version\"");
  expectError(sidecarError(R"({"format": "armtrack-recording"})"), j, 0, 0, "\"version\"");
  expectError(sidecarError(R"({"format": "something-else", "version": 1})"), j, 0, 0, "\"format\"");
  expectError(sidecarError(R"({"version": 1})"), j, 0, 0, "\"format\"");
  expectError(sidecarError(R"([1, 2])"), j, 0, 0, "object");
}

TEST_F(RecordingTest, SidecarFieldsAndDefaults) {
  const fs::path j = writeText("m.json", R"({
    "format": "armtrack-recording", "version": 1, "side": "left", "comment": "unknown key",
    "geometry": {"l3": 0.3, "thf7": 1.0},
    "up": [0, 0, 1.25], "g": 9.8,
    "camera": {"fx": 600, "fy": 601, "cx": 320, "cy": 240,
               "R": [0, -1, 0, 0, 0, -1, 1, 0, 0], "t": [0.1, 0.2, 1.5]}})");
  const RecordingMeta m = readSidecar(j);
  EXPECT_EQ(m.geometry.l3, 0.3);
  EXPECT_EQ(m.geometry.thf7, 1.0);
  EXPECT_EQ(m.geometry.l6, 0.20);  // missing keys keep the defaults
  EXPECT_EQ(m.geometry.lu3, 0.11);
  EXPECT_EQ(m.geometry.thu4, std::numbers::pi / 2);
  EXPECT_EQ(m.geometry.lu5, 0.02);
  EXPECT_EQ(m.geometry.lf6, 0.20);
  EXPECT_EQ(m.geometry.lf8, 0.01);
  EXPECT_EQ(m.up, Eigen::Vector3d(0, 0, 1));  // normalised
  EXPECT_EQ(m.g, 9.8);
  EXPECT_EQ(m.gUp(), Eigen::Vector3d(0, 0, 9.8));
  ASSERT_TRUE(m.camera.has_value());
  EXPECT_EQ(m.camera->fx, 600);
  EXPECT_EQ(m.camera->cy, 240);
  EXPECT_EQ(m.camera->dist, (std::array<double, 5>{0, 0, 0, 0, 0}));
  // Row-major R: the shoulder's z axis maps to camera -y, x to camera z.
  EXPECT_EQ(m.camera->R(0, 1), -1);
  EXPECT_EQ(m.camera->R(1, 2), -1);
  EXPECT_EQ(m.camera->R(2, 0), 1);
  const Eigen::Vector3d pCam = m.camera->R * Eigen::Vector3d(1, 0, 0) + m.camera->t;
  EXPECT_EQ(pCam, Eigen::Vector3d(0.1, 0.2, 2.5));

  writeText("m.json", R"({"format": "armtrack-recording", "version": 1, "side": "right"})");
  EXPECT_NO_THROW(readSidecar(j));
}

TEST_F(RecordingTest, UpMustBeAUnitVectorOfThreeNumbers) {
  const fs::path j = m_dir / "m.json";
  auto withUp = [&](const std::string& up) {
    writeText("m.json", R"({"format": "armtrack-recording", "version": 1, "up": )" + up + "}");
  };
  withUp("[0.6, 0, -0.9]");
  const RecordingMeta m = readSidecar(j);
  EXPECT_NEAR(m.up.norm(), 1.0, 1e-15);
  EXPECT_NEAR(m.up.x() / m.up.z(), 0.6 / -0.9, 1e-15);
  for (const std::string bad : {"[0, 0, 3]", "[0, 0, 0.4]", "[0, 0, 0]"}) {
    withUp(bad);
    expectError(errorOf([&] { readSidecar(j); }), j, 0, 0, "unit vector");
  }
  for (const std::string bad :
       {"[1, 0]", "[1, 0, 0, 0]", "[1, \"0\", 0]", "\"up\"", "[1, 0, null]"}) {
    withUp(bad);
    expectError(errorOf([&] { readSidecar(j); }), j, 0, 0, "\"up");
  }
}

TEST_F(RecordingTest, BadSidecarValues) {
  const fs::path j = m_dir / "m.json";
  auto sidecarError = [&](const std::string& rest) {
    writeText("m.json", R"({"format": "armtrack-recording", "version": 1, )" + rest + "}");
    return errorOf([&] { readSidecar(j); });
  };
  expectError(sidecarError(R"("geometry": {"l3": "long"})"), j, 0, 0, "\"geometry.l3\"");
  expectError(sidecarError(R"("g": -9.81)"), j, 0, 0, "\"g\"");
  expectError(sidecarError(R"("camera": {"fx": 1, "fy": 1, "cx": 1})"), j, 0, 0, "camera.cy");
  expectError(sidecarError(R"("camera": {"fx": 1, "fy": 1, "cx": 1, "cy": 1, "R": [1, 0, 0]})"), j,
              0, 0, "\"camera.R\"");
}

// ---------------------------------------------------------------------------------------------
// Write failures

}  // namespace
}  // namespace armtrack
