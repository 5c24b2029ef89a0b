#include "core/storage/DatabaseFiles.h"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include "core/storage/StorageError.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

constexpr const char* kCompanions[] = {"", "-wal", "-shm", "-journal"};

QString osReason(int err) {
  return QString::fromLocal8Bit(std::strerror(err));
}

std::string encoded(const QString& path) {
  return QFile::encodeName(path).toStdString();
}

// path with its last component's symbolic links followed (at most 40, as the kernel does); a
// dangling link gives the path it points to.
std::string followLinks(std::string p) {
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::vector<char> buf(PATH_MAX + 1);
    const ssize_t n = ::readlink(p.c_str(), buf.data(), buf.size() - 1);
    if (n <= 0) return p;
    std::string target(buf.data(), static_cast<std::size_t>(n));
    if (target[0] != '/') {
      const std::size_t slash = p.rfind('/');
      target = (slash == std::string::npos ? std::string() : p.substr(0, slash + 1)) + target;
    }
    p = target;
  }
  return p;
}

// What a path stands for on disk: an existing file by device and inode, a file that does not
// exist yet by its folder's device and inode and its name.
struct Identity {
  bool exists = false;
  dev_t dev = 0;
  ino_t ino = 0;
  std::string name;  // when it does not exist
};

std::optional<Identity> identityOf(const std::string& given) {
  const std::string p = followLinks(given);
  Identity id;
  struct stat st {};
  if (::stat(p.c_str(), &st) == 0) {
    id.exists = true;
    id.dev = st.st_dev;
    id.ino = st.st_ino;
    return id;
  }
  if (errno != ENOENT) return std::nullopt;
  const std::size_t slash = p.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : p.substr(0, slash);
  id.name = slash == std::string::npos ? p : p.substr(slash + 1);
  if (id.name.empty() || id.name == "." || id.name == "..") return std::nullopt;
  struct stat ds {};
  if (::stat(dir.c_str(), &ds) != 0 || !S_ISDIR(ds.st_mode)) return std::nullopt;
  id.dev = ds.st_dev;
  id.ino = ds.st_ino;
  return id;
}

bool same(const Identity& a, const Identity& b) {
  return a.exists == b.exists && a.dev == b.dev && a.ino == b.ino && a.name == b.name;
}

// The folder SQLite puts a database's companions in: that of the file it resolves to.
std::string resolvedDatabase(const QString& dbPath) {
  return followLinks(encoded(dbPath));
}

std::string folderOf(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

}  // namespace

QString sqliteFileAt(const QString& dbPath, const QString& path) {
  const std::optional<Identity> target = identityOf(encoded(path));
  if (!target) return {};
  std::vector<std::string> bases{encoded(dbPath)};
  if (const std::string real = resolvedDatabase(dbPath); real != bases.front())
    bases.push_back(real);
  for (const std::string& base : bases)
    for (const char* suffix : kCompanions) {
      const std::string candidate = base + suffix;
      const std::optional<Identity> id = identityOf(candidate);
      if (id && same(*id, *target)) return QFile::decodeName(candidate.c_str());
    }
  return {};
}

QString createPrivateFile(const QString& path) {
  const int fd = ::open(encoded(path).c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                        S_IRUSR | S_IWUSR);
  if (fd < 0) return osReason(errno);
  // The umask can only take bits away; this puts back exactly 0600 whatever it was.
  const bool ok = ::fchmod(fd, S_IRUSR | S_IWUSR) == 0;
  const int err = errno;
  ::close(fd);
  if (!ok) {
    ::unlink(encoded(path).c_str());
    return osReason(err);
  }
  return {};
}

QString makePrivateFolders(const QString& folder) {
  const QString absolute = QDir::cleanPath(QFileInfo(folder).absoluteFilePath());
  std::vector<QString> missing;
  for (QString p = absolute; !p.isEmpty() && !QFileInfo(p).exists();) {
    missing.push_back(p);
    const QString up = QFileInfo(p).path();
    if (up == p) break;
    p = up;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    const std::string p = encoded(*it);
    if (::mkdir(p.c_str(), S_IRWXU) != 0 && errno != EEXIST)
      return "cannot create the folder '" + *it + "': " + osReason(errno) +
             "; choose a folder you may write to";
    ::chmod(p.c_str(), S_IRWXU);  // the umask may have taken the owner's bits away
  }
  if (!QFileInfo(absolute).isDir())
    return "'" + absolute + "' is not a folder; choose another location";
  return {};
}

