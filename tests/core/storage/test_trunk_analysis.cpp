// Trunk compensation in a session's analysis (issue 26, acceptance 3's first half): a simulated
// patient reaches again and again and leans and turns the trunk with each reach (a sternum IMU
// and a Kinect that sees the shoulder); the session is imported and analysed in the records, and
// each repetition's largest trunk flexion, lateral bending and axial rotation and the shoulder's
// largest displacement are compared with the simulation's truth over the same repetition: the
// true_trunk_* columns, and the true shoulder s_W = h - R h (R the true trunk rotation, h the
// simulator's hip pivot), neither of which the analysis sees.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonObject>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>

#include "core/kinematics/ClinicalAngles.h"
#include "core/kinematics/Trunk.h"
#include "core/storage/SessionAnalysis.h"
#include "tests/core/storage/StorageTestSupport.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;

namespace {

constexpr double kToDeg = 180.0 / std::numbers::pi;

/// Seated reaching: shoulder flexion from rest up to each peak (deg) and back, the elbow opening
/// as the arm reaches, with holds and pauses. The first reach starts after 4 s at rest.
class Reaches final : public Trajectory {
 public:
  explicit Reaches(const std::vector<double>& peaksDeg) {
    const ClinicalAngles rest{10, 5, 0, 80, 0};
    m_path.add(0.0, fromClinical(rest));
    m_path.hold(4.0);
    const double rises[] = {1.4, 1.7, 1.2, 1.5};
    const double holds[] = {0.5, 0.8, 0.4, 0.6};
    const double pauses[] = {1.0, 1.4, 0.9, 1.2};
    for (std::size_t r = 0; r < peaksDeg.size(); ++r) {
      const double f = (peaksDeg[r] - rest.shoulderFlexion) / (110.0 - rest.shoulderFlexion);
      const ClinicalAngles top{peaksDeg[r], 5 + 10 * f, 5 * f, 80 - 60 * f, 10 * f};
      m_path.add(m_path.endTime() + rises[r % 4], fromClinical(top));
      m_path.hold(holds[r % 4]);
      m_path.add(m_path.endTime() + rises[r % 4], fromClinical(rest));
      m_path.hold(pauses[r % 4]);
    }
    m_path.hold(1.5);
  }
  JointMotion at(double t) const override { return m_path.at(t); }
  double duration() const { return m_path.endTime(); }

