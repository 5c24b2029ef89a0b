#include "tests/support/PostgresServer.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <pwd.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <QAtomicInt>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMap>
#include <QProcess>
#include <QSaveFile>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QSqlRecord>
#include <QStandardPaths>
#include <cerrno>
#include <cstdlib>

namespace armtrack::test {

namespace {

constexpr const char* kSuperuser = "armtrack_super";
/// Where servers live: under /tmp, not $TMPDIR, since a Unix socket path must stay under 108
/// bytes.
constexpr const char* kFolderTemplate = "/tmp/armtrack-pg-XXXXXX";

[[noreturn]] void failWith(const QString& why) {
  throw std::runtime_error(("test PostgreSQL server: " + why).toStdString());
}

// The folder with initdb, pg_ctl and postgres: $ARMTRACK_PG_BINDIR, else the newest
// /usr/lib/postgresql/N/bin (Debian's layout), else where pg_ctl is on the PATH.
QString findBinDir() {
  const QByteArray env = qgetenv("ARMTRACK_PG_BINDIR");
  if (!env.isEmpty()) return QString::fromLocal8Bit(env);
  QDir versions("/usr/lib/postgresql");
  QStringList names = versions.entryList(QDir::Dirs | QDir::NoDotAndDotDot);
  std::sort(names.begin(), names.end(),
            [](const QString& a, const QString& b) { return a.toInt() > b.toInt(); });
  for (const QString& v : names) {
    const QString bin = versions.filePath(v + "/bin");
    if (QFileInfo(bin + "/initdb").isExecutable() && QFileInfo(bin + "/pg_ctl").isExecutable())
      return bin;
  }
  const QString ctl = QStandardPaths::findExecutable("pg_ctl");
  if (!ctl.isEmpty()) return QFileInfo(QFileInfo(ctl).canonicalFilePath()).path();
  failWith(
      "no PostgreSQL server binaries (initdb, pg_ctl): install the Debian package 'postgresql' "
      "or set ARMTRACK_PG_BINDIR");
}

// A loopback port nobody listens on right now (the kernel's choice).
int freePort() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) failWith("cannot create a socket to find a free port");
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = 0;
  socklen_t len = sizeof addr;
  int port = 0;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0 &&
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) == 0)
    port = ntohs(addr.sin_port);
  ::close(fd);
  if (port == 0) failWith("cannot find a free loopback port");
  return port;
}

QString tail(const QString& path, int chars = 1500) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return "(no log at " + path + ")";
  const QByteArray all = f.readAll();
  return QString::fromLocal8Bit(all.right(chars));
}

QString connectionName() {
  static QAtomicInt counter;
  return QString("pg-test-super-%1").arg(counter.fetchAndAddRelaxed(1));
}

}  // namespace

PostgresServer::PostgresServer(bool durable) {
  sweepAbandoned();
  try {
    start(durable, QString("pid %1").arg(::getpid()));
  } catch (...) {
    stop();  // a half-started server and its folder do not outlive the failure
    throw;
  }
}

void PostgresServer::start(bool durable, const QString& owner) {
  m_bin = findBinDir();
  m_asPostgresUser = ::geteuid() == 0;
  QByteArray templ(kFolderTemplate);
  if (!::mkdtemp(templ.data())) failWith("cannot create a folder in /tmp");
  m_dir = QString::fromLocal8Bit(templ);
  m_data = m_dir + "/data";
  // Who stops this server: a later start sweeps it away once that owner is gone.
  QFile ownerFile(m_dir + "/owner");
  if (!ownerFile.open(QIODevice::WriteOnly) || ownerFile.write(owner.toUtf8()) < 0)
    failWith("cannot write " + ownerFile.fileName());
  ownerFile.close();
  if (m_asPostgresUser) {
    const passwd* pw = ::getpwnam("postgres");
    if (!pw)
      failWith(
          "running as root, and PostgreSQL refuses to run as root, but there is no 'postgres' "
          "account to run it as (the Debian package 'postgresql' creates it)");
    if (::chown(templ.constData(), pw->pw_uid, pw->pw_gid) != 0)
      failWith("cannot hand " + m_dir + " to the postgres account");
  }
  QFile::setPermissions(m_dir, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner |
                                   QFile::ReadGroup | QFile::ExeGroup | QFile::ReadOther |
                                   QFile::ExeOther);
  run(m_bin + "/initdb", {"-D", m_data, "-U", kSuperuser, "--auth-local=trust",
                          "--auth-host=scram-sha-256", "-E", "UTF8", "--no-locale", "-N"});
  const QString log = m_dir + "/server.log";
  QString lastError;
  for (int attempt = 0; attempt < 3 && !m_started; ++attempt) {
    m_port = freePort();
    QString options = "-k " + m_dir + " -p " + QString::number(m_port) +
                      " -c listen_addresses=127.0.0.1 -c max_connections=100";
    if (!durable)
      options +=
          " -c fsync=off -c synchronous_commit=off -c full_page_writes=off -c shared_buffers=16MB";
    try {
      run(m_bin + "/pg_ctl", {"-D", m_data, "-l", log, "-w", "-t", "60", "-o", options, "start"});
      m_started = true;
    } catch (const std::exception& e) {
      lastError = QString::fromLocal8Bit(e.what()) + "\nserver log:\n" + tail(log);
    }
  }
  if (!m_started) failWith("the server did not start:\n" + lastError);
  superuserSql("postgres", {QString("CREATE ROLE %1 LOGIN PASSWORD '%2'").arg(kRole, kPassword)});
}

