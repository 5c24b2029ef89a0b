// The progress report: ROM per angle against date for sessions with known ranges, read back
// through pdftotext and pdftoppm; plus the chart axis ticks.
#include <QFile>
#include <iostream>

#include "ReportTestSupport.h"
#include "core/reports/Charts.h"
#include "core/reports/Reports.h"

namespace armtrack::reports {
namespace {

using namespace test;

class ProgressReport : public ReportTest {};

ProgressReportData progressData() {
  ProgressReportData d;
  d.patient.code = "P-0042";
  d.patient.name = QString::fromUtf8("Łukasz Żółć");
  d.patient.birthDate = "1961-03-14";
  d.patient.affectedSide = "left";
  d.fromDate = "2026-10-01";
  d.toDate = "2026-11-30";
  d.therapistName = "Dr. Jane Smith";
  // Given out of order: the report sorts by date. Shoulder flexion ROM 60, 75, 90, 104.5 deg,
  // from 10 deg of extension, so the largest flexion reached is 10 deg less.
  const double romDeg[4] = {60, 75, 90, 104.5};
  const char* dates[4] = {"2026-10-02T09:00:00Z", "2026-10-16T09:00:00Z", "2026-11-01T09:00:00Z",
                          "2026-11-20T09:00:00Z"};
  for (int i : {2, 0, 3, 1}) {
    ProgressSession s;
    s.id = 100 + i;
    s.startedAt = dates[i];
    s.protocolName = "Flexion 120";
    s.durationS = 300 + i;
    s.repetitions = 10 + i;
    s.romRad = {romDeg[i] * kDegToRad, 0.5, 0.4, 1.2, std::nullopt};
    s.maxRad = {(romDeg[i] - 10) * kDegToRad, 0.3, 0.2, 1.0, std::nullopt};
    // 10 deg of extension, external rotation 17 deg; no supination (pronation not measured).
    s.minRad = {-10 * kDegToRad, -0.2, -0.3, -0.2, std::nullopt};
    d.sessions.push_back(s);
  }
  return d;
}

TEST_F(ProgressReport, ChartsAndTableForEverySession) {
  const ProgressReportData d = progressData();
  const QString pdf = dir.filePath("progress.pdf");
  const int pages = writeProgressReport(d, pdf);
  const QStringList text = pageTexts(pdf);
  ASSERT_EQ(text.size(), pages);
  const QString all = text.join('\n');
  for (const char* s : {"Progress report", "Patient and period", "Range of motion over time",
                        "Sessions", "2026-10-01", "2026-11-30", "AAOS"})
    EXPECT_TRUE(all.contains(s)) << s;
  for (int i = 0; i < pages; ++i) {
    EXPECT_TRUE(text[i].contains(QString::fromUtf8("Łukasz Żółć")));
    EXPECT_TRUE(text[i].contains(QString("Page %1 of %2").arg(i + 1).arg(pages)));
  }
  for (int a = 0; a < kNumClinicalAngles; ++a)
    EXPECT_TRUE(all.contains(QString::fromUtf8(clinicalAngleInfo()[a].name.data()) +
                             ": largest angle reached (deg)"));
  // The opposite motions that have a normal limit of their own, each with its chart.
  for (const char* motion :
       {"Shoulder extension", "Shoulder external rotation", "Forearm supination"})
    EXPECT_TRUE(all.contains(QString(motion) + ": largest angle reached (deg)")) << motion;
  EXPECT_FALSE(all.contains("Shoulder adduction")) << "no normal limit: no chart";
  // The table lists the sessions in date order with their ROM in degrees.
  int last = -1;
  for (const char* row : {"2026-10-02", "2026-10-16", "2026-11-01", "2026-11-20"}) {
    const int at =
        all.indexOf(QRegularExpression(QString("%1\\s+1\\d\\d\\s+Flexion 120").arg(row)));
    EXPECT_GT(at, last) << row;
    last = at;
  }
  EXPECT_EQ(all.count("not measured in this period"), 2)
      << "forearm pronation and supination have no values";
  for (const char* rom : {" 60.0 ", " 75.0 ", " 90.0 ", " 104.5 ", " 28.6 ", " 68.8 "})
    EXPECT_TRUE(all.contains(rom)) << rom;

  const std::vector<QImage> images = renderPages(pdf, dir.path());
  ASSERT_EQ(static_cast<int>(images.size()), pages);
  for (const QImage& img : images) EXPECT_GT(inkFraction(img), 0.01);
  const BlueInk b = blueInk(images[0]);
  EXPECT_GT(b.count, 100) << "the ROM lines";
}

// The trunk's compensation over the weeks (issue 26): a chart of each session's largest trunk
// flexion when some session measured it, without a normal range; none otherwise.
TEST_F(ProgressReport, TrunkCompensationChartWhenMeasured) {
  ProgressReportData d = progressData();
  QString pdf = dir.filePath("no-trunk.pdf");
  writeProgressReport(d, pdf);
  const QString title = "Trunk compensation: largest trunk flexion (deg)";
  QString all = pageTexts(pdf).join('\n');
  EXPECT_FALSE(all.contains(title));
  const int normals = all.count("shaded: AAOS normal range");
  for (ProgressSession& s : d.sessions)  // 16 deg down to 7 deg, one session not measured
    if (s.id != 101) s.trunkFlexionDeg = 16.0 - 3.0 * static_cast<double>(s.id - 100);
  pdf = dir.filePath("trunk.pdf");
  writeProgressReport(d, pdf);
  all = pageTexts(pdf).join('\n');
  EXPECT_TRUE(all.contains(title)) << all.toStdString();
  EXPECT_EQ(all.count("shaded: AAOS normal range"), normals) << "no normal range for the trunk";
  const std::vector<QImage> images = renderPages(pdf, dir.path());
  ASSERT_FALSE(images.empty());
}

// Three simulated sessions of growing range, turned into rows by progressSession(): the table
// shows each session's shoulder-flexion ROM as the metrics give it, within 1 deg of the truth.
TEST_F(ProgressReport, FromSimulatedSessions) {
  ProgressReportData d = progressData();
  d.sessions.clear();
  const double peaks[3] = {70, 95, 125};
  std::vector<double> romDeg;
  for (int i = 0; i < 3; ++i) {
    const SimulatedSession sim = simulateSession({peaks[i], peaks[i] - 5});
    storage::SessionInfo info;
    info.id = 200 + i;
    info.startedAt = QString("2026-11-%1T08:00:00Z").arg(3 + 7 * i, 2, 10, QLatin1Char('0'));
    info.protocolName = "Flexion 120";
    const ProgressSession row = progressSession(info, sim.metrics);
    ASSERT_TRUE(row.romRad[0].has_value());
    EXPECT_EQ(row.repetitions, 2);
    EXPECT_DOUBLE_EQ(row.durationS, sim.metrics.durationS);
    romDeg.push_back(*row.romRad[0] * kRadToDeg);
    EXPECT_NEAR(romDeg.back(), peaks[i] - 10, 1.0);
    // The chart's value: the largest flexion reached, not the ROM from the 10 deg rest.
    ASSERT_TRUE(row.maxRad[0].has_value());
    EXPECT_NEAR(*row.maxRad[0] * kRadToDeg, peaks[i], 1.0);
    // The opposite motion's chart takes the smallest angle: the ROM's other end.
    ASSERT_TRUE(row.minRad[0].has_value());
    EXPECT_NEAR(*row.minRad[0], *row.maxRad[0] - *row.romRad[0], 1e-9);
    d.sessions.push_back(row);
  }
  const QString pdf = dir.filePath("simulated.pdf");
  writeProgressReport(d, pdf);
  const QString all = pageTexts(pdf).join('\n');
  for (int i = 0; i < 3; ++i) {
    const QString row = QString("2026-11-%1\\s+%2\\s+Flexion 120\\s+\\S+ s\\s+2\\s+%3\\s")
                            .arg(3 + 7 * i, 2, 10, QLatin1Char('0'))
                            .arg(200 + i)
                            .arg(QRegularExpression::escape(QString::number(romDeg[i], 'f', 1)));
    EXPECT_TRUE(all.contains(QRegularExpression(row))) << row;
  }
}

TEST_F(ProgressReport, NoSessionsSaysSo) {
  ProgressReportData d = progressData();
  d.sessions.clear();
  const QString pdf = dir.filePath("none.pdf");
  EXPECT_EQ(writeProgressReport(d, pdf), 1);
  const QString all = pageTexts(pdf).join('\n');
  EXPECT_TRUE(all.contains("No sessions in the period (2026-10-01 to 2026-11-30)."));
  EXPECT_TRUE(all.contains("Page 1 of 1"));
  EXPECT_FALSE(all.contains("largest angle reached (deg)")) << "no empty charts";
}

// Dates left empty (all sessions) or not dates at all: the header and the period show the
// sessions' first and last day, never "progress - to -" or "From - To -".
TEST_F(ProgressReport, PeriodIsTheSessionsWhenTheDatesAreMissingOrWrong) {
  ProgressReportData d = progressData();
  d.fromDate.clear();
  d.toDate = "not a date";
  EXPECT_EQ(progressPeriod(d), "2026-10-02 to 2026-11-20");
  const QString pdf = dir.filePath("open.pdf");
  writeProgressReport(d, pdf);
  const QString all = pageTexts(pdf).join('\n').simplified();
  EXPECT_TRUE(
      all.contains(QString::fromUtf8("Łukasz Żółć (P-0042), progress 2026-10-02 to "
                                     "2026-11-20")))
      << all.left(400).toStdString();
  EXPECT_TRUE(all.contains("Period 2026-10-02 to 2026-11-20"));
  EXPECT_FALSE(all.contains("- to -"));
  EXPECT_FALSE(all.contains("From -"));
  // One date given: it stays, the other comes from the sessions.
  d.fromDate = "2026-10-10";
  EXPECT_EQ(progressPeriod(d), "2026-10-10 to 2026-11-20");
  d.sessions.clear();
  d.toDate.clear();
  EXPECT_EQ(progressPeriod(d), "from 2026-10-10");
  d.fromDate.clear();
  EXPECT_EQ(progressPeriod(d), "no sessions");
}

// The % of normal of each chart is the patient page's (named motion against its own normal):
// the latest flexion reached 94.5 deg of AAOS 180, 53 %, not its 104.5 deg ROM over 240 (44 %).
TEST_F(ProgressReport, PercentOfNormalIsThePatientPagesDefinition) {
  const QString pdf = dir.filePath("percent.pdf");
  writeProgressReport(progressData(), pdf);
  const QString all = pageTexts(pdf).join('\n').simplified();
  EXPECT_TRUE(all.contains("Shoulder flexion: largest angle reached (deg); latest 53 % of normal"))
      << all.toStdString();
  EXPECT_FALSE(all.contains("latest 44 %"));
}

TEST_F(ProgressReport, UnwritablePathIsNamed) {
  const QString bad = dir.filePath("no/such/folder/p.pdf");
  try {
    writeProgressReport(progressData(), bad);
    FAIL() << "no error";
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find(bad.toStdString()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(QFile::exists(bad));
}

TEST(ChartTicks, NiceStepsCoverTheRange) {
  EXPECT_EQ(niceTicks(0, 10, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(niceTicks(-12, 37, 4), (std::vector<double>{-10, 0, 10, 20, 30}));
  EXPECT_EQ(niceTicks(0, 1, 4), (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
  EXPECT_TRUE(niceTicks(5, 5, 4).empty());
  EXPECT_TRUE(niceTicks(0, std::numeric_limits<double>::infinity(), 4).empty());
}

}  // namespace
}  // namespace armtrack::reports
