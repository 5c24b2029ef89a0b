// `record --db`: a live session recorded straight into the clinical records (issue 10), on SQLite
// and on PostgreSQL: the rows arrive as chunks of under a second, a SIGKILL loses at most the last
// second and leaves the session marked interrupted, a write the database refuses (a full disk) is
// told and leaves what was written intact, and the recorded session's PDF report has every section
// with the stored metrics, which match the virtual arm's true angles.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <numbers>
#include <sstream>

#include "app/cli/Cli.h"
#include "core/io/Recording.h"
#include "core/kinematics/ClinicalAngles.h"
#include "tests/core/reports/ReportTestSupport.h"
#include "tests/support/DatabaseEngines.h"

using armtrack::cli::runCli;
using armtrack::test::Engine;
using Clock = std::chrono::steady_clock;

namespace {

constexpr const char* kPass = "admin-pass-1";

/// How far a recorded session's minimum, maximum and range of motion may be from the virtual
/// arm's true ones (deg): issue 10's 1 deg. Measured on 8 s of its default multi-joint motion:
/// ROM within 0.13 deg, minimum and maximum within 0.24 deg, on both engines.
constexpr double kTruthTolDeg = 1.0;

struct Result {
  int code;
  std::string out, err;
};

class RecordDb : public ::testing::TestWithParam<Engine> {
 protected:
  void SetUp() override {
    ASSERT_TRUE(m_dir.isValid());
    m_db = armtrack::test::newDatabase(GetParam(), m_dir, "clinic").toStdString();
    ::setenv("ARMTRACK_PASSWORD", kPass, 1);
    const Result init = run({"db", "init", "--admin", "boss"}, false);
    ASSERT_EQ(init.code, 0) << init.err;
    const Result p = run({"patient", "add", "--code", "P01", "--name", "Ada Example", "--birth",
                          "1950-01-02", "--sex", "f", "--side", "right"});
    ASSERT_EQ(p.code, 0) << p.err;
  }
  void TearDown() override { ::unsetenv("ARMTRACK_PASSWORD"); }

  Result run(std::vector<std::string> args, bool signIn = true) {
    args.insert(args.end(), {"--db", m_db});
    if (signIn) args.insert(args.end(), {"--user", "boss"});
    std::ostringstream out, err;
    const int code = runCli(args, out, err);
    return {code, out.str(), err.str()};
  }
  QStringList recordArgs(const char* duration) const {
    return {"record",
            "--device",
            "virtual-arm",
            "--duration",
            duration,
            "--db",
            QString::fromStdString(m_db),
            "--user",
            "boss",
            "--patient",
            "P01",
            "--plugins",
            ARMTRACK_PLUGIN_DIR,
            "--quiet"};
  }
  QJsonObject show(const std::string& id) {
    const Result r = run({"session", "show", id, "--json"});
    EXPECT_EQ(r.code, 0) << r.err;
    return QJsonDocument::fromJson(QByteArray::fromStdString(r.out)).object();
  }
  /// (t_first, t_last) of every chunk of the session, in order, read with plain SQL.
  std::vector<std::pair<double, double>> chunks(const std::string& id) {
    std::vector<std::pair<double, double>> spans;
    for (const QVariantList& row : armtrack::test::rawQuery(
             QString::fromStdString(m_db),
             QString("SELECT t_first, t_last FROM recording_chunks WHERE session_id = %1 "
                     "ORDER BY seq")
                 .arg(std::stoll(id))))
      spans.emplace_back(row[0].toDouble(), row[1].toDouble());
    return spans;
  }
  /// Waits (up to 60 s, while p runs) until the session's chunks reach `seconds` of session
  /// time; the last chunk's end, or -1.
  double waitForChunksTo(QProcess& p, const std::string& id, double seconds) {
    for (int i = 0; i < 600 && p.state() == QProcess::Running; ++i) {
      const auto spans = chunks(id);
      if (!spans.empty() && spans.back().second >= seconds) return spans.back().second;
      p.waitForFinished(100);
    }
    return -1.0;
  }

