// The trunk's columns of the recording format (issue 26): the sternum IMU (tr_*), the optical
// shoulder (shoulder_*), the true trunk angles (true_trunk_*) and the sidecar's "trunk" block.
#include "tests/core/io/RecordingTestSupport.h"

namespace armtrack::recording_test {
namespace {

using RecordingTrunk = RecordingTest;

constexpr const char* kTrunkSidecar =
    R"({"format": "armtrack-recording", "version": 1,
        "trunk": {"imu_position": [0.1, 0.06, -0.18], "imu_rotation": [1, 0, 0, 0, 1, 0, 0, 0, 1]}})";

/// mixedRecording() with a trunk IMU, an optical shoulder and true trunk angles on some rows,
/// awkward doubles throughout, and a tilted sternum IMU.
Recording trunkRecording() {
  Recording rec = mixedRecording();
  AwkwardDoubles r;
  auto v3 = [&] { return Eigen::Vector3d(r(), r(), r()); };
  for (std::size_t i = 0; i < rec.samples.size(); ++i) {
    ArmSample& s = rec.samples[i];
    if (i % 3 == 0) s.trunk = ImuReading{v3(), v3()};
    if (i % 4 == 1) s.shoulder = v3();
    if (i % 5 == 1) s.trueTrunk = v3();
  }
  TrunkMount m;
  m.imuPosition = Eigen::Vector3d(0.12, 0.07, -0.2);
  m.imuRotation =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, -1.0, 0.5).normalized()).toRotationMatrix();
  rec.meta.trunk = m;
  return rec;
}

void expectSameTrunk(const std::vector<ArmSample>& a, const std::vector<ArmSample>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string row = "sample " + std::to_string(i) + " ";
    ASSERT_EQ(a[i].trunk.has_value(), b[i].trunk.has_value()) << row;
    if (a[i].trunk) {
      expectBitwiseEqual(a[i].trunk->gyr, b[i].trunk->gyr, row + "tr gyr");
      expectBitwiseEqual(a[i].trunk->acc, b[i].trunk->acc, row + "tr acc");
    }
    expectSameOptional(a[i].shoulder, b[i].shoulder, row + "shoulder");
    expectSameOptional(a[i].trueTrunk, b[i].trueTrunk, row + "trueTrunk");
  }
}

TEST_F(RecordingTrunk, WholeRecordingRoundTripsBitForBit) {
  const Recording rec = trunkRecording();
  const fs::path csv = m_dir / "rec.csv";
  writeRecording(csv, rec);
  const Recording back = readRecording(csv);
  EXPECT_TRUE(back.warnings.empty());
  expectSameSamples(back.samples, rec.samples);
  expectSameTrunk(back.samples, rec.samples);
  ASSERT_TRUE(back.meta.trunk.has_value());
  expectBitwiseEqual(back.meta.trunk->imuPosition, rec.meta.trunk->imuPosition, "position");
  expectBitwiseEqual(back.meta.trunk->imuRotation.reshaped(),
                     rec.meta.trunk->imuRotation.reshaped(), "rotation");
  // The header: the fixed order, the trunk's groups beside their kin.
  const std::string text = readText(csv);
  const std::string header =
      text.substr(text.find('\n') + 1, text.find('\n', text.find('\n') + 1) - text.find('\n') - 1);
  EXPECT_EQ(header,
            "t,ua_gx,ua_gy,ua_gz,ua_ax,ua_ay,ua_az,fa_gx,fa_gy,fa_gz,fa_ax,fa_ay,fa_az,"
            "tr_gx,tr_gy,tr_gz,tr_ax,tr_ay,tr_az,elbow_x,elbow_y,elbow_z,wrist_x,wrist_y,wrist_z,"
            "shoulder_x,shoulder_y,shoulder_z,cam_wrist_u,cam_wrist_v,cam_elbow_u,cam_elbow_v,"
            "true_th0,true_th1,true_th2,true_th4,true_th5,"
            "true_trunk_flex,true_trunk_lat,true_trunk_rot");
  const std::string json = readText(sidecarPath(csv));
  EXPECT_NE(json.find("\"trunk\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"imu_rotation\""), std::string::npos) << json;
  // Written back, the same bytes.
  writeRecording(m_dir / "again.csv", back);
  EXPECT_EQ(readText(m_dir / "again.csv"), text);
  EXPECT_EQ(readText(m_dir / "again.json"), json);
}

