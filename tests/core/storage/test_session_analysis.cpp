// Session analysis in the records: a simulated repetitive exercise (minimum-jerk shoulder flexion
// with known angles, simulated IMUs and Kinect) imported, estimated and measured from the
// database and checked against the true angles; versions and history; estimates read back bit
// for bit as estimating the CSV gives them; damaged blobs; settings; access; cancelling.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <iostream>

#include <QJsonArray>
#include <QJsonDocument>
#include <QSqlQuery>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <thread>

#include "core/estimation/RecordingEstimator.h"
#include "core/kinematics/ClinicalAngles.h"
#include "core/storage/EstimateCodec.h"
#include "core/storage/SessionAnalysis.h"
#include "tests/core/storage/StorageTestSupport.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;

namespace {

/// Seated shoulder flexion (forearm resting forward at 30 deg flexion, elbow at 45 deg) up to a
/// peak and back, the other angles following in proportion, with holds and pauses; peaks in
/// degrees of flexion. The first repetition starts after 4 s at rest, as a session starts with the
/// patient positioned: the filter's heading settles from the optical data in the first seconds.
class Exercise final : public Trajectory {
 public:
  ClinicalAngles rest{30, 5, 0, 45, 0};
  ClinicalAngles top{120, 15, 10, 65, 10};
  std::vector<double> peakDeg;

  static constexpr double kRestS = 4.0;
  /// The same movement between other rest and top postures.
  Exercise(std::vector<double> peaks, ClinicalAngles restPose, ClinicalAngles topPose)
      : rest(restPose), top(topPose), peakDeg(std::move(peaks)) {
    build();
  }
  explicit Exercise(std::vector<double> peaks) : peakDeg(std::move(peaks)) { build(); }
  void build() {
    double t = kRestS;
    m_path.add(0.0, fromClinical(rest));
    m_path.add(t, fromClinical(rest));
    const double rises[] = {1.2, 1.5, 1.0, 1.4, 1.3};
    const double holds[] = {0.4, 0.8, 0.3, 0.6, 0.5};
    const double pauses[] = {0.8, 1.5, 1.0, 0.6, 1.2};
    for (std::size_t r = 0; r < peakDeg.size(); ++r) {
      const double f =
          (peakDeg[r] - rest.shoulderFlexion) / (top.shoulderFlexion - rest.shoulderFlexion);
      const auto a = asArray(rest), b = asArray(top);
      ClinicalAngles c{a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]),
                       a[3] + f * (b[3] - a[3]), a[4] + f * (b[4] - a[4])};
      const double rise = rises[r % 5];
      m_path.add(t + rise, fromClinical(c));
      m_path.hold(holds[r % 5]);
      m_path.add(m_path.endTime() + rise, fromClinical(rest));
      m_path.hold(pauses[r % 5]);
      t = m_path.endTime();
    }
    m_path.hold(1.5);
  }
  JointMotion at(double t) const override { return m_path.at(t); }
  double duration() const { return m_path.endTime(); }

 private:
  MinimumJerkPath m_path;
};

/// The exercise simulated (two IMUs at 1 kHz with Table 5 noise, Kinect at 30 Hz with 1 cm
/// noise, true angles) and written to csv; returns what a reader of the CSV sees.
Recording simulateExercise(const std::filesystem::path& csv, const Exercise& e) {
  SimulationParams sim;
  sim.duration = e.duration();
  sim.upperArm.gyroNoiseStd = sim.forearm.gyroNoiseStd = Table5::gyroStd();
  sim.upperArm.accelNoiseStd = sim.forearm.accelNoiseStd = Table5::accelStd();
  sim.seed = 5;
  writeRecording(csv, simulateRecording(e, sim));
  return readRecording(csv);
}

/// The true clinical angles (deg) of the recording's IMU rows: their range per angle.
std::array<double, 5> trueRomDeg(const Recording& rec) {
  std::array<double, 5> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (const ArmSample& s : rec.samples) {
    if (!s.trueAngles) continue;
    const auto c = asArray(toClinical(*s.trueAngles));
    for (int a = 0; a < 5; ++a) {
      lo[a] = std::min(lo[a], c[a]);
      hi[a] = std::max(hi[a], c[a]);
    }
  }
  std::array<double, 5> rom;
  for (int a = 0; a < 5; ++a) rom[a] = hi[a] - lo[a];
  return rom;
}

/// Estimates of the CSV itself, as `estimate` makes them.
EstimateColumns estimateDirectly(const Recording& rec, const EstimateOptions& options) {
  EstimateColumns c;
  EstimateCallbacks cb;
  cb.row = [&](const EstimateRow& r) { c.append(r); };
  estimateRecording(rec, estimatorParamsFor(rec.meta, options), cb);
  return c;
}