  QTemporaryDir m_dir;
  std::string m_db;
};

/// Reads the child's standard output until the "session ID" line; the id, or "" after 20 s.
std::string waitForSessionLine(QProcess& p) {
  for (int i = 0; i < 200; ++i) {
    p.waitForReadyRead(100);
    while (p.canReadLine()) {
      const QString line = QString::fromUtf8(p.readLine()).trimmed();
      if (line.startsWith("session ")) return line.mid(8).toStdString();
    }
  }
  return {};
}

}  // namespace

TEST_P(RecordDb, RecordsASessionInChunksOfUnderASecond) {
  QProcess p;
  p.start(ARMTRACK_CLI, recordArgs("3"));
  ASSERT_TRUE(p.waitForFinished(60000));
  const std::string out = p.readAllStandardOutput().toStdString();
  ASSERT_EQ(p.exitCode(), 0) << out << p.readAllStandardError().toStdString();
  ASSERT_EQ(out.rfind("session ", 0), 0u) << out;
  const std::string id = out.substr(8, out.find('\n') - 8);

  const QJsonObject s = show(id);
  EXPECT_EQ(s["status"].toString(), "complete");
  EXPECT_EQ(s["patient"].toString(), "P01");
  EXPECT_GT(s["duration_s"].toDouble(), 2.0);
  EXPECT_GT(s["samples"].toInteger(), 2000);    // two IMUs at 1 kHz for about 3 s
  EXPECT_EQ(s["estimate_version"].toInt(), 1);  // analysed once stored, as an import is
  // What it was recorded with: the device, and the live filter its analysis uses too.
  EXPECT_EQ(s["devices"].toObject()["virtual-arm#1"].toObject()["plugin"].toString(),
            "virtual-arm");
  EXPECT_EQ(s["filter_settings"].toObject()["filter"].toString(), "ekf");
  EXPECT_TRUE(s["metrics"].isObject());
  // The count printed is what the database holds.
  EXPECT_NE(
      out.find("recorded " + std::to_string(s["rows"].toInteger()) + " rows in session " + id),
      std::string::npos)
      << out;

  const auto spans = chunks(id);
  ASSERT_GE(spans.size(), 3u);
  for (std::size_t i = 0; i < spans.size(); ++i) {
    EXPECT_LT(spans[i].second - spans[i].first, 1.0) << "chunk " << i;
    if (i > 0) {
      EXPECT_GE(spans[i].first, spans[i - 1].second) << "chunk " << i;
    }
  }
  // The rows read back as a recording, in time order, with the live estimates beside them.
  const std::string csv = m_dir.filePath("back.csv").toStdString();
  const Result exp = run({"export", id, "--format", "recording", "--out", csv});
  ASSERT_EQ(exp.code, 0) << exp.err;
  const armtrack::Recording rec = armtrack::readRecording(csv);
  EXPECT_EQ(static_cast<long long>(rec.samples.size()), s["rows"].toInteger());
  ASSERT_FALSE(rec.samples.empty());
  EXPECT_TRUE(rec.samples.back().trueAngles.has_value());
  int estimated = 0;
  for (const armtrack::ArmSample& r : rec.samples) estimated += r.estimate.has_value();
  EXPECT_GT(estimated, 1000);
}

