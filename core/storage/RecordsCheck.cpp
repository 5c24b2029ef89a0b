// Checks of stored recordings and estimates (RecordsCheck.h), and the checks of ClinicalStore
// that use them: db check's, an export's, and the audit log's chain for administrators.
#include "core/storage/RecordsCheck.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QSqlQuery>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "core/storage/AuditLog.h"
#include "core/storage/ChunkCodec.h"
#include "core/storage/ClinicalStore.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

constexpr qsizetype kMaxProblems = 10;  // per session; then how many more

QString chunkName(qint64 seq) {
  return "chunk " + QString::number(seq);
}

QString number(double v) {
  return QString::number(v, 'g', 17);
}

// Times the index and the decoded samples should agree on (SQLite gives -0 back as 0).
bool sameTime(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

void capProblems(QStringList& problems) {
  if (problems.size() <= kMaxProblems) return;
  const qsizetype more = problems.size() - kMaxProblems;
  problems = problems.mid(0, kMaxProblems);
  problems << "and " + QString::number(more) + " more problem(s)";
}

struct IndexedChunk {
  double tFirst = 0;
  double tLast = 0;
  qint64 rows = 0;
};

}  // namespace

QString missingChunks(qint64 expected, qint64 found) {
  if (found - expected == 1) return chunkName(expected) + " is missing";
  return "chunks " + QString::number(expected) + " to " + QString::number(found - 1) +
         " are missing";
}

std::string damagedRecordingMessage(qint64 sessionId, const QString& problem) {
  const QString session = "session " + QString::number(sessionId);
  return (session + (problem.startsWith("chunk") ? ", " : ": ") + problem + ". The recording of " +
          session +
          " is damaged: restore a backup of the database made before the damage ('armtrack-cli db "
          "check' lists every damaged session)")
      .toStdString();
}

std::vector<ArmSample> decodeStoredChunk(const StoredChunk& c, double previousLastT) {
  if (!ChunkCodec::knows(c.codec)) throw std::runtime_error("unknown codec '" + c.codec + "'");
  std::vector<ArmSample> samples = ChunkCodec::decode(std::string(c.data), c.rows, c.codec);
  if (!samples.empty() && samples.front().t < previousLastT)
    throw std::runtime_error("starts before the previous chunk ends");
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (!(samples[i].t >= samples[i - 1].t))
      throw std::runtime_error("its times go backwards at row " + std::to_string(i));
  return samples;
}

QStringList recordingProblems(Database& db, qint64 sessionId, RecordingDepth depth) {
  QStringList problems;
  std::map<qint64, IndexedChunk> index;
  std::set<qint64> flagged;  // chunks the index already shows as wrong
  qint64 sessionRows = 0;
  {
    // One statement, one snapshot: the row count and the chunks that make it up.
    QSqlQuery q = db.exec(
        "SELECT s.sample_rows, c.seq, c.t_first, c.t_last, c.row_count, c.codec FROM sessions s "
        "LEFT JOIN recording_chunks c ON c.session_id = s.id WHERE s.id = ? ORDER BY c.seq",
        {sessionId});
    bool found = false;
    qint64 expected = 0;
    double lastT = -std::numeric_limits<double>::infinity();
    while (q.next()) {
      found = true;
      sessionRows = q.value(0).toLongLong();
      if (q.value(1).isNull()) continue;  // no chunks at all
      const qint64 seq = q.value(1).toLongLong();
      IndexedChunk c{q.value(2).toDouble(), q.value(3).toDouble(), q.value(4).toLongLong()};
      const QString codec = q.value(5).toString();
      if (seq != expected) problems << missingChunks(expected, seq);
      expected = seq + 1;
      const QString name = chunkName(seq);
      const auto flag = [&](const QString& what) {
        problems << name + ": " + what;
        flagged.insert(seq);
      };
      if (!ChunkCodec::knows(codec.toStdString()))
        flag("unknown codec '" + codec + "'");
      else if (c.rows <= 0)
        flag("the index says it holds " + QString::number(c.rows) + " rows");
      else if (!(c.tFirst <= c.tLast))
        flag("its times run backwards in the index (" + number(c.tFirst) + " s to " +
             number(c.tLast) + " s)");
      else if (c.tFirst < lastT)
        flag("starts (" + number(c.tFirst) + " s) before the chunk before it ends (" +
             number(lastT) + " s)");
      if (c.tLast > lastT) lastT = c.tLast;
      index[seq] = c;
    }
    if (!found) throw StorageError(Kind::NotFound, "unknown session " + std::to_string(sessionId));
  }
  qint64 held = 0;
  for (const auto& [seq, c] : index) held += c.rows;
  if (held != sessionRows)
    problems << "the chunks hold " + QString::number(held) + " rows, the session says " +
                    QString::number(sessionRows) +
                    (held < sessionRows ? " (chunks at the end are missing)" : "");

  double lastT = -std::numeric_limits<double>::infinity();
  readChunks(db, sessionId, [&](const StoredChunk& c) {
    const auto it = index.find(c.seq);
    if (it == index.end() || flagged.count(c.seq) > 0) return;  // written since, or told
    try {
      if (depth == RecordingDepth::Checksums) {
        ChunkCodec::verify(c.data, c.rows, c.codec);
        return;
      }
      const std::vector<ArmSample> samples = decodeStoredChunk(c, lastT);
      if (samples.empty()) return;
      if (!sameTime(samples.front().t, it->second.tFirst) ||
          !sameTime(samples.back().t, it->second.tLast))
        throw std::runtime_error("its times (" + number(samples.front().t).toStdString() +
                                 " s to " + number(samples.back().t).toStdString() +
                                 " s) are not the index's (" +
                                 number(it->second.tFirst).toStdString() + " s to " +
                                 number(it->second.tLast).toStdString() + " s)");
      lastT = samples.back().t;
    } catch (const std::runtime_error& e) {
      problems << chunkName(c.seq) + ": " + QString::fromStdString(e.what());
    }
  });
  capProblems(problems);
  return problems;
}