void expectSameEstimates(const StoredAnalysis& a, const EstimateColumns& c) {
  ASSERT_EQ(a.t.size(), c.t.size());
  ASSERT_GT(c.t.size(), 0u);
  for (std::size_t i = 0; i < c.t.size(); ++i) {
    bool same = sameBits(a.t[i], c.t[i]) && a.status[i] == c.status[i];
    for (int j = 0; j < kNumJoints; ++j)
      same = same && sameBits(a.joints[i](j), c.th[i](j)) && sameBits(a.sd[i](j), c.sd[i](j));
    ASSERT_TRUE(same) << "row " << i << " differs";
  }
}

// One exercise shared by the tests that need its truth: 4 full repetitions and a partial one.
const std::vector<double> kPeaks{120, 120, 70, 120, 120};

}  // namespace

TEST(SessionAnalysis, ExerciseFromTheDatabaseMatchesTheTruth) {
  Fixture f;
  f.store->addPatient(makePatient("P1"));
  f.store->addProtocol(makeProtocol("flexion", "shoulder_flexion", 30, 120, 5));
  const Exercise exercise(kPeaks);
  const Recording rec = simulateExercise(f.file("ex.csv"), exercise);
  const qint64 id = f.store->importRecording(f.file("ex.csv"), "P1", "flexion");
  EXPECT_FALSE(latestAnalysis(*f.store, id).has_value());

  std::vector<int> seen;
  AnalysisOptions options;
  options.progress = [&](int p) { seen.push_back(p); };
  const AnalysisResult r = analyseSession(*f.store, id, options);
  EXPECT_FALSE(r.cancelled);
  EXPECT_EQ(r.estimateVersion, 1);
  EXPECT_EQ(r.settingsSource, "defaults");
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front(), 0);
  EXPECT_EQ(seen.back(), 100);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));

  const std::optional<StoredAnalysis> a = latestAnalysis(*f.store, id);
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->version, 1);
  ASSERT_TRUE(a->metrics.has_value());
  const QJsonObject m = *a->metrics;
  EXPECT_EQ(m, r.metricsJson);
  EXPECT_EQ(m["format"].toString(), kMetricsFormat);
  EXPECT_EQ(m["estimate_version"].toInt(), 1);
  const QJsonObject params = QJsonDocument::fromJson(a->paramsJson.toUtf8()).object();
  EXPECT_EQ(params["filter"].toString(), "ekf");
  EXPECT_EQ(params["method"].toString(),
            QString::fromStdString(methodName(MeasurementModel::AccelGyro)));
  EXPECT_TRUE(params["optical_used"].toBool());
  EXPECT_FALSE(params["library_version"].toString().isEmpty());

  // Repetitions on the protocol's angle: the true count; the 50-deg one is partial against the
  // protocol's 90-deg target span.
  const QJsonObject reps = m["repetitions"].toObject();
  EXPECT_EQ(reps["primary_angle"].toString(), "shoulder_flexion");
  EXPECT_EQ(reps["count"].toInt(), static_cast<int>(kPeaks.size()));
  EXPECT_EQ(reps["partial"].toInt(), 1);
  const QJsonArray list = reps["list"].toArray();
  ASSERT_EQ(list.size(), static_cast<qsizetype>(kPeaks.size()));
  for (qsizetype i = 0; i < list.size(); ++i) {
    const QJsonObject rep = list[i].toObject();
    EXPECT_EQ(rep["partial"].toBool(), kPeaks[i] < 110) << i;
    EXPECT_LT(rep["start_s"].toDouble(), rep["end_s"].toDouble());
    EXPECT_TRUE(rep["angles"].toObject().contains("elbow_flexion"));
    EXPECT_TRUE(rep.contains("sparc") && rep.contains("ldlj"));
  }
  EXPECT_TRUE(m["sparc"].isDouble()) << m["sparc_status"].toString().toStdString();
  EXPECT_LT(m["sparc"].toDouble(), 0.0);
  EXPECT_TRUE(m["ldlj"].isDouble());

  // Range of motion of every moving angle against the true angles' range: within 1 deg (the
  // issue's bar) for all five. Shoulder abduction and internal rotation carry what is left of the
  // heading error the filter corrects from the Kinect's 1 cm noise; with today's defaults their
  // ROM came out 0.06-0.58 deg off on simulation seeds 1, 2, 3, 5, 7 and 11 (0.8-1.7 deg before
  // the estimator's heading work), the other three within 0.2 deg.
  const std::array<double, 5> trueRom = trueRomDeg(rec);
  const QJsonObject angles = m["angles"].toObject();
  for (int k = 0; k < 5; ++k) {
    const QString key = QString::fromUtf8(clinicalAngleInfo()[k].key.data());
    const QJsonObject one = angles[key].toObject();
    for (const char* field : {"min_deg", "max_deg", "rom_deg", "peak_velocity_deg_s",
                              "mean_velocity_deg_s", "movement_time_s"})
      EXPECT_TRUE(one[field].isDouble()) << key.toStdString() << " " << field;
    if (trueRom[k] < 5.0) continue;
    const double rom = one["rom_deg"].toDouble();
    const double err = rom - trueRom[k];
    // The figure measured, for the log and the test report (XML: property <key>_rom_error_deg).
    char line[200];
    std::snprintf(line, sizeof line, "%s: ROM %.2f deg, true %.2f deg, error %+.2f deg",
                  key.toStdString().c_str(), rom, trueRom[k], err);
    std::cout << line << "\n";
    RecordProperty(key.toStdString() + "_rom_error_deg",
                   QString::number(err, 'f', 3).toStdString());
    EXPECT_LT(std::abs(err), 1.0) << line;
  }

  // The stored estimates are exactly those of estimating the CSV.
  const EstimateColumns direct = estimateDirectly(rec, {});
  expectSameEstimates(*a, direct);
  ASSERT_EQ(a->clinical.t.size(), a->t.size());
  EXPECT_DOUBLE_EQ(a->clinical.angle[10][0], toClinical(a->joints[10]).shoulderFlexion * kDegToRad);

  // Re-analysis without optical data is version 2; version 1 stays as it was.
  AnalysisOptions noOptical;
  noOptical.noOptical = true;
  EXPECT_EQ(analyseSession(*f.store, id, noOptical).estimateVersion, 2);
  EXPECT_EQ(f.store->estimateVersions(id), 2);
  const std::optional<StoredAnalysis> v2 = latestAnalysis(*f.store, id);
  ASSERT_TRUE(v2 && v2->metrics);
  EXPECT_EQ(v2->version, 2);
  EXPECT_EQ((*v2->metrics)["estimate_version"].toInt(), 2);
  EXPECT_FALSE(QJsonDocument::fromJson(v2->paramsJson.toUtf8())["optical"].toBool());
  const std::optional<StoredAnalysis> v1 = storedAnalysis(*f.store, id, 1);
  ASSERT_TRUE(v1.has_value());
  EXPECT_EQ(v1->version, 1);
  EXPECT_FALSE(v1->metrics.has_value());  // the newest metrics belong to version 2
  expectSameEstimates(*v1, direct);
  EXPECT_FALSE(storedAnalysis(*f.store, id, 3).has_value());
}

