// armtrack-cli's clinical-records commands, on SQLite and PostgreSQL: db, user, patient, protocol,
// session, report, export, audit; their errors (wrong password, unknown patient, newer schema,
// corrupt file), access control for home accounts (a SIGKILL in the middle of an import:
// test_import_crash_cli.cpp).
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "app/cli/Cli.h"
#include "core/io/Recording.h"
#include "core/kinematics/ClinicalAngles.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/storage/Schema.h"
#include "tests/app/StorageCliFixture.h"
#include "tests/support/DatabaseEngines.h"
#include "tests/support/LeaningPatient.h"

namespace fs = std::filesystem;
using armtrack::cli::runCli;
using armtrack::test::Engine;

namespace {

using armtrack::test::CliFixture;
using armtrack::test::kAdminPass;
using armtrack::test::Result;
using armtrack::test::StorageCli;

/// What only a SQLite file has: the default location, a file that is not a database.
class StorageCliSqlite : public CliFixture {
 protected:
  void SetUp() override { init(Engine::Sqlite); }
};

std::string bytesOf(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_P(StorageCli, ImportListShowExportRoundTrip) {
  addPatients();
  const Result protocol = run({"protocol", "add", "--name", "reach", "--angle", "shoulder_flexion",
                               "--target-min", "0", "--target-max", "120", "--reps", "8"});
  ASSERT_EQ(protocol.code, 0) << protocol.err;
  const std::string csv = simulate("rec.csv", 4.0);
  const Result imp = run({"session", "import", csv, "--patient", "P01", "--protocol", "reach"});
  ASSERT_EQ(imp.code, 0) << imp.err;
  const std::string id = imp.out.substr(0, imp.out.find('\n'));
  EXPECT_EQ(imp.out, id + "\n");

  const Result show = run({"session", "show", id, "--json"});
  ASSERT_EQ(show.code, 0) << show.err;
  const QJsonObject s = QJsonDocument::fromJson(QByteArray::fromStdString(show.out)).object();
  EXPECT_EQ(s["id"].toInteger(), std::stoll(id));
  EXPECT_EQ(s["patient"].toString(), "P01");
  EXPECT_EQ(s["status"].toString(), "complete");
  EXPECT_NEAR(s["duration_s"].toDouble(), 4.0, 0.01);
  EXPECT_EQ(s["samples"].toInteger(), 4001);  // 1 kHz IMU rows
  EXPECT_EQ(s["protocol"].toString(), "reach");

  const Result list = run({"session", "list", "--patient", "P01", "--json"});
  ASSERT_EQ(list.code, 0) << list.err;
  EXPECT_EQ(QJsonDocument::fromJson(QByteArray::fromStdString(list.out)).array().size(), 1);
  const Result patients = run({"patient", "list", "--json"});
  EXPECT_EQ(QJsonDocument::fromJson(QByteArray::fromStdString(patients.out)).array().size(), 2);

  const std::string back = path("back.csv");
  const Result exp = run({"export", id, "--format", "recording", "--out", back});
  ASSERT_EQ(exp.code, 0) << exp.err;
  EXPECT_EQ(bytesOf(back), bytesOf(csv));
  EXPECT_EQ(bytesOf(armtrack::sidecarPath(back).string()),
            bytesOf(armtrack::sidecarPath(csv).string()));
  EXPECT_EQ(run({"export", id, "--format", "recording", "--out", back}).code, 1);  // exists
  EXPECT_EQ(run({"export", id, "--format", "mot", "--out", path("x.mot")}).code, 0);
  EXPECT_EQ(run({"export", id, "--format", "pdf", "--out", path("x.pdf")}).code, 2);

  const Result audit = run({"audit", "--json"});
  ASSERT_EQ(audit.code, 0) << audit.err;
  EXPECT_NE(audit.out.find("\"export\""), std::string::npos);
  EXPECT_EQ(audit.out.find("Name P01"), std::string::npos);  // identifiers only

  const Result backup = run({"db", "backup", "--out", path("copy.db")});
  if (m_engine == Engine::Sqlite) {
    EXPECT_EQ(backup.code, 0) << backup.err;
    EXPECT_TRUE(fs::exists(path("copy.db")));
  } else {
    // db backup copies SQLite files; on PostgreSQL it says to use pg_dump, and writes nothing.
    EXPECT_NE(backup.code, 0);
    EXPECT_NE(backup.err.find("pg_dump -Fc"), std::string::npos) << backup.err;
    EXPECT_FALSE(fs::exists(path("copy.db")));
  }
  const Result check = run({"db", "check"});
  EXPECT_EQ(check.code, 0) << check.err;
  EXPECT_EQ(check.out.rfind(m_engine == Engine::Sqlite ? "ok: " : "ok: postgresql://", 0), 0u)
      << check.out;
  EXPECT_EQ(run({"db", "migrate"}).code, 0);
}

TEST_P(StorageCli, ClearErrors) {
  addPatients();
  Result r = run({"patient", "list"}, "boss", "not-the-password");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("wrong user name or password"), std::string::npos) << r.err;
  r = run({"session", "list", "--patient", "NOPE"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown patient 'NOPE'"), std::string::npos) << r.err;
  r = run({"patient", "list"}, nullptr);
  EXPECT_EQ(r.code, 2);  // --user is required
  r = run({"db", "init", "--admin", "again"}, nullptr);
  EXPECT_EQ(r.code, 1);  // accounts exist
  sql({"UPDATE schema_version SET version = 42"});
  r = run({"patient", "list"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("newer than this ArmTrack"), std::string::npos) << r.err;

  const std::string garbage = path("garbage.db");
  std::ofstream(garbage) << "this is not a database at all, just text that got here somehow";
  const std::string before = bytesOf(garbage);
  std::ostringstream out, err;
  EXPECT_EQ(runCli({"patient", "list", "--db", garbage, "--user", "boss"}, out, err), 1);
  EXPECT_NE(err.str().find(garbage), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("not a SQLite database"), std::string::npos) << err.str();
  EXPECT_EQ(bytesOf(garbage), before);
  std::ostringstream out2, err2;
  EXPECT_EQ(
      runCli({"patient", "list", "--db", "postgresql://me@127.0.0.1:1/armtrack", "--user", "boss"},
             out2, err2),
      1);
  // Nothing listens on port 1: the message says where it looked and what to check.
  EXPECT_NE(err2.str().find("host 127.0.0.1 port 1"), std::string::npos) << err2.str();
  EXPECT_NE(err2.str().find("pg_isready"), std::string::npos) << err2.str();
}

TEST_P(StorageCli, HomeAccountCannotReachAnotherPatient) {
  addPatients();
  const std::string csv = simulate("rec.csv", 1.0);
  const std::string mine = importFor("P01", csv);
  const std::string other = importFor("P02", csv);
  ::setenv("ARMTRACK_NEW_PASSWORD", "home-pass-1", 1);
  Result r = run({"user", "add", "home1", "--role", "home", "--patient", "P01"});
  ASSERT_EQ(r.code, 0) << r.err;

  ASSERT_EQ(run({"protocol", "add", "--name", "reach", "--angle", "shoulder_flexion",
                 "--target-min", "0", "--target-max", "90", "--reps", "10"})
                .code,
            0);
  ASSERT_EQ(run({"protocol", "assign", "reach", "--patient", "P01", "--per-week", "5"}).code, 0);
  ASSERT_EQ(run({"protocol", "assign", "reach", "--patient", "P02", "--per-week", "2"}).code, 0);
  auto home = [&](std::vector<std::string> args) {
    return run(std::move(args), "home1", "home-pass-1");
  };
  r = home({"patient", "list", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const QJsonArray visible = QJsonDocument::fromJson(QByteArray::fromStdString(r.out)).array();
  ASSERT_EQ(visible.size(), 1);
  EXPECT_EQ(visible[0].toObject()["code"].toString(), "P01");
  EXPECT_EQ(home({"session", "list", "--patient", "P01"}).code, 0);
  EXPECT_EQ(home({"session", "show", mine}).code, 0);
  EXPECT_EQ(home({"session", "list", "--patient", "P02"}).code, 1);
  EXPECT_EQ(home({"session", "show", other, "--json"}).code, 1);
  EXPECT_EQ(home({"export", other, "--format", "recording", "--out", path("stolen.csv")}).code, 1);
  EXPECT_FALSE(fs::exists(path("stolen.csv")));
  for (const char* format : {"csv", "mot", "bids"}) {
    EXPECT_EQ(home({"export", other, "--format", format, "--out", path("stolen")}).code, 1);
    EXPECT_FALSE(fs::exists(path("stolen")));
  }
  // Its own session, which was too short (1 s) to analyse: the error says what to do.
  r = home({"export", mine, "--format", "mot", "--out", path("mine.mot")});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("session reestimate"), std::string::npos) << r.err;
  EXPECT_EQ(home({"export", mine, "--format", "recording", "--out", path("mine.csv")}).code, 0);
  r = home({"report", "--patient", "P02", "--from", "2020-01-01", "--to", "2099-01-01", "--pdf",
            path("stolen.pdf")});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_FALSE(fs::exists(path("stolen.pdf")));
  EXPECT_EQ(home({"session", "import", csv, "--patient", "P02"}).code, 1);
  EXPECT_EQ(home({"patient", "add", "--code", "P03", "--name", "x"}).code, 1);
  EXPECT_EQ(home({"user", "add", "evil", "--role", "admin"}).code, 1);
  EXPECT_EQ(home({"audit"}).code, 1);
  r = home({"patient", "programme", "P01", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"sessions_per_week\": 5"), std::string::npos) << r.out;
  EXPECT_EQ(home({"patient", "programme", "P02"}).code, 1);
  EXPECT_EQ(home({"protocol", "assign", "reach", "--patient", "P01", "--per-week", "9"}).code, 1);
  EXPECT_EQ(home({"session", "list", "--patient", "P02"}).err.find("Name P02"), std::string::npos);
}

// Import estimates the session and stores its metrics; show prints them (JSON and table);
// reestimate adds a version and keeps the earlier one. The ranges are checked against the
// recording's true angles.
TEST_P(StorageCli, ImportStoresMetricsAndReestimateAddsAVersion) {
  addPatients();
  ASSERT_EQ(run({"protocol", "add", "--name", "reach", "--angle", "elbow_flexion", "--target-min",
                 "20", "--target-max", "110", "--reps", "8"})
                .code,
            0);
  const std::string csv = simulate("rec.csv", 6.0);
  const Result imp = run({"session", "import", csv, "--patient", "P01", "--protocol", "reach"});
  ASSERT_EQ(imp.code, 0) << imp.err;
  const std::string id = imp.out.substr(0, imp.out.find('\n'));
  EXPECT_EQ(imp.out, id + "\n");
  EXPECT_NE(imp.err.find("session import: estimates and metrics version 1 (EKF"), std::string::npos)
      << imp.err;
  EXPECT_NE(imp.err.find("on elbow_flexion"), std::string::npos) << imp.err;
  EXPECT_EQ(imp.err.find("progress:"), std::string::npos) << imp.err;  // a short recording

  Result show = run({"session", "show", id, "--json"});
  ASSERT_EQ(show.code, 0) << show.err;
  QJsonObject s = QJsonDocument::fromJson(QByteArray::fromStdString(show.out)).object();
  EXPECT_EQ(s["status"].toString(), "complete");
  EXPECT_EQ(s["samples"].toInteger(), 6001);
  EXPECT_EQ(s["estimate_version"].toInt(), 1);
  EXPECT_TRUE(s["sparc"].isDouble() || s["sparc"].isNull());
  EXPECT_TRUE(s.contains("ldlj"));
  const QJsonObject reps = s["repetitions"].toObject();
  EXPECT_EQ(reps["primary_angle"].toString(), "elbow_flexion");
  EXPECT_EQ(reps["count"].toInt(), reps["list"].toArray().size());

  // Each angle's range against the true angles after the filter's first second (which the
  // metrics leave out): within 2 deg.
  const armtrack::Recording rec = armtrack::readRecording(csv);
  const QJsonObject metrics = s["metrics"].toObject();
  ASSERT_EQ(metrics.size(), 5);
  for (int k = 0; k < 5; ++k) {
    const std::string_view key = armtrack::clinicalAngleInfo()[k].key;
    double lo = 1e9, hi = -1e9;
    for (const armtrack::ArmSample& x : rec.samples) {
      if (!x.trueAngles || x.t < 1.0) continue;
      const double v = armtrack::asArray(armtrack::toClinical(*x.trueAngles))[k];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    const QJsonObject one = metrics[QString::fromUtf8(key.data(), key.size())].toObject();
    for (const char* f : {"min_deg", "max_deg", "rom_deg", "peak_velocity_deg_s",
                          "mean_velocity_deg_s", "movement_time_s"})
      EXPECT_TRUE(one[f].isDouble()) << key << " " << f;
    EXPECT_NEAR(one["rom_deg"].toDouble(), hi - lo, 2.0) << key;
    EXPECT_NEAR(one["max_deg"].toDouble(), hi, 2.0) << key;
  }

  show = run({"session", "show", id});
  ASSERT_EQ(show.code, 0) << show.err;
  EXPECT_NE(show.out.find("metrics (estimates version 1)"), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("| Elbow flexion | "), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("repetitions: "), std::string::npos) << show.out;

  const Result re = run({"session", "reestimate", id, "--filter", "ukf", "--no-optical"});
  ASSERT_EQ(re.code, 0) << re.err;
  EXPECT_EQ(re.out, "2\n");
  EXPECT_NE(re.err.find("version 2 (UKF"), std::string::npos) << re.err;
  EXPECT_NE(re.err.find("no optical data fused"), std::string::npos) << re.err;
  show = run({"session", "show", id, "--json"});
  s = QJsonDocument::fromJson(QByteArray::fromStdString(show.out)).object();
  EXPECT_EQ(s["estimate_version"].toInt(), 2);
  const auto versions = query(
      QString("SELECT version, params_json, codec FROM estimates WHERE session_id = %1 ORDER BY "
              "version")
          .arg(std::stoll(id)));
  ASSERT_EQ(versions.size(), 2u);
  EXPECT_EQ(versions[0][0].toInt(), 1);
  EXPECT_NE(versions[0][1].toString().indexOf("\"filter\":\"ekf\""), -1);
  EXPECT_EQ(versions[0][2].toString(), "est-f64-zstd-v1-chunks");  // EstimateCodec::kChunkedName
  EXPECT_NE(versions[1][1].toString().indexOf("\"optical\":false"), -1);

  EXPECT_EQ(run({"session", "reestimate", id, "--filter", "kalman"}).code, 2);
  EXPECT_EQ(run({"session", "reestimate", "999"}).code, 1);
  EXPECT_EQ(run({"session", "reestimate"}).code, 2);
}

// The filter and method chosen for a re-estimation become the session's filter settings
// (filter_json): session show reports them, and the next re-estimation without options uses them.
TEST_P(StorageCli, ReestimateStoresTheChosenFilterSettingsAndShowReportsThem) {
  addPatients();
  const std::string id = importFor("P01", simulate("rec.csv", 3.0));
  Result show = run({"session", "show", id, "--json"});
  ASSERT_EQ(show.code, 0) << show.err;
  QJsonObject s = QJsonDocument::fromJson(QByteArray::fromStdString(show.out)).object();
  ASSERT_TRUE(s["filter_settings"].isObject()) << show.out;
  EXPECT_TRUE(s["filter_settings"].toObject().isEmpty()) << show.out;  // an import: defaults

  Result r = run({"session", "reestimate", id, "--filter", "ukf", "--method", "B"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("(UKF, method B"), std::string::npos) << r.err;
  show = run({"session", "show", id, "--json"});
  s = QJsonDocument::fromJson(QByteArray::fromStdString(show.out)).object();
  const QJsonObject f = s["filter_settings"].toObject();
  EXPECT_EQ(f["filter"].toString(), "ukf") << show.out;
  EXPECT_EQ(f["method"].toString(), "B") << show.out;
  EXPECT_EQ(f["optical"].toBool(false), true) << show.out;
  show = run({"session", "show", id});
  EXPECT_NE(show.out.find("filter settings: {\"camera\":true,\"filter\":\"ukf\",\"method\":\"B\""),
            std::string::npos)
      << show.out;

  r = run({"session", "reestimate", id});  // no options: the session's settings
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("(UKF, method B, optical fused, session settings)"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.out, "3\n");
  EXPECT_EQ(run({"session", "reestimate", id, "--method", "Z"}).code, 2);
  EXPECT_NE(run({"audit", "--json"}).out.find("filter settings"), std::string::npos);
}

// A home account may read its own session's metrics but analyses nothing, and another patient's
// session is unknown to it.
TEST_P(StorageCli, HomeAccountNeitherAnalysesNorSeesAnotherPatientsMetrics) {
  addPatients();
  const std::string csv = simulate("rec.csv", 2.0);
  const std::string mine = importFor("P01", csv);
  const std::string other = importFor("P02", csv);
  ::setenv("ARMTRACK_NEW_PASSWORD", "home-pass-1", 1);
  ASSERT_EQ(run({"user", "add", "home1", "--role", "home", "--patient", "P01"}).code, 0);
  auto home = [&](std::vector<std::string> args) {
    return run(std::move(args), "home1", "home-pass-1");
  };
  Result r = home({"session", "show", mine, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(QJsonDocument::fromJson(QByteArray::fromStdString(r.out))["estimate_version"].toInt(),
            1);
  r = home({"session", "reestimate", other});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown session"), std::string::npos) << r.err;
  r = home({"session", "reestimate", mine});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("home account"), std::string::npos) << r.err;
  r = home({"session", "import", csv, "--patient", "P01"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("not analysed"), std::string::npos) << r.err;
  const std::string homeId = r.out.substr(0, r.out.find('\n'));
  r = home({"session", "show", homeId, "--json"});
  EXPECT_TRUE(QJsonDocument::fromJson(QByteArray::fromStdString(r.out))["metrics"].isNull());
  EXPECT_EQ(QJsonDocument::fromJson(QByteArray::fromStdString(r.out))["analysis"].toString(),
            "pending");
  r = home({"session", "show", homeId});
  EXPECT_NE(r.out.find("metrics: none"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(analysis pending)"), std::string::npos) << r.out;
  // The next command of a therapist or administrator analyses it, saying so.
  r = run({"session", "show", homeId, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("session " + homeId + ": its analysis had not been done"), std::string::npos)
      << r.err;
  EXPECT_TRUE(QJsonDocument::fromJson(QByteArray::fromStdString(r.out))["metrics"].isObject());
}

// A version-1 file (the later columns and tables dropped again) is refused until `db migrate`, then
// works.
TEST_P(StorageCli, OlderSchemaNeedsDbMigrate) {
  addPatients();
  // Version 9's tables, version 8's column (the programmes table goes with versions 2 to 4
  // below), version 7's, version 6's triggers, indexes, tables and columns, then those of
  // versions 2 to 4.
  sql({"DROP TABLE sync_upload_chunks", "DROP TABLE sync_uploads", "DROP TABLE devices",
       "DROP TABLE enrolment_codes"});
  sql({"ALTER TABLE protocols DROP COLUMN trunk_limit_deg"});
  sql({"ALTER TABLE users DROP COLUMN disabled"});
  if (m_engine == Engine::Postgres)
    sql({"DROP TRIGGER audit_log_no_change ON audit_log",
         "DROP TRIGGER audit_log_no_truncate ON audit_log"});
  else
    sql({"DROP TRIGGER audit_log_no_update", "DROP TRIGGER audit_log_no_delete"});
  sql({"DROP INDEX users_by_name_key",
       "DROP INDEX patients_by_code_key",
       "DROP INDEX protocols_by_name_key",
       "DROP TABLE sign_in_failures",
       "DROP TABLE estimate_chunks",
       "ALTER TABLE users DROP COLUMN name_key",
       "ALTER TABLE patients DROP COLUMN code_key",
       "ALTER TABLE protocols DROP COLUMN name_key",
       "ALTER TABLE audit_log DROP COLUMN prev_hash",
       "ALTER TABLE audit_log DROP COLUMN hash",
       "ALTER TABLE sessions DROP COLUMN origin",
       "ALTER TABLE sessions DROP COLUMN analysis",
       "ALTER TABLE sessions DROP COLUMN analysis_note",
       "ALTER TABLE sessions DROP COLUMN analysis_host",
       "ALTER TABLE sessions DROP COLUMN analysis_pid",
       "ALTER TABLE estimates DROP COLUMN complete",
       "ALTER TABLE estimates DROP COLUMN writer_host",
       "ALTER TABLE estimates DROP COLUMN writer_pid",
       "ALTER TABLE metrics DROP COLUMN series_codec",
       "ALTER TABLE metrics DROP COLUMN series"});
  sql({"ALTER TABLE users DROP COLUMN failed_attempts",
       "ALTER TABLE users DROP COLUMN last_failed_at", "DROP TABLE programmes",
       "ALTER TABLE sessions DROP COLUMN setting", "ALTER TABLE sessions DROP COLUMN pain_score",
       "ALTER TABLE sessions DROP COLUMN patient_comment",
       "ALTER TABLE sessions DROP COLUMN home_summary_json",
       "UPDATE schema_version SET version = 1"});
  Result r = run({"patient", "list"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("db migrate"), std::string::npos) << r.err;
  r = run({"db", "migrate"});
  ASSERT_EQ(r.code, 0) << r.err;
  // From version 1 to this build's.
  const std::string applied =
      std::to_string(armtrack::storage::latestSchemaVersion() - 1) + " step(s) applied";
  EXPECT_NE(r.out.find(applied), std::string::npos) << r.out;
  r = run({"patient", "list"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("P02"), std::string::npos);
}

// Without --db the records are armtrack.db in the application data folder.
TEST_F(StorageCliSqlite, DefaultLocationIsTheAppDataFolder) {
  const std::string data = path("xdg");
  ::setenv("XDG_DATA_HOME", data.c_str(), 1);
  std::ostringstream out, err;
  ::setenv("ARMTRACK_PASSWORD", kAdminPass, 1);
  const int code = runCli({"db", "init", "--admin", "boss"}, out, err);
  ::unsetenv("XDG_DATA_HOME");
  EXPECT_EQ(code, 0) << err.str();
  EXPECT_TRUE(fs::exists(data + "/ArmTrack/ArmTrack/armtrack.db")) << err.str();
}

namespace {

/// The real executable (tests/app/CliRun.h).
Result runProcess(const QStringList& args) {
  return armtrack::test::cliProcess(QStringLiteral(ARMTRACK_CLI), args);
}

std::string pdfText(const std::string& pdf) {
  QProcess p;
  p.start("pdftotext", {"-layout", QString::fromStdString(pdf), "-"});
  if (!p.waitForFinished(30000)) return {};
  return p.readAllStandardOutput().toStdString();
}

}  // namespace

// The analysed session leaves the records as a PDF report, a progress report, a clinical CSV, an
// OpenSim motion file and a BIDS data set, each audited; the numbers are those of session show.
TEST_P(StorageCli, ReportsAndExportsOfAnAnalysedSession) {
  addPatients();
  ASSERT_EQ(run({"protocol", "add", "--name", "reach", "--angle", "shoulder_flexion",
                 "--target-min", "0", "--target-max", "120", "--reps", "8"})
                .code,
            0);
  const std::string csv = simulate("rec.csv", 8.0);
  const Result imp = run({"session", "import", csv, "--patient", "P01", "--protocol", "reach"});
  ASSERT_EQ(imp.code, 0) << imp.err;
  const std::string id = imp.out.substr(0, imp.out.find('\n'));
  const Result show = run({"session", "show", id, "--json"});
  const QJsonObject metrics =
      QJsonDocument::fromJson(QByteArray::fromStdString(show.out)).object()["metrics"].toObject();
  const double flexionRom = metrics["shoulder_flexion"].toObject()["rom_deg"].toDouble();
  ASSERT_GT(flexionRom, 10.0) << show.out;

  const QString db = QString::fromStdString(m_db);
  const QStringList signIn{"--db", db, "--user", "boss"};
  const std::string pdf = path("report.pdf");
  Result r = runProcess(
      QStringList{"report", QString::fromStdString(id), "--pdf", QString::fromStdString(pdf)} +
      signIn);
  ASSERT_EQ(r.code, 0) << r.err;
  // Plain output for the user: the one line saying what was written, no warnings from Qt.
  EXPECT_EQ(r.err.rfind("report: session " + id + ", ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(bytesOf(pdf).substr(0, 5), "%PDF-");
  const std::string text = pdfText(pdf);
  if (text.empty()) {
    ADD_FAILURE() << "pdftotext (poppler-utils) is needed to read the report back";
  } else {
    for (const char* heading : {"Session report", "Metrics per clinical angle", "Repetitions",
                                "Name P01", "Shoulder flexion", "Page 1 of"})
      EXPECT_NE(text.find(heading), std::string::npos) << heading;
    char rom[32];
    std::snprintf(rom, sizeof rom, "%.1f", flexionRom);
    EXPECT_NE(text.find(rom), std::string::npos) << "flexion ROM " << rom << " not in the report";
    // The calibration in words (issue 25, item 7): no sensor calibration for an import, the
    // sidecar's lengths in cm and mounting in deg, no stored keys or matrices.
    const QString flat = QString::fromStdString(text).simplified();
    for (const char* words :
         {"Sensor calibration: none was made for this session", "Segments: upper arm ",
          " cm (shoulder to elbow), forearm ", "Upper-arm sensor: ", " deg about the segment"})
      EXPECT_TRUE(flat.contains(QString::fromLatin1(words))) << words << "\n" << text;
    for (const char* raw : {"geometry.", "camera.R", "geometry.l3"})
      EXPECT_EQ(text.find(raw), std::string::npos) << raw;
  }
  EXPECT_EQ(runProcess(QStringList{"report", QString::fromStdString(id), "--pdf",
                                   QString::fromStdString(pdf)} +
                       signIn)
                .code,
            1);  // exists: only with --overwrite
  const std::string progress = path("progress.pdf");
  r = runProcess(QStringList{"report", "--patient", "P01", "--from", "2000-01-01", "--to",
                             "2099-12-31", "--pdf", QString::fromStdString(progress)} +
                 signIn);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("1 sessions"), std::string::npos) << r.err;
  EXPECT_EQ(runProcess(QStringList{"report", "--patient", "P01", "--from", "2000-13-01", "--to",
                                   "2099-12-31", "--pdf", QString::fromStdString(path("x.pdf"))} +
                       signIn)
                .code,
            2);

  // Clinical CSV: the angles the metrics were computed from; the metrics smooth them, so the
  // flexion column's range is within a degree of the ROM that show printed.
  ASSERT_EQ(run({"export", id, "--format", "csv", "--out", path("angles.csv")}).code, 0);
  std::ifstream angles(path("angles.csv"));
  std::string header, line;
  std::getline(angles, header);
  EXPECT_EQ(header.rfind("time_s,shoulder_flexion_deg,", 0), 0u) << header;
  double lo = 1e9, hi = -1e9;
  while (std::getline(angles, line)) {
    const double v = std::atof(line.c_str() + line.find(',') + 1);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_NEAR(hi - lo, flexionRom, 1.0);
  EXPECT_TRUE(fs::exists(path("angles_metrics.csv")));

  ASSERT_EQ(run({"export", id, "--format", "mot", "--out", path("angles.mot")}).code, 0);
  std::ifstream mot(path("angles.mot"));
  std::vector<std::string> head;
  for (int i = 0; i < 7 && std::getline(mot, line); ++i) head.push_back(line);
  ASSERT_EQ(head.size(), 7u);
  EXPECT_EQ(head[1], "version=1");
  EXPECT_EQ(head[4], "inDegrees=yes");
  EXPECT_EQ(head[5], "endheader");
  EXPECT_EQ(head[6], "time\tarm_flex_r\tarm_add_r\tarm_rot_r\telbow_flex_r\tpro_sup_r");

  r = run({"export", id, "--format", "bids", "--out", path("bids")});
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path motion = fs::path(path("bids")) / "sub-P01" / ("ses-" + id) / "motion";
  for (const char* sys : {"imu", "optical", "angles"}) {
    bool found = false;
    for (const auto& e : fs::directory_iterator(motion))
      found |=
          e.path().filename().string().find(std::string("tracksys-") + sys) != std::string::npos;
    EXPECT_TRUE(found) << sys;
  }

  const Result audit = run({"audit", "--json"});
  for (const char* what : {"report pdf", "format csv", "format mot", "format bids", "progress"})
    EXPECT_NE(audit.out.find(what), std::string::npos) << what;
  EXPECT_EQ(audit.out.find("Name P01"), std::string::npos);  // identifiers only
}

// `session show` of a session whose patient leaned with each reach (a sternum IMU and a Kinect
// that sees the shoulder; issue 26): --json has the trunk's four values and each repetition's,
// the text a trunk line, the report a trunk section; a session without trunk sensors has null
// values and no line.
TEST_F(StorageCliSqlite, SessionShowPrintsTheTrunk) {
  addPatients();
  const armtrack::Recording rec = armtrack::test::leaningReaches(24, 821);
  armtrack::writeRecording(path("lean.csv"), rec);
  const std::string id = importFor("P01", path("lean.csv"));

  Result show = run({"session", "show", id, "--json"});
  ASSERT_EQ(show.code, 0) << show.err;
  const QJsonObject s = QJsonDocument::fromJson(QByteArray::fromStdString(show.out)).object();
  const QJsonObject trunk = s["trunk"].toObject();
  const double trueLean = armtrack::test::trueLeanDeg(rec);
  EXPECT_NEAR(trueLean, 18.0, 0.5);
  EXPECT_NEAR(trunk["max_flexion_deg"].toDouble(), trueLean, 1.5) << show.out;
  for (const char* key : {"max_lateral_deg", "max_rotation_deg", "max_shoulder_displacement_cm"})
    EXPECT_GT(trunk[key].toDouble(), 5.0) << key;
  const QJsonArray list = s["repetitions"].toObject()["list"].toArray();
  ASSERT_GE(list.size(), 3);
  for (const QJsonValue& v : list) {
    const QJsonObject t = v.toObject()["trunk"].toObject();
    EXPECT_NEAR(t["max_flexion_deg"].toDouble(), trueLean, 1.5);
    EXPECT_TRUE(t.contains("compensated") && t["compensated"].isNull());
  }
  show = run({"session", "show", id});
  ASSERT_EQ(show.code, 0) << show.err;
  EXPECT_NE(show.out.find("trunk (largest): flexion 1"), std::string::npos) << show.out;
  EXPECT_NE(show.out.find(", trunk flexion 1"), std::string::npos) << show.out;
  // The session report's trunk section, with the session's largest flexion as stored.
  const Result report = runProcess({"report", QString::fromStdString(id), "--pdf",
                                    QString::fromStdString(path("lean.pdf")), "--lang", "en",
                                    "--db", QString::fromStdString(m_db), "--user", "boss"});
  ASSERT_EQ(report.code, 0) << report.err;
  const std::string text = pdfText(path("lean.pdf"));
  EXPECT_NE(text.find("Trunk compensation"), std::string::npos) << text;
  char flexion[64];
  std::snprintf(flexion, sizeof flexion, "Trunk flexion %.1f deg",
                trunk["max_flexion_deg"].toDouble());
  EXPECT_NE(QString::fromStdString(text).simplified().indexOf(QLatin1String(flexion)), -1)
      << flexion << "\n"
      << text;

  const std::string plain = importFor("P02", simulate("arm.csv", 4.0));
  show = run({"session", "show", plain, "--json"});
  const QJsonObject p = QJsonDocument::fromJson(QByteArray::fromStdString(show.out)).object();
  EXPECT_TRUE(p["trunk"].isObject());
  EXPECT_TRUE(p["trunk"].toObject()["max_flexion_deg"].isNull());
  show = run({"session", "show", plain});
  EXPECT_EQ(show.out.find("trunk"), std::string::npos) << show.out;
}

INSTANTIATE_TEST_SUITE_P(Engines, StorageCli, testing::Values(Engine::Sqlite, Engine::Postgres),
                         armtrack::test::engineName);