QString privateAppDataFolder() {
  const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
  if (dir.isEmpty())
    throw StorageError(Kind::Io, "no application data folder on this system; pass --db PATH");
  if (const QString why = makePrivateFolders(dir); !why.isEmpty())
    throw StorageError(Kind::Io, why.toStdString());
  // The folder is ArmTrack's own (and so is its organisation folder): nobody else has a reason to
  // read it. Folders of other owners are left alone.
  QStringList own{dir};
  const QFileInfo up(QFileInfo(dir).path());
  if (!QCoreApplication::organizationName().isEmpty() &&
      up.fileName() == QCoreApplication::organizationName())
    own << up.filePath();
  for (const QString& d : own) {
    struct stat st {};
    const std::string p = encoded(d);
    if (::stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == ::geteuid() &&
        (st.st_mode & (S_IRWXG | S_IRWXO)) != 0)
      ::chmod(p.c_str(), S_IRWXU);
  }
  return dir;
}

QString sqliteReadOnlyReason(const QString& dbPath) {
  const std::string real = resolvedDatabase(dbPath);
  if (::access(real.c_str(), W_OK) != 0) {
    const int err = errno;
    if (err == ENOENT) return {};  // created later, where the folder decides
    return "the file '" + dbPath + "' cannot be written (" + osReason(err) + ")";
  }
  const std::string dir = folderOf(real);
  if (::access(dir.c_str(), W_OK) == 0) return {};
  const int err = errno;
  // SQLite works in a folder it cannot write to while the -wal and -shm it needs are there and
  // writable (another connection made them).
  bool companions = true;
  for (const char* suffix : {"-wal", "-shm"})
    companions = companions && ::access((real + suffix).c_str(), W_OK) == 0;
  if (companions) return {};
  return "its folder '" + QFile::decodeName(dir.c_str()) + "' cannot be written (" + osReason(err) +
         "), and SQLite needs to create '" + QFileInfo(QFile::decodeName(real.c_str())).fileName() +
         "-wal' and -shm there to write";
}

QStringList missingCompanions(const QString& dbPath) {
  QStringList out;
  const std::string real = resolvedDatabase(dbPath);
  for (const char* suffix : {"-wal", "-shm"}) {
    struct stat st {};
    if (::lstat((real + suffix).c_str(), &st) != 0 && errno == ENOENT)
      out << QFile::decodeName((real + suffix).c_str());
  }
  return out;
}

void removeCheckLeftovers(const QString& dbPath, const QStringList& created) {
  if (created.isEmpty()) return;
  const std::string real = resolvedDatabase(dbPath);
  const std::string wal = real + "-wal", shm = real + "-shm";
  const auto emptyFile = [](const std::string& p) {
    struct stat st {};
    return ::lstat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && st.st_size == 0;
  };
  const auto absent = [](const std::string& p) {
    struct stat st {};
    return ::lstat(p.c_str(), &st) != 0 && errno == ENOENT;
  };
  const bool madeWal = created.contains(QFile::decodeName(wal.c_str()));
  const bool madeShm = created.contains(QFile::decodeName(shm.c_str()));
  const int fd = ::open(shm.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) {  // no index: nobody reads the log through one
    if (madeWal && emptyFile(wal)) ::unlink(wal.c_str());
    return;
  }
  // SQLite's "dead man switch" byte (UNIX_SHM_DMS, offset 128 of the -shm): every connection in
  // WAL mode holds a read lock on it. Holding the write lock, nobody else uses the log or its
  // index, and nobody can start to until it is released (a new connection is told to wait).
  struct flock lock {};
  lock.l_type = F_WRLCK;
  lock.l_whence = SEEK_SET;
  lock.l_start = 128;
  lock.l_len = 1;
  if (::fcntl(fd, F_SETLK, &lock) == 0) {
    if (madeWal && emptyFile(wal)) ::unlink(wal.c_str());
    if (madeShm && (absent(wal) || emptyFile(wal))) ::unlink(shm.c_str());
  }
  ::close(fd);  // releases the lock
}

QString immutableUri(const QString& dbPath) {
  const QByteArray path = QFile::encodeName(
      QFileInfo(QFile::decodeName(resolvedDatabase(dbPath).c_str())).absoluteFilePath());
  QString uri = "file:";
  for (const char c : path) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 128 && std::isalnum(u)) || c == '/' || c == '.' || c == '_' || c == '-' || c == '~')
      uri += QChar(c);
    else
      uri += '%' + QString::number(u, 16).rightJustified(2, '0').toUpper();
  }
  return uri + "?mode=ro&immutable=1";
}

}  // namespace armtrack::storage
