#include "tests/support/PostgresServer.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <pwd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <QAtomicInt>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QSqlRecord>
#include <QStandardPaths>
#include <cstdlib>

namespace armtrack::test {

namespace {

constexpr const char* kSuperuser = "armtrack_super";

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
  try {
    start(durable);
  } catch (...) {
    stop();  // a half-started server and its folder do not outlive the failure
    throw;
  }
}

void PostgresServer::start(bool durable) {
  m_bin = findBinDir();
  m_asPostgresUser = ::geteuid() == 0;
  // Under /tmp, not $TMPDIR: a Unix socket path must stay under 108 bytes.
  QByteArray templ("/tmp/armtrack-pg-XXXXXX");
  if (!::mkdtemp(templ.data())) failWith("cannot create a folder in /tmp");
  m_dir = QString::fromLocal8Bit(templ);
  m_data = m_dir + "/data";
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
                      " -c listen_addresses=127.0.0.1 -c max_connections=40";
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
  stop();
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
  if (!server) server = std::make_unique<PostgresServer>();
  return *server;
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
      for (const QString& s : statements) {
        QSqlQuery q(db);
        if (!q.exec(s)) {
          error = "'" + s.left(200) + "' failed: " + q.lastError().text();
          break;
        }
        while (rows && q.next()) {
          QVariantList row;
          for (int i = 0; i < q.record().count(); ++i) row << q.value(i);
          rows->push_back(row);
        }
      }
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

QString PostgresServer::tcpUrl(const QString& database) const {
  return QString("postgresql://%1@127.0.0.1:%2/%3").arg(kRole).arg(m_port).arg(database);
}

}  // namespace armtrack::test