 private:
  MinimumJerkPath m_path;
};

struct SimSetup {
  bool trunkMoves = true;
  bool trunkImu = true;
  double leanDeg = 18.0;
  std::uint64_t seed = 1;
  Side side = Side::Right;
};

/// Two arm IMUs and the sternum IMU at 200 Hz (Table 5 noise), a 30 Hz Kinect with 1 cm noise
/// that reports the shoulder, the trunk leaning with each reach; written to csv, read back.
Recording simulateReaches(const std::filesystem::path& csv, const Reaches& reaches,
                          const SimSetup& s) {
  SimulationParams p = defaultSimulation();
  p.duration = reaches.duration();
  p.seed = s.seed;
  p.side = s.side;
  p.upperArm.rateHz = p.forearm.rateHz = 200.0;
  p.trunk.enabled = s.trunkMoves;
  p.trunk.leanDeg = s.leanDeg;
  p.trunk.lateralRatio = 0.5;
  p.trunk.rotationRatio = 0.5;
  p.trunk.swaySeed = s.seed + 100;
  p.trunkImu.enabled = s.trunkImu;
  p.trunkImu.rateHz = 200.0;
  p.kinect.shoulder = true;
  writeRecording(csv, simulateRecording(reaches, p));
  return readRecording(csv);
}

/// The truth over [from, to]: the largest |true trunk angle| (deg) of the rows inside, and the
/// largest distance (cm) of the true shoulder h - R h from its start (the trunk is upright at
/// t = 0, so the start is the origin). The recording's frame 0 has the same axes for both arms
/// (z0 to the patient's right), so R is the physical rotation trunkRotation(a) in it for either
/// side (trunkRotation(a, Side::Left) is that rotation in a left arm's mirror image, where the
/// estimator works), and h the side's hip pivot.
struct Truth {
  double flexionDeg = 0, lateralDeg = 0, rotationDeg = 0, displacementCm = 0;
};
Truth truthOver(const Recording& rec, double from, double to) {
  Truth out;
  const Eigen::Vector3d hip = defaultHip(rec.meta.side);
  for (const ArmSample& s : rec.samples) {
    if (!s.trueTrunk || s.t < from || s.t > to) continue;
    const Eigen::Vector3d& a = *s.trueTrunk;
    out.flexionDeg = std::max(out.flexionDeg, std::abs(a(0)) * kToDeg);
    out.lateralDeg = std::max(out.lateralDeg, std::abs(a(1)) * kToDeg);
    out.rotationDeg = std::max(out.rotationDeg, std::abs(a(2)) * kToDeg);
    const Eigen::Vector3d shoulder = hip - trunkRotation(a) * hip;
    out.displacementCm = std::max(out.displacementCm, 100.0 * shoulder.norm());
  }
  return out;
}

/// Imports the recording for patient P1 under the protocol "reach" and analyses it.
AnalysisResult importAndAnalyse(Fixture& f, const std::filesystem::path& csv,
                                std::optional<double> limitDeg, qint64* idOut = nullptr) {
  const qint64 id = f.store->importRecording(csv, "P1", "reach");
  if (idOut) *idOut = id;
  AnalysisOptions options;
  options.trunkFlexionLimitDeg = limitDeg;
  return analyseSession(*f.store, id, options);
}

Fixture& withPatient(Fixture& f) {
  f.store->addPatient(makePatient("P1"));
  f.store->addProtocol(makeProtocol("reach", "shoulder_flexion", 10, 110, 4));
  return f;
}

double num(const QJsonObject& o, const char* key) {
  EXPECT_TRUE(o.value(key).isDouble()) << key;
  return o.value(key).toDouble();
}

// Peaks chosen so that the lean of the low reach (about 8 deg, the simulator's lean grows with
// shoulder flexion from 20 to 90 deg) stays under the 12-deg limit and the others (18 deg) pass
// it by far more than the tolerance.
const std::vector<double> kPeaks{110, 110, 50, 105};
constexpr double kLimitDeg = 12.0;

}  // namespace

