// HomeSyncClient's uploads: the queue of home sessions not yet acknowledged, each exported once
// into the outbox (its CSV is what the checksum names), declared, sent in chunks and completed.
#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QUuid>
#include <algorithm>
#include <stdexcept>

#include "app/sync/HomeSyncClient.h"
#include "core/storage/ClinicalStore.h"

namespace armtrack::sync {

namespace {

QString sha256Of(QFile& file) {
  QCryptographicHash hash(QCryptographicHash::Sha256);
  file.seek(0);
  hash.addData(&file);
  return QString::fromLatin1(hash.result().toHex());
}

}  // namespace

QString HomeSyncClient::outboxPath(qint64 sessionId, const char* ext) const {
  return QDir(m_folder).filePath("outbox/session-" + QString::number(sessionId) + ext);
}

std::vector<qint64> HomeSyncClient::waitingSessions() {
  std::vector<qint64> out;
  if (m_device.patient.isEmpty()) return out;
  std::vector<storage::SessionInfo> sessions;
  try {
    sessions = store().listSessions(m_device.patient);
  } catch (const storage::StorageError& e) {
    if (e.kind() == storage::StorageError::Kind::NotFound) return out;  // nothing recorded yet
    throw;
  }
  for (const storage::SessionInfo& s : sessions) {
    if (s.setting != storage::kSettingHome || s.status == storage::kStatusRecording ||
        s.sampleRows == 0)
      continue;
    const std::optional<UploadRecord> u = state().upload(s.id);
    if (!u || !u->sent()) out.push_back(s.id);
  }
  std::sort(out.begin(), out.end());
  return out;
}

void HomeSyncClient::countWaiting() {
  try {
    state();
    m_status.lastSent = m_state->lastSent();
    m_status.waiting = static_cast<int>(waitingSessions().size());
  } catch (const std::exception& e) {
    m_status.detail = QString::fromLocal8Bit(e.what());
  }
}

UploadRecord HomeSyncClient::prepare(qint64 sessionId) {
  std::optional<UploadRecord> known = state().upload(sessionId);
  const QString csvPath = outboxPath(sessionId, ".csv");
  QFile csv(csvPath);
  if (known && csv.exists() && csv.size() == known->sizeBytes) return *known;
  QDir().mkpath(QFileInfo(csvPath).absolutePath());
  QFile::remove(csvPath);
  QFile::remove(outboxPath(sessionId, ".json"));
  store().exportRecording(sessionId, csvPath.toStdString());
  if (!csv.open(QIODevice::ReadOnly))
    throw std::runtime_error("cannot read the outgoing copy '" + csvPath.toStdString() + "'");
  UploadRecord r;
  r.sessionId = sessionId;
  r.sha256 = sha256Of(csv);
  r.sizeBytes = csv.size();
  r.chunks = static_cast<int>(
      std::max<qint64>(1, (r.sizeBytes + m_options.chunkBytes - 1) / m_options.chunkBytes));
  // The same contents keep their UUID (the server may hold part of them); others get a new one.
  const bool same = known && known->sha256 == r.sha256 && known->chunks == r.chunks;
  r.uuid = same ? known->uuid : QUuid::createUuid().toString(QUuid::WithoutBraces);
  r.declared = same && known->declared;
  state().saveUpload(r);
  return r;
}

void HomeSyncClient::uploadNext() {
  if (m_queue.empty()) return finish(SyncProblem::None, {});
  const qint64 sessionId = m_queue.front();
  m_queue.pop_front();
  UploadRecord record;
  try {
    record = prepare(sessionId);
  } catch (const std::exception& e) {
    // One session that cannot be read does not hold up the others; it is tried again next time.
    m_status.detail = "session " + QString::number(sessionId) + ": " + e.what();
    return uploadNext();
  }
  upload(record);
}

void HomeSyncClient::upload(const UploadRecord& record) {
  const QString path = "/api/v1/sessions/" + record.uuid;
  const auto declared = [this, record](const Answer& a) {
    if (a.status == 409) {
      // The UUID is taken with other contents at the server: a new one next time.
      state().forgetUpload(record.sessionId);
      return uploadNext();
    }
    if (a.status == 400) return uploadNext();  // refused as it is (e.g. an unknown protocol)
    if (a.status != 200 && a.status != 201) return stopOn(a, "declare");
    m_status.lastContact = QDateTime::currentDateTimeUtc();
    UploadRecord r = record;
    if (!r.declared) {
      r.declared = true;
      state().saveUpload(r);
    }
    std::deque<int> missing;
    for (const QJsonValue& v : QJsonDocument::fromJson(a.body).object().value("missing").toArray())
      missing.push_back(v.toInt());
    sendChunks(r, std::move(missing));
  };
  const auto declare = [this, record, path, declared] {
    storage::SessionInfo s = store().session(record.sessionId);
    QJsonObject meta{
        {"sha256", record.sha256}, {"size_bytes", record.sizeBytes}, {"chunks", record.chunks}};
    if (!s.protocolName.isEmpty()) meta.insert("protocol", s.protocolName);
    QFile sidecar(outboxPath(record.sessionId, ".json"));
    if (sidecar.open(QIODevice::ReadOnly)) {
      const QJsonDocument doc = QJsonDocument::fromJson(sidecar.readAll());
      if (doc.isObject()) meta.insert("sidecar", doc.object());
    }
    meta.insert(
        "outcome",
        QJsonObject{{"pain_score", s.painScore ? QJsonValue(*s.painScore) : QJsonValue()},
                    {"comment", s.patientComment},
                    {"summary", QJsonDocument::fromJson(s.homeSummaryJson.toUtf8()).object()}});
    request("PUT", path, QJsonDocument(meta).toJson(QJsonDocument::Compact), {}, true, declared);
  };
  if (!record.declared) {
    try {
      return declare();
    } catch (const std::exception& e) {
      m_status.detail = QString::fromLocal8Bit(e.what());
      return uploadNext();
    }
  }
  // Declared before: ask where it stands (after a dropped connection), declare again if the
  // server has forgotten it.
  request("GET", path, {}, {}, true, [this, declare, declared](const Answer& a) {
    if (a.status == 404) {
      try {
        return declare();
      } catch (const std::exception& e) {
        m_status.detail = QString::fromLocal8Bit(e.what());
        return uploadNext();
      }
    }
    declared(a);
  });
}

void HomeSyncClient::sendChunks(UploadRecord record, std::deque<int> missing) {
  if (missing.empty()) return complete(record);
  const int n = missing.front();
  missing.pop_front();
  QFile csv(outboxPath(record.sessionId, ".csv"));
  if (n < 0 || n >= record.chunks || !csv.open(QIODevice::ReadOnly) ||
      !csv.seek(qint64{n} * m_options.chunkBytes)) {
    state().forgetUpload(record.sessionId);  // the copy is gone: exported again next time
    return uploadNext();
  }
  const QByteArray bytes = csv.read(m_options.chunkBytes);
  const QByteArray sha = QCryptographicHash::hash(bytes, QCryptographicHash::Sha256).toHex();
  request("PUT", "/api/v1/sessions/" + record.uuid + "/chunks/" + QString::number(n), bytes,
          {{"X-Chunk-Sha256", sha}, {"Content-Type", "application/octet-stream"}}, true,
          [this, record, n, missing = std::move(missing)](const Answer& a) mutable {
            if (a.status != 200) return stopOn(a, "chunk " + QString::number(n));
            emit chunkSent(record.sessionId, n);
            sendChunks(record, std::move(missing));
          });
}

void HomeSyncClient::complete(UploadRecord record) {
  request("POST", "/api/v1/sessions/" + record.uuid + "/complete", {}, {}, true,
          [this, record](const Answer& a) mutable {
            if (a.status == 422) {
              // The joined recording did not match: the server dropped its chunks; a fresh copy
              // and a new UUID next time.
              state().forgetUpload(record.sessionId);
              QFile::remove(outboxPath(record.sessionId, ".csv"));
              return uploadNext();
            }
            if (a.status != 200) return stopOn(a, "complete");
            // Acknowledged whole: only now is the session sent and its outgoing copy removed.
            record.serverSession =
                QJsonDocument::fromJson(a.body).object().value("session").toInteger();
            record.sentAt = QDateTime::currentDateTimeUtc();
            state().saveUpload(record);
            QFile::remove(outboxPath(record.sessionId, ".csv"));
            QFile::remove(outboxPath(record.sessionId, ".json"));
            m_status.lastSent = record.sentAt;
            m_status.lastContact = record.sentAt;
            countWaiting();
            emit sessionSent(record.sessionId, record.serverSession);
            emit statusChanged(m_status);
            uploadNext();
          });
}

}  // namespace armtrack::sync
