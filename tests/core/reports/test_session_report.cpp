// The session report, read back as a reader would: the text through pdftotext (every section,
// the patient on every page, page numbers, the printed ranges against the metrics and the
// simulated truth) and the pages through pdftoppm (not blank, plots drawn).
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <cmath>
#include <iostream>
#include <limits>

#include "ReportTestSupport.h"
#include "core/reports/Reports.h"

namespace armtrack::reports {
namespace {

using namespace test;

const QStringList kSections = {"Session report",
                               "Patient and session",
                               "Devices and calibration",
                               "Metrics per clinical angle",
                               "Joint angles over time",
                               "Repetitions",
                               "Comparison with normative ranges",
                               "Comparison with earlier sessions",
                               "Therapist's notes"};

class SessionReport : public ReportTest {};

/// The numbers on the line of the metrics table that starts with `name`.
std::vector<double> metricsRow(const QString& page, const QString& name) {
  const int from = page.indexOf("Metrics per clinical angle");
  const int to = page.indexOf("samples used", from);
  if (from < 0 || to < 0) return {};
  for (const QString& line : page.mid(from, to - from).split('\n')) {
    const QString l = line.trimmed();
    if (!l.startsWith(name)) continue;
    std::vector<double> v;
    for (const QString& tok : l.mid(name.size()).split(' ', Qt::SkipEmptyParts))
      v.push_back(tok.toDouble());
    return v;
  }
  return {};
}

TEST_F(SessionReport, TextHasEverySectionThePatientOnEveryPageAndTheMetrics) {
  const SimulatedSession sim = simulateSession({110, 120, 115, 118, 60});
  const SessionReportData d = sessionData(sim);
  const QString pdf = path("session.pdf");
  const int pages = writeSessionReport(d, pdf);
  ASSERT_GE(pages, 2);
  const QStringList text = pageTexts(pdf);
  ASSERT_EQ(text.size(), pages);
  const QString all = text.join('\n');
  for (const QString& s : kSections)
    EXPECT_TRUE(all.contains(s)) << "missing section " << s.toStdString();
  for (int i = 0; i < pages; ++i) {
    SCOPED_TRACE(i + 1);
    EXPECT_TRUE(text[i].contains("Anna Example"));
    EXPECT_TRUE(text[i].contains("2026-11-20"));
    EXPECT_TRUE(text[i].contains(QString("Page %1 of %2").arg(i + 1).arg(pages)));
  }
  for (const char* s : {"P-0042", "1961-03-14", "Dr. Jane Smith", "Flexion 120", "virtual-arm",
                        "Frozen shoulder", "Continue the programme twice a week."})
    EXPECT_TRUE(all.contains(s)) << s;
  // The calibration in words: the verdict and its reason, lengths in cm, mounting in deg, no
  // stored keys or matrices.
  const QString flat = all.simplified();
  for (const char* s :
       {"Sensor calibration: Usable, not perfect (worst: forearm gyroscope at 2.1",
        "upper arm 30.0 cm (shoulder to elbow), forearm 25.0 cm (elbow to wrist)",
        "Upper-arm sensor: 11.0 cm from the shoulder, mounted at 90.0 deg",
        "Forearm sensor: 20.0 cm from the elbow", "Camera: calibrated, 1.00 m from the shoulder"})
    EXPECT_TRUE(flat.contains(s)) << s;
  for (const char* raw : {"geometry.", "camera.R", "camera.", "l3:", "thu4", "\"verdict\""})
    EXPECT_FALSE(all.contains(raw)) << raw;
  EXPECT_TRUE(all.contains(QRegularExpression("Duration\\s+\\d+\\.\\d s"))) << "duration";

  // Each angle's row: min, max, ROM, peak and mean velocity as the metrics give them, in degrees.
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    const QString name = QString::fromUtf8(clinicalAngleInfo()[a].name.data());
    SCOPED_TRACE(name.toStdString());
    EXPECT_GE(all.count(name), 3) << "table, plot and bar name the angle";
    const AngleMetricsDeg m = inDegrees(sim.metrics.session.angle[a]);
    std::vector<double> row;
    for (const QString& page : text)
      if (row.empty()) row = metricsRow(page, name);
    ASSERT_EQ(row.size(), 6u);
    EXPECT_NEAR(row[0], m.minDeg, 0.051);
    EXPECT_NEAR(row[1], m.maxDeg, 0.051);
    EXPECT_NEAR(row[2], m.romDeg, 0.051);
    EXPECT_NEAR(row[3], m.peakVelocityDegPerS, 0.051);
    // Independent truth: the printed range is that of the simulated trajectory.
    EXPECT_NEAR(row[2], sim.trueRomDeg[a], 1.0);
  }
  // Five repetitions, one of them partial (60 deg against a 100+ deg reference); each row of the
  // table as the metrics give it.
  EXPECT_TRUE(all.contains("5 repetitions counted on Shoulder flexion: 4 full, 1 partial"));
  ASSERT_EQ(sim.metrics.repetitions.repetitions.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    const Repetition& rep = sim.metrics.repetitions.repetitions[i];
    const QString row = QString("%1 +%2 +%3 +%4 +%5 +%6")
                            .arg(i + 1)
                            .arg(rep.startS - sim.series.t.front(), 0, 'f', 2)
                            .arg(rep.endS - sim.series.t.front(), 0, 'f', 2)
                            .arg(rep.excursionRad * kRadToDeg, 0, 'f', 1)
                            .arg(inDegrees(rep.metrics.angle[0]).peakVelocityDegPerS, 0, 'f', 1)
                            .arg(rep.partial ? "yes" : "no");
    EXPECT_TRUE(all.contains(QRegularExpression("\\n" + row + "\\n"))) << row;
    // The truth: each excursion is its simulated peak minus the 10 deg rest.
    EXPECT_NEAR(rep.excursionRad * kRadToDeg, sim.peaksDeg[i] - 10, 1.0);
  }
  EXPECT_TRUE(all.contains("AAOS"));
  EXPECT_TRUE(all.contains("this session"));
  EXPECT_TRUE(all.contains("Change since last"));
  EXPECT_TRUE(all.contains("Other side"));
  EXPECT_TRUE(all.contains("shaded: protocol target 10.0 to 120.0 deg"));
  // The counted angle's plot numbers the repetitions; the partial fifth is "5p".
  EXPECT_TRUE(all.contains("numbers: repetitions at their peaks (p = partial)"));
  EXPECT_TRUE(all.contains(QRegularExpression("\\b4\\s+5p\\b")));
}

// Times are recording time, as the review shows them: from the recording's first row (here
// 1.3 s before the first analysed angle, the filter's start-up left out), not from the first
// analysed angle; an event marked 12.0 s into the recording is printed and drawn at 12.0 s.
TEST_F(SessionReport, TimesAreRecordingTimeAsInTheReview) {
  const SimulatedSession sim = simulateSession({110, 120, 115});
  SessionReportData d = sessionData(sim);
  const double start = sim.series.t.front() - 1.3;
  d.recordingStartS = start;
  d.session.notes = "Tired at the end.\n[0:12.0] Pain";
  d.events = parseEventMarks(d.session.notes.toStdString(), start);
  EXPECT_DOUBLE_EQ(timeOrigin(d), start);
  const QString pdf = path("times.pdf");
  writeSessionReport(d, pdf);
  const QString all = pageTexts(pdf).join('\n');
  ASSERT_EQ(sim.metrics.repetitions.repetitions.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const Repetition& rep = sim.metrics.repetitions.repetitions[i];
    // Independent of the report: the session clock's time less the first row's.
    const QString row = QString("\n%1 +%2 +%3 ")
                            .arg(i + 1)
                            .arg(rep.startS - start, 0, 'f', 2)
                            .arg(rep.endS - start, 0, 'f', 2);
    EXPECT_TRUE(all.contains(QRegularExpression(row))) << row.toStdString();
  }
  EXPECT_TRUE(all.simplified().contains(
      "Events marked (time since the recording began, as in the review): 0:12.0 Pain"))
      << all.toStdString();
  EXPECT_GE(all.count("Pain"), 2) << "listed and drawn on the plots";
  EXPECT_FALSE(all.contains("[0:12.0]")) << "the event line is not printed twice";
  EXPECT_TRUE(all.contains("Tired at the end."));
}

/// The grey normal-range bars of the normative comparison on a rendered page: per bar (top to
/// bottom), the first and last column (px) of its grey. A row's grey is split by the grid lines
/// under it (darker) and by the patient's blue bar, so runs less than 4 px apart are joined and
/// the bar's extent is that of its widest row (a row above or below the blue bar).
std::vector<std::pair<int, int>> normalBars(const QImage& img) {
  auto barGrey = [](QRgb c) {
    return std::abs(qRed(c) - qGreen(c)) < 4 && std::abs(qGreen(c) - qBlue(c)) < 4 &&
           qRed(c) >= 205 && qRed(c) <= 232;
  };
  std::vector<std::pair<int, int>> bars;
  std::pair<int, int> widest{0, -1};
  int bandRows = 0;
  for (int y = 0; y <= img.height(); ++y) {
    std::pair<int, int> best{0, -1}, cur{0, -1};
    for (int x = 0; y < img.height() && x < img.width(); ++x) {
      if (!barGrey(img.pixel(x, y))) continue;
      if (cur.second >= 0 && x - cur.second <= 4)
        cur.second = x;
      else
        cur = {x, x};
      if (cur.second - cur.first > best.second - best.first) best = cur;
    }
    if (best.second - best.first >= 30) {
      if (bandRows++ == 0 || best.second - best.first > widest.second - widest.first) widest = best;
    } else {
      if (bandRows >= 6) bars.push_back(widest);  // a bar is 5.5 mm (13 px) tall
      bandRows = 0;
    }
  }
  return bars;
}

// The normal ranges by age and sex: a 65-year-old woman's session picks the values of women aged
// 45-69 where the table gives them, AAOS for the rest, and the report says which source each
// limit comes from; the bars are drawn to those limits. The values are the test's own (made up,
// not the study's), so what is checked is the picking and the drawing.
TEST_F(SessionReport, NormalRangesByAgeAndSexNameTheirSourcePerAngle) {
  const SimulatedSession sim = simulateSession({110, 120, 115});
  SessionReportData d = sessionData(sim);  // born 1961-03-14, female, session 2026-11-20: 65
  const std::vector<SoucieValue> table = {
      {SoucieMotion::ShoulderFlexion, 3, Sex::Female, 160.5, 158.0, 163.0},
      {SoucieMotion::ElbowFlexion, 3, Sex::Female, 145.5, 144.0, 147.0},
      {SoucieMotion::ElbowExtension, 3, Sex::Female, 2.5, 1.5, 3.5},
      {SoucieMotion::ForearmPronation, 3, Sex::Female, 75.5, 74.0, 77.0},
      {SoucieMotion::ForearmSupination, 3, Sex::Female, 85.5, 84.0, 87.0},
      {SoucieMotion::ShoulderFlexion, 3, Sex::Male, 150.5, 148.0, 153.0},  // not her row
      {SoucieMotion::ShoulderFlexion, 2, Sex::Female, 170.5, 168.0, 173.0},
  };
  d.soucieValues = table;
  const QString pdf = path("soucie.pdf");
  writeSessionReport(d, pdf);
  const QString all = pageTexts(pdf).join('\n').simplified();
  const QString soucie = "Soucie et al. 2011, females aged 45-69";
  for (const QString& row :
       {QString("Shoulder flexion -60.0 – 160.5 %1 (maximum); AAOS (minimum)").arg(soucie),
        QString("Shoulder abduction 0.0 – 180.0 AAOS"),
        QString("Shoulder internal rotation -90.0 – 70.0 AAOS"),
        QString("Elbow flexion -2.5 – 145.5 %1").arg(soucie),
        QString("Forearm pronation -85.5 – 75.5 %1").arg(soucie)})
    EXPECT_TRUE(all.contains(row)) << row;
  // % of normal: flexion's largest angle against the flexion limit (160.5), not the whole arc.
  EXPECT_TRUE(all.contains("of 160.5 deg"));
  EXPECT_FALSE(all.contains("of 220.5 deg"));
  EXPECT_TRUE(all.contains("healthy females aged 45-69; the patient was 65 on the day"));
  EXPECT_TRUE(all.contains("Haemophilia 2011;17(3):500-507, doi:10.1111/j."));  // the line breaks
  EXPECT_TRUE(all.contains("archive.cdc.gov/www_cdc_gov/ncbddd/jointrom/"));
  EXPECT_TRUE(all.contains("AAOS: AAOS 1965"));
  EXPECT_FALSE(all.contains("are not used"));

  // Drawn to those limits: against the same report with the AAOS values, the flexion bar ends
  // 19.5 deg earlier, abduction's and rotation's bars are the same.
  SessionReportData aaos = d;
  aaos.soucieValues = {};
  writeSessionReport(aaos, path("aaos.pdf"));
  const QString aaosText = pageTexts(path("aaos.pdf")).join('\n').simplified();
  EXPECT_TRUE(aaosText.contains("this version has none for females aged 45-69"));
  EXPECT_TRUE(aaosText.contains("Shoulder flexion -60.0 – 180.0 AAOS"));
  // The page of the comparison; its first five grey bands are the bars (the table under them
  // has no grey fill).
  auto barsOf = [&](const QString& file) {
    QDir(dir.path()).mkpath(file);
    const QStringList text = pageTexts(path(file + ".pdf"));
    const std::vector<QImage> images = renderPages(path(file + ".pdf"), path(file));
    for (qsizetype i = 0; i < text.size() && i < static_cast<qsizetype>(images.size()); ++i) {
      if (!text[i].contains("Comparison with normative ranges")) continue;
      std::vector<std::pair<int, int>> bars = normalBars(images[static_cast<std::size_t>(i)]);
      if (bars.size() > 5) bars.resize(5);
      return bars;
    }
    return std::vector<std::pair<int, int>>{};
  };
  const auto withSoucie = barsOf("soucie");
  const auto withAaos = barsOf("aaos");
  ASSERT_EQ(withSoucie.size(), 5u) << "the normative bars were not found on any page";
  ASSERT_EQ(withAaos.size(), 5u);
  const double pxPerDeg = (withAaos[1].second - withAaos[1].first) / 180.0;  // abduction 0-180
  ASSERT_GT(pxPerDeg, 0.3);
  EXPECT_NEAR(withAaos[0].second - withSoucie[0].second, 19.5 * pxPerDeg, 1.5);
  EXPECT_NEAR(withAaos[0].first, withSoucie[0].first, 1.0);  // extension: AAOS in both
  for (int a : {1, 2}) {
    EXPECT_NEAR(withAaos[a].first, withSoucie[a].first, 1.0) << a;
    EXPECT_NEAR(withAaos[a].second, withSoucie[a].second, 1.0) << a;
  }
  EXPECT_NEAR(withAaos[4].second - withSoucie[4].second, 4.5 * pxPerDeg, 1.5);  // pronation 75.5
  EXPECT_NEAR(withAaos[4].first - withSoucie[4].first, 5.5 * pxPerDeg, 1.5);    // supination 85.5
}

// Out of the study's reach every range is AAOS and the report says why.
TEST_F(SessionReport, NormalRangesFallBackToAaosAndSayWhy) {
  const SimulatedSession sim = simulateSession({110});
  const std::vector<SoucieValue> table = {
      {SoucieMotion::ShoulderFlexion, 3, Sex::Female, 160.5, 158.0, 163.0},
      {SoucieMotion::ShoulderFlexion, 3, Sex::Male, 150.5, 148.0, 153.0}};
  struct Case {
    QString birth, sex, says;
  };
  const Case cases[] = {
      {"1950-01-02", "f",
       "the patient was 76 on the day of the session, outside the study's 2 to "
       "69 years"},
      {"1961-03-14", "x", "the patient's sex is not recorded as female or male"},
      {"", "m", "the date of birth is not recorded"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.says.toStdString());
    SessionReportData d = sessionData(sim);
    d.patient.birthDate = c.birth;
    d.patient.sex = c.sex;
    d.soucieValues = table;
    const QString pdf = path("fallback.pdf");
    writeSessionReport(d, pdf);
    const QString all = pageTexts(pdf).join('\n').simplified();
    EXPECT_TRUE(all.contains(c.says));
    EXPECT_TRUE(all.contains("Shoulder flexion -60.0 – 180.0 AAOS"));
    EXPECT_FALSE(all.contains("Soucie et al. 2011,"));
    EXPECT_FALSE(all.contains("doi:10.1111"));  // cited only when used
  }
}

TEST_F(SessionReport, PagesRenderNotBlankWithPlotsDrawn) {
  const SimulatedSession sim = simulateSession({110, 120, 115, 118, 60});
  const QString pdf = path("session.pdf");
  const int pages = writeSessionReport(sessionData(sim), pdf);
  const std::vector<QImage> images = renderPages(pdf, dir.path());
  ASSERT_EQ(static_cast<int>(images.size()), pages);
  const QStringList text = pageTexts(pdf);
  bool sawPlots = false, sawBand = false;
  for (int i = 0; i < pages; ++i) {
    SCOPED_TRACE(i + 1);
    const QImage& img = images[i];
    ASSERT_FALSE(img.isNull());
    // A4 at 60 dpi: 8.27 x 11.69 in.
    EXPECT_NEAR(img.width(), 496, 2);
    EXPECT_NEAR(img.height(), 702, 2);
    EXPECT_GT(inkFraction(img), 0.01) << "page looks blank";
    if (text[i].contains("Joint angles over time") || text[i].contains("Elbow flexion (deg)")) {
      // The angle curves span most of the plot width (the text width is 174 of 210 mm).
      const BlueInk b = blueInk(img);
      EXPECT_GT(b.count, 300);
      EXPECT_GT(b.maxX - b.minX, 0.6 * img.width());
      sawPlots = true;
      qint64 green = 0;
      for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
          const QRgb c = img.pixel(x, y);
          if (qGreen(c) > qRed(c) + 15 && qGreen(c) > qBlue(c) + 15) ++green;
        }
      if (green > 2000) sawBand = true;  // the shaded target band of shoulder flexion
    }
  }
  EXPECT_TRUE(sawPlots);
  EXPECT_TRUE(sawBand);
}

