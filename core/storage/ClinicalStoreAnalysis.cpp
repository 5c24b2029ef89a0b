// Estimates, metrics and the analysis state of ClinicalStore's sessions (docs/storage.md,
// "Estimates", "Metrics" and "Analysis state").
#include <tuple>
#include <vector>

#include "core/storage/AuditLog.h"
#include "core/storage/ClinicalStore.h"
#include "core/storage/ProcessIdentity.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

using detail::processEnded;
using detail::thisHost;
using detail::thisProcess;

}  // namespace

int ClinicalStore::saveEstimates(qint64 sessionId, const QString& paramsJson, const QString& codec,
                                 const QByteArray& data) {
  require(isStaff(), "store estimates");
  visibleSessionStatus(sessionId);
  int version = 0;
  m_db.transaction([&] {
    version = estimateVersions(sessionId) + 1;
    m_db.exec(
        "INSERT INTO estimates (session_id, version, created_at, params_json, codec, data) "
        "VALUES (?, ?, ?, ?, ?, ?)",
        {sessionId, version, utcNow(), paramsJson, codec, data});
  });
  return version;
}

int ClinicalStore::estimateVersions(qint64 sessionId) {
  visibleSessionStatus(sessionId);
  QSqlQuery q = m_db.exec(
      "SELECT coalesce(max(version), 0) FROM estimates WHERE session_id = ? AND complete = 1",
      {sessionId});
  return q.next() ? q.value(0).toInt() : 0;
}

int ClinicalStore::saveMetrics(qint64 sessionId, const QString& perAngleJson,
                               const QString& perRepetitionJson) {
  require(isStaff(), "store metrics");
  visibleSessionStatus(sessionId);
  int version = 0;
  m_db.transaction([&] { version = insertMetrics(sessionId, perAngleJson, perRepetitionJson); });
  return version;
}

int ClinicalStore::insertMetrics(qint64 sessionId, const QString& perAngleJson,
                                 const QString& perRepetitionJson, const StoredSeries& series) {
  QSqlQuery q =
      m_db.exec("SELECT coalesce(max(version), 0) FROM metrics WHERE session_id = ?", {sessionId});
  const int version = (q.next() ? q.value(0).toInt() : 0) + 1;
  q.finish();
  m_db.exec(
      "INSERT INTO metrics (session_id, version, created_at, per_angle_json, "
      "per_repetition_json, series_codec, series) VALUES (?, ?, ?, ?, ?, ?, ?)",
      {sessionId, version, utcNow(), perAngleJson, perRepetitionJson,
       series.codec.isEmpty() ? QVariant() : QVariant(series.codec),
       series.codec.isEmpty() ? QVariant() : QVariant(series.data)});
  return version;
}

std::optional<ClinicalStore::StoredSeries> ClinicalStore::latestMetricSeries(qint64 sessionId) {
  visibleSessionStatus(sessionId);
  QSqlQuery q = m_db.exec(
      "SELECT series_codec, series FROM metrics WHERE session_id = ? ORDER BY version DESC "
      "LIMIT 1",
      {sessionId});
  if (!q.next() || q.value(0).isNull()) return std::nullopt;
  return StoredSeries{q.value(0).toString(), q.value(1).toByteArray()};
}

std::optional<std::pair<QString, QString>> ClinicalStore::latestMetrics(qint64 sessionId) {
  visibleSessionStatus(sessionId);
  QSqlQuery q = m_db.exec(
      "SELECT per_angle_json, per_repetition_json FROM metrics WHERE "
      "session_id = ? ORDER BY version DESC LIMIT 1",
      {sessionId});
  if (!q.next()) return std::nullopt;
  return std::make_pair(q.value(0).toString(), q.value(1).toString());
}

