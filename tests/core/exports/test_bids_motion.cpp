// BIDS motion export (BIDS 1.9, motion modality) of a simulated session: one file set per
// tracking system, the required columns and fields, row and channel counts that agree, and values
// read back against the simulation they came from (docs/exports.md).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "core/exports/Exports.h"
#include "tests/core/exports/ExportTestSupport.h"

namespace armtrack {
namespace {

using namespace exporttest;
using nlohmann::json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The restricted keywords of the specification's channels.tsv (motion.md).
const std::set<std::string> kTypes{"ACCEL", "ANGACCEL", "GYRO", "JNTANG", "LATENCY",
                                   "MAGN",  "MISC",     "ORNT", "POS",    "VEL"};
const std::set<std::string> kComponents{"x",      "y",      "z",      "quat_x",
                                        "quat_y", "quat_z", "quat_w", "n/a"};

struct Channels {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

Channels readChannels(const fs::path& p) {
  const auto lines = readLines(p);
  Channels c;
  c.header = split(lines.at(0), '\t');
  for (std::size_t i = 1; i < lines.size(); ++i) c.rows.push_back(split(lines[i], '\t'));
  return c;
}

/// motion.tsv: no header, every cell a number or n/a; throws on anything else.
std::vector<std::vector<double>> readMotion(const fs::path& p) {
  std::vector<std::vector<double>> rows;
  for (const auto& line : readLines(p)) {
    std::vector<double> row;
    for (const auto& cell : split(line, '\t')) {
      if (cell == "n/a") {
        row.push_back(kNaN);
        continue;
      }
      std::size_t used = 0;
      row.push_back(std::stod(cell, &used));
      if (used != cell.size()) throw std::runtime_error("not a number: " + cell);
    }
    rows.push_back(row);
  }
  return rows;
}

/// Checks one tracking system's files against the specification's rules and returns the parsed
/// motion rows.
std::vector<std::vector<double>> checkSystem(const BidsTrackingSystemFiles& f,
                                             const std::string& task) {
  SCOPED_TRACE(f.label);
  const Channels ch = readChannels(f.channelsTsv);
  // The REQUIRED columns, first and in this order.
  EXPECT_GE(ch.header.size(), 5u);
  EXPECT_EQ(std::vector<std::string>(ch.header.begin(), ch.header.begin() + 5),
            (std::vector<std::string>{"name", "component", "type", "tracked_point", "units"}));
  std::map<std::string, int> typeCount;
  std::set<std::string> points;
  for (const auto& r : ch.rows) {
    EXPECT_EQ(r.size(), ch.header.size());
    EXPECT_TRUE(kTypes.count(r[2])) << r[2];
    EXPECT_TRUE(kComponents.count(r[1])) << r[1];
    ++typeCount[r[2]];
    if (r[2] != "LATENCY") points.insert(r[3]);
  }
  EXPECT_EQ(ch.rows.front()[2], "LATENCY");
  EXPECT_EQ(ch.rows.front()[4], "s");

  const json j = json::parse(readText(f.motionJson));
  EXPECT_TRUE(j.at("SamplingFrequency").is_number());   // REQUIRED
  EXPECT_TRUE(j.at("TrackingSystemName").is_string());  // REQUIRED
  EXPECT_EQ(j.at("TaskName"), task);                    // REQUIRED
  EXPECT_EQ(j.at("MotionChannelCount"), ch.rows.size());
  for (const auto& [type, n] : typeCount) EXPECT_EQ(j.at(type + "ChannelCount"), n) << type;
  EXPECT_EQ(j.at("TrackedPointsCount"), points.size());

  const auto rows = readMotion(f.motionTsv);
  EXPECT_EQ(rows.size(), f.rows);
  for (const auto& r : rows) EXPECT_EQ(r.size(), ch.rows.size());  // columns = channel rows
  EXPECT_EQ(f.channels, ch.rows.size());
  EXPECT_EQ(rows.front().front(), 0.0);  // latency from the first sample
  return rows;
}

BidsOptions options() {
  BidsOptions o;
  o.subject = "P001";
  o.session = "20261125";
  o.task = "flexion";
  o.taskDescription = "shoulder flexion repetitions";
  return o;
}

TEST(BidsMotion, OneFileSetPerTrackingSystemWithTheSpecificationsColumnsAndFields) {
  const SinusoidTrajectory tr = knownMovement();
  const Recording rec = simulatedSession(tr, 5.0, 200.0);
  const AngleSeries angles = truthSeries(rec);
  TempDir dir;
  const BidsExportResult r = writeBidsMotion(dir.path(), &rec, &angles, Side::Right, options());

  EXPECT_EQ(r.motionDir, dir / "sub-P001" / "ses-20261125" / "motion");
  ASSERT_EQ(r.systems.size(), 3u);
  EXPECT_EQ(r.systems[0].label, "imu");
  EXPECT_EQ(r.systems[1].label, "optical");
  EXPECT_EQ(r.systems[2].label, "angles");
  EXPECT_EQ(r.systems[0].motionTsv.filename(),
            "sub-P001_ses-20261125_task-flexion_tracksys-imu_motion.tsv");
  EXPECT_EQ(r.systems[1].channelsTsv.filename(),
            "sub-P001_ses-20261125_task-flexion_tracksys-optical_channels.tsv");
  EXPECT_EQ(r.systems[2].motionJson.filename(),
            "sub-P001_ses-20261125_task-flexion_tracksys-angles_motion.json");
  const json d = json::parse(readText(dir / "dataset_description.json"));
  EXPECT_EQ(d.at("BIDSVersion"), "1.9.0");
  EXPECT_TRUE(d.at("Name").is_string());

  std::size_t imuRows = 0, opticalRows = 0;
  for (const ArmSample& s : rec.samples) {
    imuRows += s.hasImu();
    opticalRows += s.elbow.has_value();
  }
  EXPECT_EQ(imuRows, 1001u);
  EXPECT_EQ(opticalRows, 151u);
  EXPECT_EQ(r.systems[0].rows, imuRows);
  EXPECT_EQ(r.systems[1].rows, opticalRows);
  EXPECT_EQ(r.systems[2].rows, angles.t.size());
  EXPECT_EQ(r.systems[0].channels, 13u);  // latency + 2 IMUs x (3 gyro + 3 accel)
  EXPECT_EQ(r.systems[1].channels, 7u);   // latency + elbow and wrist x 3
  EXPECT_EQ(r.systems[2].channels, 6u);   // latency + 5 angles

  for (const auto& f : r.systems) checkSystem(f, "flexion");
  const json imu = json::parse(readText(r.systems[0].motionJson));
  EXPECT_EQ(imu.at("SamplingFrequency"), 200.0);
  EXPECT_NEAR(imu.at("SamplingFrequencyEffective").get<double>(), 200.0, 1e-6);
  EXPECT_EQ(imu.at("GYROChannelCount"), 6);
  EXPECT_EQ(imu.at("ACCELChannelCount"), 6);
  EXPECT_EQ(imu.at("TaskDescription"), "shoulder flexion repetitions");
  const json optical = json::parse(readText(r.systems[1].motionJson));
  EXPECT_EQ(optical.at("SamplingFrequency"), 30.0);
  EXPECT_EQ(optical.at("POSChannelCount"), 6);
  const json ang = json::parse(readText(r.systems[2].motionJson));
  EXPECT_EQ(ang.at("JNTANGChannelCount"), 5);

  // Units and types as stored.
  const Channels ic = readChannels(r.systems[0].channelsTsv);
  EXPECT_EQ(ic.rows[1],
            (std::vector<std::string>{"upperarm_gyro_x", "x", "GYRO", "RightUpperArm", "rad/s",
                                      "sensor", "upper-arm IMU angular velocity, x axis"}));
  EXPECT_EQ(ic.rows[4][2], "ACCEL");
  EXPECT_EQ(ic.rows[4][4], "m/s^2");
  const Channels ac = readChannels(r.systems[2].channelsTsv);
  for (std::size_t k = 1; k < ac.rows.size(); ++k) {
    EXPECT_EQ(ac.rows[k][2], "JNTANG");
    EXPECT_EQ(ac.rows[k][4], "deg");
    EXPECT_EQ(ac.rows[k][0], clinicalAngleInfo()[k - 1].key);
  }
  const Channels oc = readChannels(r.systems[1].channelsTsv);
  EXPECT_EQ(oc.rows[4][3], "RightWrist");
  EXPECT_EQ(oc.rows[4][4], "m");
  // Frames named in channels.tsv are described in channels.json.
  const json ocj = json::parse(readText(r.systems[1].channelsJson));
  EXPECT_TRUE(ocj.at("reference_frame").at("Levels").contains("shoulder"));
}

// A session with a sternum IMU and an optical shoulder (issue 26): the IMU system carries the
// sternum's gyroscope and accelerometer (rad/s, m/s^2, its own axes), the optical system the
// shoulder, and the optical positions say they are in the world frame.
TEST(BidsMotion, TrunkImuAndShoulderHaveTheirChannels) {
  const SinusoidTrajectory tr = knownMovement();
  Recording rec = simulatedSession(tr, 2.0, 100.0);
  std::size_t k = 0;
  for (ArmSample& s : rec.samples) {
    const double x = 0.1 * static_cast<double>(k++);
    if (s.hasImu())
      s.trunk = ImuReading{Eigen::Vector3d(0.01 * x, -0.02, 1e-7),
                           Eigen::Vector3d(9.81, 0.3 * std::sin(x), -0.1)};
    if (s.elbow) s.shoulder = Eigen::Vector3d(0.001 * x, 0.05, -0.01);
  }
  // A row with the sternum alone: the arm's channels are n/a there.
  ArmSample* alone = nullptr;
  for (ArmSample& s : rec.samples)
    if (s.hasImu() && s.t > 1.0) {
      s.upperArm.reset();
      s.forearm.reset();
      alone = &s;
      break;
    }
  ASSERT_NE(alone, nullptr);
  TempDir dir;
  const BidsExportResult r = writeBidsMotion(dir.path(), &rec, nullptr, Side::Left, options());
  ASSERT_EQ(r.systems.size(), 2u);
  for (const auto& f : r.systems) checkSystem(f, "flexion");
  EXPECT_EQ(r.systems[0].channels, 19u);  // latency + 3 IMUs x (3 gyro + 3 accel)
  EXPECT_EQ(r.systems[1].channels, 10u);  // latency + elbow, wrist and shoulder x 3
  const Channels ic = readChannels(r.systems[0].channelsTsv);
  EXPECT_EQ(ic.rows[13],
            (std::vector<std::string>{"trunk_gyro_x", "x", "GYRO", "Sternum", "rad/s", "sensor",
                                      "trunk (sternum) IMU angular velocity, x axis"}));
  EXPECT_EQ(ic.rows[18],
            (std::vector<std::string>{"trunk_acc_z", "z", "ACCEL", "Sternum", "m/s^2", "sensor",
                                      "trunk (sternum) IMU specific force, z axis"}));
  const json imu = json::parse(readText(r.systems[0].motionJson));
  EXPECT_EQ(imu.at("GYROChannelCount"), 9);
  EXPECT_EQ(imu.at("ACCELChannelCount"), 9);
  EXPECT_EQ(imu.at("TrackedPointsCount"), 3);
  EXPECT_NE(imu.at("TrackingSystemName").get<std::string>().find("sternum"), std::string::npos);
  const auto rows = readMotion(r.systems[0].motionTsv);
  std::size_t i = 0, sternumOnly = 0;
  for (const ArmSample& s : rec.samples) {
    if (!s.hasImu() && !s.trunk) continue;
    const auto& row = rows.at(i++);
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(row[13 + j], s.trunk->gyr(j));
      EXPECT_EQ(row[16 + j], s.trunk->acc(j));
    }
    if (!s.hasImu()) {
      ++sternumOnly;
      for (int c = 1; c <= 12; ++c) EXPECT_TRUE(std::isnan(row[c])) << c;
    }
  }
  EXPECT_EQ(i, rows.size());
  EXPECT_EQ(sternumOnly, 1u);

