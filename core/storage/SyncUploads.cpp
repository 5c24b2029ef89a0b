#include "core/storage/SyncUploads.h"

#include <QCryptographicHash>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QUuid>

#include "core/storage/AuditLog.h"
#include "core/storage/TextRules.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

std::string notFound() {
  return "no such upload";  // the same for another patient's (docs/sync.md, "Security")
}

void checkUuid(const QString& uuid) {
  if (QUuid::fromString(uuid).isNull() || uuid.size() != 36)
    throw StorageError(Kind::Usage, "an upload is named by a UUID (8-4-4-4-12 hex digits)");
}

constexpr int kMaxCommentChars = 2000;  // as ClinicalStore::saveHomeOutcome

/// Reads metaJson's protocol, sidecar and outcome into meta, checking what can be checked before
/// the recording arrives (Usage otherwise).
void readDeclaration(UploadMeta& meta) {
  const QJsonObject o = QJsonDocument::fromJson(meta.metaJson.toUtf8()).object();
  meta.protocol = o.value("protocol").toString();
  if (o.value("sidecar").isObject())
    meta.sidecarJson = QString::fromUtf8(
        QJsonDocument(o.value("sidecar").toObject()).toJson(QJsonDocument::Compact));
  const QJsonValue outcome = o.value("outcome");
  meta.hasOutcome = outcome.isObject();
  if (outcome.isUndefined() || outcome.isNull()) return;
  if (!outcome.isObject()) throw StorageError(Kind::Usage, "outcome must be a JSON object");
  const QJsonObject out = outcome.toObject();
  const QJsonValue pain = out.value("pain_score");
  if (!pain.isUndefined() && !pain.isNull()) {
    if (!pain.isDouble() || pain.toDouble() != pain.toInt(-1) || pain.toInt() < 0 ||
        pain.toInt() > 10)
      throw StorageError(Kind::Usage, "outcome.pain_score must be a whole number 0-10 or null");
    meta.painScore = pain.toInt();
  }
  meta.comment = out.value("comment").toString();
  if (meta.comment.size() > kMaxCommentChars)
    throw StorageError(Kind::Usage, "outcome.comment is longer than " +
                                        std::to_string(kMaxCommentChars) + " characters");
  if (out.contains("summary") && !out.value("summary").isObject())
    throw StorageError(Kind::Usage, "outcome.summary must be a JSON object");
  if (out.value("summary").isObject())
    meta.summaryJson = QString::fromUtf8(
        QJsonDocument(out.value("summary").toObject()).toJson(QJsonDocument::Compact));
}

}  // namespace

QString sha256Hex(const QByteArray& data) {
  return QString::fromLatin1(QCryptographicHash::hash(data, QCryptographicHash::Sha256).toHex());
}

bool isSha256Hex(const QString& text) {
  if (text.size() != 64) return false;
  for (QChar c : text)
    if (!c.isDigit() && !(c.toLower() >= 'a' && c.toLower() <= 'f')) return false;
  return true;
}

SyncUploads::SyncUploads(ClinicalStore& store) : m_store(store), m_db(store.database()) {
  if (store.deviceId() == 0 || !store.user().patientId)
    throw StorageError(Kind::AccessDenied, "uploads are made by an enrolled home device");
}

SyncUploads::Row SyncUploads::visible(const QString& uuid) {
  checkUuid(uuid);
  QSqlQuery q = m_db.exec(
      "SELECT patient_id, sha256, size_bytes, chunk_count, meta_json, session_id FROM "
      "sync_uploads WHERE uuid = ?",
      {uuid.toLower()});
  if (!q.next() || q.value(0).toLongLong() != *m_store.user().patientId)
    throw StorageError(Kind::NotFound, notFound());
  Row r;
  r.patientId = q.value(0).toLongLong();
  r.meta.sha256 = q.value(1).toString();
  r.meta.sizeBytes = q.value(2).toLongLong();
  r.meta.chunkCount = q.value(3).toInt();
  r.meta.metaJson = q.value(4).toString();
  r.sessionId = q.value(5).isNull() ? 0 : q.value(5).toLongLong();
  readDeclaration(r.meta);
  return r;
}