// Without a protocol the analysis counts where the live counter counted (repetitionAngle():
// shoulder flexion), even when another angle moves more: here the forearm turns 100 deg of
// pronation while the shoulder flexes 40 deg, and the review and report must not count the
// session on pronation after the live screen counted it on flexion.
TEST(SessionAnalysis, WithoutProtocolCountsOnTheLiveCountersAngle) {
  Fixture f;
  f.store->addPatient(makePatient("P1"));
  const Exercise exercise({70, 70, 70}, {30, 5, 0, 45, -40}, {70, 10, 5, 55, 60});
  simulateExercise(f.file("ex.csv"), exercise);
  const qint64 id = f.store->importRecording(f.file("ex.csv"), "P1");
  const AnalysisResult r = analyseSession(*f.store, id);
  const QJsonObject reps = r.metricsJson["repetitions"].toObject();
  EXPECT_EQ(reps["primary_angle"].toString(), "shoulder_flexion");
  EXPECT_EQ(r.metrics.repetitions.primaryAngle, repetitionAngle(std::nullopt));
  // The pronation did move most: the old rule would have chosen it.
  EXPECT_GT(r.metrics.session.angle[4].romRad, r.metrics.session.angle[0].romRad);
}

TEST(SessionAnalysis, WithoutProtocolCountsOnShoulderFlexion) {
  Fixture f;
  f.store->addPatient(makePatient("P1"));
  const Exercise exercise({120, 120, 120});
  simulateExercise(f.file("ex.csv"), exercise);
  const qint64 id = f.store->importRecording(f.file("ex.csv"), "P1");
  const AnalysisResult r = analyseSession(*f.store, id);
  const QJsonObject reps = r.metricsJson["repetitions"].toObject();
  EXPECT_EQ(reps["primary_angle"].toString(), "shoulder_flexion");
  EXPECT_EQ(reps["count"].toInt(), 3);
  EXPECT_EQ(reps["partial"].toInt(), 0);
  EXPECT_FALSE(reps.contains("protocol"));
}