  const Channels oc = readChannels(r.systems[1].channelsTsv);
  EXPECT_EQ(oc.rows[7], (std::vector<std::string>{"shoulder_pos_x", "x", "POS", "LeftShoulder", "m",
                                                  "world", "shoulder position, x axis"}));
  for (std::size_t c = 1; c < oc.rows.size(); ++c) EXPECT_EQ(oc.rows[c][5], "world");
  const json ocj = json::parse(readText(r.systems[1].channelsJson));
  EXPECT_TRUE(ocj.at("reference_frame").at("Levels").contains("world"));
  EXPECT_FALSE(ocj.at("reference_frame").at("Levels").contains("shoulder"));
  const auto opt = readMotion(r.systems[1].motionTsv);
  std::size_t o = 0;
  for (const ArmSample& s : rec.samples) {
    if (!s.elbow) continue;
    for (int j = 0; j < 3; ++j) EXPECT_EQ(opt.at(o)[7 + j], (*s.shoulder)(j));
    ++o;
  }
  EXPECT_EQ(o, opt.size());
}

TEST(BidsMotion, ValuesAreTheSimulatedOnes) {
  const SinusoidTrajectory tr = knownMovement();
  const Recording rec = simulatedSession(tr, 3.0, 100.0);
  const AngleSeries angles = truthSeries(rec);
  TempDir dir;
  const BidsExportResult r = writeBidsMotion(dir.path(), &rec, &angles, Side::Right, options());

  // Raw channels read back exactly (shortest round-trip form).
  const auto imu = readMotion(r.systems[0].motionTsv);
  const auto opt = readMotion(r.systems[1].motionTsv);
  std::size_t i = 0, o = 0;
  for (const ArmSample& s : rec.samples) {
    if (s.hasImu()) {
      const auto& row = imu.at(i++);
      EXPECT_NEAR(row[0], s.t, 1e-6);  // the first IMU sample is at t = 0
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(row[1 + k], s.upperArm->gyr(k));
        EXPECT_EQ(row[4 + k], s.upperArm->acc(k));
        EXPECT_EQ(row[7 + k], s.forearm->gyr(k));
        EXPECT_EQ(row[10 + k], s.forearm->acc(k));
      }
    }
    if (s.elbow) {
      const auto& row = opt.at(o++);
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(row[1 + k], (*s.elbow)(k));
        EXPECT_EQ(row[4 + k], (*s.wrist)(k));
      }
    }
  }
  // Joint angles: the true clinical angles in degrees.
  const auto ang = readMotion(r.systems[2].motionTsv);
  ASSERT_EQ(ang.size(), angles.t.size());
  for (std::size_t k = 0; k < ang.size(); ++k) {
    const auto truth = trueClinicalDeg(tr, angles.t[k]);
    EXPECT_NEAR(ang[k][0], angles.t[k] - angles.t[0], 1e-6);
    for (int a = 0; a < 5; ++a) EXPECT_NEAR(ang[k][1 + a], truth[a], 2e-6);
  }
}

