// Sessions, their recordings (compressed chunks), estimates and metrics of ClinicalStore.
#include <QFile>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <limits>

#include "core/storage/AuditLog.h"
#include "core/storage/ChunkCodec.h"
#include "core/storage/ClinicalStore.h"
#include "core/storage/ProcessIdentity.h"
#include "core/storage/RecordingChunks.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

constexpr double kChunkSeconds = 1.0;            // a chunk spans about this much time
constexpr std::size_t kMaxChunkRows = 1u << 16;  // and never more rows than this

std::string text(const QString& s) {
  return s.toStdString();
}

int maskOf(const RecordingColumns& c) {
  return (c.upperArm ? 1 : 0) | (c.forearm ? 2 : 0) | (c.elbow ? 4 : 0) | (c.wrist ? 8 : 0) |
         (c.camWrist ? 16 : 0) | (c.camElbow ? 32 : 0) | (c.truth ? 64 : 0) |
         (c.estimate ? 128 : 0) | (c.trunk ? 256 : 0) | (c.shoulder ? 512 : 0) |
         (c.trueTrunk ? 1024 : 0);
}

// The sidecar of meta as JSON text, written by core/io itself so the two never disagree.
QString sidecarText(const RecordingMeta& meta) {
  QTemporaryDir dir;
  if (!dir.isValid()) throw StorageError(Kind::Io, "cannot create a temporary folder");
  const std::string path = dir.filePath("meta.json").toStdString();
  writeSidecar(path, meta);
  QFile f(QString::fromStdString(path));
  if (!f.open(QIODevice::ReadOnly)) throw StorageError(Kind::Io, "cannot read back the sidecar");
  return QString::fromUtf8(f.readAll());
}

RecordingMeta metaFromText(const QString& json, qint64 sessionId) {
  QTemporaryDir dir;
  if (!dir.isValid()) throw StorageError(Kind::Io, "cannot create a temporary folder");
  const QString path = dir.filePath("meta.json");
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly) || f.write(json.toUtf8()) < 0)
    throw StorageError(Kind::Io, "cannot write a temporary sidecar");
  f.close();
  try {
    return readSidecar(path.toStdString());
  } catch (const RecordingError& e) {
    throw StorageError(Kind::Corrupt,
                       "session " + std::to_string(sessionId) +
                           ": its stored calibration (sidecar) is unreadable: " + e.message());
  }
}

}  // namespace

RecordingColumns columnsOf(int m) {
  RecordingColumns c;
  c.upperArm = m & 1;
  c.forearm = m & 2;
  c.elbow = m & 4;
  c.wrist = m & 8;
  c.camWrist = m & 16;
  c.camElbow = m & 32;
  c.truth = m & 64;
  c.estimate = m & 128;
  c.trunk = m & 256;
  c.shoulder = m & 512;
  c.trueTrunk = m & 1024;
  return c;
}

int ClinicalStore::markDeadRecordingsInterrupted() {
  struct Dead {
    qint64 id;
    bool imported;
  };
  std::vector<Dead> dead;
  QSqlQuery q = m_db.exec(
      "SELECT id, recorder_host, recorder_pid, origin FROM sessions "
      "WHERE status = 'recording'");
  while (q.next())
    if (detail::processEnded(q.value(1).toString(), q.value(2).toLongLong()))
      dead.push_back({q.value(0).toLongLong(), q.value(3).toString() == kOriginImport});
  q.finish();
  if (m_db.isReadOnly()) {
    // Nothing can be written: reading still works, and the caller says why they stay.
    m_staleRecordingsKept = static_cast<int>(dead.size());
    return 0;
  }
  int interrupted = 0;
  for (const Dead& d : dead) {
    m_db.transaction([&] {
      if (d.imported) {
        // An import is all or nothing: one whose process died is removed whole.
        m_db.exec("DELETE FROM sessions WHERE id = ?", {d.id});
        appendAudit(m_db, {"system", "delete", "session", QString::number(d.id),
                           "import did not finish: removed"});
        ++m_removedImportsOnOpen;
      } else {
        m_db.exec("UPDATE sessions SET status = 'interrupted', analysis = 'none' WHERE id = ?",
                  {d.id});
        appendAudit(m_db, {"system", "update", "session", QString::number(d.id),
                           "recorder died: interrupted"});
        ++interrupted;
      }
    });
  }
  // Analyses whose process died: the session's analysis is pending again (the next command or
  // start of the app runs it) and the estimates they had begun to write are removed.
  std::vector<qint64> claims;
  QSqlQuery a = m_db.exec(
      "SELECT id, analysis_host, analysis_pid FROM sessions WHERE analysis_pid IS NOT NULL");
  while (a.next())
    if (detail::processEnded(a.value(1).toString(), a.value(2).toLongLong()))
      claims.push_back(a.value(0).toLongLong());
  a.finish();
  for (qint64 id : claims)
    m_db.transaction([&] {
      removeDeadDrafts(id);
      m_db.exec("UPDATE sessions SET analysis_host = NULL, analysis_pid = NULL WHERE id = ?", {id});
    });
  return interrupted;
}