// The layout comes from the PDF writer's resolution, never the screen's: a report written by a
// process on a high-DPI screen (device pixel ratio 2, Qt scale factor 2) has its words in the
// same places as one written with the defaults. Each is written by a child run of this test.
// Qt 6 keeps the screens' logical DPI at 96, so what this catches is a dependence on the device
// pixel ratio or scale factor (sizing anything by qApp->devicePixelRatio() fails it).
TEST_F(SessionReport, SameLayoutOnAHighDpiScreen) {
  const QString out = qEnvironmentVariable("ARMTRACK_REPORT_CHILD_OUT");
  if (!out.isEmpty()) {
    writeSessionReport(sessionData(simulateSession({110, 120, 60})), out);
    return;
  }
  auto write = [&](const QString& name, bool highDpi) {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("ARMTRACK_REPORT_CHILD_OUT", path(name));
    env.remove("ARMTRACK_KEEP_REPORTS");
    if (highDpi) {
      // A 4K screen at 192 dpi with a device pixel ratio of 2 (the offscreen platform's own
      // configuration), and Qt's scale factor on top.
      QFile config(path("hidpi.json"));
      EXPECT_TRUE(config.open(QIODevice::WriteOnly));
      config.write(R"({"screens": [{"name": "hidpi", "x": 0, "y": 0, "width": 3840,
                       "height": 2160, "logicalDpi": 192, "logicalBaseDpi": 96, "dpr": 2}]})");
      config.close();
      env.insert("QT_QPA_PLATFORM", "offscreen:configfile=" + path("hidpi.json"));
      env.insert("QT_SCALE_FACTOR", "2");
      env.insert("QT_FONT_DPI", "192");
    }
    QProcess child;
    child.setProcessEnvironment(env);
    child.start(QCoreApplication::applicationFilePath(),
                {"--gtest_filter=SessionReport.SameLayoutOnAHighDpiScreen"});
    EXPECT_TRUE(child.waitForFinished(120000));
    EXPECT_EQ(child.exitCode(), 0) << child.readAllStandardOutput().toStdString();
    return pageTexts(path(name));
  };
  const QStringList normal = write("normal.pdf", false);
  const QStringList high = write("high.pdf", true);
  ASSERT_GE(normal.size(), 2);
  EXPECT_EQ(high, normal);
  // Every word with its box, from <body> on (the head holds the PDF's creation time).
  auto words = [&](const QString& name) {
    const QString html = QString::fromUtf8(run("pdftotext", {"-bbox", path(name), "-"}));
    return html.mid(html.indexOf("<body>"));
  };
  const QString bbox = words("high.pdf");
  const QString bboxNormal = words("normal.pdf");
  EXPECT_GT(bbox.count("<word "), 500);
  EXPECT_EQ(bbox, bboxNormal) << "word positions differ";
  EXPECT_TRUE(bbox.contains("width=\"595.")) << "A4 is 595 x 842 pt";
}

