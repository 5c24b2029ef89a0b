// armtrack-cli's clinical-records commands: db, user, patient, protocol, session, export, audit;
// their errors (wrong password, unknown patient, newer schema, corrupt file), access control for
// home accounts, and a SIGKILL in the middle of an import.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QThread>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "app/cli/Cli.h"
#include "core/io/Recording.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "tests/support/PostgresServer.h"

namespace fs = std::filesystem;
using armtrack::cli::runCli;

namespace {

struct Result {
  int code;
  std::string out, err;
};

constexpr const char* kAdminPass = "admin-pass-1";

class StorageCli : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(m_dir.isValid());
    m_db = m_dir.filePath("clinic.db").toStdString();
    ::setenv("ARMTRACK_PASSWORD", kAdminPass, 1);
    ASSERT_EQ(run({"db", "init", "--admin", "boss"}, nullptr).code, 0);
  }
  void TearDown() override {
    ::unsetenv("ARMTRACK_PASSWORD");
    ::unsetenv("ARMTRACK_NEW_PASSWORD");
  }
  // Runs the tool with --db appended, signed in as user (nullptr: no --user) with password.
  Result run(std::vector<std::string> args, const char* user = "boss",
             const char* password = kAdminPass) {
    args.push_back("--db");
    args.push_back(m_db);
    if (user) {
      args.push_back("--user");
      args.push_back(user);
      ::setenv("ARMTRACK_PASSWORD", password, 1);
    }
    std::ostringstream out, err;
    const int code = runCli(args, out, err);
    return {code, out.str(), err.str()};
  }
  std::string path(const char* name) const { return m_dir.filePath(name).toStdString(); }
  std::string simulate(const char* name, double seconds) {
    armtrack::SimulationParams sim;
    sim.duration = seconds;
    armtrack::TrajectoryOptions options;
    const auto trajectory = armtrack::makeTrajectory("multi-joint", options);
    armtrack::writeRecording(path(name), armtrack::simulateRecording(*trajectory, sim));
    return path(name);
  }
  std::string importFor(const char* patient, const std::string& csv) {
    const Result r = run({"session", "import", csv, "--patient", patient});
    EXPECT_EQ(r.code, 0) << r.err;
    return r.out.substr(0, r.out.find('\n'));
  }
  void addPatients() {
    for (const char* code : {"P01", "P02"}) {
      const Result r = run({"patient", "add", "--code", code, "--name", std::string("Name ") + code,
                            "--birth", "1958-03-04", "--sex", "m", "--side", "left"});
      ASSERT_EQ(r.code, 0) << r.err;
    }
  }

  QTemporaryDir m_dir;
  std::string m_db;
};

// The same commands against a database on a PostgreSQL server the test starts
// (tests/support/PostgresServer; the test fails with the reason when it cannot).
class StorageCliOnPostgres : public StorageCli {
 protected:
  void SetUp() override {
    static int counter = 0;
    m_db = armtrack::test::PostgresServer::shared()
               .createDatabase(QString("cli%1").arg(counter++))
               .toStdString();
    ::setenv("ARMTRACK_PASSWORD", kAdminPass, 1);
    const Result init = run({"db", "init", "--admin", "boss"}, nullptr);
    ASSERT_EQ(init.code, 0) << init.err;
  }
};

