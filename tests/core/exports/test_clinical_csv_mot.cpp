// Clinical CSV and OpenSim .mot exports of a simulated session with known angles, read back and
// compared with the angles the simulation started from (docs/exports.md); and what the writers do
// with hostile input and folders they cannot write.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "core/exports/Exports.h"
#include "core/kinematics/Trunk.h"
#include "core/metrics/ClinicalMetrics.h"
#include "tests/core/exports/ExportTestSupport.h"

namespace armtrack {
namespace {

using namespace exporttest;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ------------------------------------------------------------------ OpenSim reader

/// A .mot file read with OpenSim's storage rules: a header of lines up to "endheader" (the first
/// line is the name; key=value lines), nRows and nColumns required and matched by the data, a
/// tab-separated label line starting with "time", then rows of nColumns tab-separated numbers.
struct MotFile {
  std::string name;
  std::map<std::string, std::string> header;
  std::vector<std::string> labels;
  std::vector<std::vector<double>> rows;
};

MotFile readMot(const fs::path& p) {
  const auto lines = readLines(p);
  MotFile m;
  std::size_t i = 0;
  for (; i < lines.size() && lines[i] != "endheader"; ++i) {
    const auto eq = lines[i].find('=');
    if (i == 0 && eq == std::string::npos)
      m.name = lines[i];
    else if (eq != std::string::npos)
      m.header[lines[i].substr(0, eq)] = lines[i].substr(eq + 1);
  }
  if (i == lines.size()) throw std::runtime_error("no endheader");
  ++i;
  if (i == lines.size()) throw std::runtime_error("no label line");
  m.labels = split(lines[i++], '\t');
  const std::size_t nRows = std::stoul(m.header.at("nRows"));
  const std::size_t nColumns = std::stoul(m.header.at("nColumns"));
  if (m.labels.size() != nColumns) throw std::runtime_error("labels do not match nColumns");
  for (; i < lines.size(); ++i) {
    const auto f = split(lines[i], '\t');
    if (f.size() != nColumns)
      throw std::runtime_error("row " + std::to_string(m.rows.size() + 1) + " has " +
                               std::to_string(f.size()) + " columns");
    std::vector<double> row;
    for (const auto& s : f) {
      std::size_t used = 0;
      row.push_back(std::stod(s, &used));
      if (used != s.size()) throw std::runtime_error("not a number: " + s);
    }
    m.rows.push_back(row);
  }
  if (m.rows.size() != nRows) throw std::runtime_error("rows do not match nRows");
  return m;
}

// ------------------------------------------------------------------ clinical CSV

TEST(ClinicalCsv, AnglesAreTheTrueAnglesInDegreesWithTheirSd) {
  const SinusoidTrajectory tr = knownMovement();
  const Recording rec = simulatedSession(tr, 10.0, 100.0);
  const AngleSeries series = truthSeries(rec);
  ASSERT_EQ(series.t.size(), 1001u);
  std::vector<ClinicalRow> sd(series.t.size());
  for (std::size_t i = 0; i < sd.size(); ++i)
    for (int a = 0; a < 5; ++a) sd[i][a] = (0.5 + 0.1 * a) * kDegToRad;
  const SessionMetrics metrics = computeSessionMetrics(series);

  TempDir dir;
  const CsvExportResult r = writeClinicalCsv(dir / "session.csv", series, metrics, &sd);
  EXPECT_EQ(r.rows, series.t.size());
  EXPECT_EQ(r.skippedRows, 0u);
  EXPECT_EQ(r.emptyCells, 0u);
  EXPECT_EQ(r.metricsCsv, dir / "session_metrics.csv");
  EXPECT_EQ(listing(dir.path()), (std::vector<std::string>{"session.csv", "session_metrics.csv"}));

  const auto lines = readLines(r.anglesCsv);
  ASSERT_EQ(lines.size(), series.t.size() + 1);
  EXPECT_EQ(lines[0],
            "time_s,shoulder_flexion_deg,shoulder_abduction_deg,shoulder_internal_rotation_deg,"
            "elbow_flexion_deg,forearm_pronation_deg,shoulder_flexion_sd_deg,"
            "shoulder_abduction_sd_deg,shoulder_internal_rotation_sd_deg,elbow_flexion_sd_deg,"
            "forearm_pronation_sd_deg");
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto f = split(lines[i], ',');
    ASSERT_EQ(f.size(), 11u) << "line " << i + 1;
    const double t = std::stod(f[0]);
    EXPECT_NEAR(t, (i - 1) / 100.0, 1e-9);
    const auto truth = trueClinicalDeg(tr, t);
    for (int a = 0; a < 5; ++a) {
      EXPECT_NEAR(std::stod(f[1 + a]), truth[a], 2e-6) << "line " << i + 1 << " angle " << a;
      EXPECT_NEAR(std::stod(f[6 + a]), 0.5 + 0.1 * a, 1e-6);
    }
  }
}

TEST(ClinicalCsv, MetricsTableHoldsTheTrueRangeAndEveryRepetition) {
  const SinusoidTrajectory tr = knownMovement();
  const AngleSeries series = truthSeries(simulatedSession(tr, 12.0, 100.0));
  const SessionMetrics metrics = computeSessionMetrics(series);
  ASSERT_GE(metrics.repetitions.repetitions.size(), 4u);

  TempDir dir;
  const CsvExportResult r = writeClinicalCsv(dir / "s.csv", series, metrics);
  const auto lines = readLines(r.metricsCsv);
  EXPECT_EQ(lines[0],
            "scope,repetition,start_s,end_s,partial,angle,min_deg,max_deg,rom_deg,"
            "peak_velocity_deg_s,mean_velocity_deg_s,movement_time_s");
  ASSERT_EQ(lines.size(), 1 + 5 * (1 + metrics.repetitions.repetitions.size()));
  // Whole session: the true range of each angle is twice its amplitude (every angle passes
  // through both extremes within 12 s); the smoothed metrics must find it within 1 deg.
  const auto& info = clinicalAngleInfo();
  const double amplitudeDeg[5] = {0.5 * kRadToDeg, 0.3 * kRadToDeg, 0.35 * kRadToDeg,
                                  0.6 * kRadToDeg, 0.5 * kRadToDeg};
  for (int a = 0; a < 5; ++a) {
    const auto f = split(lines[1 + a], ',');
    ASSERT_EQ(f.size(), 12u);
    EXPECT_EQ(f[0], "session");
    EXPECT_EQ(f[1], "");
    EXPECT_EQ(f[5], info[a].key);
    EXPECT_NEAR(std::stod(f[2]), 0.0, 1e-9);
    EXPECT_NEAR(std::stod(f[3]), 12.0, 1e-9);
    EXPECT_NEAR(std::stod(f[8]), 2 * amplitudeDeg[a], 1.0) << info[a].key;
    EXPECT_NEAR(std::stod(f[8]), std::stod(f[7]) - std::stod(f[6]), 1e-3);
  }
  // Repetitions, in order, each with the five angles and the values computeSessionMetrics gave.
  const auto& reps = metrics.repetitions.repetitions;
  for (std::size_t k = 0; k < reps.size(); ++k)
    for (int a = 0; a < 5; ++a) {
      const auto f = split(lines[1 + 5 * (k + 1) + a], ',');
      EXPECT_EQ(f[0], "repetition");
      EXPECT_EQ(f[1], std::to_string(k + 1));
      EXPECT_EQ(f[4], reps[k].partial ? "yes" : "no");
      EXPECT_NEAR(std::stod(f[2]), reps[k].startS, 1e-6);
      EXPECT_NEAR(std::stod(f[8]), reps[k].metrics.angle[a].romRad * kRadToDeg, 1e-4);
    }
}

TEST(ClinicalCsv, NonFiniteTimesAreSkippedAndNonFiniteAnglesLeftEmpty) {
  AngleSeries s;
  s.t = {0.0, kNaN, 0.02, 0.03};
  s.angle = {ClinicalRow{0.1, 0.2, 0.3, 0.4, 0.5}, ClinicalRow{0.1, 0.2, 0.3, 0.4, 0.5},
             ClinicalRow{kNaN, 0.2, INFINITY, 0.4, 0.5}, ClinicalRow{0.1, 0.2, 0.3, 0.4, 0.5}};
  const SessionMetrics metrics;  // the angles file is what this test reads
  TempDir dir;
  const CsvExportResult r = writeClinicalCsv(dir / "a.csv", s, metrics);
  EXPECT_EQ(r.rows, 3u);
  EXPECT_EQ(r.skippedRows, 1u);
  EXPECT_EQ(r.emptyCells, 2u);
  const auto lines = readLines(dir / "a.csv");
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[2], "0.020000,,11.459156,,22.918312,28.647890");
  // No "-0.000000" for a negative value that rounds to zero.
  AngleSeries tiny{{0.0, 0.01}, {ClinicalRow{-1e-12, -0.0, 0, 0, 0}, ClinicalRow{}}};
  writeClinicalCsv(dir / "z.csv", tiny, metrics);
  EXPECT_EQ(readLines(dir / "z.csv")[1], "0.000000,0.000000,0.000000,0.000000,0.000000,0.000000");
}