TEST_F(SessionReport, NoRepetitionsNoNotesNoEarlierSessions) {
  // A still arm: nothing to count.
  SimulatedSession sim = simulateSession({});
  SessionReportData d = sessionData(sim);
  d.session.notes.clear();
  d.earlierSessions.clear();
  d.otherSide.reset();
  d.protocol.reset();
  d.session.protocolName.clear();
  d.session.devicesJson = "{}";
  const QString pdf = path("still.pdf");
  writeSessionReport(d, pdf);
  const QString all = pageTexts(pdf).join('\n');
  for (const QString& s : kSections) EXPECT_TRUE(all.contains(s)) << s.toStdString();
  EXPECT_TRUE(all.contains("No repetitions were detected (0 repetitions)."));
  EXPECT_TRUE(all.contains("No notes."));
  EXPECT_TRUE(all.contains("No earlier sessions to compare with."));
  EXPECT_TRUE(all.contains("No devices were recorded"));
  EXPECT_FALSE(all.contains("shaded: protocol target"));
  EXPECT_FALSE(all.contains("numbers: repetitions at their peaks"));
}

// The trunk section (issue 26): the session's four values and each repetition's as given, the
// repetitions over the limit counted; "not measured" for a value without its sensor; no section
// for an analysis made before the trunk was measured.
TEST_F(SessionReport, TrunkCompensationSection) {
  const SimulatedSession sim = simulateSession({110, 120, 60});
  SessionReportData d = sessionData(sim);
  ASSERT_EQ(d.metrics.repetitions.repetitions.size(), 3u);
  TrunkCompensation t;
  t.session = {17.84, 9.12, 8.46, 18.27, std::nullopt};
  t.repetitions = {{17.84, 9.12, 8.46, 18.27, true},
                   {16.31, 8.05, 7.9, 16.6, true},
                   {6.52, 2.8, 3.51, 6.7, false}};
  t.repetitionsWithCompensation = 2;
  d.trunk = t;
  d.trunkFlexionLimitDeg = 12;
  QString pdf = path("trunk.pdf");
  writeSessionReport(d, pdf);
  QString all = pageTexts(pdf).join('\n');
  EXPECT_TRUE(all.contains("Trunk compensation")) << all.toStdString();
  EXPECT_TRUE(all.contains("17.8 deg"));
  EXPECT_TRUE(all.contains("18.3 cm"));
  EXPECT_TRUE(
      all.contains("2 of 3 repetitions were made with trunk compensation (trunk flexion "
                   "over 12.0 deg)."))
      << all.toStdString();
  // The table: one line per repetition with its four values and the verdict.
  const QRegularExpression row3(
      QStringLiteral("\\b3\\s+6\\.5\\s+2\\.8\\s+3\\.5\\s+6\\.7\\s+no\\b"));
  EXPECT_TRUE(row3.match(all).hasMatch()) << all.toStdString();
  const QRegularExpression row2(
      QStringLiteral("\\b2\\s+16\\.3\\s+8\\.1\\s+7\\.9\\s+16\\.6\\s+yes\\b"));
  EXPECT_TRUE(row2.match(all).hasMatch()) << all.toStdString();
  QDir().mkpath(path("trunkpages"));
  const std::vector<QImage> pages = renderPages(pdf, path("trunkpages"));
  EXPECT_FALSE(pages.empty());

  // A shoulder without a sternum sensor: the angles not measured, no limit.
  t.session = {std::nullopt, std::nullopt, std::nullopt, 12.5, std::nullopt};
  for (TrunkExtremes& r : t.repetitions) r = {std::nullopt, std::nullopt, std::nullopt, 11.0, {}};
  t.repetitionsWithCompensation.reset();
  d.trunk = t;
  d.trunkFlexionLimitDeg.reset();
  pdf = path("shoulder.pdf");
  writeSessionReport(d, pdf);
  all = pageTexts(pdf).join('\n');
  EXPECT_TRUE(all.contains("not measured"));
  EXPECT_TRUE(all.contains("12.5 cm"));
  EXPECT_FALSE(all.contains("repetitions were made with trunk compensation"));

  // Nothing measured: one sentence; analysed before the trunk: no section.
  d.trunk = TrunkCompensation{};
  pdf = path("none.pdf");
  writeSessionReport(d, pdf);
  all = pageTexts(pdf).join('\n');
  EXPECT_TRUE(all.contains("Not measured: the session had no sternum sensor"));
  d.trunk.reset();
  pdf = path("old.pdf");
  writeSessionReport(d, pdf);
  EXPECT_FALSE(pageTexts(pdf).join('\n').contains("Trunk compensation"));
}