// Both sides (seed 811 a right arm leaning 18 deg, 812 a left one leaning 16 deg).
TEST(TrunkAnalysis, EveryRepetitionsTrunkMatchesTheSimulatedTruth) {
  for (const std::uint64_t seed : {811u, 812u}) {
    Fixture f;
    withPatient(f);
    const Reaches reaches(kPeaks);
    SimSetup setup;
    setup.seed = seed;
    setup.leanDeg = seed == 811u ? 18.0 : 16.0;
    setup.side = seed == 811u ? Side::Right : Side::Left;
    const Recording rec = simulateReaches(f.file("lean.csv"), reaches, setup);
    ASSERT_TRUE(rec.meta.trunk.has_value());
    qint64 id = 0;
    const AnalysisResult r = importAndAnalyse(f, f.file("lean.csv"), kLimitDeg, &id);

    // What is stored is what the analysis returned, and what a reader gets back.
    const std::optional<QJsonObject> stored = latestMetricsJson(*f.store, id);
    ASSERT_TRUE(stored.has_value());
    EXPECT_EQ(*stored, r.metricsJson);
    const QJsonObject reps = stored->value("repetitions").toObject();
    const QJsonArray list = reps.value("list").toArray();
    ASSERT_EQ(list.size(), static_cast<qsizetype>(kPeaks.size())) << "seed " << seed;

    std::size_t compensated = 0;
    for (qsizetype i = 0; i < list.size(); ++i) {
      const QJsonObject rep = list[i].toObject();
      const QJsonObject trunk = rep.value("trunk").toObject();
      const Truth truth =
          truthOver(rec, rep.value("start_s").toDouble(), rep.value("end_s").toDouble());
      const double flex = num(trunk, "max_flexion_deg");
      const double lat = num(trunk, "max_lateral_deg");
      const double rot = num(trunk, "max_rotation_deg");
      const double disp = num(trunk, "max_shoulder_displacement_cm");
      char line[300];
      std::snprintf(line, sizeof line,
                    "seed %d rep %d: flexion %.2f (true %.2f), lateral %.2f (%.2f), rotation "
                    "%.2f (%.2f) deg, shoulder %.2f (%.2f) cm",
                    int(seed), int(i), flex, truth.flexionDeg, lat, truth.lateralDeg, rot,
                    truth.rotationDeg, disp, truth.displacementCm);
      std::cout << line << "\n";
      EXPECT_NEAR(flex, truth.flexionDeg, 1.5) << line;
      EXPECT_NEAR(lat, truth.lateralDeg, 1.5) << line;
      EXPECT_NEAR(rot, truth.rotationDeg, 1.5) << line;
      EXPECT_NEAR(disp, truth.displacementCm, 1.5) << line;
      // The limit judges each repetition as its true lean does (none lies near the limit).
      ASSERT_GT(std::abs(truth.flexionDeg - kLimitDeg), 2.0) << line;
      const bool trulyCompensated = truth.flexionDeg > kLimitDeg;
      ASSERT_TRUE(trunk.value("compensated").isBool()) << line;
      EXPECT_EQ(trunk.value("compensated").toBool(), trulyCompensated) << line;
      compensated += trulyCompensated ? 1 : 0;
      // The same in the result's structure.
      ASSERT_LT(static_cast<std::size_t>(i), r.trunk.repetitions.size());
      EXPECT_DOUBLE_EQ(*r.trunk.repetitions[static_cast<std::size_t>(i)].maxFlexionDeg, flex);
    }
    EXPECT_EQ(compensated, 3u) << "seed " << seed;
    EXPECT_EQ(reps.value("repetitions_with_compensation").toInt(-1), static_cast<int>(compensated));

    // The session's values: the largest of the whole recording.
    const QJsonObject session = stored->value("trunk").toObject();
    const Truth all = truthOver(rec, -1e9, 1e9);
    EXPECT_NEAR(num(session, "max_flexion_deg"), all.flexionDeg, 1.5);
    EXPECT_NEAR(num(session, "max_lateral_deg"), all.lateralDeg, 1.5);
    EXPECT_NEAR(num(session, "max_rotation_deg"), all.rotationDeg, 1.5);
    EXPECT_NEAR(num(session, "max_shoulder_displacement_cm"), all.displacementCm, 1.5);
    EXPECT_EQ(num(session, "flexion_limit_deg"), kLimitDeg);

    // The reader of stored metrics gives the same values back.
    const std::optional<TrunkCompensation> back = trunkCompensationFromJson(*stored);
    ASSERT_TRUE(back.has_value());
    ASSERT_EQ(back->repetitions.size(), kPeaks.size());
    EXPECT_EQ(back->session.maxFlexionDeg, r.trunk.session.maxFlexionDeg);
    EXPECT_EQ(back->repetitions[2].compensated, std::optional<bool>(false));
    EXPECT_EQ(back->repetitionsWithCompensation, std::optional<std::size_t>(compensated));
  }
}

// A trunk that stays still (only the sternum IMU's and the Kinect's noise): every repetition's
// trunk values stay near zero. Without a limit, "compensated" and the count are null.
// Without a limit from the caller, the session's protocol's trunk limit (set by a therapist in
// the admin screen or `protocol edit --trunk-limit`) judges the repetitions; the caller's wins.
TEST(TrunkAnalysis, TheProtocolsTrunkLimitJudgesTheRepetitions) {
  Fixture f;
  f.store->addPatient(makePatient("P1"));
  Protocol limited = makeProtocol("reach", "shoulder_flexion", 10, 110, 4);
  limited.trunkLimitDeg = kLimitDeg;
  f.store->addProtocol(limited);
  const Reaches reaches(kPeaks);
  SimSetup setup;
  setup.seed = 811;
  setup.leanDeg = 18.0;
  const Recording rec = simulateReaches(f.file("lean.csv"), reaches, setup);
  qint64 id = 0;
  const AnalysisResult byProtocol = importAndAnalyse(f, f.file("lean.csv"), std::nullopt, &id);
  const QJsonObject reps = byProtocol.metricsJson.value("repetitions").toObject();
  EXPECT_EQ(reps.value("repetitions_with_compensation").toInt(-1), 3);
  EXPECT_EQ(num(byProtocol.metricsJson.value("trunk").toObject(), "flexion_limit_deg"), kLimitDeg);
  // A caller's limit above every lean: no repetition was made with compensation.
  AnalysisOptions high;
  high.trunkFlexionLimitDeg = 40.0;
  const AnalysisResult byCaller = analyseSession(*f.store, id, high);
  EXPECT_EQ(byCaller.metricsJson.value("repetitions")
                .toObject()
                .value("repetitions_with_compensation")
                .toInt(-1),
            0);
}