std::vector<int> SyncUploads::missingChunks(const QString& uuid, int count) {
  std::vector<bool> have(static_cast<std::size_t>(count), false);
  QSqlQuery q = m_db.exec("SELECT seq FROM sync_upload_chunks WHERE uuid = ?", {uuid.toLower()});
  while (q.next()) {
    const int seq = q.value(0).toInt();
    if (seq >= 0 && seq < count) have[static_cast<std::size_t>(seq)] = true;
  }
  std::vector<int> missing;
  for (int i = 0; i < count; ++i)
    if (!have[static_cast<std::size_t>(i)]) missing.push_back(i);
  return missing;
}

UploadState SyncUploads::declare(const QString& uuid, const UploadMeta& declared) {
  checkUuid(uuid);
  UploadMeta meta = declared;
  readDeclaration(meta);
  if (!meta.protocol.isEmpty() &&
      !m_db.exec("SELECT 1 FROM protocols WHERE name_key = ?", {nameKey(meta.protocol)}).next())
    throw StorageError(Kind::Usage, "no protocol of that name at the clinic");
  if (!isSha256Hex(meta.sha256))
    throw StorageError(Kind::Usage, "sha256 must be 64 hex digits (the whole recording's)");
  if (meta.sizeBytes <= 0 || meta.sizeBytes > kMaxUploadBytes)
    throw StorageError(Kind::Usage, "size_bytes must be 1 byte to 8 GiB");
  if (meta.chunkCount < 1 || meta.chunkCount > kMaxUploadChunks || meta.chunkCount > meta.sizeBytes)
    throw StorageError(Kind::Usage, "chunks must be 1 to 100000 and no more than the bytes");
  const qint64 patient = *m_store.user().patientId;
  QSqlQuery q = m_db.exec(
      "SELECT patient_id, sha256, size_bytes, chunk_count FROM sync_uploads "
      "WHERE uuid = ?",
      {uuid.toLower()});
  if (q.next()) {
    if (q.value(0).toLongLong() != patient) {
      // Another patient's UUID: told as a conflict would tell that it exists. A real device
      // makes random UUIDs, so this is a probe or a bug; refused as not found, audited.
      q.finish();
      appendAudit(m_db, {m_store.user().name, "sync-refused", "upload", uuid.toLower(),
                         "device " + QString::number(m_store.deviceId()) +
                             ": declared another patient's upload"});
      throw StorageError(Kind::NotFound, notFound());
    }
    if (q.value(1).toString() != meta.sha256.toLower() ||
        q.value(2).toLongLong() != meta.sizeBytes || q.value(3).toInt() != meta.chunkCount)
      throw StorageError(Kind::Exists,
                         "this upload was declared with another checksum, size or chunk count");
    q.finish();
    return state(uuid);
  }
  q.finish();
  m_db.exec(
      "INSERT INTO sync_uploads (uuid, patient_id, device_id, sha256, size_bytes, chunk_count, "
      "meta_json, created_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
      {uuid.toLower(), patient, m_store.deviceId(), meta.sha256.toLower(), meta.sizeBytes,
       meta.chunkCount, meta.metaJson, utcNow()});
  UploadState s = state(uuid);
  s.created = true;
  return s;
}

UploadState SyncUploads::state(const QString& uuid) {
  const Row r = visible(uuid);
  UploadState s;
  s.sessionId = r.sessionId;
  if (r.sessionId == 0) s.missing = missingChunks(uuid, r.meta.chunkCount);
  return s;
}

void SyncUploads::putChunk(const QString& uuid, int seq, const QByteArray& data,
                           const QString& sha256) {
  const Row r = visible(uuid);
  if (seq < 0 || seq >= r.meta.chunkCount)
    throw StorageError(Kind::Usage, "chunk number out of range: the upload has " +
                                        std::to_string(r.meta.chunkCount) + " chunks from 0");
  if (data.isEmpty() || data.size() > kMaxChunkBytes)
    throw StorageError(Kind::Usage, "a chunk is 1 byte to 8 MiB");
  const QString actual = sha256Hex(data);
  if (!isSha256Hex(sha256) || actual != sha256.toLower()) {
    appendAudit(m_db, {m_store.user().name, "sync-refused", "upload", uuid.toLower(),
                       "chunk " + QString::number(seq) + " does not match its checksum"});
    throw StorageError(Kind::Corrupt, "chunk " + std::to_string(seq) +
                                          " does not match its sha256: send it again");
  }
  if (r.sessionId != 0) return;  // complete already; nothing more to keep
  QSqlQuery q = m_db.exec("SELECT sha256 FROM sync_upload_chunks WHERE uuid = ? AND seq = ?",
                          {uuid.toLower(), seq});
  if (q.next()) {
    if (q.value(0).toString() != actual)
      throw StorageError(Kind::Exists,
                         "chunk " + std::to_string(seq) + " was received with other contents");
    return;
  }
  q.finish();
  m_db.exec("INSERT INTO sync_upload_chunks (uuid, seq, sha256, data) VALUES (?, ?, ?, ?)",
            {uuid.toLower(), seq, actual, data});
}

