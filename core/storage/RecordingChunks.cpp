#include "core/storage/RecordingChunks.h"

#include <libpq-fe.h>

#include <QSqlQuery>

#include "core/storage/ChunkCodec.h"

namespace armtrack::storage {

void writeChunk(Database& db, qint64 sessionId, std::span<const ArmSample> samples) {
  using Kind = StorageError::Kind;
  if (samples.empty()) return;
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (!(samples[i].t >= samples[i - 1].t))
      throw StorageError(Kind::Usage, "samples must be in time order");
  const std::string frame = ChunkCodec::encode(samples);
  qint64 imu = 0;
  for (const ArmSample& a : samples) imu += a.hasImu() ? 1 : 0;
  db.transaction([&] {
    // PostgreSQL: a chunk's commit does not wait for its WAL flush, the trade-off SQLite's
    // synchronous=NORMAL makes: a server crash or power cut may lose the last chunks (up to
    // ~0.6 s of them), never corrupt the database. Accounts and clinical records keep full
    // durability: this holds for this transaction only.
    if (db.isPostgres()) db.exec("SET LOCAL synchronous_commit = off");
    QSqlQuery last = db.exec(
        "SELECT seq, t_last FROM recording_chunks WHERE session_id = ? "
        "ORDER BY seq DESC LIMIT 1",
        {sessionId});
    int seq = 0;
    if (last.next()) {
      seq = last.value(0).toInt() + 1;
      if (samples.front().t < last.value(1).toDouble())
        throw StorageError(Kind::Usage, "a chunk may not start before the previous one ends");
    }
    last.finish();
    db.exec(
        "INSERT INTO recording_chunks (session_id, seq, t_first, t_last, row_count, codec, "
        "data) VALUES (?, ?, ?, ?, ?, ?, ?)",
        {sessionId, seq, samples.front().t, samples.back().t, static_cast<qint64>(samples.size()),
         QString::fromLatin1(ChunkCodec::kName),
         QByteArray(frame.data(), static_cast<qsizetype>(frame.size()))});
    db.exec(
        "UPDATE sessions SET sample_rows = sample_rows + ?, imu_samples = imu_samples + ?, "
        "duration_s = ? - (SELECT t_first FROM recording_chunks WHERE session_id = ? AND "
        "seq = 0) WHERE id = ?",
        {static_cast<qint64>(samples.size()), imu, samples.back().t, sessionId, sessionId});
  });
}

namespace {

std::uint64_t bigEndian(const char* p, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | static_cast<unsigned char>(p[i]);
  return v;
}

// PostgreSQL through libpq: binary results in single-row mode (one chunk in memory at a time).
void readChunksBinary(Database& db, PGconn* conn, qint64 sessionId,
                      const std::function<void(const StoredChunk&)>& chunk) {
  using Kind = StorageError::Kind;
  const std::string id = std::to_string(sessionId);
  const char* params[] = {id.c_str()};
  const auto fail = [&](const std::string& why) {
    throw StorageError(Kind::Io, "database '" + db.url().display().toStdString() +
                                     "' cannot read the recording: " + why);
  };
  if (!PQsendQueryParams(conn,
                         "SELECT seq::int8, row_count::int8, codec, data FROM recording_chunks "
                         "WHERE session_id = $1::int8 ORDER BY seq",
                         1, nullptr, params, nullptr, nullptr, /*resultFormat=binary*/ 1) ||
      !PQsetSingleRowMode(conn))
    fail(PQerrorMessage(conn));
  std::string error;
  // Every result is read, also after a failure, so the connection is left idle for Qt.
  while (PGresult* r = PQgetResult(conn)) {
    const ExecStatusType status = PQresultStatus(r);
    if (status == PGRES_SINGLE_TUPLE && error.empty()) {
      try {
        StoredChunk c;
        c.seq = static_cast<int>(bigEndian(PQgetvalue(r, 0, 0), 8));
        c.rows = bigEndian(PQgetvalue(r, 0, 1), 8);
        c.codec.assign(PQgetvalue(r, 0, 2), static_cast<std::size_t>(PQgetlength(r, 0, 2)));
        c.data =
            std::string_view(PQgetvalue(r, 0, 3), static_cast<std::size_t>(PQgetlength(r, 0, 3)));
        chunk(c);
      } catch (...) {
        PQclear(r);
        while (PGresult* rest = PQgetResult(conn)) PQclear(rest);
        throw;
      }
    } else if (status != PGRES_TUPLES_OK && status != PGRES_SINGLE_TUPLE && error.empty()) {
      error = PQresultErrorMessage(r);
    }
    PQclear(r);
  }
  if (!error.empty()) fail(error);
}

}  // namespace

void readChunks(Database& db, qint64 sessionId,
                const std::function<void(const StoredChunk&)>& chunk) {
  if (PGconn* conn = db.isPostgres() ? static_cast<PGconn*>(db.postgresConnection()) : nullptr) {
    readChunksBinary(db, conn, sessionId, chunk);
    return;
  }
  QSqlQuery q = db.exec(
      "SELECT seq, row_count, codec, data FROM recording_chunks WHERE session_id = ? ORDER BY seq",
      {sessionId});
  while (q.next()) {
    const QByteArray data = q.value(3).toByteArray();
    StoredChunk c;
    c.seq = q.value(0).toInt();
    c.rows = q.value(1).toULongLong();
    c.codec = q.value(2).toString().toStdString();
    c.data = std::string_view(data.constData(), static_cast<std::size_t>(data.size()));
    chunk(c);
  }
}

}  // namespace armtrack::storage