// The virtual arm's resolution=shimmer3 puts its readings on a Shimmer3's lattice, which the
// records store as counts (the chunk codec's lattice mode): every IMU value read back is a whole
// count times the converter's step, and the chunks take far less than the same recording's at
// full precision (the live estimates, full-precision doubles, are in both).
TEST_P(RecordDb, ARecordingAtAShimmer3sResolutionIsStoredAsCounts) {
  auto record = [&](const char* options) {
    QStringList args = recordArgs("3");
    args[2] = QString("virtual-arm:truth=off,%1").arg(options);
    QProcess p;
    p.start(ARMTRACK_CLI, args);
    EXPECT_TRUE(p.waitForFinished(60000));
    const std::string out = p.readAllStandardOutput().toStdString();
    EXPECT_EQ(p.exitCode(), 0) << out << p.readAllStandardError().toStdString();
    return out.substr(8, out.find('\n') - 8);
  };
  const std::string full = record("resolution=full"), shimmer = record("resolution=shimmer3");
  auto bytesPerRow = [&](const std::string& id) {
    const auto rows = armtrack::test::rawQuery(
        QString::fromStdString(m_db),
        QString("SELECT sum(length(data)), sum(row_count) FROM recording_chunks WHERE "
                "session_id = %1")
            .arg(std::stoll(id)));
    return rows.at(0)[0].toDouble() / rows.at(0)[1].toDouble();
  };
  const double fullBytes = bytesPerRow(full), shimmerBytes = bytesPerRow(shimmer);
  std::printf("[ figures  ] record --db, bytes a row: full precision %.1f, shimmer3 %.1f\n",
              fullBytes, shimmerBytes);
  EXPECT_LT(shimmerBytes, 0.7 * fullBytes);

  const std::string csv = m_dir.filePath("shimmer.csv").toStdString();
  const Result exp = run({"export", shimmer, "--format", "recording", "--out", csv});
  ASSERT_EQ(exp.code, 0) << exp.err;
  const armtrack::Recording rec = armtrack::readRecording(csv);
  constexpr double kDeg = std::numbers::pi / 180.0;
  std::size_t values = 0;
  for (const armtrack::ArmSample& s : rec.samples)
    for (const auto* imu : {&s.upperArm, &s.forearm})
      if (*imu)
        for (int k = 0; k < 3; ++k) {
          const double g = (**imu).gyr[k] / kDeg * 65.5, a = (**imu).acc[k] * 83.0;
          ASSERT_NEAR(g, std::round(g), 1e-6);
          ASSERT_NEAR(a, std::round(a), 1e-6);
          values += 2;
        }
  EXPECT_GT(values, 12000u);  // two IMUs at 1 kHz for about 3 s
}

// Another process watches the session grow while it is recorded (a GUI would), then the recorder
// is killed: what the watcher saw stays, and at most the last second is lost. On SQLite this also
// holds the recorder to its file locks: had it lost them, the watcher closing its connection would
// checkpoint the database and delete the write-ahead log the recorder goes on appending to, so the
// watcher would never see the recording grow and the kill would lose everything after that.
TEST_P(RecordDb, SigkillLosesAtMostTheLastSecondAndMarksTheSessionInterrupted) {
  QProcess p;
  p.start(ARMTRACK_CLI, recordArgs("20"));
  ASSERT_TRUE(p.waitForStarted());
  const std::string id = waitForSessionLine(p);
  const Clock::time_point started = Clock::now();  // the session's clock starts just after
  ASSERT_FALSE(id.empty()) << p.readAllStandardError().toStdString();
  // Kill it once the watcher sees 3 s stored, however long a loaded machine took to get there.
  const double seen = waitForChunksTo(p, id, 3.0);
  ASSERT_GE(seen, 3.0) << "the recording did not grow for a watcher; "
                       << p.readAllStandardError().toStdString();
  const double killedAt = std::chrono::duration<double>(Clock::now() - started).count();
  p.kill();  // SIGKILL: no chance to commit anything more
  ASSERT_TRUE(p.waitForFinished());

  const QJsonObject s = show(id);  // opening the database finds the dead recorder
  EXPECT_EQ(s["status"].toString(), "interrupted");
  const auto spans = chunks(id);
  ASSERT_FALSE(spans.empty());
  EXPECT_GE(spans.back().second, seen) << "what the watcher saw was lost";
  const double lost = killedAt - spans.back().second;
  std::cout << "killed at " << killedAt << " s of session time; stored up to "
            << spans.back().second << " s: lost " << lost << " s\n";
  // A chunk is committed every 0.7-0.9 s of data; 0.2 s allows for the pipeline's latency and
  // the scheduler of a loaded test machine.
  EXPECT_LT(lost, 1.2);
  EXPECT_EQ(run({"db", "check"}).code, 0);  // opens clean
  const Result exp = run(
      {"export", id, "--format", "recording", "--out", m_dir.filePath("killed.csv").toStdString()});
  EXPECT_EQ(exp.code, 0) << exp.err;  // every stored chunk decodes
}