qint64 SyncUploads::complete(const QString& uuid, const std::function<void(qint64)>& analyse) {
  const Row r = visible(uuid);
  if (r.sessionId != 0) return r.sessionId;
  const std::vector<int> missing = missingChunks(uuid, r.meta.chunkCount);
  if (!missing.empty())
    throw StorageError(Kind::Usage, std::to_string(missing.size()) +
                                        " chunk(s) still missing, the first " +
                                        std::to_string(missing.front()));
  QTemporaryDir dir;
  if (!dir.isValid()) throw StorageError(Kind::Io, "no temporary folder for the upload");
  const QString csv = dir.filePath("recording.csv");
  QFile out(csv);
  if (!out.open(QIODevice::WriteOnly))
    throw StorageError(Kind::Io, "cannot write " + csv.toStdString());
  QCryptographicHash whole(QCryptographicHash::Sha256);
  qint64 bytes = 0;
  for (int seq = 0; seq < r.meta.chunkCount; ++seq) {  // one chunk in memory at a time
    QSqlQuery q = m_db.exec("SELECT data FROM sync_upload_chunks WHERE uuid = ? AND seq = ?",
                            {uuid.toLower(), seq});
    if (!q.next()) throw StorageError(Kind::Usage, "chunk " + std::to_string(seq) + " missing");
    const QByteArray data = q.value(0).toByteArray();
    whole.addData(data);
    bytes += data.size();
    if (out.write(data) != data.size())
      throw StorageError(Kind::Io, "cannot write " + csv.toStdString());
  }
  out.close();
  if (bytes != r.meta.sizeBytes || QString::fromLatin1(whole.result().toHex()) != r.meta.sha256) {
    // Each chunk fitted its own checksum, the whole does not: start again from nothing.
    m_db.exec("DELETE FROM sync_upload_chunks WHERE uuid = ?", {uuid.toLower()});
    appendAudit(m_db, {m_store.user().name, "sync-refused", "upload", uuid.toLower(),
                       "the joined chunks do not match the declared checksum or size"});
    throw StorageError(Kind::Corrupt,
                       "the recording does not match its declared sha256 or size: its chunks "
                       "were discarded, send them again");
  }
  if (!r.meta.sidecarJson.isEmpty()) {
    QFile side(dir.filePath("recording.json"));
    if (!side.open(QIODevice::WriteOnly) || side.write(r.meta.sidecarJson.toUtf8()) < 0)
      throw StorageError(Kind::Io, "cannot write the sidecar");
  }
  QSqlQuery p = m_db.exec("SELECT code FROM patients WHERE id = ?", {r.patientId});
  if (!p.next()) throw StorageError(Kind::NotFound, notFound());
  const QString patientCode = p.value(0).toString();
  p.finish();
  const qint64 id = m_store.importRecording(csv.toStdString(), patientCode, r.meta.protocol);
  bool won = false;
  m_db.transaction([&] {
    won = m_db.exec(
                  "UPDATE sync_uploads SET session_id = ?, completed_at = ? WHERE uuid = ? AND "
                  "session_id IS NULL",
                  {id, utcNow(), uuid.toLower()})
              .numRowsAffected() == 1;
    if (won) {
      m_db.exec("DELETE FROM sync_upload_chunks WHERE uuid = ?", {uuid.toLower()});
      appendAudit(m_db, {m_store.user().name, "sync-upload", "session", QString::number(id),
                         "upload " + uuid.toLower() + " from device " +
                             QString::number(m_store.deviceId())});
    } else {  // another server completed it meanwhile: keep theirs
      m_db.exec("DELETE FROM sessions WHERE id = ?", {id});
    }
  });
  if (!won) return state(uuid).sessionId;
  if (r.meta.hasOutcome) {
    try {  // checked when declared; a failure here leaves the session stored without it
      m_store.saveHomeOutcome(id, r.meta.painScore, r.meta.comment, r.meta.summaryJson);
    } catch (const StorageError&) {
    }
  }
  if (analyse) analyse(id);
  return id;
}

}  // namespace armtrack::storage