PostgresServer::~PostgresServer() {
  if (m_owned) stop();
}

void PostgresServer::stop() {
  if (m_started) {
    m_started = false;
    try {
      run(m_bin + "/pg_ctl", {"-D", m_data, "-m", "immediate", "-w", "stop"}, 30000);
    } catch (...) {
      // The folder goes anyway; a postmaster whose lock file is gone exits within a minute.
    }
  }
  if (!m_dir.isEmpty()) QDir(m_dir).removeRecursively();
  m_dir.clear();
}

PostgresServer& PostgresServer::shared() {
  static std::unique_ptr<PostgresServer> server;
  if (!server) {
    const QString state = qEnvironmentVariable("ARMTRACK_TEST_PG_STATE");
    server = state.isEmpty() ? std::make_unique<PostgresServer>() : attach(state);
  }
  return *server;
}

namespace {

/// key=value lines of a state file; empty when it cannot be read.
QMap<QString, QString> readState(const QString& stateFile) {
  QMap<QString, QString> state;
  QFile f(stateFile);
  if (!f.open(QIODevice::ReadOnly)) return state;
  for (const QByteArray& line : f.readAll().split('\n')) {
    const qsizetype eq = line.indexOf('=');
    if (eq > 0) state.insert(QString::fromUtf8(line.left(eq)), QString::fromUtf8(line.mid(eq + 1)));
  }
  return state;
}

void writeState(const QString& stateFile, const QMap<QString, QString>& state) {
  QSaveFile f(stateFile);
  if (!f.open(QIODevice::WriteOnly)) failWith("cannot write " + stateFile);
  for (auto it = state.begin(); it != state.end(); ++it)
    f.write((it.key() + "=" + QString(it.value()).replace('\n', ' ') + "\n").toUtf8());
  if (!f.commit()) failWith("cannot write " + stateFile);
}

}  // namespace

std::unique_ptr<PostgresServer> PostgresServer::attach(const QString& stateFile) {
  const QMap<QString, QString> state = readState(stateFile);
  if (state.contains("error")) failWith("the shared test server did not start: " + state["error"]);
  if (!state.contains("dir") || !QFileInfo::exists(state["dir"] + "/data/postmaster.pid"))
    failWith("no shared test server is running (state file " + stateFile +
             "; CTest starts it in the fixture test armtrack_pg_server_start)");
  auto s = std::unique_ptr<PostgresServer>(new PostgresServer(AttachTag{}));
  s->m_owned = false;
  s->m_started = true;
  s->m_dir = state["dir"];
  s->m_data = s->m_dir + "/data";
  s->m_bin = state["bin"];
  s->m_port = state["port"].toInt();
  s->m_asPostgresUser = state["postgres_user"] == "1";
  return s;
}

bool PostgresServer::startDetached(const QString& stateFile) {
  stopDetached(stateFile);  // what an interrupted run left
  sweepAbandoned();
  PostgresServer s(AttachTag{});
  try {
    s.start(false, "fixture " + QFileInfo(stateFile).absoluteFilePath());
  } catch (const std::exception& e) {
    s.stop();
    writeState(stateFile, {{"error", QString::fromLocal8Bit(e.what())}});
    return false;
  }
  writeState(stateFile, {{"dir", s.m_dir},
                         {"bin", s.m_bin},
                         {"port", QString::number(s.m_port)},
                         {"postgres_user", s.m_asPostgresUser ? "1" : "0"}});
  s.m_owned = false;  // it outlives this process
  return true;
}

void PostgresServer::stopDetached(const QString& stateFile) {
  const QMap<QString, QString> state = readState(stateFile);
  if (state.contains("dir")) {
    PostgresServer s(AttachTag{});
    s.m_dir = state["dir"];
    s.m_data = s.m_dir + "/data";
    s.m_bin = state["bin"];
    s.m_asPostgresUser = state["postgres_user"] == "1";
    s.m_started = QFileInfo::exists(s.m_data + "/postmaster.pid");
    s.stop();
  }
  QFile::remove(stateFile);
}