TEST(BidsMotion, IrregularTimesGoToTheLatencyChannelAndBothRates) {
  // Angles at about 50 Hz with jittered times starting at 2 s.
  AngleSeries s;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.004, 0.004);
  for (int i = 0; i < 500; ++i) {
    s.t.push_back(2.0 + i * 0.02 + (i > 0 && i < 499 ? jitter(rng) : 0.0));
    s.angle.push_back(ClinicalRow{0.1 * i / 500, 0, 0, 0.5, 0});
  }
  TempDir dir;
  const BidsExportResult r = writeBidsMotion(dir.path(), nullptr, &s, Side::Left, options());
  ASSERT_EQ(r.systems.size(), 1u);
  const auto rows = checkSystem(r.systems[0], "flexion");
  for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_NEAR(rows[i][0], s.t[i] - 2.0, 1e-6);
  const json j = json::parse(readText(r.systems[0].motionJson));
  EXPECT_NEAR(j.at("SamplingFrequency").get<double>(), 50.0, 2.0);  // median interval
  EXPECT_NEAR(j.at("SamplingFrequencyEffective").get<double>(), 499 / (s.t.back() - s.t[0]), 1e-9);
  EXPECT_NEAR(j.at("RecordingDuration").get<double>(), 9.98, 1e-9);
  EXPECT_EQ(readChannels(r.systems[0].channelsTsv).rows[1][3], "LeftShoulder");
}