qint64 ClinicalStore::beginSession(const QString& patientCode, const QString& protocolName,
                                   const QString& calibrationJson, int columnsMask,
                                   const SessionSettings& settings) {
  for (const auto& [name, json] : {std::pair{"devices", &settings.devicesJson},
                                   std::pair{"filter settings", &settings.filterJson}})
    if (!QJsonDocument::fromJson(json->toUtf8()).isObject())
      throw StorageError(Kind::Usage,
                         std::string("a session's ") + name + " must be a JSON object");
  const qint64 patientId = visiblePatientId(patientCode);
  const std::optional<qint64> protocol = protocolId(protocolName);
  qint64 id = 0;
  m_db.transaction([&] {
    id = m_db.insert(
        "INSERT INTO sessions (patient_id, therapist_id, protocol_id, started_at, devices_json, "
        "calibration_json, filter_json, status, columns_mask, recorder_host, recorder_pid, "
        "setting, origin) VALUES (?, ?, ?, ?, ?, ?, ?, 'recording', ?, ?, ?, ?, ?)",
        {patientId, isStaff() && user().id > 0 ? QVariant(user().id) : QVariant(),
         protocol ? QVariant(*protocol) : QVariant(), utcNow(), settings.devicesJson,
         calibrationJson, settings.filterJson, columnsMask, detail::thisHost(),
         detail::thisProcess(), isStaff() ? kSettingClinic : kSettingHome,
         settings.origin == kOriginImport ? kOriginImport : kOriginLive});
    audit("create", "session", QString::number(id), "patient " + patientCode);
  });
  return id;
}

qint64 ClinicalStore::beginRecording(const QString& patientCode, const QString& protocolName,
                                     const RecordingMeta& meta, const RecordingColumns& columns,
                                     const SessionSettings& settings) {
  return beginSession(patientCode, protocolName, sidecarText(meta), maskOf(columns), settings);
}

RecordingMeta ClinicalStore::recordingMeta(qint64 sessionId) {
  return metaFromText(visibleSession(sessionId).calibrationJson, sessionId);
}

std::optional<double> ClinicalStore::recordingStartS(qint64 sessionId) {
  visibleSession(sessionId);  // NotFound for a session the account may not see
  QSqlQuery q =
      m_db.exec("SELECT MIN(t_first) FROM recording_chunks WHERE session_id = ?", {sessionId});
  if (!q.next() || q.value(0).isNull()) return std::nullopt;
  return q.value(0).toDouble();
}

QString ClinicalStore::userName(qint64 userId) {
  require(isStaff(), "read account names");
  QSqlQuery q = m_db.exec("SELECT name FROM users WHERE id = ?", {userId});
  if (!q.next()) throw StorageError(Kind::NotFound, "unknown account " + std::to_string(userId));
  return q.value(0).toString();
}

void ClinicalStore::appendChunk(qint64 sessionId, std::span<const ArmSample> samples) {
  if (samples.empty()) return;
  const QString status = visibleSessionStatus(sessionId);
  if (status != kStatusRecording)
    throw StorageError(Kind::Usage, "session " + std::to_string(sessionId) + " is " + text(status) +
                                        ", not recording");
  writeChunk(m_db, sessionId, samples);
}

void ClinicalStore::finishSession(qint64 sessionId, const QString& status) {
  visibleSessionStatus(sessionId);
  if (status != kStatusComplete && status != kStatusInterrupted)
    throw StorageError(Kind::Usage, "a session finishes as complete or interrupted");
  // A complete session's analysis stays pending until it is stored; an interrupted one is
  // analysed only when asked (session reestimate, Re-estimate in the application).
  m_db.exec(
      "UPDATE sessions SET status = ?, recorder_pid = NULL, analysis = CASE WHEN ? = "
      "'interrupted' AND analysis = 'pending' THEN 'none' ELSE analysis END WHERE id = ?",
      {status, status, sessionId});
}

