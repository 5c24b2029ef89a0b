// The files the clinical-records commands write (docs/storage.md, "Files and permissions";
// docs/exports.md): no command writes over the open database or its -wal, -shm or -journal,
// whatever the path says; a database that cannot be written is read, never called damaged;
// every export of patient data is 0600 in folders of 0700 whatever the umask; a BIDS export
// never replaces files without --overwrite nor mixes two patients in one subject. The commands
// run as the real armtrack-cli program; the permission cases as the account nobody when the
// tests run as root (root ignores file modes), and fail with the reason when that is impossible.
#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <QSysInfo>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <set>

#include "core/storage/Database.h"
#include "tests/app/StorageCliFixture.h"
#include "tests/support/FileInspection.h"

namespace armtrack::test {
namespace {

namespace fs = std::filesystem;

struct Proc {
  int code = -1;
  std::string out, err;
};

std::string readBack(int fd) {
  std::string text;
  ::lseek(fd, 0, SEEK_SET);
  char buf[4096];
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;) text.append(buf, static_cast<size_t>(n));
  ::close(fd);
  return text;
}

int scratchFile() {
  char name[] = "/tmp/armtrack-test-output-XXXXXX";
  const int fd = ::mkstemp(name);
  ::unlink(name);
  return fd;
}

/// Runs armtrack-cli with args in folder cwd (empty: this one). asOther: as the account nobody
/// when this process is root, else as this (non-root) user; a failure names why it could not.
Proc runCli(const std::vector<std::string>& args, const std::string& cwd = {},
            bool asOther = false) {
  std::optional<std::pair<uid_t, gid_t>> who;
  if (asOther && ::geteuid() == 0) {
    const passwd* pw = ::getpwnam("nobody");
    if (!pw) {
      ADD_FAILURE() << "these tests run as root, which ignores file modes, and there is no "
                       "account 'nobody' to run armtrack-cli as: create one, or run the tests "
                       "as a user who is not root";
      return {};
    }
    who = std::pair{pw->pw_uid, pw->pw_gid};
  }
  std::vector<char*> argv{const_cast<char*>(ARMTRACK_CLI)};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const int out = scratchFile(), err = scratchFile();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(out, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    if (who &&
        (::setgroups(0, nullptr) != 0 || ::setgid(who->second) != 0 || ::setuid(who->first) != 0)) {
      const char m[] = "cannot switch to the account nobody (setgid/setuid failed)\n";
      (void)!::write(STDERR_FILENO, m, sizeof m - 1);
      ::_exit(125);
    }
    if (!cwd.empty() && ::chdir(cwd.c_str()) != 0) ::_exit(124);
    ::execv(ARMTRACK_CLI, argv.data());
    ::_exit(126);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  Proc p;
  p.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  p.out = readBack(out);
  p.err = readBack(err);
  if (p.code >= 124 && p.code <= 126) ADD_FAILURE() << "could not run armtrack-cli: " << p.err;
  return p;
}

using armtrack::test::modeOf;
using armtrack::test::namesIn;

/// Sets the umask for its lifetime (armtrack-cli inherits it).
struct Umask {
  mode_t old;
  explicit Umask(mode_t m) : old(::umask(m)) {}
  ~Umask() { ::umask(old); }
};

/// The commands against a database with one analysed session of patient P01 (and P02), run as
/// the armtrack-cli program.
class FilesCli : public CliFixture {
 protected:
  void prepare(Engine engine) {
    init(engine);
    addPatients();
    m_id = importFor("P01", simulate("rec.csv", 4.0));
    ASSERT_FALSE(m_id.empty());
  }
  Proc cliAs(std::vector<std::string> args, const std::string& cwd = {}, bool asOther = false) {
    for (const char* a : {"--db", m_db.c_str(), "--user", "boss"}) args.push_back(a);
    ::setenv("ARMTRACK_PASSWORD", kAdminPass, 1);
    return runCli(args, cwd, asOther);
  }
  fs::path dir() const { return m_dir.path().toStdString(); }
  std::string m_id;
};

class DatabaseFilesCli : public FilesCli {
 protected:
  void SetUp() override { prepare(Engine::Sqlite); }
};

class FilesCliEngines : public FilesCli, public ::testing::WithParamInterface<Engine> {
 protected:
  void SetUp() override { prepare(GetParam()); }
};

// Item 1 of issue 24: `export --out p.db --overwrite --db p.db` replaced the database with the
// CSV. Every command that writes a file, given the database by its path, a symbolic link, a hard
// link, its -wal (missing, and there while another connection has it open) or a relative path
// through "..", is refused with a message saying so, and the database is unchanged.
TEST_F(DatabaseFilesCli, NoCommandWritesOverTheDatabaseOrItsFiles) {
  const fs::path db = m_db;
  fs::create_directory(dir() / "sub");
  fs::create_symlink(db, dir() / "link.db");
  fs::create_hard_link(db, dir() / "hard.db");
  const std::string relative = "sub/../" + db.filename().string();
  const std::vector<std::pair<const char*, std::string>> paths{
      {"itself", db.string()},
      {"symbolic link", (dir() / "link.db").string()},
      {"hard link", (dir() / "hard.db").string()},
      {"-wal", db.string() + "-wal"},
      {"relative through ..", relative}};
  using Args = std::vector<std::string>;
  const std::vector<std::pair<const char*, std::function<Args(const std::string&)>>> commands{
      {"export csv",
       [&](const std::string& p) {
         return Args{"export", m_id, "--format", "csv", "--out", p, "--overwrite"};
       }},
      {"export mot",
       [&](const std::string& p) {
         return Args{"export", m_id, "--format", "mot", "--out", p, "--overwrite"};
       }},
      {"export recording",
       [&](const std::string& p) {
         return Args{"export", m_id, "--format", "recording", "--out", p, "--overwrite"};
       }},
      {"report",
       [&](const std::string& p) {
         return Args{"report", m_id, "--pdf", p, "--overwrite"};
       }},
      {"progress report",
       [&](const std::string& p) {
         return Args{"report", "--patient",  "P01",   "--from", "2000-01-01",
                     "--to",   "2100-01-01", "--pdf", p,        "--overwrite"};
       }},
      {"db backup", [&](const std::string& p) {
         return Args{"db", "backup", "--out", p};
       }}};
  const std::string before = bytesOf(db);
  const auto refused = [&](const Args& args, const std::string& what) {
    SCOPED_TRACE(what);
    const Proc r = cliAs(args, dir().string());
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("would destroy the records, so nothing was written"), std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("exists; pass --overwrite"), std::string::npos) << r.err;
  };
  for (const auto& [command, args] : commands)
    for (const auto& [how, p] : paths) {
      refused(args(p), std::string(command) + ", the database's " + how + ": " + p);
      ASSERT_TRUE(bytesOf(db) == before) << "the database changed: " << command << ", " << how;
      ASSERT_FALSE(fs::exists(db.string() + "-journal"));
    }
  // The files written beside the one named: a CSV's metrics, a recording's sidecar, each file of
  // a BIDS data set, given as links to the database.
  const std::string motion = "sub-P01_ses-" + m_id + "_task-armtrack_tracksys-imu_motion.tsv";
  const fs::path motionDir = dir() / "bids" / "sub-P01" / ("ses-" + m_id) / "motion";
  fs::create_directories(motionDir);
  {
    std::ofstream(dir() / "bids" / "participants.tsv")
        << "participant_id\tpatient_code\nsub-P01\tP01\n";
  }
  for (const bool hard : {false, true}) {
    const auto linkTo = [&](const fs::path& name) {
      fs::remove(name);
      hard ? fs::create_hard_link(db, name) : fs::create_symlink(db, name);
    };
    linkTo(dir() / "m_metrics.csv");
    refused({"export", m_id, "--format", "csv", "--out", (dir() / "m.csv").string(), "--overwrite"},
            "the CSV's metrics file");
    linkTo(dir() / "r.json");
    refused({"export", m_id, "--format", "recording", "--out", (dir() / "r.csv").string(),
             "--overwrite"},
            "the recording's sidecar");
    linkTo(motionDir / motion);
    refused({"export", m_id, "--format", "bids", "--out", (dir() / "bids").string(), "--overwrite"},
            "a BIDS motion file");
    ASSERT_TRUE(bytesOf(db) == before)
        << "the database changed: " << (hard ? "hard" : "symbolic") << " links";
  }
  // While another connection has the database open its -wal and -shm exist; still refused.
  {
    storage::Database holder(storage::DatabaseUrl::parse(QString::fromStdString(m_db)), {});
    ASSERT_TRUE(fs::exists(db.string() + "-wal"));
    for (const auto& [command, args] : commands)
      for (const std::string& p : {db.string() + "-wal", db.string() + "-shm"})
        refused(args(p), std::string(command) + " while open: " + p);
  }
  const Proc check = cliAs({"db", "check"});
  EXPECT_EQ(check.code, 0) << check.err;
  EXPECT_TRUE(bytesOf(db) == before) << "the database changed";
  const Proc list = cliAs({"session", "list", "--patient", "P01"});
  EXPECT_EQ(list.code, 0) << list.err;
  EXPECT_NE(list.out.find("complete"), std::string::npos) << list.out;
}

// Item 5: a healthy database in a folder this account cannot write was "failed its integrity
// check ... restore a backup". Now it is read (nothing is created beside it), and a change is
// refused saying the database is read-only and why, never that it is damaged.
TEST_F(DatabaseFilesCli, AReadOnlyFolderIsReadAndWritesSayWhy) {
  // The test's folder: the owner's (root's, or this user's), readable by all, writable by none
  // but its owner; the database the same. The commands run as someone else.
  fs::permissions(dir(), fs::perms(0755));
  fs::permissions(m_db, fs::perms(0644));
  const std::set<std::string> names = namesIn(dir());
  const std::string before = bytesOf(m_db);
  if (::geteuid() != 0) {  // not root: this user may write; take that away
    fs::permissions(dir(), fs::perms(0555));
    fs::permissions(m_db, fs::perms(0444));
  }
  Proc r = cliAs({"patient", "list"}, {}, true);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("P01"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("P02"), std::string::npos) << r.out;
  r = cliAs({"session", "show", m_id}, {}, true);  // audited, so a write: refused as one
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("is read-only"), std::string::npos) << r.err;
  r = cliAs({"patient", "add", "--code", "P03", "--name", "Name P03"}, {}, true);
  EXPECT_EQ(r.code, 1);
  for (const char* says : {"is read-only", "cannot be written", m_db.c_str(), "not damaged"})
    EXPECT_NE(r.err.find(says), std::string::npos) << says << " in: " << r.err;
  for (const char* never : {"integrity", "restore", "attempt to write"})
    EXPECT_EQ(r.err.find(never), std::string::npos) << never << " in: " << r.err;
  r = cliAs({"db", "check"}, {}, true);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(namesIn(dir()), names);  // no -wal, -shm or temporary file made
  EXPECT_TRUE(bytesOf(m_db) == before) << "the database changed";
  fs::permissions(dir(), fs::perms(0700));
  fs::permissions(m_db, fs::perms(0600));
}