// A live recording can hold two readings at one time (the synchroniser's merge); they are kept,
// and the rate comes from the intervals that are not zero.
TEST(BidsMotion, EqualTimesAreKeptAndLeftOutOfTheRate) {
  AngleSeries s;
  for (int i = 0; i < 101; ++i) {
    s.t.push_back(i * 0.01);
    s.angle.push_back(ClinicalRow{0.01 * i, 0, 0, 0, 0});
    if (i == 0 || i == 50) {
      s.t.push_back(i * 0.01);
      s.angle.push_back(ClinicalRow{0.01 * i, 0, 0, 0, 0});
    }
  }
  TempDir dir;
  const BidsExportResult r = writeBidsMotion(dir.path(), nullptr, &s, Side::Right, options());
  ASSERT_EQ(r.systems.size(), 1u);
  EXPECT_EQ(r.systems[0].rows, 103u);
  const json j = json::parse(readText(r.systems[0].motionJson));
  EXPECT_NEAR(j.at("SamplingFrequency").get<double>(), 100.0, 1e-9);
}

TEST(BidsMotion, MissingValuesAreNaAndRowsWithoutTimeAreDropped) {
  AngleSeries s;
  for (int i = 0; i < 6; ++i) {
    s.t.push_back(i * 0.01);
    s.angle.push_back(ClinicalRow{0.1, 0.2, 0.3, 0.4, 0.5});
  }
  s.angle[2][1] = kNaN;
  s.angle[3][4] = INFINITY;
  s.t[4] = kNaN;
  TempDir dir;
  const BidsExportResult r = writeBidsMotion(dir.path(), nullptr, &s, Side::Right, options());
  EXPECT_EQ(r.skippedAngleRows, 1u);
  ASSERT_EQ(r.systems.size(), 1u);
  EXPECT_EQ(r.systems[0].rows, 5u);
  EXPECT_EQ(r.systems[0].missingValues, 2u);
  const auto lines = readLines(r.systems[0].motionTsv);
  EXPECT_EQ(lines[2], "0.020000\t5.729578\tn/a\t17.188734\t22.918312\t28.647890");
  EXPECT_EQ(split(lines[3], '\t')[5], "n/a");
  checkSystem(r.systems[0], "flexion");
}

