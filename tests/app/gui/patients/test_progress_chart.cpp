// The patient page's progress chart against sessions with known angles: simulated recordings
// imported and analysed by the records' own services, loaded as the patient page loads them
// (loadPatientOverview), drawn by the chart. Each angle's normal range counts motion in one
// direction from the neutral position (core/metrics/NormativeRanges.h), so the chart must plot
// the largest angle in that direction, not the range of motion: a shoulder that rotates from 60
// deg external to 20 deg internal has an 80 deg range but reached 20 of the 70 deg of normal
// internal rotation.
#include <QAreaSeries>
#include <QChart>
#include <QComboBox>
#include <QDateTime>
#include <QLineSeries>
#include <QRegularExpression>
#include <QStandardItemModel>
#include <QTemporaryDir>
#include <QTest>
#include <QValueAxis>
#include <cmath>

#include "app/clinical/Outputs.h"
#include "app/gui/patients/ProgressChart.h"
#include "app/gui/services/PatientRecords.h"
#include "core/kinematics/ClinicalAngles.h"
#include "core/reports/Reports.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/storage/SessionAnalysis.h"
#include "tests/app/gui/support/GuiTestSupport.h"
#include "tests/support/GuiTestMain.h"
#include "tests/support/LeaningPatient.h"

using namespace armtrack;

namespace {

/// Clinical angles (deg) swinging between lo and hi at 0.2 Hz.
struct Swing {
  ClinicalAngles lo, hi;
};

/// Imports a 20 s recording of the swing (both IMUs at 100 Hz and a Kinect, the simulator's
/// noise) for patient P1, analyses it and dates it daysAgo back. Returns the session id.
qint64 addSession(storage::Database& db, storage::ClinicalStore& store, const Swing& swing,
                  double daysAgo, std::uint64_t seed, const QString& folder) {
  const JointVector lo = fromClinical(swing.lo), hi = fromClinical(swing.hi);
  SinusoidTrajectory t;
  t.offset = (lo + hi) / 2;
  t.amplitude = (hi - lo) / 2;
  t.frequency.setConstant(0.2);
  t.phase.setConstant(-M_PI / 2);  // from lo
  SimulationParams sim = defaultSimulation();
  sim.duration = 20;
  sim.seed = seed;
  sim.upperArm.rateHz = sim.forearm.rateHz = 100;
  const std::string csv = (folder + QStringLiteral("/s%1.csv").arg(seed)).toStdString();
  writeRecording(csv, simulateRecording(t, sim));
  const qint64 id = store.importRecording(csv, QStringLiteral("P1"), {});
  storage::analyseSession(store, id);
  db.exec(QStringLiteral("UPDATE sessions SET started_at = ? WHERE id = ?"),
          {QDateTime::currentDateTimeUtc()
               .addSecs(-static_cast<qint64>(daysAgo * 86400))
               .toString(Qt::ISODateWithMs),
           id});
  return id;
}

double cell(const QStandardItemModel* t, int row, int column) {
  return t->item(row, column)->text().remove(u'%').trimmed().toDouble();
}

}  // namespace

class TestProgressChart : public QObject {
  Q_OBJECT
  QTemporaryDir m_dir;
  gui::PatientOverview m_overview;

 private slots:
  void initTestCase() {
    storage::DatabaseUrl url;
    url.path = m_dir.filePath(QStringLiteral("records.db"));
    storage::Database db(url, {.create = true, .migrate = false});
    storage::ClinicalStore store(db);
    store.initialise(QStringLiteral("admin"), "a-long-password");
    store.signIn(QStringLiteral("admin"), "a-long-password");
    storage::Patient p;
    p.code = QStringLiteral("P1");
    p.name = QStringLiteral("Known Angles");
    store.addPatient(p);
    // Older session: every angle mostly on its negative side (extension, external rotation,
    // supination), the rotation never reaching neutral.
    Swing first;
    first.lo = {-30, 5, -70, 10, -75};
    first.hi = {60, 25, -20, 90, -30};
    // Newer session: each angle crosses neutral.
    Swing second;
    second.lo = {30, 10, -60, 20, -70};
    second.hi = {110, 30, 20, 100, 10};
    addSession(db, store, first, 8, 11, m_dir.path());
    addSession(db, store, second, 1, 12, m_dir.path());
    m_overview = gui::loadPatientOverview(store, QStringLiteral("P1"));
  }

