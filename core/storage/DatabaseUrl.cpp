#include "core/storage/DatabaseUrl.h"

#include <QDir>
#include <QStandardPaths>
#include <QUrl>

#include "core/storage/StorageError.h"

namespace armtrack::storage {

namespace {

[[noreturn]] void bad(const QString& why) {
  throw StorageError(StorageError::Kind::Usage, ("--db: " + why).toStdString());
}

}  // namespace

DatabaseUrl DatabaseUrl::parse(const QString& text) {
  if (text.trimmed().isEmpty()) bad("empty database location");
  DatabaseUrl url;
  if (text.startsWith("postgresql://") || text.startsWith("postgres://")) {
    const QUrl u(text, QUrl::StrictMode);
    if (!u.isValid() || u.host().isEmpty())
      bad("'" + text + "' is not of the form postgresql://user@host:port/dbname");
    if (!u.password().isEmpty())
      bad("put no password in the URL; use ARMTRACK_DB_PASSWORD or ~/.pgpass");
    url.engine = Engine::Postgres;
    url.user = u.userName();
    url.host = u.host();
    url.port = u.port(5432);
    url.database = u.path().mid(1);
    if (url.database.isEmpty() || url.database.contains('/'))
      bad("'" + text + "' names no database (postgresql://user@host:port/dbname)");
    return url;
  }
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
  const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
  if (dir.isEmpty())
    throw StorageError(StorageError::Kind::Io,
                       "no application data folder on this system; pass --db PATH");
  QDir().mkpath(dir);
  DatabaseUrl url;
  url.path = QDir(dir).filePath("armtrack.db");
  return url;
}

QString DatabaseUrl::display() const {
  if (engine == Engine::Sqlite) return path;
  return "postgresql://" + (user.isEmpty() ? QString() : user + "@") + host + ":" +
         QString::number(port) + "/" + database;
}

}  // namespace armtrack::storage