// Item 5: a read-only file holding a session left `recording` by a process that has ended made
// every command fail with "attempt to write a readonly database". It is left as it is, with a
// note, and reading works; with another connection holding the database open (its -wal there,
// not yet checkpointed) the newest rows are read too.
TEST_F(DatabaseFilesCli, AStaleRecordingInAReadOnlyFileIsLeftWithANote) {
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);
  // A live recording's (a dead import would be removed, not marked interrupted).
  sql({QString("UPDATE sessions SET status = 'recording', origin = 'live', recorder_host = '%1', "
               "recorder_pid = %2 WHERE id = %3")
           .arg(QSysInfo::machineHostName())
           .arg(dead)
           .arg(QString::fromStdString(m_id))});
  // The folder may be written by the account the commands run as; the file may not.
  fs::permissions(dir(), fs::perms(0777));
  fs::permissions(m_db, fs::perms(0644));
  if (::geteuid() != 0) fs::permissions(m_db, fs::perms(0444));
  const std::set<std::string> names = namesIn(dir());
  const std::string before = bytesOf(m_db);
  Proc r = cliAs({"session", "list", "--patient", "P01"}, {}, true);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("recording"), std::string::npos) << r.out;
  for (const char* says : {"note:", "is read-only", "1 session(s) left in 'recording'"})
    EXPECT_NE(r.err.find(says), std::string::npos) << says << " in: " << r.err;
  r = cliAs({"db", "check"}, {}, true);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(namesIn(dir()), names);
  EXPECT_TRUE(bytesOf(m_db) == before) << "the database changed";
  {
    // The owner has it open and adds a patient, not yet checkpointed into the file.
    storage::Database owner(storage::DatabaseUrl::parse(QString::fromStdString(m_db)), {});
    owner.exec("PRAGMA wal_autocheckpoint = 0");
    owner.exec("UPDATE patients SET name = 'Renamed' WHERE code = 'P02'");
    fs::permissions(m_db + "-wal", fs::perms(0644));
    fs::permissions(m_db + "-shm", fs::perms(0644));
    r = cliAs({"patient", "list"}, {}, true);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("Renamed"), std::string::npos) << r.out;
  }
  fs::permissions(m_db, fs::perms(0600));
  fs::permissions(dir(), fs::perms(0700));
  // With write access again the session is marked interrupted.
  r = cliAs({"session", "list", "--patient", "P01"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("interrupted"), std::string::npos) << r.out;
}