  void theOverviewHoldsEachSessionsExtremes() {
    QCOMPARE(m_overview.progress.size(), std::size_t{2});
    QVERIFY(m_overview.progress[0].startedAt < m_overview.progress[1].startedAt);
    const double lo[5] = {30, 10, -60, 20, -70}, hi[5] = {110, 30, 20, 100, 10};
    for (std::size_t a = 0; a < 5; ++a) {
      const gui::SessionExtremes& s = m_overview.progress[1];
      QVERIFY(s.minRad[a] && s.maxRad[a]);
      QVERIFY2(std::abs(*s.minRad[a] * kRadToDeg - lo[a]) < 3,
               qPrintable(QString::number(*s.minRad[a] * kRadToDeg)));
      QVERIFY2(std::abs(*s.maxRad[a] * kRadToDeg - hi[a]) < 3,
               qPrintable(QString::number(*s.maxRad[a] * kRadToDeg)));
    }
  }

  void theChartPlotsTheLargestAngleAgainstTheNormalOfThatDirection() {
    gui::ProgressChart chart;
    chart.resize(900, 400);
    chart.show();
    chart.setSessions(m_overview.progress);
    // The simulated largest angle per session in the named direction (flexion, abduction,
    // internal rotation, elbow flexion, pronation), and that motion's normal range (AAOS).
    const double largest[2][5] = {{60, 25, -20, 90, -30}, {110, 30, 20, 100, 10}};
    const double normal[5] = {180, 180, 70, 150, 80};
    for (int a = 0; a < 5; ++a) {
      chart.setAngle(a);
      QCOMPARE(chart.points(), 2);
      const QStandardItemModel* t = chart.table();
      QCOMPARE(t->rowCount(), 2);
      QVERIFY(t->horizontalHeaderItem(1)->text().startsWith(QStringLiteral("Largest")));
      QLineSeries* line = nullptr;
      QAreaSeries* area = nullptr;
      for (QAbstractSeries* s : chart.chart()->series()) {
        if (auto* l = qobject_cast<QLineSeries*>(s)) line = l;
        if (auto* found = qobject_cast<QAreaSeries*>(s)) area = found;
      }
      QVERIFY(line && area);
      QCOMPARE(area->upperSeries()->at(0).y(), normal[a]);
      QCOMPARE(area->lowerSeries()->at(0).y(), 0.0);
      QCOMPARE(line->count(), 2);
      for (int row = 0; row < 2; ++row) {
        const QString what = QStringLiteral("angle %1, session %2: %3 deg")
                                 .arg(a)
                                 .arg(row)
                                 .arg(t->item(row, 1)->text());
        QVERIFY2(std::abs(cell(t, row, 1) - largest[row][a]) < 3, qPrintable(what));
        QVERIFY2(std::abs(line->at(row).y() - largest[row][a]) < 3, qPrintable(what));
        // Of normal: the largest angle over the normal range; nothing below neutral.
        const double percent = std::max(0.0, 100 * cell(t, row, 1) / normal[a]);
        QVERIFY2(std::abs(cell(t, row, 2) - percent) <= 1, qPrintable(t->item(row, 2)->text()));
      }
      // The axis shows every point, the rotation's -20 deg too.
      QValueAxis* y = nullptr;
      for (QAbstractAxis* axis : chart.chart()->axes(Qt::Vertical))
        if (auto* v = qobject_cast<QValueAxis*>(axis)) y = v;
      QVERIFY(y);
      QVERIFY(y->min() <= std::min(0.0, largest[0][a] - 1));
      QVERIFY(y->max() >= std::max(normal[a], largest[1][a]));
    }
    // The two cases a range of motion got wrong: internal rotation 80 deg of range but 20 deg
    // reached (29 % of 70, not 114 %); pronation 80 deg of range but 10 deg reached (13 %, not
    // 100 %); and a rotation that never reached neutral is 0 % of normal.
    chart.setAngle(2);
    QVERIFY2(std::abs(cell(chart.table(), 1, 2) - 29) <= 5,
             qPrintable(chart.table()->item(1, 2)->text()));
    QCOMPARE(cell(chart.table(), 0, 2), 0.0);
    QVERIFY(QTest::qWaitForWindowExposed(&chart));
    test::saveScreenshot(test::grabFromScreen(&chart), QStringLiteral("progress_chart_rotation"));
    chart.setAngle(4);
    QVERIFY2(std::abs(cell(chart.table(), 1, 2) - 13) <= 5,
             qPrintable(chart.table()->item(1, 2)->text()));
  }