TEST_F(RecordingTrunk, RowByRowWriterAndReaderCarryTheTrunk) {
  const Recording rec = trunkRecording();
  RecordingColumns c;
  c.upperArm = c.forearm = c.elbow = c.wrist = c.camWrist = c.camElbow = c.truth = true;
  c.trunk = c.shoulder = c.trueTrunk = true;
  const fs::path csv = m_dir / "live.csv";
  {
    RecordingWriter w(csv, rec.meta, c);
    for (const ArmSample& s : rec.samples) w.append(s);
    w.close();
  }
  RecordingReader reader(csv);
  EXPECT_TRUE(reader.columns().trunk);
  EXPECT_TRUE(reader.columns().shoulder);
  EXPECT_TRUE(reader.columns().trueTrunk);
  EXPECT_FALSE(reader.columns().estimate);
  std::vector<ArmSample> back;
  ArmSample s;
  while (reader.next(s)) back.push_back(s);
  expectSameSamples(back, rec.samples);
  expectSameTrunk(back, rec.samples);
  // The whole-recording writer writes the same file.
  writeRecording(m_dir / "whole.csv", rec);
  EXPECT_EQ(readText(csv), readText(m_dir / "whole.csv"));
}

TEST_F(RecordingTrunk, ColumnsAreFoundByNameInAnyOrder) {
  writeText("rec.json", kTrunkSidecar);
  const fs::path p = writeText("rec.csv",
                               "true_trunk_rot,tr_az,shoulder_z,t,tr_gx,true_trunk_flex,tr_ay,"
                               "shoulder_x,tr_gz,tr_ax,shoulder_y,true_trunk_lat,tr_gy,note\n"
                               "0.3,9.8,0.03,0.5,0.1,0.1,0.2,0.01,0.3,-0.1,0.02,0.2,0.2,x\n"
                               ",,,0.6,,,,,,,,,,y\n");
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 2u);
  const ArmSample& s = rec.samples[0];
  ASSERT_TRUE(s.trunk && s.shoulder && s.trueTrunk);
  EXPECT_EQ(s.trunk->gyr, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_EQ(s.trunk->acc, Eigen::Vector3d(-0.1, 0.2, 9.8));
  EXPECT_EQ(*s.shoulder, Eigen::Vector3d(0.01, 0.02, 0.03));
  EXPECT_EQ(*s.trueTrunk, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_FALSE(rec.samples[1].trunk || rec.samples[1].shoulder || rec.samples[1].trueTrunk);
  EXPECT_TRUE(rec.warnings.empty());
}

// A group half in the header is refused at the header, naming the column that lacks its kin.
TEST_F(RecordingTrunk, GroupHalfInTheHeaderIsRefused) {
  struct Case {
    const char* header;
    int column;
    const char* message;
  };
  const Case cases[] = {
      {"t,tr_gx,tr_gy\n", 2, "column \"tr_gx\" without \"tr_gz\": the trunk (sternum) gyroscope"},
      {"t,tr_ax,tr_az\n", 2, "column \"tr_ax\" without \"tr_ay\""},
      {"t,shoulder_y,shoulder_z\n", 2, "column \"shoulder_y\" without \"shoulder_x\""},
      {"t,ua_gx,ua_gy,ua_gz,true_trunk_lat\n", 5,
       "column \"true_trunk_lat\" without \"true_trunk_flex\": the true trunk angles needs all of "
       "true_trunk_flex, true_trunk_lat, true_trunk_rot"},
      {"t,tr_gx,tr_gy,tr_gz,tr_gx\n", 5, "duplicate column \"tr_gx\""},
  };
  for (const Case& c : cases) {
    const fs::path p =
        writeCsv(std::string(c.header) + "0" +
                 std::string(std::count(c.header, c.header + strlen(c.header), ','), ',') + "\n");
    expectError(readError(p), p, 1, c.column, c.message);
  }
}

// A trunk IMU reading needs its gyroscope and accelerometer; a group is whole on a row or absent.
TEST_F(RecordingTrunk, GroupHalfOnARowIsRefused) {
  const std::string h = "t,tr_gx,tr_gy,tr_gz,tr_ax,tr_ay,tr_az,shoulder_x,shoulder_y,shoulder_z\n";
  writeText("rec.json", kTrunkSidecar);
  fs::path p = writeText("rec.csv", h + "0,1,2,3,4,5,6,,,\n0.1,1,,3,4,5,6,,,\n");
  expectError(readError(p), p, 3, 3,
              "empty cell in column \"tr_gy\" while \"tr_gx\" is set: the trunk (sternum) "
              "gyroscope needs all of tr_gx, tr_gy, tr_gz or none");
  p = writeText("rec.csv", h + "0,1,2,3,,,,,,\n");
  expectError(readError(p), p, 2, 5,
              "trunk (sternum) gyroscope values but no trunk (sternum) accelerometer values "
              "(tr_ax, tr_ay, tr_az); an IMU reading needs both");
  p = writeText("rec.csv", h + "0,,,,4,5,6,,,\n");
  expectError(readError(p), p, 2, 2, "trunk (sternum) accelerometer values but no trunk");
  p = writeText("rec.csv", h + "0,,,,,,,0.1,,0.3\n");
  expectError(readError(p), p, 2, 9, "empty cell in column \"shoulder_y\" while \"shoulder_x\"");
  // The accelerometer without the gyroscope's columns at all.
  p = writeText("rec.csv", "t,tr_ax,tr_ay,tr_az\n0,1,2,3\n");
  expectError(readError(p), p, 2, 2, "trunk (sternum) accelerometer values but no trunk");
}

TEST_F(RecordingTrunk, GarbageAndNonFiniteCellsAreRefusedWhereTheyAre) {
  writeText("rec.json", kTrunkSidecar);
  const std::string h =
      "t,tr_gx,tr_gy,tr_gz,tr_ax,tr_ay,tr_az,shoulder_x,shoulder_y,shoulder_z,true_trunk_flex,"
      "true_trunk_lat,true_trunk_rot\n";
  const std::string ok = "0,1,2,3,4,5,6,0.1,0.2,0.3,0.01,0.02,0.03\n";
  struct Case {
    const char* row;
    int column;
    const char* message;
  };
  const Case cases[] = {
      {"0.1,1,2,3,4,5,nan,,,,,,\n", 7, "not a finite number \"nan\" in column \"tr_az\""},
      {"0.1,inf,2,3,4,5,6,,,,,,\n", 2, "in column \"tr_gx\""},
      {"0.1,,,,,,,0.1,1e999,0.3,,,\n", 9, "number out of range \"1e999\" in column \"shoulder_y\""},
      {"0.1,,,,,,,,,,0.1,0.2,abc\n", 13, "bad number \"abc\" in column \"true_trunk_rot\""},
      {"0.1,,,,,,,,,,0.1,0x1p3,0.3\n", 12, "bad number \"0x1p3\" in column \"true_trunk_lat\""},
      {"0.1,1,2,3,4,5,6,,,,,\n", 13, "row has 12 fields, header has 13"},
  };
  for (const Case& c : cases) {
    const fs::path p = writeText("rec.csv", h + ok + c.row + ok);
    expectError(readError(p), p, 3, c.column, c.message);
  }
}

// Like ua_*, the reader checks only that tr_* are finite numbers: the sensor's full scale is the
// estimator's plausibility check (core/estimation/SampleGate.h), so a recording of a sensor
// outside it is kept exactly for inspection.
TEST_F(RecordingTrunk, AbsurdButFiniteValuesAreKeptExactly) {
  writeText("rec.json", kTrunkSidecar);
  const fs::path p =
      writeText("rec.csv",
                "t,tr_gx,tr_gy,tr_gz,tr_ax,tr_ay,tr_az,shoulder_x,shoulder_y,shoulder_z,"
                "true_trunk_flex,true_trunk_lat,true_trunk_rot\n"
                "0,1e300,-1e300,5e-324,-0,1.7976931348623157e308,0,1e6,-1e6,0,100,-100,1e-300\n");
  const Recording rec = readRecording(p);
  ASSERT_EQ(rec.samples.size(), 1u);
  const ArmSample& s = rec.samples[0];
  EXPECT_EQ(s.trunk->gyr(0), 1e300);
  EXPECT_EQ(s.trunk->gyr(2), 5e-324);
  EXPECT_TRUE(std::signbit(s.trunk->acc(0)));
  EXPECT_EQ(s.trunk->acc(1), 1.7976931348623157e308);
  EXPECT_EQ(s.shoulder->y(), -1e6);
  EXPECT_EQ(s.trueTrunk->x(), 100.0);
}

TEST_F(RecordingTrunk, TruncatedLastRowIsDroppedAndACutInsideIsAnError) {
  writeText("rec.json", kTrunkSidecar);
  const std::string h = "t,tr_gx,tr_gy,tr_gz,tr_ax,tr_ay,tr_az\n";
  fs::path p = writeText("rec.csv", h + "0,1,2,3,4,5,6\n0.01,1,2,3,4,5,6\n0.02,1,2,3,4,");
  Recording rec = readRecording(p);
  EXPECT_EQ(rec.samples.size(), 2u);
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_NE(rec.warnings[0].find("cut short"), std::string::npos);
  p = writeText("rec.csv", h + "0,1,2,3,4,5,6\n0.01,1,2,3,4,\n0.02,1,2,3,4,5,6\n");
  expectError(readError(p), p, 3, 7, "row has 6 fields, header has 7");
}

// tr_* without the sidecar's "trunk" block: read with the usual mounting and a warning that says
// what to add (docs/recording-format.md, "Trunk").
TEST_F(RecordingTrunk, TrunkImuWithoutMountingWarnsAndAssumesTheSternum) {
  writeText("rec.json", R"({"format": "armtrack-recording", "version": 1, "side": "left"})");
  const fs::path p =
      writeText("rec.csv", "t,tr_gx,tr_gy,tr_gz,tr_ax,tr_ay,tr_az\n0,0,0,0,9.8,0,0\n");
  const Recording rec = readRecording(p);
  ASSERT_TRUE(rec.meta.trunk.has_value());
  EXPECT_EQ(rec.meta.trunk->imuPosition, Eigen::Vector3d(0.10, 0.06, 0.18));  // medial: +z, left
  EXPECT_EQ(rec.meta.trunk->imuRotation, Eigen::Matrix3d::Identity());
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_NE(rec.warnings[0].find("has no \"trunk\" block"), std::string::npos) << rec.warnings[0];
  EXPECT_NE(rec.warnings[0].find("add the block"), std::string::npos) << rec.warnings[0];
  // A right arm's sternum is at -z; without a sidecar at all, both warnings.
  fs::remove(m_dir / "rec.json");
  const Recording noSidecar = readRecording(p);
  EXPECT_EQ(noSidecar.meta.trunk->imuPosition, Eigen::Vector3d(0.10, 0.06, -0.18));
  EXPECT_EQ(noSidecar.warnings.size(), 2u);
  // The optical shoulder alone needs no mounting: no warning, no trunk block.
  writeText("rec.json", R"({"format": "armtrack-recording", "version": 1})");
  const fs::path q = writeText("rec.csv", "t,shoulder_x,shoulder_y,shoulder_z\n0,0,0,0\n");
  const Recording shoulder = readRecording(q);
  EXPECT_TRUE(shoulder.warnings.empty());
  EXPECT_FALSE(shoulder.meta.trunk.has_value());
}

TEST_F(RecordingTrunk, BadTrunkBlocksAreRefusedNamingTheKey) {
  const std::string head = R"({"format": "armtrack-recording", "version": 1, "trunk": )";
  struct Case {
    const char* trunk;
    const char* message;
  };
  const Case cases[] = {
      {"[1, 2, 3]", "\"trunk\" must be an object"},
      {R"({"imu_position": [0.1, 0, 0]})", "missing \"trunk.imu_rotation\""},
      {R"({"imu_rotation": [1, 0, 0, 0, 1, 0, 0, 0, 1]})", "missing \"trunk.imu_position\""},
      {R"({"imu_position": [0.1, 0], "imu_rotation": [1, 0, 0, 0, 1, 0, 0, 0, 1]})",
       "\"trunk.imu_position\" must be an array of 3 numbers"},
      {R"({"imu_position": [0.1, "0", 0], "imu_rotation": [1, 0, 0, 0, 1, 0, 0, 0, 1]})",
       "\"trunk.imu_position[1]\" must be a finite number"},
      {R"({"imu_position": [0.1, 0, 0], "imu_rotation": [1, 0, 0, 0, 1, 0, 0, 0]})",
       "\"trunk.imu_rotation\" must be an array of 9 numbers"},
      {R"({"imu_position": [0.1, 0, 0], "imu_rotation": [2, 0, 0, 0, 2, 0, 0, 0, 2]})",
       "\"trunk.imu_rotation\" is not a rotation matrix"},
      {R"({"imu_position": [0.1, 0, 0], "imu_rotation": [1, 0, 0, 0, 1, 0, 0, 0, -1]})",
       "det R = -1"},
      {R"({"imu_position": [0.1, 0, 0], "imu_rotation": [1, 0.01, 0, 0, 1, 0, 0, 0, 1]})",
       "\"trunk.imu_rotation\" is not a rotation matrix"},
      {R"({"imu_position": [0.1, 0, 0], "imu_rotation": [0, 0, 0, 0, 0, 0, 0, 0, 0]})",
       "\"trunk.imu_rotation\" is not a rotation matrix"},
      {R"({"imu_position": [100, 60, -180], "imu_rotation": [1, 0, 0, 0, 1, 0, 0, 0, 1]})",
       "\"trunk.imu_position\" is 214.476"},
      {R"({"imu_position": [0, 0, 1.0001], "imu_rotation": [1, 0, 0, 0, 1, 0, 0, 0, 1]})",
       "a sternum IMU sits within 1 m of the shoulder"},
  };
  for (const Case& c : cases) {
    writeText("rec.json", head + c.trunk + "}");
    const fs::path p = writeText("rec.csv", "t\n0\n");
    const RecordingError e = readError(p);
    EXPECT_EQ(e.file(), (m_dir / "rec.json").string()) << c.trunk;
    EXPECT_NE(e.message().find(c.message), std::string::npos)
        << c.trunk << "\n"
        << e.message() << "\nexpected: " << c.message;
  }
  // A number beyond a double: a JSON error at its line and column.
  writeText("rec.json", head + R"({"imu_position": [1e999, 0, 0], "imu_rotation": []}})");
  const RecordingError e = readError(writeText("rec.csv", "t\n0\n"));
  EXPECT_EQ(e.line(), 1);
  EXPECT_GT(e.column(), 1);
  // A rotation within the tolerance, a position just inside the limit: read.
  writeText("rec.json", head + R"({"imu_position": [0, 0, 0.9999],
      "imu_rotation": [1, 0.0009, 0, 0, 1, 0, 0, 0, 1]}})");
  EXPECT_NO_THROW(readRecording(writeText("rec.csv", "t\n0\n")));
}