// Item 13: the database, its backups and every export were 0644 (the umask's). Now 0600 whatever
// the umask, and the folders an export makes 0700; the folder the user names is left alone.
TEST_P(FilesCliEngines, EveryExportIsPrivateWhateverTheUmask) {
  for (const mode_t mask : {mode_t{022}, mode_t{0}}) {
    SCOPED_TRACE("umask " + std::to_string(mask));
    const Umask umask(mask);
    const fs::path out = dir() / ("out" + std::to_string(mask));
    fs::create_directory(out);
    fs::permissions(out, fs::perms(0755));
    const auto exportTo = [&](const char* format, const fs::path& p) {
      const Proc r = cliAs({"export", m_id, "--format", format, "--out", p.string()});
      EXPECT_EQ(r.code, 0) << format << ": " << r.err;
    };
    exportTo("recording", out / "rec.csv");
    exportTo("csv", out / "angles.csv");
    exportTo("mot", out / "angles.mot");
    exportTo("bids", out / "bids");
    Proc r = cliAs({"report", m_id, "--pdf", (out / "report.pdf").string()});
    EXPECT_EQ(r.code, 0) << r.err;
    r = cliAs({"report", "--patient", "P01", "--from", "2000-01-01", "--to", "2100-01-01", "--pdf",
               (out / "progress.pdf").string()});
    EXPECT_EQ(r.code, 0) << r.err;
    std::size_t files = 0, folders = 0;
    for (const auto& e : fs::recursive_directory_iterator(out)) {
      const unsigned want = e.is_directory() ? 0700u : 0600u;
      EXPECT_EQ(modeOf(e.path()), want) << e.path();
      (e.is_directory() ? folders : files) += 1;
    }
    EXPECT_EQ(folders, 4u);  // bids, sub-P01, ses-N, motion
    EXPECT_GE(files, 10u);
    EXPECT_EQ(modeOf(out), 0755u);  // named by the user: left as it is
    if (GetParam() == Engine::Sqlite) {
      EXPECT_EQ(modeOf(m_db), 0600u);
      r = cliAs({"db", "backup", "--out", (out / "backup.db").string()});
      EXPECT_EQ(r.code, 0) << r.err;
      EXPECT_EQ(modeOf(out / "backup.db"), 0600u);
    }
  }
}