std::string bytesOf(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_F(StorageCli, ImportListShowExportRoundTrip) {
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
  EXPECT_EQ(run({"export", id, "--format", "mot", "--out", path("x.mot")}).code, 1);
  EXPECT_EQ(run({"export", id, "--format", "pdf", "--out", path("x.pdf")}).code, 2);

  const Result audit = run({"audit", "--json"});
  ASSERT_EQ(audit.code, 0) << audit.err;
  EXPECT_NE(audit.out.find("\"export\""), std::string::npos);
  EXPECT_EQ(audit.out.find("Name P01"), std::string::npos);  // identifiers only

  const Result backup = run({"db", "backup", "--out", path("copy.db")});
  EXPECT_EQ(backup.code, 0) << backup.err;
  EXPECT_TRUE(fs::exists(path("copy.db")));
  const Result check = run({"db", "check"});
  EXPECT_EQ(check.code, 0) << check.err;
  EXPECT_EQ(check.out.rfind("ok: ", 0), 0u) << check.out;
  EXPECT_EQ(run({"db", "migrate"}).code, 0);
}

TEST_F(StorageCli, ClearErrors) {
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
  {
    QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "cli-raw");
    db.setDatabaseName(QString::fromStdString(m_db));
    ASSERT_TRUE(db.open());
    QSqlQuery(db).exec("UPDATE schema_version SET version = 42");
    db.close();
  }
  QSqlDatabase::removeDatabase("cli-raw");
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

TEST_F(StorageCli, HomeAccountCannotReachAnotherPatient) {
  addPatients();
  const std::string csv = simulate("rec.csv", 1.0);
  const std::string mine = importFor("P01", csv);
  const std::string other = importFor("P02", csv);
  ::setenv("ARMTRACK_NEW_PASSWORD", "home-pass", 1);
  Result r = run({"user", "add", "home1", "--role", "home", "--patient", "P01"});
  ASSERT_EQ(r.code, 0) << r.err;

  ASSERT_EQ(run({"protocol", "add", "--name", "reach", "--angle", "shoulder_flexion",
                 "--target-min", "0", "--target-max", "90", "--reps", "10"})
                .code,
            0);
  ASSERT_EQ(run({"protocol", "assign", "reach", "--patient", "P01", "--per-week", "5"}).code, 0);
  ASSERT_EQ(run({"protocol", "assign", "reach", "--patient", "P02", "--per-week", "2"}).code, 0);
  auto home = [&](std::vector<std::string> args) {
    return run(std::move(args), "home1", "home-pass");
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

// A version-1 file (the later columns and tables dropped again) is refused until `db migrate`, then
// works.
TEST_F(StorageCli, OlderSchemaNeedsDbMigrate) {
  addPatients();
  {
    QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "cli-v1");
    db.setDatabaseName(QString::fromStdString(m_db));
    ASSERT_TRUE(db.open());
    for (const char* sql : {"ALTER TABLE users DROP COLUMN failed_attempts",
                            "ALTER TABLE users DROP COLUMN last_failed_at", "DROP TABLE programmes",
                            "UPDATE schema_version SET version = 1"})
      ASSERT_TRUE(QSqlQuery(db).exec(sql)) << sql;
    db.close();
  }
  QSqlDatabase::removeDatabase("cli-v1");
  Result r = run({"patient", "list"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("db migrate"), std::string::npos) << r.err;
  r = run({"db", "migrate"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("2 step(s) applied"), std::string::npos) << r.out;
  r = run({"patient", "list"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("P02"), std::string::npos);
}

// Without --db the records are armtrack.db in the application data folder.
TEST_F(StorageCli, DefaultLocationIsTheAppDataFolder) {
  const std::string data = path("xdg");
  ::setenv("XDG_DATA_HOME", data.c_str(), 1);
  std::ostringstream out, err;
  ::setenv("ARMTRACK_PASSWORD", kAdminPass, 1);
  const int code = runCli({"db", "init", "--admin", "boss"}, out, err);
  ::unsetenv("XDG_DATA_HOME");
  EXPECT_EQ(code, 0) << err.str();
  EXPECT_TRUE(fs::exists(data + "/ArmTrack/ArmTrack/armtrack.db")) << err.str();
}

// A real process killed with SIGKILL while it imports: the file checks clean afterwards and the
// session is interrupted with the chunks committed before the kill.
TEST_F(StorageCli, SigkillDuringImportLeavesAnInterruptedSession) {
  addPatients();
  const std::string csv = simulate("long.csv", 60.0);
  QProcess p;
  p.start(ARMTRACK_CLI, {"session", "import", QString::fromStdString(csv), "--patient", "P02",
                         "--db", QString::fromStdString(m_db), "--user", "boss"});
  ASSERT_TRUE(p.waitForStarted());
  // Watch the file from a second connection (WAL lets it read while the importer writes) and
  // kill the importer as soon as it has committed its first chunks.
  qint64 rowsBeforeKill = 0;
  {
    QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "cli-watch");
    db.setDatabaseName(QString::fromStdString(m_db));
    ASSERT_TRUE(db.open());
    for (int i = 0; i < 6000 && p.state() == QProcess::Running; ++i) {
      QSqlQuery q(db);
      if (q.exec("SELECT coalesce(sum(sample_rows), 0) FROM sessions") && q.next() &&
          q.value(0).toLongLong() > 2000) {
        rowsBeforeKill = q.value(0).toLongLong();
        break;
      }
      q.finish();
      QThread::msleep(5);
    }
    db.close();
  }
  QSqlDatabase::removeDatabase("cli-watch");
  ASSERT_EQ(p.state(), QProcess::Running) << "the import ended before it could be killed";
  p.kill();  // SIGKILL
  p.waitForFinished();
  ASSERT_GT(rowsBeforeKill, 0);

  const Result list = run({"session", "list", "--patient", "P02", "--json"});
  ASSERT_EQ(list.code, 0) << list.err;
  const QJsonArray sessions = QJsonDocument::fromJson(QByteArray::fromStdString(list.out)).array();
  ASSERT_EQ(sessions.size(), 1);
  const QJsonObject s = sessions[0].toObject();
  EXPECT_EQ(s["status"].toString(), "interrupted");
  EXPECT_GE(s["rows"].toInteger(), rowsBeforeKill);  // everything committed is kept
  EXPECT_LT(s["rows"].toInteger(), 61201);           // and the session is not passed off as whole
  const Result check = run({"db", "check"});
  EXPECT_EQ(check.code, 0) << check.err;
  // What was kept reads back, and exports.
  EXPECT_EQ(run({"export", std::to_string(s["id"].toInteger()), "--format", "recording", "--out",
                 path("partial.csv")})
                .code,
            0);
  EXPECT_EQ(static_cast<qint64>(armtrack::readRecording(path("partial.csv")).samples.size()),
            s["rows"].toInteger());
}

TEST_F(StorageCliOnPostgres, ImportExportCheckAndBackupAdvice) {
  addPatients();
  const std::string csv = simulate("rec.csv", 3.0);
  const std::string id = importFor("P01", csv);
  const Result list = run({"session", "list", "--patient", "P01", "--json"});
  ASSERT_EQ(list.code, 0) << list.err;
  EXPECT_EQ(QJsonDocument::fromJson(QByteArray::fromStdString(list.out)).array().size(), 1);
  const std::string back = path("back.csv");
  const Result exp = run({"export", id, "--format", "recording", "--out", back});
  ASSERT_EQ(exp.code, 0) << exp.err;
  EXPECT_EQ(bytesOf(back), bytesOf(csv));
  const Result check = run({"db", "check"});
  EXPECT_EQ(check.code, 0) << check.err;
  EXPECT_EQ(check.out.rfind("ok: postgresql://", 0), 0u) << check.out;
  EXPECT_EQ(run({"db", "migrate"}).code, 0);
  // db backup copies SQLite files; on PostgreSQL it says to use pg_dump, and writes nothing.
  const Result backup = run({"db", "backup", "--out", path("copy.dump")});
  EXPECT_NE(backup.code, 0);
  EXPECT_NE(backup.err.find("pg_dump -Fc"), std::string::npos) << backup.err;
  EXPECT_FALSE(fs::exists(path("copy.dump")));
  EXPECT_EQ(run({"patient", "list"}, "boss", "wrong-password").code, 1);
}