TEST(EstimateCodec, RoundTripIsBitExactAndDamageIsRefused) {
  EstimateColumns c;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double values[] = {0.0,  -0.0,  1e-300, 3.141592653589793,
                           -2.5, 1e300, nan,    std::numeric_limits<double>::infinity()};
  for (int i = 0; i < 40; ++i) {
    EstimateRow r;
    r.t = 0.001 * i;
    for (int j = 0; j < kNumJoints; ++j) {
      r.th(j) = values[(i + j) % 8];
      r.sd(j) = values[(i * 3 + j) % 8];
    }
    r.status = i % 4;
    c.append(r);
  }
  const std::string blob = EstimateCodec::encode(c);
  const EstimateColumns d = EstimateCodec::decode(blob, 40);
  ASSERT_EQ(d.size(), 40u);
  for (std::size_t i = 0; i < 40; ++i) {
    EXPECT_TRUE(sameBits(d.t[i], c.t[i]));
    EXPECT_EQ(d.status[i], c.status[i]);
    for (int j = 0; j < kNumJoints; ++j) {
      EXPECT_TRUE(sameBits(d.th[i](j), c.th[i](j))) << i << " " << j;
      EXPECT_TRUE(sameBits(d.sd[i](j), c.sd[i](j))) << i << " " << j;
    }
  }
  EXPECT_EQ(EstimateCodec::decode(EstimateCodec::encode(EstimateColumns{}), 0).size(), 0u);

  const auto refused = [](const std::string& b, std::uint64_t rows, const std::string& says) {
    try {
      EstimateCodec::decode(b, rows);
      ADD_FAILURE() << "accepted: " << says;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  refused(blob, 41, "rows need");
  refused(blob.substr(0, blob.size() / 2), 40, "zstd");
  refused("not a blob at all", 40, "not a zstd frame");
  std::string flipped = blob;
  flipped[flipped.size() / 2] ^= 0x5a;
  refused(flipped, 40, "zstd");

  EstimateColumns bad = c;
  bad.status[3] = 7;
  EXPECT_THROW(EstimateCodec::encode(bad), std::invalid_argument);
  bad = c;
  bad.sd.pop_back();
  EXPECT_THROW(EstimateCodec::encode(bad), std::invalid_argument);
}

// The trunk's six columns (issue 26) come back bit for bit after the arm's; a blob without them
// decodes without trunk columns; a blob's trunk columns must match its rows.
TEST(EstimateCodec, TrunkColumnsRoundTripAndLeaveOtherBlobsAsTheyWere) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EstimateColumns withTrunk, armOnly;
  for (int i = 0; i < 30; ++i) {
    EstimateRow r;
    r.t = 0.005 * i;
    r.th.setConstant(0.1 * i);
    r.sd.setConstant(0.01);
    r.status = i % 5;
    r.trunk = Eigen::Vector3d(0.3 * std::sin(i), -0.1 * i, i % 7 == 0 ? nan : -0.0);
    r.trunkSd = Eigen::Vector3d(1e-300, 0.02, i % 7 == 0 ? nan : 0.004);
    withTrunk.append(r, true);
    armOnly.append(r);
  }
  const std::string blob = EstimateCodec::encode(withTrunk);
  const EstimateColumns d = EstimateCodec::decode(blob, 30);
  ASSERT_TRUE(d.hasTrunk());
  ASSERT_EQ(d.trunk.size(), 30u);
  for (std::size_t i = 0; i < 30; ++i) {
    EXPECT_EQ(d.status[i], withTrunk.status[i]);
    EXPECT_TRUE(sameBits(d.th[i](4), withTrunk.th[i](4)));
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(sameBits(d.trunk[i](k), withTrunk.trunk[i](k))) << i << " " << k;
      EXPECT_TRUE(sameBits(d.trunkSd[i](k), withTrunk.trunkSd[i](k))) << i << " " << k;
    }
  }
  const EstimateColumns arm = EstimateCodec::decode(EstimateCodec::encode(armOnly), 30);
  EXPECT_FALSE(arm.hasTrunk());
  EXPECT_TRUE(arm.trunkSd.empty());
  // Other row counts are refused, with or without the trunk.
  EXPECT_THROW(EstimateCodec::decode(blob, 29), std::runtime_error);
  EXPECT_THROW(EstimateCodec::decode(blob, 31), std::runtime_error);
  EstimateColumns bad = withTrunk;
  bad.trunk.pop_back();
  EXPECT_THROW(EstimateCodec::encode(bad), std::invalid_argument);
  bad = withTrunk;
  bad.trunkSd.clear();
  EXPECT_THROW(EstimateCodec::encode(bad), std::invalid_argument);
}