QStringList estimateProblems(Database& db, qint64 sessionId) {
  struct Version {
    QString paramsJson;
    qint64 dataBytes = 0;
    std::vector<std::pair<qint64, qint64>> chunks;  // seq, rows
  };
  std::map<int, Version> versions;
  {
    QSqlQuery q = db.exec(
        "SELECT e.version, e.params_json, length(e.data), c.seq, c.row_count FROM estimates e "
        "LEFT JOIN estimate_chunks c ON c.estimate_id = e.id WHERE e.session_id = ? AND "
        "e.complete = 1 ORDER BY e.version, c.seq",
        {sessionId});
    while (q.next()) {
      Version& v = versions[q.value(0).toInt()];
      v.paramsJson = q.value(1).toString();
      v.dataBytes = q.value(2).toLongLong();
      if (!q.value(3).isNull())
        v.chunks.emplace_back(q.value(3).toLongLong(), q.value(4).toLongLong());
    }
  }
  QStringList problems;
  for (const auto& [version, v] : versions) {
    const QString name = "estimates version " + QString::number(version);
    if (v.chunks.empty()) {
      if (v.dataBytes == 0) problems << name + ": it has neither chunks nor data";
      continue;  // stored whole (estimates.data), before estimate_chunks
    }
    qint64 expected = 0;
    qint64 rows = 0;
    for (const auto& [seq, count] : v.chunks) {
      if (seq != expected) problems << name + ": " + missingChunks(expected, seq);
      expected = seq + 1;
      rows += count;
    }
    const QJsonValue said = QJsonDocument::fromJson(v.paramsJson.toUtf8()).object()["rows"];
    if (!said.isDouble())
      problems << name + ": its parameters (params_json) give no row count";
    else if (static_cast<qint64>(said.toDouble()) != rows)
      problems << name + ": its chunks hold " + QString::number(rows) +
                      " rows, its parameters say " + QString::number(said.toInteger());
  }
  capProblems(problems);
  return problems;
}

RecordsCheckReport ClinicalStore::checkRecords() {
  RecordsCheckReport report;
  std::vector<std::pair<qint64, QString>> sessions;  // id, status
  {
    QSqlQuery q =
        user().role == Role::Home
            ? m_db.exec("SELECT id, status FROM sessions WHERE patient_id = ? ORDER BY id",
                        {user().patientId.value_or(-1)})
            : m_db.exec("SELECT id, status FROM sessions ORDER BY id");
    while (q.next()) sessions.emplace_back(q.value(0).toLongLong(), q.value(1).toString());
  }
  for (const auto& [id, status] : sessions) {
    // A live writer's session is checked when it is finished (sessions of a writer that died
    // were marked interrupted when this store opened, and are checked).
    if (status == kStatusRecording) {
      report.beingRecorded.push_back(id);
      continue;
    }
    QStringList problems;
    try {
      problems = recordingProblems(m_db, id, RecordingDepth::Decode) + estimateProblems(m_db, id);
    } catch (const StorageError& e) {
      if (e.kind() == Kind::NotFound) continue;  // removed meanwhile
      throw;
    }
    ++report.sessionsChecked;
    if (problems.isEmpty()) continue;
    // Removed while it was read: not damage.
    QSqlQuery still = m_db.exec("SELECT status FROM sessions WHERE id = ?", {id});
    if (!still.next()) continue;
    report.damaged.push_back({id, problems});
  }
  return report;
}

void ClinicalStore::requireIntactRecording(qint64 sessionId) {
  visibleSessionStatus(sessionId);
  const QStringList problems = recordingProblems(m_db, sessionId, RecordingDepth::Checksums);
  if (!problems.isEmpty())
    throw StorageError(Kind::Corrupt, damagedRecordingMessage(sessionId, problems.join("; ")));
}

AuditChainReport ClinicalStore::verifyAuditLog(const std::optional<AuditAnchor>& expect) {
  require(user().role == Role::Admin, "verify the audit log");
  return verifyAuditChain(m_db, expect);
}

}  // namespace armtrack::storage
