// The SQLite database's files (docs/storage.md, "Files and permissions"): a path is one of the
// database's files by identity, not by name; a backup never writes over them; the database, its
// -wal and -shm and its backups are 0600 whatever the umask, in a default folder of 0700; a
// damaged database is refused with nothing left beside it. These are SQLite's own (files and
// modes); the CLI tests (tests/app/test_files_cli.cpp) run the read-only cases as another user.
#include <sys/stat.h>
#include <unistd.h>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <algorithm>
#include <filesystem>
#include <set>

#include "core/storage/DatabaseFiles.h"
#include "tests/core/storage/StorageTestSupport.h"
#include "tests/support/FileInspection.h"

namespace armtrack::storage::test {
namespace {

namespace fs = std::filesystem;

using armtrack::test::modeOf;
using armtrack::test::namesIn;

qint64 countOf(Database& db, const char* table) {
  QSqlQuery q = db.exec(QString("SELECT count(*) FROM ") + table);
  return q.next() ? q.value(0).toLongLong() : -1;
}

/// Sets the umask for its lifetime.
struct Umask {
  mode_t old;
  explicit Umask(mode_t m) : old(::umask(m)) {}
  ~Umask() { ::umask(old); }
};

TEST(DatabaseFiles, OwnFilesAreFoundByIdentityNotByName) {
  Fixture f;  // open: its -wal and -shm exist
  const fs::path db = f.path.toStdString();
  const fs::path dir = db.parent_path();
  ASSERT_TRUE(fs::exists(db.string() + "-wal"));
  fs::create_directory(dir / "sub");
  fs::create_symlink(db, dir / "link.db");
  fs::create_hard_link(db, dir / "hard.db");
  fs::create_directory_symlink(dir, dir / "alias");
  fs::create_symlink(db.string() + "-journal", dir / "dangling.db");
  { std::ofstream(dir / "other.db") << "x"; }
  const auto at = [&](const fs::path& p) {
    return sqliteFileAt(f.path, QString::fromStdString(p.string()));
  };
  EXPECT_EQ(at(db), f.path);
  EXPECT_EQ(at(dir / "sub" / ".." / db.filename()), f.path);
  EXPECT_EQ(at(dir / "link.db"), f.path);
  EXPECT_EQ(at(dir / "hard.db"), f.path);
  EXPECT_EQ(at(dir / "alias" / db.filename()), f.path);
  EXPECT_EQ(at(db.string() + "-wal"), f.path + "-wal");
  EXPECT_EQ(at(db.string() + "-shm"), f.path + "-shm");
  EXPECT_EQ(at(db.string() + "-journal"), f.path + "-journal");  // does not exist
  EXPECT_EQ(at(dir / "alias" / (db.filename().string() + "-journal")), f.path + "-journal");
  EXPECT_EQ(at(dir / "dangling.db"), f.path + "-journal");
  EXPECT_TRUE(at(dir / "other.db").isEmpty());
  EXPECT_TRUE(at(dir / "new.db").isEmpty());
  EXPECT_TRUE(at(db.string() + "-wal2").isEmpty());
  EXPECT_TRUE(at(dir).isEmpty());
  EXPECT_TRUE(at(dir / "missing" / db.filename()).isEmpty());
  f.close();
  ASSERT_FALSE(fs::exists(db.string() + "-wal"));  // closed: the log is gone, its name is not
  EXPECT_EQ(at(db.string() + "-wal"), f.path + "-wal");
  EXPECT_EQ(at(dir / "sub" / ".." / (db.filename().string() + "-wal")), f.path + "-wal");
}

TEST(DatabaseFiles, BackupNeverWritesOverTheDatabaseOrItsFiles) {
  Fixture f;
  for (int i = 0; i < 5; ++i) f.store->addPatient(makePatient(QString("P%1").arg(i)));
  const fs::path db = f.path.toStdString();
  const fs::path dir = db.parent_path();
  fs::create_directory(dir / "sub");
  fs::create_symlink(db, dir / "link.db");
  fs::create_hard_link(db, dir / "hard.db");
  fs::create_symlink(db.string() + "-journal", dir / "dangling.db");
  const qint64 patients = countOf(*f.db, "patients");
  const qint64 audit = countOf(*f.db, "audit_log");
  for (const fs::path& out : {db, dir / "link.db", dir / "hard.db", fs::path(db.string() + "-wal"),
                              fs::path(db.string() + "-shm"), fs::path(db.string() + "-journal"),
                              dir / "dangling.db", dir / "sub" / ".." / db.filename()}) {
    SCOPED_TRACE(out.string());
    const StorageError e = expectError([&] { f.db->backup(QString::fromStdString(out.string())); },
                                       Kind::Usage, "would destroy the records");
    EXPECT_NE(std::string(e.what()).find(out.string()), std::string::npos) << e.what();
    EXPECT_FALSE(fs::exists(db.string() + "-journal"));
    EXPECT_EQ(f.db->integrityCheck(), "ok");
    EXPECT_EQ(countOf(*f.db, "patients"), patients);
    EXPECT_EQ(countOf(*f.db, "audit_log"), audit);
  }
  // A backup elsewhere still works and holds every patient.
  f.db->backup(QString::fromStdString((dir / "copy.db").string()));
  Database copy(DatabaseUrl::parse(QString::fromStdString((dir / "copy.db").string())), {});
  EXPECT_EQ(countOf(copy, "patients"), patients);
}

TEST(PrivateFiles, DatabaseItsWalAndShmAndBackupsAre0600WhateverTheUmask) {
  for (const mode_t mask : {mode_t{022}, mode_t{0}}) {
    SCOPED_TRACE("umask " + std::to_string(mask));
    const Umask umask(mask);
    Fixture f;  // open, so the -wal and -shm are there
    f.store->addPatient(makePatient("P01"));
    const std::string db = f.path.toStdString();
    EXPECT_EQ(modeOf(db), 0600u);
    EXPECT_EQ(modeOf(db + "-wal"), 0600u);
    EXPECT_EQ(modeOf(db + "-shm"), 0600u);
    const fs::path backup = fs::path(db).parent_path() / "backup.db";
    f.db->backup(QString::fromStdString(backup.string()));
    EXPECT_EQ(modeOf(backup), 0600u);
    EXPECT_FALSE(fs::exists(backup.string() + "-journal"));
  }
  // A folder the caller names is left as it is (only ArmTrack's own folder is tightened).
  const Umask umask(022);
  QTemporaryDir tmp;
  const fs::path named = fs::path(tmp.path().toStdString()) / "named";
  fs::create_directory(named);
  fs::permissions(named, fs::perms(0755));
  Database db(DatabaseUrl::parse(QString::fromStdString((named / "x.db").string())),
              {.create = true, .migrate = false});
  EXPECT_EQ(modeOf(named / "x.db"), 0600u);
  EXPECT_EQ(modeOf(named), 0755u);
}

TEST(PrivateFiles, DefaultFolderIsMade0700AndTightenedWhenItIsArmTracks) {
  QTemporaryDir tmp;
  ASSERT_TRUE(tmp.isValid());
  const QByteArray oldData = qgetenv("XDG_DATA_HOME");
  const QString oldOrg = QCoreApplication::organizationName();
  const QString oldApp = QCoreApplication::applicationName();
  qputenv("XDG_DATA_HOME", QFile::encodeName(tmp.filePath("data")));
  QCoreApplication::setOrganizationName("ArmTrack");
  QCoreApplication::setApplicationName("ArmTrack");
  const Umask umask(022);
  const fs::path data = tmp.filePath("data").toStdString();
  const fs::path app = data / "ArmTrack" / "ArmTrack";

  const DatabaseUrl url = DatabaseUrl::defaultLocation();
  EXPECT_EQ(fs::path(url.path.toStdString()), app / "armtrack.db");
  EXPECT_EQ(modeOf(data), 0700u);  // made by ArmTrack: 0700 (XDG's rule too)
  EXPECT_EQ(modeOf(data / "ArmTrack"), 0700u);
  EXPECT_EQ(modeOf(app), 0700u);
  // Loosened since (an older ArmTrack made them 0755): tightened on the next use; the folder
  // above, which is not ArmTrack's, is left as it is.
  fs::permissions(app, fs::perms(0755));
  fs::permissions(data / "ArmTrack", fs::perms(0755));
  fs::permissions(data, fs::perms(0755));
  DatabaseUrl::defaultLocation();
  EXPECT_EQ(modeOf(app), 0700u);
  EXPECT_EQ(modeOf(data / "ArmTrack"), 0700u);
  EXPECT_EQ(modeOf(data), 0755u);
  // A database created there is 0600.
  {
    Database db(url, {.create = true, .migrate = false});
    EXPECT_EQ(modeOf(url.path.toStdString()), 0600u);
  }

  QCoreApplication::setOrganizationName(oldOrg);
  QCoreApplication::setApplicationName(oldApp);
  if (oldData.isNull())
    qunsetenv("XDG_DATA_HOME");
  else
    qputenv("XDG_DATA_HOME", oldData);
}

TEST(IntegrityCheck, ADamagedDatabaseIsRefusedWithNothingLeftBesideIt) {
  Fixture f;
  for (int i = 0; i < 40; ++i)
    f.store->addPatient(makePatient(QString("P%1").arg(i, 3, 10, QChar('0'))));
  f.db->exec("PRAGMA wal_checkpoint(TRUNCATE)");
  f.close();
  const fs::path db = f.path.toStdString();
  std::string bytes = fileBytes(db);
  ASSERT_GT(bytes.size(), 8192u);
  for (std::size_t i = 4096 + 8; i < 8192; ++i) bytes[i] = static_cast<char>(0xA5);
  { std::ofstream(db, std::ios::binary | std::ios::trunc) << bytes; }
  const std::set<std::string> before = namesIn(db.parent_path());
  ASSERT_EQ(before.count(db.filename().string() + "-wal"), 0u);
  expectError([&] { Database again(DatabaseUrl::parse(f.path), {}); }, Kind::Corrupt,
              "integrity check");
  EXPECT_EQ(namesIn(db.parent_path()), before);
  EXPECT_EQ(fileBytes(db), bytes);
  // What was there before the check is never removed, even empty.
  { std::ofstream(db.string() + "-wal"); }
  expectError([&] { Database again(DatabaseUrl::parse(f.path), {}); }, Kind::Corrupt);
  EXPECT_TRUE(fs::exists(db.string() + "-wal"));
}

}  // namespace
}  // namespace armtrack::storage::test
