// analyseRecording (app/gui/services/AnalyseRecording.h), the GUI's analysis of a session it has
// just recorded: the calibration the live session used is kept with the session in the records,
// so that estimating it again later (the review, `session reestimate`, exports) gives what the
// analysis right after the session gave. A patient whose straps are turned 25 deg, with the
// simulator's own straps as the calibration (the truth, not a fit).
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <numbers>

#include "app/gui/services/AnalyseRecording.h"
#include "core/calibration/Calibration.h"
#include "core/simulation/SensorSimulator.h"
#include "core/storage/Database.h"
#include "tests/support/TurnedStrapsPatient.h"

using namespace armtrack;

namespace {

// RMS error (deg) of the first four joints of the estimates against the recording's truth, after
// the filter's first 5 s.
double rmsError(const storage::StoredAnalysis& a, const Recording& rec) {
  std::map<double, JointVector> truth;
  for (const ArmSample& s : rec.samples)
    if (s.trueAngles) truth[s.t] = *s.trueAngles;
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.t.size(); ++i) {
    const auto it = truth.find(a.t[i]);
    if (a.t[i] < 5.0 || it == truth.end()) continue;
    for (int j = 0; j < 4; ++j) {
      const double d = std::remainder(a.joints[i][j] - it->second[j], 2.0 * std::numbers::pi);
      sum += d * d;
      ++n;
    }
  }
  return n ? std::sqrt(sum / static_cast<double>(n)) * 180.0 / std::numbers::pi : std::nan("");
}

}  // namespace

class TestAnalyseRecording : public QObject {
  Q_OBJECT

  QTemporaryDir m_dir;

 private slots:
  void theCalibrationUsedIsKeptAndUsedAgain() {
    QVERIFY(m_dir.isValid());
    storage::Database db(storage::DatabaseUrl::parse(m_dir.filePath(QStringLiteral("a.db"))),
                         storage::Database::Options{true, false});
    storage::ClinicalStore store(db);
    store.initialise(QStringLiteral("boss"), "boss-pass-1");
    store.signIn(QStringLiteral("boss"), "boss-pass-1");
    storage::Patient p;
    p.code = QStringLiteral("P01");
    p.name = QStringLiteral("Ada Example");
    store.addPatient(p);
    const Recording rec = test::turnedStrapsSession(25.0, 30.0);
    const std::filesystem::path csv = m_dir.filePath(QStringLiteral("rec.csv")).toStdString();
    writeRecording(csv, rec);
    const qint64 plain = store.importRecording(csv, QStringLiteral("P01"));
    const qint64 id = store.importRecording(csv, QStringLiteral("P01"));

    // The straps as the simulator turned them (tests/support/TurnedStrapsPatient.h).
    Calibration straps;
    straps.side = rec.meta.side;
    straps.geometry = rec.meta.geometry;
    straps.upperArm.rotation = randomMisalignment(25.0 * kDeg, 63);
    straps.forearm.rotation = randomMisalignment(25.0 * kDeg, 64);

    storage::AnalysisOptions o;
    o.calibration = straps;
    QCOMPARE(gui::analyseRecording(store, id, o).outcome,
             gui::RecordingAnalysis::Outcome::Analysed);
    const QJsonObject kept =
        QJsonDocument::fromJson(store.session(id).filterJson.toUtf8()).object();
    QVERIFY(kept.value(QStringLiteral("calibration")).isObject());
    const auto first = storage::latestAnalysis(store, id);
    QVERIFY(first.has_value());

    // Later, with no calibration given: the same estimates, bit for bit.
    const storage::AnalysisResult again = storage::analyseSession(store, id);
    QVERIFY(again.calibration.has_value());
    const auto second = storage::latestAnalysis(store, id);
    QVERIFY(second.has_value());
    QVERIFY(second->version > first->version);
    QCOMPARE(second->t.size(), first->t.size());
    for (std::size_t i = 0; i < first->t.size(); ++i)
      QVERIFY(first->joints[i] == second->joints[i]);

    // And they are the straps' estimates: against the truth, and against the same recording
    // analysed with no calibration.
    storage::analyseSession(store, plain);
    const auto without = storage::latestAnalysis(store, plain);
    QVERIFY(without.has_value());
    const double with = rmsError(*second, rec), none = rmsError(*without, rec);
    qInfo("joint RMS error %.2f deg with the kept straps, %.2f deg without", with, none);
    QVERIFY2(with < 3.0, qPrintable(QString::number(with)));
    QVERIFY2(none > 3.0 * with, qPrintable(QString::number(none)));
  }
};

QTEST_GUILESS_MAIN(TestAnalyseRecording)
#include "test_analyse_recording.moc"