TEST_F(SessionReport, LongNotesFlowOntoFurtherPagesWithNothingLost) {
  const SimulatedSession sim = simulateSession({110, 120});
  SessionReportData d = sessionData(sim);
  const int shortPages = writeSessionReport(d, path("short.pdf"));
  QStringList words;
  for (int i = 1; i <= 2500; ++i) words << QString("w%1").arg(i, 4, 10, QLatin1Char('0'));
  QString notes;
  for (int i = 0; i < words.size(); ++i) notes += words[i] + ((i + 1) % 100 == 0 ? "\n" : " ");
  d.session.notes = notes;
  const QString pdf = path("long.pdf");
  const int pages = writeSessionReport(d, pdf);
  EXPECT_GE(pages, shortPages + 2);
  const QStringList text = pageTexts(pdf);
  ASSERT_EQ(text.size(), pages);
  const QString all = text.join('\n');
  // Every word once, none clipped at a page end.
  const QRegularExpression word("\\bw(\\d{4})\\b");
  std::vector<int> seen(2501, 0);
  for (auto it = word.globalMatch(all); it.hasNext();) ++seen[it.next().captured(1).toInt()];
  for (int i = 1; i <= 2500; ++i) ASSERT_EQ(seen[i], 1) << "word " << i;
  EXPECT_TRUE(text.back().contains(QString("Page %1 of %1").arg(pages)));
  EXPECT_TRUE(text.back().contains("Anna Example"));
  const std::vector<QImage> images = renderPages(pdf, dir.path());
  ASSERT_EQ(static_cast<int>(images.size()), pages);
  for (const QImage& img : images) EXPECT_GT(inkFraction(img), 0.01);
}