// A home account's recording (what the home window makes, through the same sink) is marked as
// recorded at home, and a kill keeps it up to the last second, marked interrupted.
TEST_P(RecordDb, AHomeAccountsRecordingIsMarkedHomeAndKeptWhenKilled) {
  ::setenv("ARMTRACK_NEW_PASSWORD", "home-pass-1", 1);
  const Result add = run({"user", "add", "home1", "--role", "home", "--patient", "P01"});
  ::unsetenv("ARMTRACK_NEW_PASSWORD");
  ASSERT_EQ(add.code, 0) << add.err;
  QStringList args = recordArgs("20");
  args[args.indexOf("boss")] = "home1";
  QProcess p;
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("ARMTRACK_PASSWORD", "home-pass-1");
  p.setProcessEnvironment(env);
  p.start(ARMTRACK_CLI, args);
  ASSERT_TRUE(p.waitForStarted());
  const std::string id = waitForSessionLine(p);
  ASSERT_FALSE(id.empty()) << p.readAllStandardError().toStdString();
  const double seen = waitForChunksTo(p, id, 2.0);
  ASSERT_GE(seen, 2.0) << p.readAllStandardError().toStdString();
  p.kill();
  ASSERT_TRUE(p.waitForFinished());
  const QJsonObject s = show(id);
  EXPECT_EQ(s["status"].toString(), "interrupted");
  EXPECT_EQ(s["setting"].toString(), "home");
  EXPECT_TRUE(s["pain_score"].isNull());
  const auto spans = chunks(id);
  ASSERT_FALSE(spans.empty());
  EXPECT_GE(spans.back().second, seen);
  // A therapist's recording is marked clinic.
  QProcess q;
  q.start(ARMTRACK_CLI, recordArgs("1"));
  ASSERT_TRUE(q.waitForFinished(60000));
  const std::string out = q.readAllStandardOutput().toStdString();
  ASSERT_EQ(q.exitCode(), 0) << out;
  EXPECT_EQ(show(out.substr(8, out.find('\n') - 8))["setting"].toString(), "clinic");
}