void PostgresServer::sweepAbandoned() {
  const QDir tmp(QFileInfo(kFolderTemplate).path());
  const QString prefix = QFileInfo(kFolderTemplate).fileName().remove("XXXXXX");
  for (const QFileInfo& folder : tmp.entryInfoList({prefix + "*"}, QDir::Dirs)) {
    QFile ownerFile(folder.filePath() + "/owner");
    QString owner;
    if (ownerFile.open(QIODevice::ReadOnly)) owner = QString::fromUtf8(ownerFile.readAll());
    bool abandoned = false;
    if (owner.startsWith("pid ")) {
      // A test process's own server: abandoned once that process is gone.
      abandoned = ::kill(owner.mid(4).toInt(), 0) != 0 && errno == ESRCH;
    } else if (owner.startsWith("fixture ")) {
      // The fixture's: abandoned once its state file no longer names it.
      abandoned = readState(owner.mid(8)).value("dir") != folder.filePath();
    } else {
      // No owner yet: a server starting right now, or one from before owners were written.
      abandoned = folder.lastModified().secsTo(QDateTime::currentDateTime()) > 600;
    }
    if (!abandoned) continue;
    PostgresServer s(AttachTag{});
    s.m_dir = folder.filePath();
    s.m_data = s.m_dir + "/data";
    s.m_asPostgresUser = ::geteuid() == 0;
    try {
      s.m_bin = findBinDir();
      s.m_started = QFileInfo::exists(s.m_data + "/postmaster.pid");
    } catch (...) {
    }
    s.stop();
  }
}

QString PostgresServer::run(const QString& program, const QStringList& args, int timeoutMs) {
  QProcess p;
  p.setProcessChannelMode(QProcess::MergedChannels);
  p.setWorkingDirectory(m_dir);
  if (m_asPostgresUser)
    p.start("runuser", QStringList{"-u", "postgres", "--", program} + args);
  else
    p.start(program, args);
  if (!p.waitForStarted(10000)) failWith("cannot run " + program + ": " + p.errorString());
  if (!p.waitForFinished(timeoutMs)) {
    p.kill();
    p.waitForFinished(5000);
    failWith(program + " did not finish in " + QString::number(timeoutMs / 1000) + " s");
  }
  const QString output = QString::fromLocal8Bit(p.readAll());
  if (p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0)
    failWith(QFileInfo(program).fileName() + " " + args.join(' ') + " failed (exit " +
             QString::number(p.exitCode()) + "):\n" + output.right(1500));
  return output;
}

void PostgresServer::superuserSql(const QString& database, const QStringList& statements) {
  run(database, statements, nullptr);
}

std::vector<QVariantList> PostgresServer::superuserQuery(const QString& database,
                                                         const QString& sql) {
  std::vector<QVariantList> rows;
  run(database, {sql}, &rows);
  return rows;
}

QString runSql(QSqlDatabase& db, const QStringList& statements, std::vector<QVariantList>* rows) {
  for (const QString& s : statements) {
    QSqlQuery q(db);
    if (!q.exec(s)) return "'" + s.left(200) + "' failed: " + q.lastError().text();
    while (rows && q.next()) {
      QVariantList row;
      for (int i = 0; i < q.record().count(); ++i) row << q.value(i);
      rows->push_back(row);
    }
  }
  return {};
}

void PostgresServer::run(const QString& database, const QStringList& statements,
                         std::vector<QVariantList>* rows) {
  const QString name = connectionName();
  QString error;
  {
    QSqlDatabase db = QSqlDatabase::addDatabase("QPSQL", name);
    if (!db.isValid()) failWith("the Qt PostgreSQL driver is missing (libqt6sql6-psql)");
    db.setHostName(m_dir);
    db.setPort(m_port);
    db.setUserName(kSuperuser);
    db.setDatabaseName(database);
    if (!db.open()) {
      error = "cannot connect as superuser: " + db.lastError().text();
    } else {
      error = runSql(db, statements, rows);
      db.close();
    }
  }
  QSqlDatabase::removeDatabase(name);
  if (!error.isEmpty()) failWith(error);
}

QString PostgresServer::createDatabase(const QString& name) {
  superuserSql("postgres", {QString("CREATE DATABASE %1 OWNER %2").arg(name, kRole)});
  return QString("postgresql://%1@/%2?host=%3&port=%4").arg(kRole, name, m_dir).arg(m_port);
}

QString PostgresServer::uniqueName(const QString& stem) {
  static QAtomicInt counter;
  return QString("%1_p%2_%3")
      .arg(stem.toLower())
      .arg(::getpid())
      .arg(counter.fetchAndAddRelaxed(1));
}

QString PostgresServer::tcpUrl(const QString& database) const {
  return QString("postgresql://%1@127.0.0.1:%2/%3").arg(kRole).arg(m_port).arg(database);
}

}  // namespace armtrack::test
