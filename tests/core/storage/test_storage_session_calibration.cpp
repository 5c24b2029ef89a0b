// A session recorded into the clinical records keeps the calibration its live estimate used
// (docs/storage.md, "Filter settings": "calibration"), so estimating it again later (the review,
// `session reestimate`, exports) reproduces what the therapist saw. A simulated patient whose
// straps are turned 25 deg is replayed through the live session as the GUI runs it (recording
// into the records, the straps fitted from the movement); the session is then analysed as the
// GUI does after it (the calibration kept first) and estimated again with no calibration given.
// Both engines.
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <thread>

#include "core/calibration/Calibration.h"
#include "core/session/Session.h"
#include "core/storage/DatabaseRecordingSink.h"
#include "core/storage/SessionAnalysis.h"
#include "devices/api/Options.h"
#include "tests/core/storage/StorageTestSupport.h"
#include "tests/support/LoadPlugin.h"
#include "tests/support/TurnedStrapsPatient.h"

namespace armtrack::storage::test {
namespace {

namespace fs = std::filesystem;
constexpr double kRad = 180.0 / std::numbers::pi;
constexpr double kSeconds = 80.0;   // of simulated session
constexpr double kFirstFit = 50.0;  // s: the fit, paced (the end of a reach: see
                                    // test_session_movement_calibration.cpp)

struct LiveSession {
  qint64 id = 0;
  std::vector<session::EstimateRow> results;
  session::LiveCalibrationStatus status;
};

// The recording replayed at 10x through a live session that records into the records (as the
// GUI's RecordsRecordingTarget does: the session's row begun, a DatabaseRecordingSink) and fits
// the straps from the movement, waiting for its fit so that every run fits at kFirstFit (and
// restarts at the rest that follows).
LiveSession runLive(Fixture& f, const Recording& rec) {
  LiveSession live;
  const fs::path source = f.file("source.csv");
  writeRecording(source, rec);
  devices::DevicePlugin* plugin = armtrack::test::loadPlugin(QStringLiteral("replay"));
  if (!plugin) return live;
  session::SessionParams params;
  params.meta = rec.meta;
  params.openSink = [&](const RecordingMeta& meta, const RecordingColumns& columns) {
    live.id = f.store->beginRecording("P1", "", meta, columns);
    return std::make_unique<DatabaseRecordingSink>(DatabaseUrl::parse(f.path), live.id, columns);
  };
  params.movementCalibration.enabled = true;
  params.movementCalibration.firstSeconds = kFirstFit;
  params.movementCalibration.waitForFit = true;
  session::Session session(params);
  QString why;
  auto device = plugin->create(
      devices::Options::parse(
          QStringLiteral("file=%1,speed=10").arg(QString::fromStdString(source.string()))),
      &why);
  if (!device) {
    ADD_FAILURE() << why.toStdString();
    return live;
  }
  session.addDevice(armtrack::test::hosted(std::move(device), QStringLiteral("replay")),
                    QStringLiteral("replay"));
  why = session.start();
  EXPECT_TRUE(why.isEmpty()) << why.toStdString();
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    session.takeResults(live.results);
    if (!live.results.empty() && live.results.back().t > rec.samples.back().t - 0.5) break;
  }
  session.stop();
  session.takeResults(live.results);
  live.status = session.movementCalibration();
  if (live.id) f.store->finishSession(live.id);
  return live;
}

// RMS (deg) over the first four joints (the forearm's roll is a gauge without a known rest pose)
// of a - b, over the times in [from, to) both have.
double rmsDifference(const std::map<double, JointVector>& a, const std::map<double, JointVector>& b,
                     double from, double to) {
  double sum = 0.0;
  std::size_t n = 0;
  for (auto it = a.lower_bound(from); it != a.end() && it->first < to; ++it) {
    const auto other = b.find(it->first);
    if (other == b.end()) continue;
    for (int j = 0; j < 4; ++j) {
      const double d = std::remainder(it->second[j] - other->second[j], 2.0 * std::numbers::pi);
      sum += d * d;
      ++n;
    }
  }
  return n > 100 ? std::sqrt(sum / static_cast<double>(n)) * kRad : std::nan("");
}

std::map<double, JointVector> byTime(const StoredAnalysis& a) {
  std::map<double, JointVector> out;
  for (std::size_t i = 0; i < a.t.size(); ++i) out[a.t[i]] = a.joints[i];
  return out;
}

QJsonObject filterSettings(ClinicalStore& store, qint64 id) {
  return QJsonDocument::fromJson(store.session(id).filterJson.toUtf8()).object();
}

class SessionCalibrationRecords : public Engines {};

TEST_P(SessionCalibrationRecords, StoredSessionIsEstimatedAgainWithTheStrapsItWasRecordedWith) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const LiveSession live = runLive(f, armtrack::test::turnedStrapsSession(25.0, kSeconds));
  ASSERT_GT(live.id, 0);
  ASSERT_GT(live.results.size(), 4000u);
  ASSERT_TRUE(live.status.calibration.has_value()) << live.status.line;
  const double applied = live.status.firstAppliedAt;
  // (fitted at kFirstFit, used at the rest that follows: LiveCalibrationParams::applyAtRest)
  ASSERT_LT(applied, live.status.fittedAt + 5.0);

  // The truth and the live estimates, by session time (the stored rows' times).
  std::map<double, JointVector> truth, liveEstimates;
  for (const ArmSample& s : f.store->readRecording(live.id).samples)
    if (s.trueAngles) truth[s.t] = *s.trueAngles;
  for (const session::EstimateRow& e : live.results) liveEstimates[e.t] = e.th;
  const double liveAfter = rmsDifference(liveEstimates, truth, applied + 5.0, kSeconds);