TEST(SessionAnalysis, DamagedEstimatesGiveAClearError) {
  Fixture f;
  f.store->addPatient(makePatient("P1"));
  simulateTo(f.file("a.csv"), 3.0);
  const qint64 id = f.store->importRecording(f.file("a.csv"), "P1");
  analyseSession(*f.store, id);
  ASSERT_TRUE(latestAnalysis(*f.store, id).has_value());
  const std::string where = "session " + std::to_string(id) + ", estimates version 1";

  // The estimates are stored as chunks: damage the one there is.
  const QString chunk =
      "UPDATE estimate_chunks SET data = ? WHERE estimate_id IN (SELECT id FROM "
      "estimates WHERE session_id = ?)";
  QSqlQuery q = f.db->exec(
      "SELECT c.data FROM estimate_chunks c JOIN estimates e ON e.id = c.estimate_id WHERE "
      "e.session_id = ?",
      {id});
  ASSERT_TRUE(q.next());
  QByteArray blob = q.value(0).toByteArray();
  ASSERT_FALSE(q.next());  // 3 s are one chunk
  q.finish();
  ASSERT_GT(blob.size(), 100);
  blob[blob.size() / 2] = static_cast<char>(blob[blob.size() / 2] ^ 0x21);
  f.db->exec(chunk, {blob, id});
  expectError([&] { latestAnalysis(*f.store, id); }, Kind::Corrupt, where + ": chunk 0");

  f.db->exec(chunk, {QByteArray("junk"), id});
  expectError([&] { latestAnalysis(*f.store, id); }, Kind::Corrupt, where);
  // A missing chunk, and rows that do not add up.
  f.db->exec(
      "UPDATE estimate_chunks SET seq = 1 WHERE estimate_id IN (SELECT id FROM estimates "
      "WHERE session_id = ?)",
      {id});
  expectError([&] { latestAnalysis(*f.store, id); }, Kind::Corrupt, "chunk 0 is missing");
  f.db->exec(
      "DELETE FROM estimate_chunks WHERE estimate_id IN (SELECT id FROM estimates WHERE "
      "session_id = ?)",
      {id});
  expectError([&] { latestAnalysis(*f.store, id); }, Kind::Corrupt, "chunks hold 0 rows");
  f.db->exec("UPDATE estimates SET params_json = '{}' WHERE session_id = ?", {id});
  expectError([&] { latestAnalysis(*f.store, id); }, Kind::Corrupt, "how many rows");
  f.db->exec("UPDATE estimates SET codec = 'est-f128-v9' WHERE session_id = ?", {id});
  expectError([&] { latestAnalysis(*f.store, id); }, Kind::Corrupt, "unknown codec");

  // A new analysis is readable again, and the damaged version is kept as it is.
  EXPECT_EQ(analyseSession(*f.store, id).estimateVersion, 2);
  EXPECT_TRUE(latestAnalysis(*f.store, id).has_value());
  expectError([&] { storedAnalysis(*f.store, id, 1); }, Kind::Corrupt);
}

TEST(SessionAnalysis, StoredFilterSettingsAreUsedAndCheckedAndOptionsOverrideThem) {
  Fixture f;
  f.store->addPatient(makePatient("P1"));
  const Recording rec = simulateTo(f.file("a.csv"), 2.0);
  const qint64 id = f.store->importRecording(f.file("a.csv"), "P1");
  f.db->exec("UPDATE sessions SET filter_json = ? WHERE id = ?",
             {R"({"filter":"ukf","optical":false})", id});
  const AnalysisResult r = analyseSession(*f.store, id);
  EXPECT_EQ(r.settingsSource, "session");
  EXPECT_EQ(r.settings.filter, FilterKind::Ukf);
  EXPECT_FALSE(r.stats.opticalUsed);
  EstimateOptions ukf;
  ukf.filter = FilterKind::Ukf;
  ukf.useOptical = false;
  expectSameEstimates(*latestAnalysis(*f.store, id), estimateDirectly(rec, ukf));

  AnalysisOptions ekf;
  ekf.filter = FilterKind::Ekf;
  const AnalysisResult r2 = analyseSession(*f.store, id, ekf);
  EXPECT_EQ(r2.settings.filter, FilterKind::Ekf);
  EXPECT_EQ(QJsonDocument::fromJson(latestAnalysis(*f.store, id)->paramsJson.toUtf8())["filter"]
                .toString(),
            "ekf");

  f.db->exec("UPDATE sessions SET filter_json = ? WHERE id = ?", {R"({"filter":"kalman"})", id});
  expectError([&] { analyseSession(*f.store, id); }, Kind::Usage, "\"filter\"");
  f.db->exec("UPDATE sessions SET filter_json = 'not json' WHERE id = ?", {id});
  expectError([&] { analyseSession(*f.store, id); }, Kind::Corrupt, "filter settings");
  EXPECT_EQ(f.store->estimateVersions(id), 2);
}

