#include "core/storage/DatabaseUrl.h"

#include <QDir>
#include <QRegularExpression>
#include <QUrl>

#include "core/storage/DatabaseFiles.h"
#include "core/storage/StorageError.h"

namespace armtrack::storage {

namespace {

[[noreturn]] void bad(const QString& why) {
  throw StorageError(StorageError::Kind::Usage, ("--db: " + why).toStdString());
}

const QString kPgForm = "postgresql://user@host:port/dbname";

// libpq's URI form, by hand: QUrl refuses a percent-encoded '/' in the host, which is how a
// socket folder is written there.
DatabaseUrl parsePostgres(const QString& text) {
  DatabaseUrl url;
  url.engine = DatabaseUrl::Engine::Postgres;
  QString rest = text.mid(text.indexOf("://") + 3);
  QString query;
  if (const int q = rest.indexOf('?'); q >= 0) {
    query = rest.mid(q + 1);
    rest = rest.left(q);
  }
  const int slash = rest.indexOf('/');
  if (slash < 0) bad("'" + text + "' names no database (" + kPgForm + ")");
  QString authority = rest.left(slash);
  url.database = QUrl::fromPercentEncoding(rest.mid(slash + 1).toUtf8());
  if (url.database.isEmpty() || url.database.contains('/'))
    bad("'" + text + "' names no database (" + kPgForm + ")");
  if (const int at = authority.lastIndexOf('@'); at >= 0) {
    const QString user = authority.left(at);
    if (user.contains(':'))
      bad("put no password in the URL; use ARMTRACK_DB_PASSWORD or ~/.pgpass");
    url.user = QUrl::fromPercentEncoding(user.toUtf8());
    authority = authority.mid(at + 1);
  }
  QString portText;
  if (authority.startsWith('[')) {  // [IPv6]:port
    const int close = authority.indexOf(']');
    if (close < 0) bad("'" + text + "': unclosed '[' in the host");
    url.host = authority.mid(1, close - 1);
    portText = authority.mid(close + 1).startsWith(':') ? authority.mid(close + 2) : QString();
  } else {
    const int colon = authority.lastIndexOf(':');
    url.host = QUrl::fromPercentEncoding((colon >= 0 ? authority.left(colon) : authority).toUtf8());
    if (colon >= 0) portText = authority.mid(colon + 1);
  }
  for (const QString& pair : query.split('&', Qt::SkipEmptyParts)) {
    const QString key = pair.section('=', 0, 0);
    const QString value = QUrl::fromPercentEncoding(pair.section('=', 1).toUtf8());
    if (key == "host")
      url.host = value;
    else if (key == "port")
      portText = value;
    else if (key == "password")
      bad("put no password in the URL; use ARMTRACK_DB_PASSWORD or ~/.pgpass");
    else
      bad("'" + text + "': unknown parameter '" + key + "' (host and port are understood)");
  }
  if (!portText.isEmpty()) {
    bool ok = false;
    url.port = portText.toInt(&ok);
    if (!ok || url.port < 1 || url.port > 65535)
      bad("'" + text + "': port '" + portText + "' is not a number from 1 to 65535");
  }
  if (!url.host.isEmpty() && !url.host.startsWith('/') &&
      url.host.contains(QRegularExpression("[^A-Za-z0-9.:_-]")))
    bad("'" + text + "': host '" + url.host + "' is neither a name nor a socket folder");
  return url;
}

}  // namespace

DatabaseUrl DatabaseUrl::parse(const QString& text) {
  if (text.trimmed().isEmpty()) bad("empty database location");
  DatabaseUrl url;
  if (text.startsWith("postgresql://") || text.startsWith("postgres://"))
    return parsePostgres(text);
  QString path = text;
  if (path.startsWith("sqlite://"))
    path = path.mid(9);
  else if (path.startsWith("sqlite:"))
    path = path.mid(7);
  else if (path.contains("://"))
    bad("unknown database kind in '" + text + "' (use a path, sqlite:PATH or postgresql://...)");
  if (path.isEmpty()) bad("'" + text + "' names no file");
  url.path = path;
  return url;
}

DatabaseUrl DatabaseUrl::defaultLocation() {
  // Made 0700 when missing, and tightened to 0700 when it is there and this user's: the folder
  // is ArmTrack's own and holds the records (docs/storage.md, "Files and permissions").
  const QString dir = privateAppDataFolder();
  DatabaseUrl url;
  url.path = QDir(dir).filePath("armtrack.db");
  return url;
}

QString DatabaseUrl::display() const {
  if (engine == Engine::Sqlite) return path;
  const QString who = user.isEmpty() ? QString() : user + "@";
  if (isSocket())
    return "postgresql://" + who + "/" + database +
           "?host=" + (host.isEmpty() ? QString("(default socket)") : host) +
           "&port=" + QString::number(port);
  return "postgresql://" + who + host + ":" + QString::number(port) + "/" + database;
}

}  // namespace armtrack::storage