// A long session with a gap and rows of NaN (dropped by the metrics, breaks in the plot): the
// plots are reduced to about two points per 0.25 mm, so the file stays small, and the report
// still states what was dropped.
TEST_F(SessionReport, LongSessionWithGapsAndNaNsStaysSmall) {
  SimulatedSession sim = simulateSession(std::vector<double>(200, 115.0));
  AngleSeries& s = sim.series;
  ASSERT_GT(s.t.size(), 80000u);
  for (std::size_t i = 5000; i < 5010; ++i)
    s.angle[i][2] = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 20000; i < s.t.size(); ++i) s.t[i] += 30.0;  // a 30 s gap
  ClinicalMetricsParams params;
  params.repetitions.primaryAngle = 0;
  sim.metrics = computeSessionMetrics(s, params);
  ASSERT_EQ(sim.metrics.rejectedNonFinite, 10u);
  ASSERT_EQ(sim.metrics.gaps, 1u);
  SessionReportData d = sessionData(sim);
  const QString pdf = path("long-session.pdf");
  writeSessionReport(d, pdf);
  EXPECT_LT(QFileInfo(pdf).size(), 1'500'000) << "plots not reduced";
  const QString all = pageTexts(pdf).join('\n');
  EXPECT_TRUE(all.contains(
      QString("%1 samples used, 10 rows rejected (not finite), 1 gaps").arg(sim.metrics.samples)));
  EXPECT_TRUE(all.contains("200 repetitions counted on Shoulder flexion"));
  EXPECT_TRUE(all.contains(QRegularExpression("\\n200 +\\d")));  // the last row of the table
  const std::vector<QImage> images = renderPages(pdf, dir.path());
  for (const QImage& img : images) EXPECT_GT(inkFraction(img), 0.01);
  // The plots break across the gap: no line in the plots' columns at its middle, lines at a time
  // with data. Plots span 32 to 190 mm from the page's left edge (PageWriter, Charts).
  const double span = s.t.back() - s.t.front();
  const double gapMiddle = s.t[20000] - 15.0 - s.t.front();
  auto blueInColumn = [&](const QImage& img, double tRel) {
    const int x = static_cast<int>(std::lround((32.0 + 158.0 * tRel / span) * 60 / 25.4));
    int count = 0;
    for (int dx = -1; dx <= 1; ++dx)
      for (int y = 0; y < img.height(); ++y) {
        const QRgb c = img.pixel(x + dx, y);
        if (qBlue(c) > 150 && qBlue(c) - qRed(c) > 60) ++count;
      }
    return count;
  };
  ASSERT_GE(images.size(), 2u);
  EXPECT_GT(blueInColumn(images[1], 100.0), 20) << "plots with data at 100 s";
  EXPECT_EQ(blueInColumn(images[1], gapMiddle), 0) << "a line drawn across the gap";
}

