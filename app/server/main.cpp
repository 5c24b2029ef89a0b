// armtrack-server: the clinic's sync service for home devices, HTTPS only (docs/sync.md).
#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "app/server/HttpsServer.h"
#include "app/server/SyncApi.h"
#include "app/server/Tls.h"
#include "core/storage/Database.h"

namespace {

constexpr const char* kHelp =
    R"(Usage: armtrack-server --db URL --port N --cert FILE --key FILE [options]

The clinic's sync service for home devices (docs/sync.md): HTTPS only, in front of the clinic's
records (the same --db as armtrack-cli). It keeps no state of its own.

  --db URL        the records: a SQLite file or postgresql://user@host:port/name
                  (password from ARMTRACK_DB_PASSWORD or ~/.pgpass)
  --port N        the TCP port to listen on (1-65535)
  --cert FILE     the server's certificate chain, PEM
  --key FILE      its private key, PEM (RSA or EC, unencrypted; keep it mode 0600)
  --listen ADDR   the address to listen on (default: every address)
  --rate N        requests a second per device (default 20, bursts of 200)
  --config FILE   read these options from FILE first, one 'name = value' a line (db, port,
                  cert, key, listen, rate; '#' starts a comment); the command line's win.
                  The package's default: /etc/armtrack/server.conf
  --version       the version
  --help          this text
)";

/// The options of a configuration file as command-line arguments ("--db", "URL", ...). Throws
/// std::runtime_error naming the file and line of anything it does not understand.
QStringList configArguments(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
    throw std::runtime_error("cannot read the configuration " + path.toStdString() + ": " +
                             file.errorString().toStdString());
  const QStringList known{"db", "port", "cert", "key", "listen", "rate"};
  QStringList out;
  int number = 0;
  while (!file.atEnd()) {
    ++number;
    const QString line = QString::fromUtf8(file.readLine()).section('#', 0, 0).trimmed();
    if (line.isEmpty()) continue;
    const qsizetype eq = line.indexOf('=');
    const QString name = line.left(eq).trimmed(), value = line.mid(eq + 1).trimmed();
    if (eq <= 0 || !known.contains(name) || value.isEmpty())
      throw std::runtime_error(path.toStdString() + ":" + std::to_string(number) +
                               ": expected 'name = value' with a name of db, port, cert, key, "
                               "listen, rate; found '" +
                               line.toStdString() + "'");
    out << "--" + name << value;
  }
  return out;
}

int usage(const std::string& message) {
  std::cerr << "armtrack-server: " << message << "\n(armtrack-server --help says more)\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  QString db, cert, key, listenAddress;
  int port = 0;
  double rate = 20;
  QStringList args = app.arguments().mid(1);
  // A configuration file's options come first, so that the command line's override them.
  for (qsizetype i = 0; i + 1 < args.size(); ++i) {
    if (args[i] != "--config") continue;
    try {
      const QStringList fromFile = configArguments(args[i + 1]);
      args.remove(i, 2);
      args = fromFile + args;
      break;
    } catch (const std::exception& e) {
      return usage(e.what());
    }
  }
  for (qsizetype i = 0; i < args.size(); ++i) {
    const QString& a = args[i];
    if (a == "--help" || a == "-h") return std::cout << kHelp, 0;
    if (a == "--version") return std::cout << "armtrack-server " << ARMTRACK_VERSION << "\n", 0;
    if (a == "--config") return usage("--config may be given once");
    const QStringList withValue{"--db", "--port", "--cert", "--key", "--listen", "--rate"};
    if (!withValue.contains(a)) return usage("unknown option '" + a.toStdString() + "'");
    if (i + 1 >= args.size()) return usage(a.toStdString() + " needs a value");
    const QString v = args[++i];
    bool ok = true;
    if (a == "--db") db = v;
    if (a == "--cert") cert = v;
    if (a == "--key") key = v;
    if (a == "--listen") listenAddress = v;
    if (a == "--port") port = v.toInt(&ok);
    if (a == "--rate") rate = v.toDouble(&ok);
    if (!ok || (a == "--port" && (port < 1 || port > 65535)) || (a == "--rate" && rate <= 0))
      return usage(a.toStdString() + ": not a valid value: '" + v.toStdString() + "'");
  }
  if (cert.isEmpty() || key.isEmpty())
    return usage(
        "--cert and --key are required: the server speaks HTTPS only (docs/sync.md "
        "says how to get a certificate)");
  if (db.isEmpty()) return usage("--db is required");
  if (port == 0) return usage("--port is required");
  try {
    const QSslConfiguration tls = armtrack::server::serverTls(cert, key);
    armtrack::storage::Database database(armtrack::storage::DatabaseUrl::parse(db), {});
    armtrack::server::SyncApi api(database, {rate, rate * 10, 10});
    api.log = [](const QString& line) {
      std::cerr << QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString() << ' '
                << line.toStdString() << std::endl;
    };
    // Completions (join, import, analysis) run on workers, answered when done.
    armtrack::server::HttpsServer server(
        tls, {},
        [&api](const armtrack::server::HttpRequest& r,
               armtrack::server::HttpsServer::Responder done) { api.handle(r, done); });
    const QHostAddress address =
        listenAddress.isEmpty() ? QHostAddress(QHostAddress::Any) : QHostAddress(listenAddress);
    if (address.isNull())
      return usage("--listen: not an address: '" + listenAddress.toStdString() + "'");
    if (!server.listen(address, static_cast<quint16>(port))) {
      std::cerr << "armtrack-server: cannot listen on port " << port << ": "
                << server.errorString().toStdString() << "\n";
      return 1;
    }
    std::cout << "armtrack-server: listening on https://" << address.toString().toStdString() << ':'
              << server.port() << std::endl;
    return app.exec();
  } catch (const std::exception& e) {
    std::cerr << "armtrack-server: " << e.what() << "\n";
    return 1;
  }
}
