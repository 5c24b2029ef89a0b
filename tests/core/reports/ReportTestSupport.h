// Helpers for the report tests: a Qt GUI application (offscreen), a simulated exercise session
// with known angles, and the poppler tools (pdftotext, pdftoppm) that read the PDFs back.
#pragma once

#include <gtest/gtest.h>

#include <QByteArray>
#include <QCoreApplication>
#include <QDir>
#include <QGuiApplication>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <iostream>
#include <ostream>
#include <vector>

#include "core/kinematics/ClinicalAngles.h"
#include "core/metrics/ClinicalMetrics.h"
#include "core/reports/ReportData.h"
#include "core/simulation/Trajectory.h"

// So that gtest can print QStrings in failure messages.
inline std::ostream& operator<<(std::ostream& os, const QString& s) {
  return os << s.toStdString();
}
inline std::ostream& operator<<(std::ostream& os, const QStringList& l) {
  return os << l.join(QStringLiteral(", ")).toStdString();
}

namespace armtrack::reports::test {

/// A QGuiApplication on the offscreen platform, made once per process (fonts need it).
inline void ensureGuiApp() {
  if (QCoreApplication::instance()) return;
  static int argc0 = 1;
  static char name0[] = "test_reports";
  static char* argv0[] = {name0, nullptr};
  // Offscreen, unless a test asked for an offscreen configuration of its own (screen DPI).
  if (!qEnvironmentVariable("QT_QPA_PLATFORM").startsWith(QStringLiteral("offscreen")))
    qputenv("QT_QPA_PLATFORM", "offscreen");
  if (qEnvironmentVariableIsSet("ARMTRACK_REPORT_CORE_APP")) {  // a child run without Qt Gui
    new QCoreApplication(argc0, argv0);
    return;
  }
  new QGuiApplication(argc0, argv0);  // lives until the process ends
}

/// The first of the poppler-utils tools the tests need that is not on PATH, or "".
inline std::string missingPdfTool() {
  for (const char* tool : {"pdftotext", "pdftoppm"})
    if (QStandardPaths::findExecutable(QString::fromLatin1(tool)).isEmpty()) return tool;
  return {};
}

/// Runs a program; fails the test (and returns "") on a non-zero exit.
inline QByteArray run(const QString& program, const QStringList& args) {
  QProcess p;
  p.start(program, args);
  if (!p.waitForFinished(120000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
    ADD_FAILURE() << program.toStdString() << " " << args.join(' ').toStdString()
                  << " failed: " << p.readAllStandardError().toStdString();
    return {};
  }
  return p.readAllStandardOutput();
}

/// The text of each page (pdftotext -layout; pages are separated by form feeds).
inline QStringList pageTexts(const QString& pdf) {
  const QString all = QString::fromUtf8(run("pdftotext", {"-layout", "-enc", "UTF-8", pdf, "-"}));
  QStringList pages = all.split(QLatin1Char('\f'));
  if (!pages.isEmpty() && pages.back().trimmed().isEmpty()) pages.removeLast();
  return pages;
}

/// Renders every page at 60 dpi with pdftoppm and loads the PNGs in page order.
inline std::vector<QImage> renderPages(const QString& pdf, const QString& outDir) {
  run("pdftoppm", {"-png", "-r", "60", pdf, outDir + "/page"});
  QDir dir(outDir);
  const QStringList files = dir.entryList({"page*.png"}, QDir::Files, QDir::Name);
  std::vector<QImage> images;
  for (const QString& f : files) images.emplace_back(dir.filePath(f));
  return images;
}

/// Fraction of pixels that are not (near) white.
inline double inkFraction(const QImage& img) {
  qint64 ink = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x)
      if (qGray(img.pixel(x, y)) < 235) ++ink;
  return static_cast<double>(ink) / (static_cast<double>(img.width()) * img.height());
}

/// Pixels of the plots' line colour (a saturated blue), and their horizontal extent (px).
struct BlueInk {
  qint64 count = 0;
  int minX = 1 << 30, maxX = -1;
};
inline BlueInk blueInk(const QImage& img) {
  BlueInk b;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const QRgb c = img.pixel(x, y);
      if (qBlue(c) > 150 && qBlue(c) - qRed(c) > 60 && qBlue(c) - qGreen(c) > 40) {
        ++b.count;
        b.minX = std::min(b.minX, x);
        b.maxX = std::max(b.maxX, x);
      }
    }
  return b;
}

/// A shoulder-flexion exercise from rest (10 deg) to each peak and back, the other angles
/// following in proportion, minimum-jerk moves (core/simulation), sampled at 100 Hz. The true
/// range of motion of shoulder flexion is max(peaks) - 10 deg.
struct SimulatedSession {
  AngleSeries series;
  SessionMetrics metrics;
  ClinicalAngles rest{10, 5, 0, 20, 0};
  ClinicalAngles top{100, 25, 15, 60, 20};
  std::vector<double> peaksDeg;
  /// True range (deg) of angle a over the trajectory, from the noise-free key postures.
  std::array<double, kNumClinicalAngles> trueRomDeg{};
};