TEST(ClinicalCsv, EmptySeriesIsRefusedAndWritesNothing) {
  TempDir dir;
  const SessionMetrics metrics;
  EXPECT_THROW(writeClinicalCsv(dir / "e.csv", AngleSeries{}, metrics), ExportError);
  AngleSeries allNaN{{kNaN, kNaN}, {ClinicalRow{}, ClinicalRow{}}};
  EXPECT_THROW(writeClinicalCsv(dir / "e.csv", allNaN, metrics), ExportError);
  EXPECT_TRUE(listing(dir.path()).empty());
  AngleSeries mismatched{{0.0, 1.0}, {ClinicalRow{}}};
  EXPECT_THROW(writeClinicalCsv(dir / "e.csv", mismatched, metrics), std::invalid_argument);
  std::vector<ClinicalRow> shortSd(1);
  AngleSeries two{{0.0, 1.0}, {ClinicalRow{}, ClinicalRow{}}};
  EXPECT_THROW(writeClinicalCsv(dir / "e.csv", two, metrics, &shortSd), std::invalid_argument);
  EXPECT_TRUE(listing(dir.path()).empty());
}

TEST(ClinicalCsv, AFolderThatCannotBeWrittenGivesAClearErrorAndLeavesNothing) {
  const AngleSeries series = truthSeries(simulatedSession(knownMovement(), 2.0, 50.0));
  const SessionMetrics metrics = computeSessionMetrics(series);
  TempDir dir;
  // A regular file where a folder should be: refused even for root, unlike permission bits.
  { std::ofstream(dir / "notadir") << "x"; }
  const fs::path target = dir / "notadir" / "out.csv";
  try {
    writeClinicalCsv(target, series, metrics);
    FAIL() << "no error";
  } catch (const ExportError& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
    EXPECT_EQ(e.path(), target);
  }
  // The second file cannot be created (a folder has its name): the first, an existing export,
  // keeps its old contents and no temporary file is left.
  { std::ofstream(dir / "old.csv") << "previous export\n"; }
  fs::create_directory(dir / "old_metrics.csv");
  EXPECT_THROW(writeClinicalCsv(dir / "old.csv", series, metrics), ExportError);
  EXPECT_EQ(readText(dir / "old.csv"), "previous export\n");
  EXPECT_EQ(listing(dir.path()),
            (std::vector<std::string>{"notadir", "old.csv", "old_metrics.csv"}));
}