TEST(TrunkAnalysis, StillTrunkGivesNearZero) {
  Fixture f;
  withPatient(f);
  const Reaches reaches(kPeaks);
  SimSetup setup;
  setup.trunkMoves = false;
  setup.seed = 813;
  simulateReaches(f.file("still.csv"), reaches, setup);
  const AnalysisResult r = importAndAnalyse(f, f.file("still.csv"), std::nullopt);
  const QJsonObject reps = r.metricsJson.value("repetitions").toObject();
  const QJsonArray list = reps.value("list").toArray();
  ASSERT_EQ(list.size(), static_cast<qsizetype>(kPeaks.size()));
  for (const QJsonValue& v : list) {
    const QJsonObject trunk = v.toObject().value("trunk").toObject();
    for (const char* key : {"max_flexion_deg", "max_lateral_deg", "max_rotation_deg"})
      EXPECT_LT(num(trunk, key), 1.5) << key;
    EXPECT_LT(num(trunk, "max_shoulder_displacement_cm"), 1.5);
    EXPECT_TRUE(trunk.value("compensated").isNull());
  }
  EXPECT_TRUE(reps.value("repetitions_with_compensation").isNull());
  EXPECT_TRUE(r.metricsJson.value("trunk").toObject().value("flexion_limit_deg").isNull());
}

// Without a sternum IMU the trunk's angles cannot be measured (null), but the Kinect's shoulder
// still shows how far the trunk moved; the rows the estimator flags as "trunk moved unseen"
// (status 4) are not left out of it. Without a trunk sensor of any kind every value is null and
// a limit counts nothing.
TEST(TrunkAnalysis, ShoulderOnlyAndNoTrunkData) {
  Fixture f;
  withPatient(f);
  const Reaches reaches(kPeaks);
  SimSetup setup;
  setup.trunkImu = false;
  setup.seed = 814;
  const Recording rec = simulateReaches(f.file("unseen.csv"), reaches, setup);
  qint64 id = 0;
  const AnalysisResult r = importAndAnalyse(f, f.file("unseen.csv"), kLimitDeg, &id);
  const std::optional<StoredAnalysis> a = latestAnalysis(*f.store, id);
  ASSERT_TRUE(a.has_value());
  EXPECT_GT(std::count(a->status.begin(), a->status.end(), kStatusTrunkMoved), 100);
  const QJsonObject reps = r.metricsJson.value("repetitions").toObject();
  const QJsonArray list = reps.value("list").toArray();
  ASSERT_EQ(list.size(), static_cast<qsizetype>(kPeaks.size()));
  for (const QJsonValue& v : list) {
    const QJsonObject rep = v.toObject();
    const QJsonObject trunk = rep.value("trunk").toObject();
    EXPECT_TRUE(trunk.value("max_flexion_deg").isNull());
    EXPECT_TRUE(trunk.value("compensated").isNull());
    const Truth truth =
        truthOver(rec, rep.value("start_s").toDouble(), rep.value("end_s").toDouble());
    EXPECT_NEAR(num(trunk, "max_shoulder_displacement_cm"), truth.displacementCm, 1.5);
  }
  EXPECT_TRUE(reps.value("repetitions_with_compensation").isNull());

  // An arm-only recording: the key is there, every value null.
  Fixture g;
  withPatient(g);
  simulateTo(g.file("arm.csv"), 3.0, 200.0);
  const AnalysisResult none = importAndAnalyse(g, g.file("arm.csv"), kLimitDeg);
  const QJsonObject trunk = none.metricsJson.value("trunk").toObject();
  for (const char* key :
       {"max_flexion_deg", "max_lateral_deg", "max_rotation_deg", "max_shoulder_displacement_cm"})
    EXPECT_TRUE(trunk.value(key).isNull()) << key;
  EXPECT_FALSE(measured(trunkCompensationFromJson(none.metricsJson)->session));
  EXPECT_TRUE(none.metricsJson.value("repetitions")
                  .toObject()
                  .value("repetitions_with_compensation")
                  .isNull());
}

