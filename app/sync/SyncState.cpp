#include "app/sync/SyncState.h"

#include <QDir>
#include <QFile>
#include <QSqlError>
#include <QSqlQuery>
#include <QUuid>
#include <stdexcept>

namespace armtrack::sync {

namespace {

QSqlQuery run(const QSqlDatabase& db, const QString& sql, const QVariantList& values = {}) {
  QSqlQuery q(db);
  if (!q.prepare(sql)) throw std::runtime_error(q.lastError().text().toStdString());
  for (const QVariant& v : values) q.addBindValue(v);
  if (!q.exec())
    throw std::runtime_error("the home sync's state cannot be written: " +
                             q.lastError().text().toStdString());
  return q;
}

}  // namespace

SyncState::SyncState(const QString& folder)
    : m_folder(folder),
      m_connection("armtrack-homesync-" + QUuid::createUuid().toString(QUuid::WithoutBraces)) {
  if (!QDir().mkpath(folder))
    throw std::runtime_error("cannot make the folder '" + folder.toStdString() +
                             "' for the home sync's state: check its permissions");
  // The file holds the device token: made owner-only before SQLite writes into it.
  QFile file(filePath());
  if (!file.exists()) {
    if (!file.open(QIODevice::WriteOnly))
      throw std::runtime_error("cannot create '" + filePath().toStdString() +
                               "': " + file.errorString().toStdString());
    file.close();
  }
  file.setPermissions(QFile::ReadOwner | QFile::WriteOwner);
  QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", m_connection);
  db.setDatabaseName(filePath());
  if (!db.open())
    throw std::runtime_error("cannot open '" + filePath().toStdString() +
                             "': " + db.lastError().text().toStdString());
  run(db, "CREATE TABLE IF NOT EXISTS device (key TEXT PRIMARY KEY, value BLOB)");
  run(db,
      "CREATE TABLE IF NOT EXISTS uploads (session_id INTEGER PRIMARY KEY, uuid TEXT NOT NULL, "
      "sha256 TEXT NOT NULL, size_bytes INTEGER NOT NULL, chunks INTEGER NOT NULL, declared "
      "INTEGER NOT NULL DEFAULT 0, server_session INTEGER NOT NULL DEFAULT 0, sent_at TEXT)");
}

SyncState::~SyncState() {
  QSqlDatabase::database(m_connection, false).close();
  QSqlDatabase::removeDatabase(m_connection);
}

QString SyncState::filePath() const {
  return QDir(m_folder).filePath("homesync.sqlite");
}

QSqlDatabase SyncState::db() const {
  return QSqlDatabase::database(m_connection, false);
}

DeviceState SyncState::device() const {
  DeviceState s;
  QSqlQuery q = run(db(), "SELECT key, value FROM device");
  while (q.next()) {
    const QString key = q.value(0).toString();
    const QVariant v = q.value(1);
    if (key == "server_url") s.serverUrl = v.toString();
    if (key == "certificate") s.certificate = v.toByteArray();
    if (key == "token") s.token = v.toByteArray();
    if (key == "device") s.device = v.toLongLong();
    if (key == "patient") s.patient = v.toString();
  }
  return s;
}

void SyncState::saveDevice(const DeviceState& s) {
  QSqlDatabase d = db();
  d.transaction();
  run(d, "DELETE FROM device");
  const QList<QPair<QString, QVariant>> rows{{"server_url", s.serverUrl},
                                             {"certificate", s.certificate},
                                             {"token", s.token},
                                             {"device", s.device},
                                             {"patient", s.patient}};
  for (const auto& [k, v] : rows) run(d, "INSERT INTO device (key, value) VALUES (?, ?)", {k, v});
  d.commit();
}

std::optional<UploadRecord> SyncState::upload(qint64 sessionId) const {
  QSqlQuery q = run(db(),
                    "SELECT uuid, sha256, size_bytes, chunks, declared, server_session, sent_at "
                    "FROM uploads WHERE session_id = ?",
                    {sessionId});
  if (!q.next()) return std::nullopt;
  UploadRecord r;
  r.sessionId = sessionId;
  r.uuid = q.value(0).toString();
  r.sha256 = q.value(1).toString();
  r.sizeBytes = q.value(2).toLongLong();
  r.chunks = q.value(3).toInt();
  r.declared = q.value(4).toBool();
  r.serverSession = q.value(5).toLongLong();
  if (!q.value(6).isNull()) r.sentAt = QDateTime::fromString(q.value(6).toString(), Qt::ISODate);
  return r;
}

void SyncState::saveUpload(const UploadRecord& r) {
  run(db(),
      "INSERT OR REPLACE INTO uploads (session_id, uuid, sha256, size_bytes, chunks, declared, "
      "server_session, sent_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
      {r.sessionId, r.uuid, r.sha256, r.sizeBytes, r.chunks, r.declared ? 1 : 0, r.serverSession,
       r.sentAt.isValid() ? QVariant(r.sentAt.toUTC().toString(Qt::ISODateWithMs))
                          : QVariant(QMetaType(QMetaType::QString))});
}

void SyncState::forgetUpload(qint64 sessionId) {
  run(db(), "DELETE FROM uploads WHERE session_id = ?", {sessionId});
}

QDateTime SyncState::lastSent() const {
  QSqlQuery q = run(db(), "SELECT max(sent_at) FROM uploads WHERE sent_at IS NOT NULL");
  if (!q.next() || q.value(0).isNull()) return {};
  QDateTime t = QDateTime::fromString(q.value(0).toString(), Qt::ISODateWithMs);
  return t.toUTC();
}

}  // namespace armtrack::sync