// ------------------------------------------------------------------ OpenSim .mot

TEST(OpenSimMot, ReadBackWithOpenSimRulesGivesTheTrueAnglesInOpenSimSigns) {
  const SinusoidTrajectory tr = knownMovement();
  const AngleSeries series = truthSeries(simulatedSession(tr, 10.0, 100.0));
  TempDir dir;
  const MotExportResult r = writeOpenSimMot(dir / "s.mot", series, Side::Right);
  EXPECT_EQ(r.rows, series.t.size());
  EXPECT_EQ(r.skippedRows, 0u);

  // The header lines exactly as OpenSim writes a storage file.
  const auto lines = readLines(dir / "s.mot");
  ASSERT_GE(lines.size(), 7u);
  EXPECT_EQ(lines[0], "armtrack_clinical_angles");
  EXPECT_EQ(lines[1], "version=1");
  EXPECT_EQ(lines[2], "nRows=1001");
  EXPECT_EQ(lines[3], "nColumns=6");
  EXPECT_EQ(lines[4], "inDegrees=yes");
  EXPECT_EQ(lines[5], "endheader");

  const MotFile m = readMot(dir / "s.mot");
  EXPECT_EQ(m.header.at("inDegrees"), "yes");
  EXPECT_EQ(m.labels, (std::vector<std::string>{"time", "arm_flex_r", "arm_add_r", "arm_rot_r",
                                                "elbow_flex_r", "pro_sup_r"}));
  ASSERT_EQ(m.rows.size(), series.t.size());
  for (std::size_t i = 0; i < m.rows.size(); ++i) {
    const auto& row = m.rows[i];
    const auto c = trueClinicalDeg(tr, row[0]);
    EXPECT_NEAR(row[0], series.t[i], 1e-6);
    // Printed with 6 decimals: within 5e-7 deg of the true value, plus the time's rounding.
    EXPECT_NEAR(row[1], c[0], 2e-6);   // arm_flex = flexion
    EXPECT_NEAR(row[2], -c[1], 2e-6);  // arm_add = adduction = -abduction
    EXPECT_NEAR(row[3], c[2], 2e-6);   // arm_rot = internal rotation
    EXPECT_NEAR(row[4], c[3], 2e-6);   // elbow_flex = elbow flexion
    EXPECT_NEAR(row[5], c[4], 2e-6);   // pro_sup = pronation
  }
}