std::optional<EstimateRecord> ClinicalStore::estimates(qint64 sessionId, int version) {
  visibleSessionStatus(sessionId);
  const QString columns =
      "SELECT id, version, created_at, params_json, codec, data FROM estimates ";
  QSqlQuery q =
      version > 0
          ? m_db.exec(columns + "WHERE session_id = ? AND version = ? AND complete = 1",
                      {sessionId, version})
          : m_db.exec(
                columns + "WHERE session_id = ? AND complete = 1 ORDER BY version DESC LIMIT 1",
                {sessionId});
  if (!q.next()) return std::nullopt;
  EstimateRecord e;
  e.id = q.value(0).toLongLong();
  e.version = q.value(1).toInt();
  e.createdAt = q.value(2).toString();
  e.paramsJson = q.value(3).toString();
  e.codec = q.value(4).toString();
  e.data = q.value(5).toByteArray();
  return e;
}

ClinicalStore::EstimatesDraft ClinicalStore::beginEstimates(qint64 sessionId,
                                                            const QString& codec) {
  require(isStaff(), "store estimates");
  visibleSessionStatus(sessionId);
  EstimatesDraft draft;
  m_db.transaction([&] {
    lockSessionRow(sessionId);
    removeDeadDrafts(sessionId);
    // A draft's version is negative (below every other of the session) until it is finished.
    QSqlQuery q = m_db.exec("SELECT coalesce(min(version), 0) FROM estimates WHERE session_id = ?",
                            {sessionId});
    draft.version = std::min(q.next() ? q.value(0).toInt() : 0, 0) - 1;
    q.finish();
    draft.id = m_db.insert(
        "INSERT INTO estimates (session_id, version, created_at, params_json, codec, data, "
        "complete, writer_host, writer_pid) VALUES (?, ?, ?, '{}', ?, ?, 0, ?, ?)",
        {sessionId, draft.version, utcNow(), codec, QByteArray(""), thisHost(), thisProcess()});
    m_db.exec("UPDATE sessions SET analysis_host = ?, analysis_pid = ? WHERE id = ?",
              {thisHost(), thisProcess(), sessionId});
  });
  draft.sessionId = sessionId;
  return draft;
}

void ClinicalStore::appendEstimateChunk(const EstimatesDraft& draft, int seq, qint64 rows,
                                        const QByteArray& blob) {
  m_db.transaction([&] {
    m_db.exec("INSERT INTO estimate_chunks (estimate_id, seq, row_count, data) VALUES (?, ?, ?, ?)",
              {draft.id, seq, rows, blob});
  });
}

void ClinicalStore::readEstimateChunks(
    const EstimateRecord& record,
    const std::function<void(int seq, std::uint64_t rows, const QByteArray& data)>& chunk) {
  // A few at a time (a chunk is about 3.5 MB), each batch read whole before chunk sees it.
  constexpr int kBatch = 4;
  for (int next = 0;;) {
    std::vector<std::tuple<int, std::uint64_t, QByteArray>> batch;
    {
      QSqlQuery q = m_db.exec(
          "SELECT seq, row_count, data FROM estimate_chunks WHERE estimate_id = ? AND seq >= ? "
          "ORDER BY seq LIMIT " +
              QString::number(kBatch),
          {record.id, next});
      while (q.next())
        batch.emplace_back(q.value(0).toInt(), q.value(1).toULongLong(), q.value(2).toByteArray());
    }
    for (auto& [seq, rows, data] : batch) {
      chunk(seq, rows, data);
      next = seq + 1;
      data = QByteArray();
    }
    if (batch.size() < static_cast<std::size_t>(kBatch)) return;
  }
}