// SQLite: the file size limit stands in for a full disk (writes past it fail with EFBIG; the
// signal it would raise is ignored, as a full disk raises none). PostgreSQL: the server refuses
// the chunks' inserts from the third second on, as it refuses them when its disk is full ("could
// not extend file": an error for the statement, the connection and the server stay up).
TEST_P(RecordDb, AFullDiskIsToldAndWhatWasWrittenStaysIntact) {
  QProcess p;
  if (GetParam() == Engine::Sqlite)
    p.setChildProcessModifier([limit = std::filesystem::file_size(m_db) + 160 * 1024] {
      std::signal(SIGXFSZ, SIG_IGN);
      const rlimit r{limit, limit};
      setrlimit(RLIMIT_FSIZE, &r);
    });
  p.start(ARMTRACK_CLI, recordArgs("6"));
  ASSERT_TRUE(p.waitForStarted());
  const std::string id = waitForSessionLine(p);
  ASSERT_FALSE(id.empty()) << p.readAllStandardError().toStdString();
  if (GetParam() == Engine::Postgres) {
    ASSERT_GE(waitForChunksTo(p, id, 2.0), 2.0);
    armtrack::test::rawSql(QString::fromStdString(m_db),
                           {"REVOKE INSERT ON recording_chunks FROM armtrack_test"});
  }
  ASSERT_TRUE(p.waitForFinished(60000));
  const std::string out = p.readAllStandardOutput().toStdString();
  const std::string err = p.readAllStandardError().toStdString();
  EXPECT_EQ(p.exitCode(), 1) << out << err;
  EXPECT_NE(err.find("rows were lost"), std::string::npos) << err;
  EXPECT_NE(err.find("cannot store the recording"), std::string::npos) << err;

  EXPECT_EQ(run({"db", "check"}).code, 0);
  const QJsonObject s = show(id);
  EXPECT_EQ(s["status"].toString(), "interrupted");  // rows were lost: not complete
  const long long stored = s["rows"].toInteger();
  EXPECT_GT(stored, 0);
  // What the summary says was recorded is what the database holds, and the rows it says were
  // lost are those the error names (before: "lost 0" beside "4224 of 5015 rows were lost").
  EXPECT_NE(out.find("recorded " + std::to_string(stored) + " rows"), std::string::npos) << out;
  const std::size_t of = err.find(" of ");
  const std::size_t says = err.rfind("incomplete: ", of);
  ASSERT_NE(of, std::string::npos) << err;
  ASSERT_NE(says, std::string::npos) << err;
  const std::string lostRows = err.substr(says + 12, of - says - 12);
  const std::size_t summary = out.find("session summary:");
  ASSERT_NE(summary, std::string::npos) << out;
  EXPECT_NE(out.find("lost " + lostRows + "\n", summary), std::string::npos)
      << lostRows << " rows lost, but the summary says: " << out;
  const std::string csv = m_dir.filePath("full.csv").toStdString();
  ASSERT_EQ(run({"export", id, "--format", "recording", "--out", csv}).code, 0);
  EXPECT_EQ(static_cast<long long>(armtrack::readRecording(csv).samples.size()), stored);
}