TEST(OpenSimMot, PosesOfPlainMeaningGetOpenSimsSigns) {
  // Each pose moves one joint the named way in ArmTrack's DH angles (docs/arm-model.md); OpenSim's
  // Rajagopal arm turns about +z (flexion), +x forward (adduction) and +y up the humerus
  // (internal rotation), so the expected signs follow from the model's axes.
  struct Pose {
    int joint;
    double thDeg;
    int coordinate;
    double expectedDeg;
  };
  const Pose poses[] = {
      {0, 30, 0, 30},   // arm swung forward 30 deg: arm_flex +30
      {1, 40, 1, -40},  // arm lifted sideways 40 deg (abduction): arm_add -40
      {2, -25, 2, 25},  // -th2: forearm turned toward the trunk (internal): arm_rot +25
      {3, -90, 3, 90},  // -th4: elbow bent 90 deg: elbow_flex +90
      {4, -60, 4, 60},  // -th5: thumb turned inward (pronation): pro_sup +60
  };
  for (const Pose& p : poses) {
    JointVector th = JointVector::Zero();
    th(p.joint) = p.thDeg * kDegToRad;
    const AngleSeries s = angleSeriesFromJoints({0.0}, {th});
    const ClinicalRow os = openSimCoordinatesDeg(s.angle[0]);
    for (int k = 0; k < 5; ++k)
      EXPECT_NEAR(os[k], k == p.coordinate ? p.expectedDeg : 0.0, 1e-9)
          << "joint " << p.joint << " coordinate " << k;
  }
}