// A home session is judged by the limit its exercise held the patient to, not the protocol's: the
// programme exercise's own limit (12 deg, the protocol has none), or, once the home window stored
// its summary, the summary's (40 deg; null: none). The same session at the clinic: the protocol's.
TEST(TrunkAnalysis, AHomeSessionIsJudgedByItsExercisesLimit) {
  Fixture f;
  withPatient(f);
  ProgrammeItem item;
  item.protocolName = "reach";
  item.trunkLimitDeg = kLimitDeg;
  f.store->setProgrammeExercise("P1", item);
  SimSetup setup;
  setup.seed = 813;
  simulateReaches(f.file("lean.csv"), Reaches(kPeaks), setup);
  const qint64 id = f.store->importRecording(f.file("lean.csv"), "P1", "reach");
  f.db->exec("UPDATE sessions SET setting = 'home' WHERE id = ?", {id});
  const auto judged = [&](const QJsonValue& wantLimit, int wantCompensated) {
    const QJsonObject m = analyseSession(*f.store, id).metricsJson;
    EXPECT_EQ(m.value("trunk").toObject().value("flexion_limit_deg"), wantLimit);
    EXPECT_EQ(m.value("repetitions").toObject().value("repetitions_with_compensation"),
              wantCompensated < 0 ? QJsonValue() : QJsonValue(wantCompensated));
  };
  judged(kLimitDeg, 3);  // the low reach leans about 8 deg, the others 18
  f.db->exec("UPDATE sessions SET home_summary_json = ? WHERE id = ?",
             {R"({"format": "armtrack-home-v1", "trunk_limit_deg": 40})", id});
  judged(40.0, 0);
  f.db->exec("UPDATE sessions SET home_summary_json = ? WHERE id = ?",
             {R"({"format": "armtrack-home-v1", "trunk_limit_deg": null})", id});
  judged(QJsonValue(), -1);
  f.db->exec("UPDATE sessions SET setting = 'clinic', home_summary_json = '{}' WHERE id = ?", {id});
  judged(QJsonValue(), -1);
}

// A limit that is not a positive number of degrees is refused before anything is estimated;
// metrics stored before the trunk was measured read as "no trunk".
TEST(TrunkAnalysis, BadLimitIsRefusedAndOldMetricsHaveNoTrunk) {
  Fixture f;
  withPatient(f);
  simulateTo(f.file("a.csv"), 2.0, 200.0);
  const qint64 id = f.store->importRecording(f.file("a.csv"), "P1", "reach");
  for (const double bad : {0.0, -5.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    AnalysisOptions o;
    o.trunkFlexionLimitDeg = bad;
    expectError([&] { analyseSession(*f.store, id, o); }, Kind::Usage, "trunk flexion limit");
  }
  EXPECT_EQ(f.store->estimateVersions(id), 0);
  QJsonObject old{{"format", kMetricsFormat}, {"repetitions", QJsonObject{}}};
  EXPECT_FALSE(trunkCompensationFromJson(old).has_value());
  old.insert("trunk", QJsonObject{{"max_flexion_deg", "twelve"}, {"max_lateral_deg", 3.5}});
  const std::optional<TrunkCompensation> garbage = trunkCompensationFromJson(old);
  ASSERT_TRUE(garbage.has_value());
  EXPECT_FALSE(garbage->session.maxFlexionDeg.has_value());
  EXPECT_EQ(garbage->session.maxLateralDeg, std::optional<double>(3.5));
}