// Many earlier sessions: the comparison table runs onto a second page and repeats its header.
TEST_F(SessionReport, LongTablesRepeatTheirHeader) {
  SessionReportData d = sessionData(simulateSession({110, 120}));
  d.earlierSessions.clear();
  for (int i = 0; i < 90; ++i) {
    RomSnapshot r;
    r.date = QDate(2024, 1, 1).addDays(7 * i).toString(Qt::ISODate);
    r.sessionId = 1000 + i;
    r.romRad = {1.0 + 0.01 * i, 0.5, 0.4, 1.2, 0.9};
    d.earlierSessions.push_back(r);
  }
  d.session.devicesJson = "{not json";
  const QString pdf = path("many.pdf");
  writeSessionReport(d, pdf);
  const QStringList text = pageTexts(pdf);
  const QString all = text.join('\n');
  for (int i = 0; i < 90; ++i) EXPECT_TRUE(all.contains(QString("(#%1)").arg(1000 + i))) << i;
  int pagesWithHeader = 0;
  for (const QString& page : text)
    if (page.contains(QRegularExpression("\\nSession +Shoulder +Shoulder +Shoulder +Elbow")))
      ++pagesWithHeader;
  EXPECT_GE(pagesWithHeader, 2);  // 90 rows do not fit on one page
  EXPECT_TRUE(all.contains("(not valid JSON"));
}