TEST(OpenSimMot, LeftArmUsesLeftCoordinateNames) {
  const AngleSeries series = truthSeries(simulatedSession(knownMovement(), 1.0, 50.0, Side::Left));
  TempDir dir;
  MotOptions o;
  o.name = "left_session";
  o.proSupOffsetDeg = 90;  // a model whose pro_sup is 0 in full supination
  writeOpenSimMot(dir / "l.mot", series, Side::Left, o);
  const MotFile m = readMot(dir / "l.mot");
  EXPECT_EQ(m.name, "left_session");
  EXPECT_EQ(m.labels, (std::vector<std::string>{"time", "arm_flex_l", "arm_add_l", "arm_rot_l",
                                                "elbow_flex_l", "pro_sup_l"}));
  ASSERT_EQ(m.rows.size(), series.t.size());
  for (std::size_t i = 0; i < m.rows.size(); ++i)
    EXPECT_NEAR(m.rows[i][5], series.angle[i][4] * kRadToDeg + 90, 2e-6);
}

TEST(OpenSimMot, NonFiniteRowsAreLeftOutAndCounted) {
  AngleSeries s;
  s.t = {0.0, 0.01, kNaN, 0.03, 0.04};
  for (int i = 0; i < 5; ++i) s.angle.push_back(ClinicalRow{0.1, 0.2, 0.3, 0.4, 0.5});
  s.angle[1][3] = kNaN;
  TempDir dir;
  const MotExportResult r = writeOpenSimMot(dir / "n.mot", s, Side::Right);
  EXPECT_EQ(r.rows, 3u);
  EXPECT_EQ(r.skippedRows, 2u);
  const MotFile m = readMot(dir / "n.mot");
  ASSERT_EQ(m.rows.size(), 3u);
  EXPECT_DOUBLE_EQ(m.rows[1][0], 0.03);
}