TEST(SessionAnalysis, MethodAndCalibrationOptionsGiveTheEstimatesOfTheCsvWithThem) {
  Fixture f;
  f.store->addPatient(makePatient("P1"));
  const Recording rec = simulateTo(f.file("a.csv"), 2.0);
  const qint64 id = f.store->importRecording(f.file("a.csv"), "P1");

  AnalysisOptions methodC;
  methodC.model = MeasurementModel::InclinometerGyro;
  const AnalysisResult r = analyseSession(*f.store, id, methodC);
  EXPECT_EQ(r.settings.model, MeasurementModel::InclinometerGyro);
  EstimateOptions c;
  c.model = MeasurementModel::InclinometerGyro;
  expectSameEstimates(*latestAnalysis(*f.store, id), estimateDirectly(rec, c));

  // A calibration: longer segments and a gyroscope bias; the same as calibrating the CSV.
  Calibration cal;
  cal.side = rec.meta.side;
  cal.geometry = rec.meta.geometry;
  cal.geometry.l3 += 0.03;
  cal.geometry.l6 -= 0.02;
  cal.upperArm.gyroBias = Eigen::Vector3d(0.01, -0.02, 0.005);
  AnalysisOptions calibrated;
  calibrated.calibration = cal;
  analyseSession(*f.store, id, calibrated);
  const auto stored = latestAnalysis(*f.store, id);
  EXPECT_TRUE(QJsonDocument::fromJson(stored->paramsJson.toUtf8())["calibration"].toBool());
  Recording corrected = rec;
  applyCalibration(cal, corrected);
  expectSameEstimates(*stored, estimateDirectly(corrected, {}));
  // ... and not those of the uncorrected recording.
  const EstimateColumns plain = estimateDirectly(rec, {});
  ASSERT_EQ(plain.th.size(), stored->joints.size());
  double largest = 0;
  for (std::size_t i = 0; i < plain.th.size(); ++i)
    largest = std::max(largest, (plain.th[i] - stored->joints[i]).cwiseAbs().maxCoeff());
  EXPECT_GT(largest, 1e-3);

  // A calibration of the other arm is refused in words; nothing is stored.
  cal.side = cal.side == Side::Left ? Side::Right : Side::Left;
  calibrated.calibration = cal;
  expectError([&] { analyseSession(*f.store, id, calibrated); }, Kind::Usage,
              "calibration does not fit");
  EXPECT_EQ(f.store->estimateVersions(id), 2);
}

TEST(SessionAnalysis, HomeAccountCannotAnalyseOrReadAnotherPatient) {
  Fixture f;
  f.store->addPatient(makePatient("MINE"));
  f.store->addPatient(makePatient("OTHER"));
  simulateTo(f.file("a.csv"), 1.5);
  const qint64 mine = f.store->importRecording(f.file("a.csv"), "MINE");
  const qint64 other = f.store->importRecording(f.file("a.csv"), "OTHER");
  analyseSession(*f.store, mine);
  analyseSession(*f.store, other);
  f.store->addUser("home", Role::Home, "h-pass-long", "MINE");
  ClinicalStore home(*f.db);
  home.signIn("home", "h-pass-long");
  expectError([&] { analyseSession(home, other); }, Kind::NotFound);
  expectError([&] { latestAnalysis(home, other); }, Kind::NotFound);
  expectError([&] { storedAnalysis(home, other, 1); }, Kind::NotFound);
  expectError([&] { analyseSession(home, mine); }, Kind::AccessDenied);
  EXPECT_EQ(f.store->estimateVersions(mine), 1);
  // Its own patient's analysis it may read.
  const auto own = latestAnalysis(home, mine);
  ASSERT_TRUE(own.has_value());
  EXPECT_TRUE(own->metrics.has_value());
}

TEST(SessionAnalysis, CancelStoresNothingAndNoImuIsAClearError) {
  Fixture f;
  f.store->addPatient(makePatient("P1"));
  simulateTo(f.file("a.csv"), 1.0);
  const qint64 id = f.store->importRecording(f.file("a.csv"), "P1");
  std::atomic<bool> cancel{true};
  AnalysisOptions options;
  options.cancel = &cancel;
  EXPECT_TRUE(analyseSession(*f.store, id, options).cancelled);
  EXPECT_EQ(f.store->estimateVersions(id), 0);
  EXPECT_FALSE(latestAnalysis(*f.store, id).has_value());

  // Cancelled half-way (from the progress callback, as a GUI's button would between two reports):
  // the run stops early and stores nothing.
  simulateTo(f.file("long.csv"), 4.0);
  const qint64 longer = f.store->importRecording(f.file("long.csv"), "P1");
  cancel = false;
  int last = -1;
  options.progress = [&](int p) {
    last = p;
    if (p >= 40) cancel = true;
  };
  const AnalysisResult r = analyseSession(*f.store, longer, options);
  EXPECT_TRUE(r.cancelled);
  EXPECT_LT(last, 100);
  EXPECT_GT(r.stats.estimates, 0u);
  EXPECT_LT(r.stats.estimates, 3000u);
  EXPECT_EQ(f.store->estimateVersions(longer), 0);

  // A recording of Kinect rows only: nothing to estimate from.
  Recording rec = simulateTo(f.file("b.csv"), 1.0);
  std::vector<ArmSample> optical;
  for (ArmSample s : rec.samples) {
    s.upperArm.reset();
    s.forearm.reset();
    s.trueAngles.reset();
    if (s.elbow || s.wrist) optical.push_back(s);
  }
  rec.samples = optical;
  ASSERT_FALSE(rec.samples.empty());
  writeRecording(f.file("c.csv"), rec);
  const qint64 none = f.store->importRecording(f.file("c.csv"), "P1");
  expectError([&] { analyseSession(*f.store, none); }, Kind::Usage, "IMU");
  EXPECT_EQ(f.store->estimateVersions(none), 0);
}