// Item 7: a BIDS export replaced files without --overwrite, and patients P-01 and P01 both went
// to sub-P01. Now an export that would replace a file is refused before anything is written,
// and each patient code has its own subject, listed with it in participants.tsv.
TEST_P(FilesCliEngines, BidsNeverReplacesFilesUnaskedNorMixesPatients) {
  const fs::path root = dir() / "bids";
  Proc r = cliAs({"export", m_id, "--format", "bids", "--out", root.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path subject = root / "sub-P01";
  ASSERT_TRUE(fs::is_directory(subject));
  const fs::path imu = subject / ("ses-" + m_id) / "motion" /
                       ("sub-P01_ses-" + m_id + "_task-armtrack_tracksys-imu_motion.tsv");
  { std::ofstream(imu, std::ios::trunc) << "edited\n"; }
  const std::string participants = bytesOf(root / "participants.tsv");
  r = cliAs({"export", m_id, "--format", "bids", "--out", root.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("exists; nothing was written"), std::string::npos) << r.err;
  EXPECT_EQ(bytesOf(imu), "edited\n");
  r = cliAs({"export", m_id, "--format", "bids", "--out", root.string(), "--overwrite"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(bytesOf(imu), "edited\n");
  EXPECT_EQ(bytesOf(root / "participants.tsv"), participants);

  ASSERT_EQ(cliAs({"patient", "add", "--code", "P-01", "--name", "Another"}).code, 0);
  const std::string other = importFor("P-01", simulate("rec2.csv", 4.0));
  r = cliAs({"export", other, "--format", "bids", "--out", root.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  std::set<std::string> subjects;
  for (const auto& e : fs::directory_iterator(root))
    if (e.is_directory()) subjects.insert(e.path().filename().string());
  ASSERT_EQ(subjects.size(), 2u);
  EXPECT_EQ(subjects.count("sub-P01"), 1u);
  const std::string second = *std::find_if(subjects.begin(), subjects.end(),
                                           [](const std::string& s) { return s != "sub-P01"; });
  EXPECT_EQ(second.rfind("sub-P01h", 0), 0u) << second;
  EXPECT_TRUE(fs::exists(root / second / ("ses-" + other)));
  EXPECT_FALSE(fs::exists(subject / ("ses-" + other)));  // not in P01's folder
  const std::string rows = bytesOf(root / "participants.tsv");
  EXPECT_NE(rows.find("sub-P01\tP01\n"), std::string::npos) << rows;
  EXPECT_NE(rows.find(second + "\tP-01\n"), std::string::npos) << rows;
}

INSTANTIATE_TEST_SUITE_P(Engines, FilesCliEngines,
                         ::testing::Values(Engine::Sqlite, Engine::Postgres), engineName);

}  // namespace
}  // namespace armtrack::test