// The torso's rotation on the pelvis as the Rajagopal model's back joint builds it from the
// lumbar coordinates (deg): about its axes 0 0 1, then the moved 1 0 0, then the moved 0 1 0, in
// the pelvis frame (x forward, y up, z to the right), written in frame 0's axes (x0 down, y0
// forward, z0 to the patient's right): independent of the export's mapping.
Eigen::Matrix3d torsoFromLumbar(double extDeg, double bendDeg, double rotDeg) {
  const Eigen::Matrix3d osim = (Eigen::AngleAxisd(extDeg * kDegToRad, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(bendDeg * kDegToRad, Eigen::Vector3d::UnitX()) *
                                Eigen::AngleAxisd(rotDeg * kDegToRad, Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  Eigen::Matrix3d toFrame0;  // rows: x0 = -y, y0 = x, z0 = z
  toFrame0 << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return toFrame0 * osim * toFrame0.transpose();
}

TEST(OpenSimMot, TrunkAnglesBecomeTheLumbarCoordinatesThatTurnTheTorsoTheSameWay) {
  // Plain poses: leaning forward is lumbar flexion (negative extension), leaning to the right and
  // bringing the right shoulder forward are positive bending and rotation.
  EXPECT_TRUE(openSimLumbarDeg(Eigen::Vector3d(15, 0, 0) * kDegToRad)
                  .isApprox(Eigen::Vector3d(-15, 0, 0), 1e-12));
  // Any pose: the torso the model builds from the written coordinates is the trunk's rotation.
  const double poses[][3] = {{20, 0, 0}, {0, 10, 0}, {0, 0, 10}, {18, -7, 9}, {-5, 8, -12}};
  for (const auto& a : poses) {
    const Eigen::Vector3d trunk = Eigen::Vector3d(a[0], a[1], a[2]) * kDegToRad;
    const Eigen::Vector3d l = openSimLumbarDeg(trunk);
    EXPECT_TRUE(torsoFromLumbar(l(0), l(1), l(2)).isApprox(trunkRotation(trunk), 1e-12))
        << a[0] << " " << a[1] << " " << a[2];
  }
  // A forward lean seen in the model's own terms: the torso's up axis (-x0) tips forward (+y0).
  const Eigen::Vector3d up = torsoFromLumbar(-20, 0, 0) * -Eigen::Vector3d::UnitX();
  EXPECT_GT(up.y(), 0.3);
}

TEST(OpenSimMot, TheTrunkIsWrittenAsLumbarCoordinatesAndRowsWithoutItAreCounted) {
  const SinusoidTrajectory tr = knownMovement();
  const AngleSeries series = truthSeries(simulatedSession(tr, 1.0, 50.0));
  TrunkColumns trunk;
  for (std::size_t i = 0; i < series.t.size(); ++i)
    trunk.angleRad.push_back(Eigen::Vector3d(0.3, -0.1, 0.05) * std::sin(series.t[i]));
  trunk.angleRad[0] = Eigen::Vector3d::Constant(kNaN);  // before the sternum IMU's first sample
  TempDir dir;
  const MotExportResult r = writeOpenSimMot(dir / "t.mot", series, Side::Left, {}, &trunk);
  EXPECT_TRUE(r.trunk);
  EXPECT_EQ(r.skippedRows, 1u);
  EXPECT_EQ(r.skippedTrunkRows, 1u);
  const MotFile m = readMot(dir / "t.mot");
  EXPECT_EQ(m.labels, (std::vector<std::string>{"time", "arm_flex_l", "arm_add_l", "arm_rot_l",
                                                "elbow_flex_l", "pro_sup_l", "lumbar_extension",
                                                "lumbar_bending", "lumbar_rotation"}));
  ASSERT_EQ(m.rows.size(), series.t.size() - 1);
  for (std::size_t k = 0; k < m.rows.size(); ++k) {
    const Eigen::Vector3d want = openSimLumbarDeg(trunk.angleRad[k + 1]);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(m.rows[k][6 + j], want(j), 1e-6);
  }
  // A trunk never measured (every row NaN) leaves the file the arm's alone; so does none.
  for (auto& a : trunk.angleRad) a = Eigen::Vector3d::Constant(kNaN);
  const MotExportResult none = writeOpenSimMot(dir / "n.mot", series, Side::Left, {}, &trunk);
  EXPECT_FALSE(none.trunk);
  EXPECT_EQ(none.skippedRows, 0u);
  EXPECT_EQ(readMot(dir / "n.mot").labels.size(), 6u);
  // A trunk of the wrong length is refused, naming both counts.
  trunk.angleRad.pop_back();
  try {
    writeOpenSimMot(dir / "w.mot", series, Side::Left, {}, &trunk);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(series.t.size() - 1) + " trunk rows"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "w.mot"));
}

TEST(OpenSimMot, HostileInputIsRefusedWithoutWritingAnything) {
  TempDir dir;
  const fs::path p = dir / "h.mot";
  EXPECT_THROW(writeOpenSimMot(p, AngleSeries{}, Side::Right), ExportError);
  AngleSeries back{{0.0, 0.02, 0.01}, {ClinicalRow{}, ClinicalRow{}, ClinicalRow{}}};
  try {
    writeOpenSimMot(p, back, Side::Right);
    FAIL() << "no error";
  } catch (const ExportError& e) {
    EXPECT_NE(std::string(e.what()).find("row 3"), std::string::npos) << e.what();
  }
  AngleSeries mismatched{{0.0}, {}};
  EXPECT_THROW(writeOpenSimMot(p, mismatched, Side::Right), std::invalid_argument);
  AngleSeries one{{0.0}, {ClinicalRow{}}};
  EXPECT_THROW(writeOpenSimMot(p, one, Side::Right, {"two\nlines"}), std::invalid_argument);
  EXPECT_THROW(writeOpenSimMot(p, one, Side::Right, {"n", kNaN}), std::invalid_argument);
  EXPECT_TRUE(listing(dir.path()).empty());
  const fs::path missing = dir / "no" / "such" / "folder" / "x.mot";
  try {
    writeOpenSimMot(missing, one, Side::Right);
    FAIL() << "no error";
  } catch (const ExportError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(listing(dir.path()).empty());
}

}  // namespace
}  // namespace armtrack