  // After the session, as the GUI does (app/gui/services/AnalyseRecording.cpp): the calibration
  // the live session used is kept with the session and the session analysed with it.
  keepSessionCalibration(*f.store, live.id, *live.status.calibration);
  AnalysisOptions first;
  first.calibration = live.status.calibration;
  const AnalysisResult r1 = analyseSession(*f.store, live.id, first);
  // Later, as the review's "estimate again" and `session reestimate` do: no calibration given.
  const AnalysisResult r2 = analyseSession(*f.store, live.id);
  EXPECT_TRUE(r2.calibration.has_value()) << "estimated again without the session's straps";
  if (r2.calibration) {
    EXPECT_TRUE(r2.calibration->upperArm.rotation.isApprox(
        live.status.calibration->upperArm.rotation, 1e-12));
  }
  const std::optional<StoredAnalysis> v1 = storedAnalysis(*f.store, live.id, r1.estimateVersion);
  const std::optional<StoredAnalysis> v2 = storedAnalysis(*f.store, live.id, r2.estimateVersion);
  ASSERT_TRUE(v1 && v2);
  EXPECT_TRUE(
      QJsonDocument::fromJson(v2->paramsJson.toUtf8()).object().value("calibration").toBool());
  // The estimates of the live session's calibration itself (the stored one is its calibration
  // file's form, whose rotation vectors round the rotations by an ulp: 2e-11 rad here).
  ASSERT_EQ(v1->t.size(), v2->t.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < v1->t.size(); ++i) {
    ASSERT_TRUE(sameBits(v1->t[i], v2->t[i])) << i;
    largest = std::max(largest, (v1->joints[i] - v2->joints[i]).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(largest, 1e-6);
  // Against the live estimate and the truth after the fit (the live estimator restarted with
  // the fitted straps at `applied`; the analysis uses them from the start).
  const std::map<double, JointVector> again = byTime(*v2);
  const double againErr = rmsDifference(again, truth, applied + 5.0, kSeconds);
  const double vsLive = rmsDifference(again, liveEstimates, applied + 5.0, kSeconds);
  std::printf(
      "[ figures  ] after the fit at %.1f s: live %.2f deg off the truth, estimated again from "
      "the records %.2f deg (%.2f deg from the live estimate)\n",
      applied, liveAfter, againErr, vsLive);
  EXPECT_LT(liveAfter, 3.0);
  EXPECT_LT(againErr, 3.0);
  EXPECT_LT(vsLive, 3.0);

  // A change of filter settings (`session reestimate --filter ukf`) keeps the straps.
  EstimateOptions ukf = r2.settings;
  ukf.filter = FilterKind::Ukf;
  f.store->updateSessionFilterSettings(
      live.id,
      QString::fromUtf8(QJsonDocument(filterSettingsJson(ukf, f.store->session(live.id).filterJson))
                            .toJson(QJsonDocument::Compact)));
  const QJsonObject kept = filterSettings(*f.store, live.id);
  EXPECT_EQ(kept.value("filter").toString(), QStringLiteral("ukf"));
  EXPECT_TRUE(kept.value("calibration").isObject());
  EXPECT_TRUE(analyseSession(*f.store, live.id).calibration.has_value());
}

// Hostile stored settings: a "calibration" that is not a calibration file's object, or one no
// real arm has, is refused naming the session and the key, and marks the analysis failed.
TEST_P(SessionCalibrationRecords, DamagedStoredCalibrationIsRefusedNamingIt) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("P1"));
  const fs::path csv = f.file("rec.csv");
  simulateTo(csv, 8.0);
  const qint64 id = f.store->importRecording(csv, "P1");
  Calibration impossible;
  impossible.geometry.l3 = 5.0;  // a 5 m upper arm
  const QJsonObject good =
      QJsonDocument::fromJson(QByteArray::fromStdString(calibrationText(Calibration{}, "x")))
          .object();
  QJsonObject badGeometry = good;
  QJsonObject g = good.value("geometry").toObject();
  g.insert("l3", 5.0);
  badGeometry.insert("geometry", g);
  for (const QJsonValue& junk :
       {QJsonValue("junk"), QJsonValue(42), QJsonValue(QJsonObject{}), QJsonValue(badGeometry)}) {
    f.store->updateSessionFilterSettings(
        id, QString::fromUtf8(
                QJsonDocument(QJsonObject{{"calibration", junk}}).toJson(QJsonDocument::Compact)));
    try {
      analyseSession(*f.store, id);
      ADD_FAILURE() << "analysed with a damaged stored calibration";
    } catch (const StorageError& e) {
      EXPECT_EQ(e.kind(), Kind::Usage) << e.what();
      const std::string what = e.what();
      EXPECT_NE(what.find("session " + std::to_string(id)), std::string::npos) << what;
      EXPECT_NE(what.find("\"calibration\""), std::string::npos) << what;
    }
  }
  // And one no real arm has is not kept in the first place.
  try {
    keepSessionCalibration(*f.store, id, impossible);
    ADD_FAILURE() << "kept an impossible calibration";
  } catch (const StorageError& e) {
    EXPECT_EQ(e.kind(), Kind::Usage) << e.what();
  }
  // A good one is used.
  keepSessionCalibration(*f.store, id, Calibration{});
  EXPECT_TRUE(analyseSession(*f.store, id).calibration.has_value());
}

INSTANTIATE_TEST_SUITE_P(Engines, SessionCalibrationRecords,
                         testing::Values(Engine::Sqlite, Engine::Postgres), engineName);

}  // namespace
}  // namespace armtrack::storage::test