  void theOppositeMotionsArePlottedAgainstTheirOwnNormal() {
    gui::ProgressChart chart;
    chart.resize(900, 400);
    chart.show();
    chart.setSessions(m_overview.progress);
    // Shoulder extension, external rotation and supination: minus each session's smallest angle
    // (the sessions' lo above), against 60, 90 and 80 deg (AAOS).
    struct Expected {
      int angle;
      const char* name;
      double largest[2];
      double normal;
    };
    const Expected expected[] = {{0, "Shoulder extension", {30, -30}, 60},
                                 {2, "Shoulder external rotation", {70, 60}, 90},
                                 {4, "Forearm supination", {75, 70}, 80}};
    for (const Expected& e : expected) {
      chart.setMotion(e.angle, true);
      QCOMPARE(chart.angle(), e.angle);
      QVERIFY(chart.opposite());
      QCOMPARE(chart.motionName(), QString::fromLatin1(e.name));
      QCOMPARE(chart.chart()->title(), QString::fromLatin1(e.name));
      QCOMPARE(chart.points(), 2);
      const QStandardItemModel* t = chart.table();
      QAreaSeries* area = nullptr;
      for (QAbstractSeries* s : chart.chart()->series())
        if (auto* found = qobject_cast<QAreaSeries*>(s)) area = found;
      QVERIFY(area);
      QCOMPARE(area->upperSeries()->at(0).y(), e.normal);
      for (int row = 0; row < 2; ++row) {
        const QString what =
            QStringLiteral("%1, session %2: %3").arg(e.name).arg(row).arg(t->item(row, 1)->text());
        QVERIFY2(std::abs(cell(t, row, 1) - e.largest[row]) < 3, qPrintable(what));
        const double percent = std::max(0.0, 100 * e.largest[row] / e.normal);
        QVERIFY2(std::abs(cell(t, row, 2) - percent) <= 5, qPrintable(t->item(row, 2)->text()));
      }
    }
    // Abduction and elbow flexion have no opposite motion in the chooser: their named one is
    // drawn.
    chart.setMotion(1, true);
    QCOMPARE(chart.angle(), 1);
    QVERIFY(!chart.opposite());
    chart.setMotion(3, true);
    QCOMPARE(chart.angle(), 3);
    QVERIFY(!chart.opposite());
    // The chooser lists eight motions, the named ones where they were.
    const auto* chooser = chart.findChild<QComboBox*>();
    QVERIFY(chooser);
    QCOMPARE(chooser->count(), 8);
    chart.setAngle(2);
    QCOMPARE(chooser->currentText(), QStringLiteral("Shoulder internal rotation"));
    chart.setMotion(2, true);
    QVERIFY(QTest::qWaitForWindowExposed(&chart));
    test::saveScreenshot(test::grabFromScreen(&chart),
                         QStringLiteral("progress_chart_external_rotation"));
  }

  // One "% of normal" (issue 25, item 3): the page's and the session report's for the same
  // session, both the largest flexion over the flexion normal (AAOS 180 deg here), not the
  // report's old range of motion over flexion plus extension (240 deg).
  void thePageAndTheSessionReportShowTheSamePercentOfNormal() {
    storage::DatabaseUrl url;
    url.path = m_dir.filePath(QStringLiteral("records.db"));
    storage::Database db(url, {});
    storage::ClinicalStore store(db);
    store.signIn(QStringLiteral("admin"), "a-long-password");
    gui::ProgressChart chart;
    chart.setSessions(m_overview.progress);
    chart.setAngle(0);
    for (int row = 0; row < 2; ++row) {
      const gui::SessionExtremes& s = m_overview.progress[static_cast<std::size_t>(row)];
      const double page = cell(chart.table(), row, 2);
      // The independent truth: the largest flexion over 180 deg.
      QVERIFY(std::abs(page - 100 * *s.maxRad[0] * kRadToDeg / 180) <= 0.5);
      const QString pdf = m_dir.filePath(QStringLiteral("report%1.pdf").arg(s.id));
      reports::writeSessionReport(clinical::sessionReportData(store, s.id), pdf);
      const QString text = gui::test::pdfText(pdf).simplified();
      const QRegularExpressionMatch m =
          QRegularExpression(QStringLiteral("(-?[\\d.]+) of 180\\.0 deg, (\\d+) %")).match(text);
      QVERIFY2(m.hasMatch(), qPrintable(text.left(4000)));
      QCOMPARE(m.captured(2).toDouble(), page);
    }
  }