// Acceptance 3 of issue 10: the PDF report of a session recorded live from the virtual arm, read
// back as a reader would (pdftotext for the words, pdftoppm for the pages): every section, the
// devices it was recorded with, the metrics that session show gives, and plots drawn.
TEST_P(RecordDb, ReportOfARecordedVirtualArmSessionHasEverySection) {
  namespace rt = armtrack::reports::test;
  if (const std::string tool = rt::missingPdfTool(); !tool.empty())
    GTEST_SKIP() << tool << " not found (Debian package poppler-utils)";
  QProcess rec;
  rec.start(ARMTRACK_CLI, recordArgs("8"));
  ASSERT_TRUE(rec.waitForFinished(90000));
  const std::string out = rec.readAllStandardOutput().toStdString();
  ASSERT_EQ(rec.exitCode(), 0) << out << rec.readAllStandardError().toStdString();
  const std::string id = out.substr(8, out.find('\n') - 8);
  const QJsonObject s = show(id);
  ASSERT_EQ(s["status"].toString(), "complete");
  ASSERT_TRUE(s["metrics"].isObject()) << "record --db analyses the session";

  const QString pdf = m_dir.filePath("report.pdf");
  QProcess report;
  report.start(ARMTRACK_CLI, {"report", QString::fromStdString(id), "--pdf", pdf, "--db",
                              QString::fromStdString(m_db), "--user", "boss"});
  ASSERT_TRUE(report.waitForFinished(120000));
  ASSERT_EQ(report.exitCode(), 0) << report.readAllStandardError().toStdString();

  const QStringList text = rt::pageTexts(pdf);
  ASSERT_GE(text.size(), 2);
  const QString all = text.join('\n');
  for (const char* section : {"Session report", "Patient and session", "Devices and calibration",
                              "Metrics per clinical angle", "Joint angles over time", "Repetitions",
                              "Comparison with normative ranges",
                              "Comparison with earlier sessions", "Therapist's notes"})
    EXPECT_TRUE(all.contains(section)) << "missing section " << section;
  for (qsizetype i = 0; i < text.size(); ++i) {
    EXPECT_TRUE(text[i].contains("Ada Example")) << "page " << i + 1;
    EXPECT_TRUE(text[i].contains(QString("Page %1 of %2").arg(i + 1).arg(text.size())));
  }
  // The devices it was recorded with: the plugin, and its streams with their rates.
  // In words: the plugin, its streams and options; no stored keys.
  EXPECT_TRUE(all.contains(QRegularExpression("virtual-arm: [^\\n]*Hz"))) << all.left(3000);
  EXPECT_FALSE(all.contains(".plugin:")) << all.left(3000);
  EXPECT_TRUE(all.contains(QRegularExpression("upper.arm[^\\n]*1000 Hz"))) << all.left(3000);
  EXPECT_FALSE(all.contains("No devices were recorded"));
  // Each angle's row of the metrics table is what session show gives (min, max, ROM and peak
  // velocity, printed to 0.1), and the stored range is that of the virtual arm's own trajectory:
  // the true angles it records beside its sensors (true_th*), truth independent of the
  // estimator and the metrics, over the span the analysis covers (it leaves out the filter's
  // start-up second): the first and last time of the exported clinical angles.
  const QString anglesCsv = m_dir.filePath("angles.csv");
  ASSERT_EQ(run({"export", id, "--format", "csv", "--out", anglesCsv.toStdString()}).code, 0);
  QFile anglesFile(anglesCsv);
  ASSERT_TRUE(anglesFile.open(QIODevice::ReadOnly));
  const QList<QByteArray> lines = anglesFile.readAll().trimmed().split('\n');
  ASSERT_GT(lines.size(), 1000);
  const double analysedFrom = lines[1].split(',')[0].toDouble();
  const double analysedTo = lines.back().split(',')[0].toDouble();
  ASSERT_LT(analysedFrom, 2.0);
  ASSERT_GT(analysedTo, 7.5);
  const std::string csv = m_dir.filePath("recorded.csv").toStdString();
  ASSERT_EQ(run({"export", id, "--format", "recording", "--out", csv}).code, 0);
  const armtrack::Recording recorded = armtrack::readRecording(csv);
  std::array<double, 5> trueLo, trueHi;
  trueLo.fill(std::numeric_limits<double>::infinity());
  trueHi.fill(-std::numeric_limits<double>::infinity());
  std::size_t truthRows = 0;
  for (const armtrack::ArmSample& row : recorded.samples) {
    // The exported times are rounded to 1 us.
    if (!row.trueAngles || row.t < analysedFrom - 1e-6 || row.t > analysedTo + 1e-6) continue;
    ++truthRows;
    const std::array<double, 5> c = armtrack::asArray(armtrack::toClinical(*row.trueAngles));
    for (std::size_t a = 0; a < c.size(); ++a) {
      trueLo[a] = std::min(trueLo[a], c[a]);
      trueHi[a] = std::max(trueHi[a], c[a]);
    }
  }
  ASSERT_GT(truthRows, 5500u) << "1 kHz over the analysed span";
  const QJsonObject metrics = s["metrics"].toObject();
  const auto& infos = armtrack::clinicalAngleInfo();
  for (std::size_t a = 0; a < infos.size(); ++a) {
    const QString name = QString::fromUtf8(infos[a].name.data(), infos[a].name.size());
    const QString key = QString::fromUtf8(infos[a].key.data(), infos[a].key.size());
    SCOPED_TRACE(name.toStdString());
    const QJsonObject m = metrics[key].toObject();
    // name, then min, max, ROM, peak velocity, mean velocity, moving time.
    const QRegularExpressionMatch row =
        QRegularExpression("\\n\\s*" + QRegularExpression::escape(name) +
                           "((?:\\s+-?[0-9][0-9,]*\\.[0-9]){6})\\s*\\n")
            .match(all);
    ASSERT_TRUE(row.hasMatch()) << "no row for " << name.toStdString();
    std::vector<double> v;
    for (const QString& cell : row.captured(1).split(' ', Qt::SkipEmptyParts))
      v.push_back(QString(cell).remove(',').toDouble());
    ASSERT_EQ(v.size(), 6u);
    EXPECT_NEAR(v[0], m["min_deg"].toDouble(), 0.051);
    EXPECT_NEAR(v[1], m["max_deg"].toDouble(), 0.051);
    EXPECT_NEAR(v[2], m["rom_deg"].toDouble(), 0.051);
    EXPECT_NEAR(v[3], m["peak_velocity_deg_s"].toDouble(), 0.051);
    const double trueRom = trueHi[a] - trueLo[a];
    std::cout << name.toStdString() << ": ROM stored " << m["rom_deg"].toDouble() << " deg, true "
              << trueRom << " deg; min " << m["min_deg"].toDouble() << " / " << trueLo[a]
              << ", max " << m["max_deg"].toDouble() << " / " << trueHi[a] << "\n";
    EXPECT_NEAR(m["rom_deg"].toDouble(), trueRom, kTruthTolDeg);
    EXPECT_NEAR(m["min_deg"].toDouble(), trueLo[a], kTruthTolDeg);
    EXPECT_NEAR(m["max_deg"].toDouble(), trueHi[a], kTruthTolDeg);
  }
  // The patient (born 1950) is past the study's 69 years: every normal range is AAOS, and the
  // report says why.
  EXPECT_TRUE(all.simplified().contains(QRegularExpression(
      "the patient was \\d+ on the day of the session, outside the study's 2 to 69 years")))
      << all.toStdString();
  EXPECT_TRUE(
      all.contains(QRegularExpression("\\n\\s*Shoulder flexion\\s+-60.0 – 180.0\\s+AAOS\\s*\\n")));
  const int reps = s["repetitions"].toObject()["count"].toInt();
  EXPECT_TRUE(all.contains(reps == 1 ? QString("1 repetition counted on")
                                     : QString("%1 repetitions counted on").arg(reps)) ||
              (reps == 0 && all.contains("No repetitions")))
      << reps << " repetitions";

  const std::vector<QImage> pages = rt::renderPages(pdf, m_dir.path());
  ASSERT_EQ(static_cast<qsizetype>(pages.size()), text.size());
  bool sawPlot = false;
  for (std::size_t i = 0; i < pages.size(); ++i) {
    EXPECT_NEAR(pages[i].width(), 496, 2);  // A4 at 60 dpi
    EXPECT_NEAR(pages[i].height(), 702, 2);
    EXPECT_GT(rt::inkFraction(pages[i]), 0.01) << "page " << i + 1 << " looks blank";
    if (text[static_cast<qsizetype>(i)].contains("Joint angles over time")) {
      const rt::BlueInk b = rt::blueInk(pages[i]);
      EXPECT_GT(b.count, 300);
      EXPECT_GT(b.maxX - b.minX, 0.6 * pages[i].width()) << "the curve spans the plot";
      sawPlot = true;
    }
  }
  EXPECT_TRUE(sawPlot);
}

TEST_P(RecordDb, RefusesAnUnknownPatientAndMixedTargetsBeforeAnyDeviceStarts) {
  QStringList args = recordArgs("2");
  args[args.indexOf("P01")] = "P99";
  QProcess p;
  p.start(ARMTRACK_CLI, args);
  ASSERT_TRUE(p.waitForFinished(30000));
  EXPECT_NE(p.exitCode(), 0);
  EXPECT_NE(p.readAllStandardError().indexOf("unknown patient"), -1);

  QStringList both = recordArgs("2");
  both << "--out" << m_dir.filePath("x.csv");
  QProcess q;
  q.start(ARMTRACK_CLI, both);
  ASSERT_TRUE(q.waitForFinished(30000));
  EXPECT_EQ(q.exitCode(), 2);
  EXPECT_FALSE(QFile::exists(m_dir.filePath("x.csv")));
}

INSTANTIATE_TEST_SUITE_P(Engines, RecordDb, testing::Values(Engine::Sqlite, Engine::Postgres),
                         armtrack::test::engineName);