qint64 ClinicalStore::importRecording(const std::filesystem::path& csv, const QString& patientCode,
                                      const QString& protocolName, ImportReport* report,
                                      const ImportObserver& stored) {
  visiblePatientId(patientCode);  // refuse before reading a large file
  RecordingReader reader(csv);    // throws RecordingError naming file:line:column
  SessionSettings settings;
  settings.origin = kOriginImport;
  const qint64 id = beginSession(patientCode, protocolName, sidecarText(reader.meta()),
                                 maskOf(reader.columns()), settings);
  bool cutShort = false;
  try {
    std::vector<ArmSample> chunk;
    ArmSample sample;
    const auto store = [&] {
      appendChunk(id, chunk);
      if (stored)
        stored(id, chunk,
               reader.fileSize() > 0 ? static_cast<double>(reader.bytesRead()) /
                                           static_cast<double>(reader.fileSize())
                                     : 0.0);
      chunk.clear();
    };
    while (reader.next(sample)) {
      if (!chunk.empty() &&
          (sample.t - chunk.front().t >= kChunkSeconds || chunk.size() >= kMaxChunkRows))
        store();
      chunk.push_back(sample);
    }
    if (!chunk.empty()) store();
    cutShort = reader.cutShort();
    // A file cut short (its last line incomplete: the recorder was killed) is kept as what it
    // is, an interrupted recording; so is one with no row at all.
    finishSession(id, cutShort || reader.rows() == 0 ? kStatusInterrupted : kStatusComplete);
  } catch (...) {
    removeFailedImport(id);
    throw;
  }
  if (report) {
    report->warnings = reader.warnings();
    report->cutShort = cutShort;
    report->rows = reader.rows();
    report->gaps = reader.gaps();
  }
  return id;
}

void ClinicalStore::removeFailedImport(qint64 id) {
  // An import is all or nothing: a malformed row, a full disk or a lock leaves no partial
  // session. If the removal fails too (the lock is still held), the session stays "recording",
  // marked as an import of this process, and is removed when the database is next opened after
  // this process has ended.
  try {
    m_db.transaction([&] {
      m_db.exec("DELETE FROM sessions WHERE id = ?", {id});
      audit("delete", "session", QString::number(id), "import failed");
    });
  } catch (const std::exception&) {
  }
}

void ClinicalStore::requireVisible(bool found, qint64 patientId, qint64 sessionId) const {
  if (!found || (user().role == Role::Home && user().patientId != patientId))
    throw StorageError(Kind::NotFound, "unknown session " + std::to_string(sessionId) +
                                           ": see 'session list --patient CODE'");
}

QString ClinicalStore::visibleSessionStatus(qint64 sessionId) {
  // The session's row alone: visibleSession() also totals the chunks stored so far, which for
  // every new chunk of an hour's import read all the ones before it (3,600 chunks: 6.5 million).
  QSqlQuery q = m_db.exec("SELECT status, patient_id FROM sessions WHERE id = ?", {sessionId});
  const bool found = q.next();
  requireVisible(found, found ? q.value(1).toLongLong() : 0, sessionId);
  return q.value(0).toString();
}

SessionInfo ClinicalStore::visibleSession(qint64 sessionId) {
  QSqlQuery q = m_db.exec(
      "SELECT s.id, s.patient_id, p.code, s.therapist_id, pr.name, s.started_at, s.duration_s, "
      "s.devices_json, s.calibration_json, s.filter_json, s.notes, s.status, s.columns_mask, "
      "s.sample_rows, s.imu_samples, s.setting, s.pain_score, s.patient_comment, "
      "s.home_summary_json, s.origin, s.analysis, s.analysis_note FROM sessions s "
      "JOIN patients p ON p.id = s.patient_id "
      "LEFT JOIN protocols pr ON pr.id = s.protocol_id WHERE s.id = ?",
      {sessionId});
  const bool found = q.next();
  requireVisible(found, found ? q.value(1).toLongLong() : 0, sessionId);
  SessionInfo s;
  s.id = q.value(0).toLongLong();
  s.patientId = q.value(1).toLongLong();
  s.patientCode = q.value(2).toString();
  if (!q.value(3).isNull()) s.therapistId = q.value(3).toLongLong();
  s.protocolName = q.value(4).toString();
  s.startedAt = q.value(5).toString();
  s.durationS = q.value(6).toDouble();
  s.devicesJson = q.value(7).toString();
  s.calibrationJson = q.value(8).toString();
  s.filterJson = q.value(9).toString();
  s.notes = q.value(10).toString();
  s.status = q.value(11).toString();
  s.columnsMask = q.value(12).toInt();
  s.sampleRows = q.value(13).toLongLong();
  s.imuSamples = q.value(14).toLongLong();
  s.setting = q.value(15).toString();
  if (!q.value(16).isNull()) s.painScore = q.value(16).toInt();
  s.patientComment = q.value(17).toString();
  s.homeSummaryJson = q.value(18).toString();
  s.origin = q.value(19).toString();
  s.analysis = q.value(20).toString();
  s.analysisNote = q.value(21).toString();
  q.finish();
  QSqlQuery c = m_db.exec(
      "SELECT count(*), coalesce(sum(length(data)), 0) FROM recording_chunks "
      "WHERE session_id = ?",
      {sessionId});
  if (c.next()) {
    s.chunks = c.value(0).toLongLong();
    s.storedBytes = c.value(1).toLongLong();
  }
  return s;
}