ClinicalStore::AnalysisVersions ClinicalStore::finishAnalysis(
    const EstimatesDraft& draft, const QString& paramsJson, const QString& perAngleJson,
    const std::function<QString(int estimateVersion)>& perRepetitionJson,
    const StoredSeries& series) {
  AnalysisVersions v;
  m_db.transaction([&] {
    lockSessionRow(draft.sessionId);
    QSqlQuery q = m_db.exec(
        "SELECT coalesce(max(version), 0) FROM estimates WHERE session_id = ? AND complete = 1",
        {draft.sessionId});
    v.estimates = (q.next() ? q.value(0).toInt() : 0) + 1;
    q.finish();
    if (m_db.exec("UPDATE estimates SET version = ?, params_json = ?, complete = 1, "
                  "writer_host = NULL, writer_pid = NULL WHERE id = ? AND complete = 0",
                  {v.estimates, paramsJson, draft.id})
            .numRowsAffected() != 1)
      throw StorageError(Kind::NotFound, "session " + std::to_string(draft.sessionId) +
                                             ": the estimates being written were removed");
    // The metrics name the version they come from, which is only known now.
    v.metrics =
        insertMetrics(draft.sessionId, perAngleJson, perRepetitionJson(v.estimates), series);
    m_db.exec(
        "UPDATE sessions SET analysis = 'done', analysis_note = '', analysis_host = NULL, "
        "analysis_pid = NULL WHERE id = ?",
        {draft.sessionId});
    audit("create", "session", QString::number(draft.sessionId),
          "estimates and metrics version " + QString::number(v.estimates));
  });
  return v;
}

void ClinicalStore::abandonEstimates(const EstimatesDraft& draft) {
  m_db.transaction([&] {
    m_db.exec("DELETE FROM estimates WHERE id = ? AND complete = 0", {draft.id});
    m_db.exec(
        "UPDATE sessions SET analysis_host = NULL, analysis_pid = NULL WHERE id = ? AND "
        "analysis_pid = ? AND analysis_host = ?",
        {draft.sessionId, thisProcess(), thisHost()});
  });
}

void ClinicalStore::markAnalysisFailed(qint64 sessionId, const QString& why) {
  visibleSessionStatus(sessionId);
  m_db.transaction([&] {
    m_db.exec(
        "UPDATE sessions SET analysis = 'failed', analysis_note = ?, analysis_host = NULL, "
        "analysis_pid = NULL WHERE id = ?",
        {why.left(500), sessionId});
    audit("update", "session", QString::number(sessionId), "analysis failed");
  });
}

std::vector<qint64> ClinicalStore::pendingAnalyses() {
  std::vector<qint64> ids;
  QSqlQuery q = m_db.exec(
      "SELECT s.id, s.patient_id, s.analysis_host, s.analysis_pid FROM sessions s "
      "WHERE s.status = 'complete' AND s.analysis = 'pending' ORDER BY s.id");
  while (q.next()) {
    if (user().role == Role::Home && user().patientId != q.value(1).toLongLong()) continue;
    const bool claimed =
        !q.value(3).isNull() && !processEnded(q.value(2).toString(), q.value(3).toLongLong());
    if (!claimed) ids.push_back(q.value(0).toLongLong());
  }
  return ids;
}

void ClinicalStore::lockSessionRow(qint64 sessionId) {
  // Two analyses of one session number their versions one after the other: on SQLite the write
  // transaction already holds the database; on PostgreSQL (READ COMMITTED) both would read the
  // same highest version, so the session's row is locked until the transaction ends.
  if (m_db.isPostgres()) m_db.exec("SELECT id FROM sessions WHERE id = ? FOR UPDATE", {sessionId});
}

void ClinicalStore::removeDeadDrafts(qint64 sessionId) {
  // Drafts of this host whose writer is gone (a killed analysis); a draft of another host is
  // left alone: its process cannot be asked.
  std::vector<qint64> dead;
  QSqlQuery q = m_db.exec(
      "SELECT id, writer_host, writer_pid FROM estimates WHERE session_id = ? AND complete = 0",
      {sessionId});
  while (q.next())
    if (processEnded(q.value(1).toString(), q.value(2).toLongLong()))
      dead.push_back(q.value(0).toLongLong());
  q.finish();
  for (qint64 id : dead) m_db.exec("DELETE FROM estimates WHERE id = ?", {id});
}

}  // namespace armtrack::storage