TEST_F(SessionReport, AVeryLongNameIsCutInTheRunningHeadNotOverprinted) {
  SessionReportData d = sessionData(simulateSession({110}));
  d.patient.name = QString("Maximilian ").repeated(20).trimmed();
  const QString pdf = path("longname.pdf");
  writeSessionReport(d, pdf);
  const QStringList text = pageTexts(pdf);
  EXPECT_TRUE(text.join('\n').contains(QString::fromUtf8("…")));
  for (const QString& page : text) EXPECT_TRUE(page.contains("ArmTrack"));
}

TEST_F(SessionReport, NonLatinNamesAreSearchableText) {
  const SimulatedSession sim = simulateSession({110, 120});
  for (const QString& name : {QString::fromUtf8("Łukasz Żółć"), QString::fromUtf8("李雷"),
                              QString::fromUtf8("Ирина Петрова")}) {
    SCOPED_TRACE(name.toStdString());
    SessionReportData d = sessionData(sim);
    d.patient.name = name;
    d.therapistName = QString::fromUtf8("Zoë Ångström");
    const QString pdf = path(QString("names-%1.pdf").arg(name.size()));
    const int pages = writeSessionReport(d, pdf);
    const QStringList text = pageTexts(pdf);
    ASSERT_EQ(text.size(), pages);
    for (const QString& page : text) EXPECT_TRUE(page.contains(name));
    EXPECT_TRUE(text.join('\n').contains(QString::fromUtf8("Zoë Ångström")));
  }
}