std::vector<SessionInfo> ClinicalStore::listSessions(const QString& patientCode) {
  const qint64 patientId = visiblePatientId(patientCode);
  std::vector<qint64> ids;
  QSqlQuery q = m_db.exec("SELECT id FROM sessions WHERE patient_id = ? ORDER BY started_at, id",
                          {patientId});
  while (q.next()) ids.push_back(q.value(0).toLongLong());
  q.finish();
  std::vector<SessionInfo> sessions;
  for (qint64 id : ids) sessions.push_back(visibleSession(id));
  return sessions;
}

SessionInfo ClinicalStore::session(qint64 sessionId) {
  return visibleSession(sessionId);
}

void ClinicalStore::updateSessionNotes(qint64 sessionId, const QString& notes) {
  require(isStaff(), "change session notes");
  visibleSessionStatus(sessionId);
  m_db.transaction([&] {
    m_db.exec("UPDATE sessions SET notes = ? WHERE id = ?", {notes, sessionId});
    audit("update", "session", QString::number(sessionId), "notes");
  });
}

void ClinicalStore::updateSessionFilterSettings(qint64 sessionId, const QString& json) {
  require(isStaff(), "change a session's filter settings");
  if (!QJsonDocument::fromJson(json.toUtf8()).isObject())
    throw StorageError(Kind::Usage, "a session's filter settings must be a JSON object");
  visibleSessionStatus(sessionId);
  m_db.transaction([&] {
    m_db.exec("UPDATE sessions SET filter_json = ? WHERE id = ?", {json, sessionId});
    audit("update", "session", QString::number(sessionId), "filter settings");
  });
}

void ClinicalStore::removeSession(qint64 sessionId) {
  require(user().role == Role::Admin, "remove sessions");
  visibleSessionStatus(sessionId);
  m_db.transaction([&] {
    m_db.exec("DELETE FROM sessions WHERE id = ?", {sessionId});
    audit("delete", "session", QString::number(sessionId));
  });
}

bool ClinicalStore::readRecordingChunks(
    qint64 sessionId, const std::function<bool(std::span<const ArmSample>)>& chunk) {
  const SessionInfo s = visibleSession(sessionId);
  struct Stop {};  // thrown out of readChunks when the caller has had enough
  // The checks are db check's (RecordsCheck.h), so both name a damage alike, and the refusal
  // says what to do.
  const auto damaged = [&](const QString& problem) {
    return StorageError(Kind::Corrupt, damagedRecordingMessage(sessionId, problem));
  };
  int expectedSeq = 0;
  qint64 rows = 0;
  double lastT = -std::numeric_limits<double>::infinity();
  try {
    readChunks(m_db, sessionId, [&](const StoredChunk& c) {
      if (c.seq != expectedSeq) throw damaged(missingChunks(expectedSeq, c.seq));
      ++expectedSeq;
      std::vector<ArmSample> samples;
      try {
        samples = decodeStoredChunk(c, lastT);
      } catch (const std::runtime_error& e) {
        throw damaged("chunk " + QString::number(c.seq) + ": " + QString::fromStdString(e.what()));
      }
      if (samples.empty()) return;
      lastT = samples.back().t;
      rows += static_cast<qint64>(samples.size());
      if (!chunk(samples)) throw Stop{};
    });
  } catch (const Stop&) {
    return false;
  }
  if (rows != s.sampleRows)
    throw damaged("the chunks hold " + QString::number(rows) + " rows, the session says " +
                  QString::number(s.sampleRows) +
                  (rows < s.sampleRows ? " (chunks at the end are missing)" : ""));
  return true;
}

Recording ClinicalStore::readRecording(qint64 sessionId) {
  const SessionInfo s = visibleSession(sessionId);
  Recording rec;
  rec.meta = metaFromText(s.calibrationJson, sessionId);
  rec.samples.reserve(static_cast<std::size_t>(s.sampleRows));
  readRecordingChunks(sessionId, [&](std::span<const ArmSample> samples) {
    rec.samples.insert(rec.samples.end(), samples.begin(), samples.end());
    return true;
  });
  return rec;
}

void ClinicalStore::exportRecording(qint64 sessionId, const std::filesystem::path& csv) {
  const SessionInfo s = visibleSession(sessionId);
  // Read whole before the file is opened, so a corrupt session leaves no half-written file.
  const Recording rec = readRecording(sessionId);
  {
    RecordingWriter writer(csv, rec.meta, columnsOf(s.columnsMask));
    for (const ArmSample& sample : rec.samples) writer.append(sample);
    writer.close();
  }
  audit("export", "session", QString::number(sessionId), "recording");
}

}  // namespace armtrack::storage