namespace {

/// Rows of a raw query's single number.
qint64 count(const Fixture& f, const QString& sql) {
  const auto rows = rawQuery(f.path, sql);
  return rows.empty() ? -1 : rows[0][0].toLongLong();
}

/// A process id that no process has: a child that has exited and been reaped.
qint64 deadPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

}  // namespace

// Estimates longer than one chunk (65,536 rows) go to the database a chunk at a time as the filter
// makes them, and read back bit for bit as estimating the CSV gives them. The metrics use the
// settled rows at most 100 a second, the stored estimates every row.
TEST_P(Engines, LongEstimatesAreStoredInChunksAndReadBackBitForBit) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const Recording rec = simulateTo(f.file("long.csv"), 70.0);
  const qint64 id = f.store->importRecording(f.file("long.csv"), "P1");
  const AnalysisResult r = analyseSession(*f.store, id);
  const std::optional<StoredAnalysis> a = latestAnalysis(*f.store, id);
  ASSERT_TRUE(a.has_value());
  expectSameEstimates(*a, estimateDirectly(rec, {}));
  EXPECT_EQ(count(f, QString("SELECT count(*) FROM estimate_chunks c JOIN estimates e ON e.id = "
                             "c.estimate_id WHERE e.session_id = %1")
                         .arg(id)),
            static_cast<qint64>((a->t.size() + 65535) / 65536));
  EXPECT_GE(a->t.size(), 65536u * 1);
  EXPECT_EQ(count(f, "SELECT count(*) FROM estimates WHERE complete = 0"), 0);
  // At most one row per 10 ms cell: about 100 a second over the settled 69 s.
  const qint64 used = r.metricsJson["samples"].toInteger();
  EXPECT_LE(used, 70 * 100 + 1);
  EXPECT_GE(used, 68 * 100);
  // What the reports and exports read gives the same metrics as the analysis stored.
  const SessionAngles forReport = sessionAngles(*f.store, id);
  const SessionAngles forExport = sessionAngles(*f.store, id, SeriesRows::All);
  EXPECT_EQ(static_cast<qint64>(forReport.series.t.size()), used);
  EXPECT_GT(forExport.series.t.size(), 60000u);
  EXPECT_EQ(forExport.sdRad.size(), forExport.series.t.size());
  for (const SessionAngles* s : {&forReport, &forExport}) {
    EXPECT_EQ(s->metrics.samples, static_cast<std::size_t>(used));
    for (int k = 0; k < kNumClinicalAngles; ++k)
      EXPECT_EQ(s->metrics.session.angle[k].romRad, r.metrics.session.angle[k].romRad);
    EXPECT_EQ(s->metrics.repetitions.repetitions.size(), r.metrics.repetitions.repetitions.size());
  }
}

// The analysis state: a complete session is pending until its estimates and metrics are stored,
// an interrupted one is analysed only when asked, one whose recording cannot be analysed is
// "failed" with the reason; a cancelled analysis leaves nothing behind, not even a draft.
TEST_P(Engines, AnalysisStateFollowsWhatWasStored) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  simulateTo(f.file("a.csv"), 4.0);
  const qint64 a = f.store->importRecording(f.file("a.csv"), "P1");
  const qint64 b = f.store->importRecording(f.file("a.csv"), "P1");
  const qint64 live = f.store->beginSession("P1", "", "{}", 3);
  EXPECT_EQ(f.store->session(a).analysis, kAnalysisPending);
  EXPECT_EQ(f.store->session(a).origin, kOriginImport);
  EXPECT_EQ(f.store->session(live).origin, kOriginLive);
  EXPECT_EQ(f.store->pendingAnalyses(), (std::vector<qint64>{a, b}));  // not the one recording
  f.store->finishSession(live, kStatusInterrupted);
  EXPECT_EQ(f.store->session(live).analysis, kAnalysisNone);

  std::atomic<bool> cancel{false};
  AnalysisOptions options;
  options.cancel = &cancel;
  options.progress = [&](int p) {
    if (p >= 40) cancel = true;
  };
  ASSERT_TRUE(analyseSession(*f.store, a, options).cancelled);
  EXPECT_EQ(count(f, "SELECT count(*) FROM estimates"), 0);
  EXPECT_EQ(count(f, "SELECT count(*) FROM estimate_chunks"), 0);
  EXPECT_EQ(f.store->session(a).analysis, kAnalysisPending);

  analyseSession(*f.store, a);
  EXPECT_EQ(f.store->session(a).analysis, kAnalysisDone);
  EXPECT_EQ(f.store->pendingAnalyses(), (std::vector<qint64>{b}));

  // Kinect rows only: nothing to estimate from, for good: "failed", with why, and not pending.
  Recording rec = simulateTo(f.file("b.csv"), 1.0);
  std::vector<ArmSample> optical;
  for (ArmSample s : rec.samples) {
    s.upperArm.reset();
    s.forearm.reset();
    if (s.elbow || s.wrist) optical.push_back(s);
  }
  rec.samples = optical;
  writeRecording(f.file("c.csv"), rec);
  const qint64 none = f.store->importRecording(f.file("c.csv"), "P1");
  expectError([&] { analyseSession(*f.store, none); }, Kind::Usage, "IMU");
  EXPECT_EQ(f.store->session(none).analysis, kAnalysisFailed);
  EXPECT_NE(f.store->session(none).analysisNote.indexOf("IMU"), -1);
  EXPECT_EQ(f.store->pendingAnalyses(), (std::vector<qint64>{b}));
  EXPECT_EQ(count(f, "SELECT count(*) FROM estimates WHERE complete = 0"), 0);
}