// What the reader refuses, the writers refuse to write, leaving no file.
TEST_F(RecordingTrunk, WritersRefuseAMountingTheReaderWouldRefuse) {
  Recording rec;
  rec.samples.resize(1);
  TrunkMount bad;
  bad.imuRotation = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();  // a mirror
  rec.meta.trunk = bad;
  const fs::path csv = m_dir / "rec.csv";
  expectError(errorOf([&] { writeRecording(csv, rec); }), m_dir / "rec.json", 0, 0,
              "\"trunk.imu_rotation\" is not a rotation matrix");
  rec.meta.trunk = TrunkMount{};
  rec.meta.trunk->imuPosition.z() = std::numeric_limits<double>::quiet_NaN();
  expectError(errorOf([&] { writeRecording(csv, rec); }), m_dir / "rec.json", 0, 0,
              "cannot write non-finite values in the sidecar");
  rec.meta.trunk->imuPosition = Eigen::Vector3d(0, 2, 0);
  expectError(errorOf([&] { RecordingWriter(csv, rec.meta, RecordingColumns{}); }),
              m_dir / "rec.json", 0, 0, "\"trunk.imu_position\" is 2 m");
  EXPECT_TRUE(dirEntries().empty());
}

TEST_F(RecordingTrunk, CheckRowNamesTheTrunksColumns) {
  RecordingColumns c;
  c.upperArm = true;
  c.trunk = true;
  ArmSample s;
  s.t = 0.0;
  s.trunk = ImuReading{Eigen::Vector3d(0, 0, 0),
                       Eigen::Vector3d(0, std::numeric_limits<double>::infinity(), 0)};
  std::optional<RowProblem> p = checkRow(s, c, -1.0);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->column, 12);  // t, ua (6), tr_gx..tr_az: tr_ay is the 12th
  EXPECT_NE(p->message.find("column \"tr_ay\""), std::string::npos) << p->message;
  s.trunk->acc.y() = 9.8;
  EXPECT_FALSE(checkRow(s, c, -1.0).has_value());
  s.shoulder = Eigen::Vector3d::Zero();
  p = checkRow(s, c, -1.0);
  ASSERT_TRUE(p.has_value());
  EXPECT_NE(p->message.find("cannot write the shoulder position: the recording has no columns"),
            std::string::npos)
      << p->message;
  s.shoulder.reset();
  s.trueTrunk = Eigen::Vector3d(0.1, std::nan(""), 0.0);
  c.trueTrunk = true;
  p = checkRow(s, c, -1.0);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->column, 15);
  EXPECT_NE(p->message.find("\"true_trunk_lat\""), std::string::npos) << p->message;
  // The writer refuses the row and stays usable.
  RecordingWriter w(m_dir / "rec.csv", RecordingMeta{}, c);
  EXPECT_THROW(w.append(s), RecordingError);
  s.trueTrunk->y() = 0.2;
  EXPECT_NO_THROW(w.append(s));
  w.close();
  EXPECT_EQ(readRecording(m_dir / "rec.csv").samples.size(), 1u);
}

}  // namespace
}  // namespace armtrack::recording_test