TEST(BidsMotion, MissingSensorsAreNaInTheirSystemsRows) {
  // The forearm IMU runs at half the upper arm's rate: rows with only the upper arm carry n/a in
  // the forearm's columns.
  SimulationParams p = defaultSimulation();
  p.duration = 1.0;
  p.upperArm.rateHz = 100;
  p.forearm.rateHz = 50;
  p.kinect.enabled = false;
  const Recording rec = simulateRecording(knownMovement(), p);
  TempDir dir;
  const BidsExportResult r = writeBidsMotion(dir.path(), &rec, nullptr, Side::Right, options());
  ASSERT_EQ(r.systems.size(), 1u);  // no optical data, no angles
  EXPECT_EQ(r.systems[0].rows, 101u);
  EXPECT_EQ(r.systems[0].missingValues, 50u * 6);
  const auto rows = checkSystem(r.systems[0], "flexion");
  EXPECT_TRUE(std::isnan(rows[1][7]));
  EXPECT_FALSE(std::isnan(rows[2][7]));
}

TEST(BidsMotion, HostileInputAndUnwritableFoldersLeaveNothingBehind) {
  TempDir dir;
  AngleSeries one{{0.0}, {ClinicalRow{}}};
  EXPECT_THROW(writeBidsMotion(dir.path(), nullptr, &one, Side::Right, options()), ExportError);
  EXPECT_THROW(writeBidsMotion(dir.path(), nullptr, nullptr, Side::Right, options()), ExportError);
  AngleSeries empty;
  EXPECT_THROW(writeBidsMotion(dir.path(), nullptr, &empty, Side::Right, options()), ExportError);
  BidsOptions bad = options();
  bad.subject = "P-001";
  AngleSeries two{{0.0, 0.1}, {ClinicalRow{}, ClinicalRow{}}};
  EXPECT_THROW(writeBidsMotion(dir.path(), nullptr, &two, Side::Right, bad), std::invalid_argument);
  EXPECT_EQ(bidsLabel("P-001 a"), "P001a");
  EXPECT_THROW(bidsLabel("--"), std::invalid_argument);
  AngleSeries back{{0.0, 0.2, 0.1}, {ClinicalRow{}, ClinicalRow{}, ClinicalRow{}}};
  EXPECT_THROW(writeBidsMotion(dir.path(), nullptr, &back, Side::Right, options()), ExportError);
  EXPECT_TRUE(listing(dir.path()).empty());

  // A root that is a file: the error names the folder it could not create.
  { std::ofstream(dir / "file") << "x"; }
  try {
    writeBidsMotion(dir / "file", nullptr, &two, Side::Right, options());
    FAIL() << "no error";
  } catch (const ExportError& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "file").string()), std::string::npos) << e.what();
  }
  // Folders made, then no file can be created in them (a file name longer than the system
  // allows, while each folder name is not): the folders this export made are removed again.
  BidsOptions longNames = options();
  longNames.subject = std::string(120, 'S');
  longNames.task = std::string(120, 'T');
  const auto before = listing(dir.path());
  try {
    writeBidsMotion(dir / "new", nullptr, &two, Side::Right, longNames);
    FAIL() << "no error";
  } catch (const ExportError& e) {
    EXPECT_NE(std::string(e.what()).find("tracksys-angles"), std::string::npos) << e.what();
  }
  EXPECT_EQ(listing(dir.path()), before);
  // The last file of the set cannot be created (a folder has its name; overwrite, so the export
  // goes as far as creating it): no file of the set and no temporary file is left, and an
  // existing dataset_description.json and participants.tsv are not touched.
  const fs::path motionDir = dir / "root" / "sub-P001" / "ses-20261125" / "motion";
  const fs::path blocked =
      motionDir / "sub-P001_ses-20261125_task-flexion_tracksys-angles_motion.tsv";
  fs::create_directories(blocked);
  { std::ofstream(dir / "root" / "dataset_description.json") << "{}"; }
  {
    std::ofstream(dir / "root" / "participants.tsv")
        << "participant_id\tpatient_code\nsub-P001\tP001\n";
  }
  const Recording rec = simulatedSession(knownMovement(), 0.5, 50.0);
  BidsOptions replace = options();
  replace.overwrite = true;
  try {
    writeBidsMotion(dir / "root", &rec, &two, Side::Right, replace);
    FAIL() << "no error";
  } catch (const ExportError& e) {
    EXPECT_EQ(e.path(), blocked);
  }
  fs::remove(blocked);
  EXPECT_TRUE(fs::is_empty(motionDir));
  EXPECT_EQ(readText(dir / "root" / "dataset_description.json"), "{}");
  EXPECT_EQ(readText(dir / "root" / "participants.tsv"),
            "participant_id\tpatient_code\nsub-P001\tP001\n");
  EXPECT_FALSE(fs::exists(dir / "root" / "participants.json"));
}

