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

// Chunks are fetched kBatchChunks at a time, each batch by a query of its own that is finished
// before the caller sees its chunks: the connection is then free, so the caller may write while it
// reads (an analysis stores its estimates as it reads the recording; on PostgreSQL a connection
// cannot run a statement while another one's rows are still coming).
constexpr int kBatchChunks = 32;

// PostgreSQL through libpq: one batch in the binary wire format.
int readBatchBinary(Database& db, PGconn* conn, qint64 sessionId, int fromSeq,
                    const std::function<void(const StoredChunk&)>& chunk) {
  using Kind = StorageError::Kind;
  const std::string id = std::to_string(sessionId), from = std::to_string(fromSeq),
                    limit = std::to_string(kBatchChunks);
  const char* params[] = {id.c_str(), from.c_str(), limit.c_str()};
  PGresult* r = PQexecParams(conn,
                             "SELECT seq::int8, row_count::int8, codec, data FROM recording_chunks "
                             "WHERE session_id = $1::int8 AND seq >= $2::int8 ORDER BY seq "
                             "LIMIT $3::int8",
                             3, nullptr, params, nullptr, nullptr, /*resultFormat=binary*/ 1);
  if (PQresultStatus(r) != PGRES_TUPLES_OK) {
    const std::string why = r ? PQresultErrorMessage(r) : PQerrorMessage(conn);
    PQclear(r);
    throw StorageError(Kind::Io, "database '" + db.url().display().toStdString() +
                                     "' cannot read the recording: " + why);
  }
  const int n = PQntuples(r);
  try {
    for (int i = 0; i < n; ++i) {
      StoredChunk c;
      c.seq = static_cast<int>(bigEndian(PQgetvalue(r, i, 0), 8));
      c.rows = bigEndian(PQgetvalue(r, i, 1), 8);
      c.codec.assign(PQgetvalue(r, i, 2), static_cast<std::size_t>(PQgetlength(r, i, 2)));
      c.data =
          std::string_view(PQgetvalue(r, i, 3), static_cast<std::size_t>(PQgetlength(r, i, 3)));
      chunk(c);
    }
  } catch (...) {
    PQclear(r);
    throw;
  }
  PQclear(r);
  return n;
}

// Qt Sql: one batch, copied out of the query before the caller sees it.
int readBatch(Database& db, qint64 sessionId, int fromSeq,
              const std::function<void(const StoredChunk&)>& chunk) {
  struct Owned {
    int seq;
    std::uint64_t rows;
    std::string codec;
    QByteArray data;
  };
  std::vector<Owned> batch;
  {
    QSqlQuery q = db.exec(
        "SELECT seq, row_count, codec, data FROM recording_chunks WHERE session_id = ? AND seq >= "
        "? ORDER BY seq LIMIT " +
            QString::number(kBatchChunks),
        {sessionId, fromSeq});
    while (q.next())
      batch.push_back({q.value(0).toInt(), q.value(1).toULongLong(),
                       q.value(2).toString().toStdString(), q.value(3).toByteArray()});
  }
  for (const Owned& o : batch) {
    StoredChunk c;
    c.seq = o.seq;
    c.rows = o.rows;
    c.codec = o.codec;
    c.data = std::string_view(o.data.constData(), static_cast<std::size_t>(o.data.size()));
    chunk(c);
  }
  return static_cast<int>(batch.size());
}

}  // namespace

void readChunks(Database& db, qint64 sessionId,
                const std::function<void(const StoredChunk&)>& chunk) {
  PGconn* conn = db.isPostgres() ? static_cast<PGconn*>(db.postgresConnection()) : nullptr;
  int next = 0;
  for (;;) {
    int last = -1;
    const auto seen = [&](const StoredChunk& c) {
      last = c.seq;
      chunk(c);
    };
    const int n = conn ? readBatchBinary(db, conn, sessionId, next, seen)
                       : readBatch(db, sessionId, next, seen);
    if (n < kBatchChunks || last < 0) return;
    next = last + 1;
  }
}

}  // namespace armtrack::storage