TEST_F(SessionReport, UnwritablePathNamesItAndLeavesNoFile) {
  const SimulatedSession sim = simulateSession({110});
  const SessionReportData d = sessionData(sim);
  QFile plain(path("plain.txt"));
  ASSERT_TRUE(plain.open(QIODevice::WriteOnly));
  plain.write("x");
  plain.close();
  for (const QString& bad : {path("missing-folder/report.pdf"), path("plain.txt/report.pdf")}) {
    SCOPED_TRACE(bad.toStdString());
    try {
      writeSessionReport(d, bad);
      ADD_FAILURE() << "no error";
    } catch (const ReportError& e) {
      EXPECT_NE(std::string(e.what()).find(bad.toStdString()), std::string::npos) << e.what();
    }
    EXPECT_FALSE(QFile::exists(bad));
  }
  EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files | QDir::Dirs | QDir::NoDotAndDotDot),
            QStringList{"plain.txt"});
}

TEST_F(SessionReport, ReplacesAnEarlierFileWhole) {
  const SimulatedSession sim = simulateSession({110});
  const QString pdf = path("again.pdf");
  QFile old(pdf);
  ASSERT_TRUE(old.open(QIODevice::WriteOnly));
  old.write(QByteArray(5'000'000, 'x'));  // larger than the report: a leftover tail would show
  old.close();
  writeSessionReport(sessionData(sim), pdf);
  QFile f(pdf);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QByteArray bytes = f.readAll();
  EXPECT_TRUE(bytes.startsWith("%PDF-"));
  EXPECT_TRUE(bytes.trimmed().endsWith("%%EOF"));
  EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files), QStringList{"again.pdf"});
}

// Fonts need a QGuiApplication: a program with only a QCoreApplication (the CLI's default) gets
// a clear error, not a crash. Checked in a child run of this test that makes a QCoreApplication.
TEST_F(SessionReport, RefusesWithoutAGuiApplication) {
  if (qEnvironmentVariableIsSet("ARMTRACK_REPORT_CORE_APP")) {
    ASSERT_EQ(qobject_cast<QGuiApplication*>(QCoreApplication::instance()), nullptr);
    try {
      writeSessionReport(sessionData(simulateSession({110})), path("core.pdf"));
      FAIL() << "no error";
    } catch (const ReportError& e) {
      EXPECT_NE(std::string(e.what()).find("QGuiApplication"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(QFile::exists(path("core.pdf")));
    return;
  }
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("ARMTRACK_REPORT_CORE_APP", "1");
  QProcess child;
  child.setProcessEnvironment(env);
  child.start(QCoreApplication::applicationFilePath(),
              {"--gtest_filter=SessionReport.RefusesWithoutAGuiApplication"});
  ASSERT_TRUE(child.waitForFinished(120000));
  const QString out = QString::fromUtf8(child.readAllStandardOutput());
  EXPECT_EQ(child.exitCode(), 0) << out;
  EXPECT_TRUE(out.contains("[  PASSED  ] 1 test")) << out;
}

TEST_F(SessionReport, RefusesAnEmptySession) {
  SessionReportData d;
  d.session.id = 99;
  try {
    writeSessionReport(d, path("empty.pdf"));
    FAIL() << "no error";
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find("session 99"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(QFile::exists(path("empty.pdf")));
}

}  // namespace
}  // namespace armtrack::reports