inline SimulatedSession simulateSession(const std::vector<double>& peaksDeg) {
  SimulatedSession s;
  s.peaksDeg = peaksDeg;
  MinimumJerkPath path;
  const auto restA = asArray(s.rest), topA = asArray(s.top);
  path.add(0.0, fromClinical(s.rest));
  path.hold(1.5);
  std::array<double, kNumClinicalAngles> hi = restA, lo = restA;
  for (double peak : peaksDeg) {
    const double f = (peak - restA[0]) / (topA[0] - restA[0]);
    std::array<double, kNumClinicalAngles> c{};
    for (int a = 0; a < kNumClinicalAngles; ++a) {
      c[a] = restA[a] + f * (topA[a] - restA[a]);
      hi[a] = std::max(hi[a], c[a]);
      lo[a] = std::min(lo[a], c[a]);
    }
    const ClinicalAngles ca{c[0], c[1], c[2], c[3], c[4]};
    path.add(path.endTime() + 1.4, fromClinical(ca));
    path.hold(0.5);
    path.add(path.endTime() + 1.4, fromClinical(s.rest));
    path.hold(1.0);
  }
  path.hold(1.0);
  for (int a = 0; a < kNumClinicalAngles; ++a) s.trueRomDeg[a] = hi[a] - lo[a];
  std::vector<double> t;
  std::vector<JointVector> joints;
  for (double ts = 0; ts <= path.endTime(); ts += 0.01) {
    t.push_back(1000.0 + ts);  // a session clock that does not start at zero
    joints.push_back(path.at(ts).th);
  }
  s.series = angleSeriesFromJoints(t, joints);
  ClinicalMetricsParams params;
  params.repetitions.primaryAngle = 0;
  s.metrics = computeSessionMetrics(s.series, params);
  return s;
}

/// A complete report input around a simulated session.
inline SessionReportData sessionData(const SimulatedSession& sim) {
  SessionReportData d;
  d.patient.id = 7;
  d.patient.code = "P-0042";
  d.patient.name = "Anna Example";
  d.patient.birthDate = "1961-03-14";
  d.patient.sex = "f";
  d.patient.affectedSide = "right";
  d.patient.diagnosis = "Frozen shoulder";
  d.session.id = 31;
  d.session.patientId = 7;
  d.session.patientCode = d.patient.code;
  d.session.protocolName = "Flexion 120";
  d.session.startedAt = "2026-11-20T09:15:00Z";
  d.session.durationS = sim.metrics.durationS;
  d.session.status = "complete";
  d.session.devicesJson = R"({"imu_upper":{"plugin":"virtual-arm","rate_hz":100},"camera":"none"})";
  // The recording's sidecar as the records store it (docs/recording-format.md), with a camera.
  d.session.calibrationJson =
      R"({"format":"armtrack-recording","version":1,"side":"right","g":9.81,"up":[-1,0,0],)"
      R"("geometry":{"l3":0.30,"l6":0.25,"lu3":0.11,"thu4":1.5707963,"lu5":0.02,"lf6":0.2,)"
      R"("thf7":1.5707963,"lf8":0.01},"camera":{"fx":600,"fy":600,"cx":320,"cy":240,)"
      R"("dist":[0,0,0,0,0],"R":[1,0,0,0,1,0,0,0,1],"t":[0.0,0.6,0.8]}})";
  // What the GUI stores beside the filter: the sensor calibration's verdict and its reason.
  d.session.filterJson =
      R"({"filter":"ekf","sensor_calibration":{"verdict":"usable","reason":"Usable, not )"
      R"(perfect (worst: forearm gyroscope at 2.1 noise levels)."}})";
  d.session.notes = "Patient tolerated the exercise well.\nContinue the programme twice a week.";
  storage::Protocol p;
  p.name = "Flexion 120";
  p.angleKey = "shoulder_flexion";
  p.targetMinDeg = 10;
  p.targetMaxDeg = 120;
  p.repetitions = 5;
  d.protocol = p;
  d.therapistName = "Dr. Jane Smith";
  d.angles = sim.series;
  d.metrics = sim.metrics;
  RomSnapshot earlier;
  earlier.date = "2026-11-06T10:00:00Z";
  earlier.sessionId = 12;
  earlier.romRad = {1.5, 0.3, 0.2, 0.6, std::nullopt};
  d.earlierSessions.push_back(earlier);
  RomSnapshot other;
  other.date = "2026-10-30";
  other.romRad = {2.8, 2.6, 1.9, 2.4, 2.7};
  d.otherSide = other;
  d.generatedAt = QDateTime::fromString("2026-11-25T10:00:00Z", Qt::ISODate);
  return d;
}

/// A report test: a GUI application, the poppler tools (skipped, naming the package, when they
/// are missing) and a temporary folder for the PDFs. ARMTRACK_KEEP_REPORTS=1 keeps the folder
/// to look at (its path is printed).
class ReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ensureGuiApp();
    if (const std::string tool = missingPdfTool(); !tool.empty())
      GTEST_SKIP() << tool
                   << " not found (Debian package poppler-utils, packaging/deps-debian12.sh)";
    ASSERT_TRUE(dir.isValid());
    if (qEnvironmentVariableIsSet("ARMTRACK_KEEP_REPORTS")) {
      dir.setAutoRemove(false);
      std::cout << "reports kept in " << dir.path().toStdString() << std::endl;
    }
  }
  QString path(const QString& name) const { return dir.filePath(name); }
  QTemporaryDir dir;
};

}  // namespace armtrack::reports::test