// Issue 24, item 7: a second export into the same data set replaced the files of the first.
// Without overwrite it is refused before anything is written, naming the file; with it the
// subject's files of that session are replaced.
TEST(BidsMotion, ExistingFilesAreReplacedOnlyWithOverwrite) {
  TempDir dir;
  AngleSeries two{{0.0, 0.1, 0.2}, {ClinicalRow{}, ClinicalRow{}, ClinicalRow{}}};
  const BidsExportResult first = writeBidsMotion(dir.path(), nullptr, &two, Side::Right, options());
  ASSERT_EQ(first.systems.size(), 1u);
  const fs::path tsv = first.systems[0].motionTsv;
  { std::ofstream(tsv, std::ios::trunc) << "kept\n"; }
  const auto before = listing(dir.path());
  const std::string participants = readText(dir / "participants.tsv");
  AngleSeries other{{0.0, 0.5}, {ClinicalRow{}, ClinicalRow{}}};
  try {
    writeBidsMotion(dir.path(), nullptr, &other, Side::Right, options());
    FAIL() << "no error";
  } catch (const ExportError& e) {
    EXPECT_NE(std::string(e.what()).find("exists; nothing was written"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(listing(dir.path()), before);
  EXPECT_EQ(readText(tsv), "kept\n");
  BidsOptions replace = options();
  replace.overwrite = true;
  writeBidsMotion(dir.path(), nullptr, &other, Side::Right, replace);
  EXPECT_EQ(readLines(tsv).size(), 2u);
  EXPECT_EQ(listing(dir.path()), before);
  EXPECT_EQ(readText(dir / "participants.tsv"), participants);
}

// Issue 24, item 7: patients P-01 and P01 both went to sub-P01. Distinct codes get distinct
// subject labels, and a subject that participants.tsv gives to another patient code (or that no
// row claims) is never added to, with or without overwrite.
TEST(BidsMotion, DistinctPatientsNeverShareASubject) {
  EXPECT_EQ(bidsSubjectLabel("P01"), "P01");
  std::set<std::string> labels;
  for (const char* code : {"P01", "P-01", "P_01", "P 01", "P.01", "p01", "P-0-1",
                           "P\xc3\xa9"
                           "01"}) {
    const std::string label = bidsSubjectLabel(code);
    EXPECT_EQ(bidsLabel(label), label) << code;  // letters and digits only
    labels.insert(label);
  }
  EXPECT_EQ(labels.size(), 8u);
  EXPECT_EQ(bidsSubjectLabel("P-01").rfind("P01h", 0), 0u);
  EXPECT_EQ(bidsSubjectLabel("P-01"), bidsSubjectLabel("P-01"));  // the same every time
  EXPECT_EQ(bidsSubjectLabel("--").size(), 9u);                   // "h" and the hash
  EXPECT_THROW(bidsSubjectLabel(""), std::invalid_argument);

  TempDir dir;
  AngleSeries two{{0.0, 0.1}, {ClinicalRow{}, ClinicalRow{}}};
  BidsOptions a = options(), b = options();
  a.subject = bidsSubjectLabel("P01");
  a.patientCode = "P01";
  b.subject = bidsSubjectLabel("P-01");
  b.patientCode = "P-01";
  const BidsExportResult ra = writeBidsMotion(dir.path(), nullptr, &two, Side::Right, a);
  const BidsExportResult rb = writeBidsMotion(dir.path(), nullptr, &two, Side::Right, b);
  EXPECT_NE(ra.motionDir, rb.motionDir);
  EXPECT_EQ(readLines(dir / "participants.tsv"),
            (std::vector<std::string>{"participant_id\tpatient_code", "sub-P01\tP01",
                                      "sub-" + b.subject + "\tP-01"}));
  const json pj = json::parse(readText(dir / "participants.json"));
  EXPECT_TRUE(pj.contains("patient_code"));

  // Another patient whose label is sub-P01 (a hand-made collision): refused, nothing written.
  const auto before = listing(dir.path());
  const std::string rows = readText(dir / "participants.tsv");
  BidsOptions c = a;
  c.patientCode = "Q07";
  c.session = "other";
  c.overwrite = true;
  try {
    writeBidsMotion(dir.path(), nullptr, &two, Side::Right, c);
    FAIL() << "no error";
  } catch (const ExportError& e) {
    EXPECT_EQ(e.path(), dir / "sub-P01");
    EXPECT_NE(std::string(e.what()).find("another patient"), std::string::npos) << e.what();
  }
  // A subject folder no row claims (made by hand, or by an earlier export): refused too.
  fs::create_directories(dir / "sub-X9");
  BidsOptions d = options();
  d.subject = "X9";
  d.patientCode = "X9";
  EXPECT_THROW(writeBidsMotion(dir.path(), nullptr, &two, Side::Right, d), ExportError);
  fs::remove(dir / "sub-X9");
  EXPECT_EQ(listing(dir.path()), before);
  EXPECT_EQ(readText(dir / "participants.tsv"), rows);
  // A participants.tsv of another tool gains the column, with n/a for its own subjects.
  TempDir other;
  { std::ofstream(other / "participants.tsv") << "participant_id\tage\nsub-01\t34\n"; }
  writeBidsMotion(other.path(), nullptr, &two, Side::Right, a);
  EXPECT_EQ(readLines(other / "participants.tsv"),
            (std::vector<std::string>{"participant_id\tage\tpatient_code", "sub-01\t34\tn/a",
                                      "sub-P01\tn/a\tP01"}));
  // The caller's check sees every file before any is written, and may refuse one.
  TempDir guarded;
  std::vector<fs::path> seen;
  BidsOptions e = a;
  e.checkTarget = [&](const fs::path& p) {
    seen.push_back(p);
    if (p.filename() == "participants.tsv") throw std::runtime_error("refused");
  };
  EXPECT_THROW(writeBidsMotion(guarded.path(), nullptr, &two, Side::Right, e), std::runtime_error);
  EXPECT_TRUE(listing(guarded.path()).empty());
  e.checkTarget = [&](const fs::path& p) { seen.push_back(p); };
  seen.clear();
  writeBidsMotion(guarded.path(), nullptr, &two, Side::Right, e);
  EXPECT_EQ(seen.size(), 6u);  // participants.tsv and .json, the description, the angles' three
  for (const std::string& f : listing(guarded.path())) {
    if (fs::is_regular_file(guarded / f)) {
      EXPECT_NE(std::find(seen.begin(), seen.end(), guarded / f), seen.end()) << f;
    }
  }
}

}  // namespace
}  // namespace armtrack