  // The patient's age and sex choose the normal range as the reports do (patientNorms(): the
  // CDC's values where this version carries them for the patient's group, else AAOS).
  void thePatientsNormsAreTheReports() {
    gui::ProgressChart chart;
    chart.setSessions(m_overview.progress);
    chart.setPatient(QStringLiteral("1961-03-14"), QStringLiteral("f"));
    chart.setAngle(0);
    const QDate day =
        QDateTime::fromString(m_overview.progress.back().startedAt, Qt::ISODateWithMs).date();
    const PatientNorms norms = patientNorms(
        CivilDate{1961, 3, 14}, CivilDate{day.year(), day.month(), day.day()}, Sex::Female);
    QAreaSeries* area = nullptr;
    for (QAbstractSeries* series : chart.chart()->series())
      if (auto* found = qobject_cast<QAreaSeries*>(series)) area = found;
    QVERIFY(area);
    QVERIFY(std::abs(area->upperSeries()->at(0).y() - norms.ranges[0].maxRad * kRadToDeg) < 1e-6);
    const std::string_view source = normSourceShortName(norms.ranges[0].maxSource);
    QVERIFY(area->name().contains(QString::fromUtf8(source.data(), source.size())));
    const double largest = *m_overview.progress.back().maxRad[0];
    QVERIFY(std::abs(cell(chart.table(), 1, 2) - 100 * largest / norms.ranges[0].maxRad) <= 0.5);
  }

  // Trunk compensation over the weeks (issue 26): two sessions of a patient who leaned less with
  // therapy (16 deg, then 8 deg; sternum IMU and Kinect), each point its session's largest trunk
  // flexion against the simulated lean; patients without a trunk sensor see no trunk entry.
  void theTrunksCompensationOverTheWeeks() {
    storage::DatabaseUrl url;
    url.path = m_dir.filePath(QStringLiteral("records.db"));
    storage::Database db(url, {});
    storage::ClinicalStore store(db);
    store.signIn(QStringLiteral("admin"), "a-long-password");
    storage::Patient p;
    p.code = QStringLiteral("P2");
    p.name = QStringLiteral("Leaning Less");
    store.addPatient(p);
    std::vector<double> trueLean;
    for (const double lean : {16.0, 8.0}) {
      const Recording rec = test::leaningReaches(16, lean > 10 ? 841 : 842, lean, 100);
      trueLean.push_back(test::trueLeanDeg(rec));
      const std::string csv = m_dir.filePath(QStringLiteral("lean%1.csv").arg(lean)).toStdString();
      writeRecording(csv, rec);
      const qint64 id = store.importRecording(csv, QStringLiteral("P2"), {});
      storage::analyseSession(store, id);
      db.exec(QStringLiteral("UPDATE sessions SET started_at = ? WHERE id = ?"),
              {QDateTime::currentDateTimeUtc()
                   .addDays(lean > 10 ? -21 : -2)
                   .toString(Qt::ISODateWithMs),
               id});
    }
    const gui::PatientOverview o = gui::loadPatientOverview(store, QStringLiteral("P2"));
    QCOMPARE(o.progress.size(), std::size_t{2});
    gui::ProgressChart chart;
    chart.resize(900, 400);
    chart.show();
    chart.setSessions(o.progress);
    const auto* chooser = chart.findChild<QComboBox*>();
    QCOMPARE(chooser->count(), 9);
    chart.showTrunk();
    QVERIFY(chart.trunkShown());
    QCOMPARE(chart.motionName(), QStringLiteral("Trunk flexion (compensation)"));
    QCOMPARE(chart.points(), 2);
    const QStandardItemModel* t = chart.table();
    QCOMPARE(t->rowCount(), 2);
    for (int row = 0; row < 2; ++row)  // oldest first: the 16-degree session
      QVERIFY2(std::abs(cell(t, row, 1) - trueLean[static_cast<std::size_t>(row)]) < 1.5,
               qPrintable(t->item(row, 1)->text()));
    QVERIFY(QTest::qWaitForWindowExposed(&chart));
    test::saveScreenshot(test::grabFromScreen(&chart), QStringLiteral("progress_chart_trunk"));
    // Back to an arm motion from the chooser, and patients without a trunk sensor.
    chart.setAngle(0);
    QVERIFY(!chart.trunkShown());
    QCOMPARE(chart.table()->columnCount(), 3);
    chart.setSessions(m_overview.progress);
    QCOMPARE(chooser->count(), 8);
    chart.showTrunk();
    QVERIFY(!chart.trunkShown());
  }
};

ARMTRACK_GUI_TEST_MAIN(TestProgressChart)
#include "test_progress_chart.moc"