// An analysis whose process died left a draft of estimates and its claim on the session: opening
// the records again removes the draft, and the session is pending for the next analysis, which
// numbers its estimates as if the draft had never been.
TEST_P(Engines, ADeadAnalysisLeavesNoDraftAndItsSessionPending) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  simulateTo(f.file("a.csv"), 3.0);
  const qint64 id = f.store->importRecording(f.file("a.csv"), "P1");
  const ClinicalStore::EstimatesDraft draft = f.store->beginEstimates(id, "est-f64-zstd-v1-chunks");
  f.store->appendEstimateChunk(draft, 0, 1, QByteArray("not a blob"));
  const qint64 dead = deadPid();
  rawSql(f.path,
         {QString("UPDATE estimates SET writer_pid = %1 WHERE id = %2").arg(dead).arg(draft.id),
          QString("UPDATE sessions SET analysis_pid = %1 WHERE id = %2").arg(dead).arg(id)});
  f.close();
  f.db = std::make_unique<Database>(DatabaseUrl::parse(f.path), Database::Options{});
  f.store = std::make_unique<ClinicalStore>(*f.db);
  f.store->signIn("admin", kAdminPassword);
  EXPECT_EQ(count(f, "SELECT count(*) FROM estimates"), 0);
  EXPECT_EQ(count(f, "SELECT count(*) FROM estimate_chunks"), 0);
  EXPECT_EQ(
      count(
          f,
          QString("SELECT count(*) FROM sessions WHERE analysis_pid IS NULL AND id = %1").arg(id)),
      1);
  EXPECT_EQ(f.store->pendingAnalyses(), (std::vector<qint64>{id}));
  EXPECT_EQ(analyseSession(*f.store, id).estimateVersion, 1);
  EXPECT_EQ(f.store->session(id).analysis, kAnalysisDone);
}

// Two analyses of one session at the same time, on two connections (a re-estimate at one
// workstation while another takes up the pending analysis): both finish, as versions 1 and 2,
// each with its own metrics, and no draft is left.
TEST_P(Engines, TwoAnalysesOfOneSessionAtOnceBothFinish) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  simulateTo(f.file("a.csv"), 6.0);
  const qint64 id = f.store->importRecording(f.file("a.csv"), "P1");
  std::vector<int> versions(2, 0);
  std::vector<std::string> errors(2);
  std::atomic<int> ready{0};
  std::vector<std::thread> threads;
  for (int k = 0; k < 2; ++k)
    threads.emplace_back([&, k] {
      try {
        Database db(DatabaseUrl::parse(f.path), {});
        ClinicalStore store(db);
        store.signIn("admin", kAdminPassword);
        ++ready;
        while (ready.load() < 2) std::this_thread::yield();
        versions[static_cast<std::size_t>(k)] = analyseSession(store, id).estimateVersion;
      } catch (const std::exception& e) {
        errors[static_cast<std::size_t>(k)] = e.what();
      }
    });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(errors, (std::vector<std::string>{"", ""}));
  std::sort(versions.begin(), versions.end());
  EXPECT_EQ(versions, (std::vector<int>{1, 2}));
  EXPECT_EQ(f.store->estimateVersions(id), 2);
  EXPECT_EQ(count(f, "SELECT count(*) FROM estimates WHERE complete = 0"), 0);
  EXPECT_EQ(count(f, QString("SELECT count(*) FROM metrics WHERE session_id = %1").arg(id)), 2);
  const std::optional<StoredAnalysis> newest = latestAnalysis(*f.store, id);
  ASSERT_TRUE(newest && newest->metrics);
  EXPECT_EQ((*newest->metrics)["estimate_version"].toInt(), 2);
}

INSTANTIATE_TEST_SUITE_P(Records, Engines, ::testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
