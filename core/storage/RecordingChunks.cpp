#include "core/storage/RecordingChunks.h"

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
         QString::fromLatin1(ChunkCodec::kName), QByteArray(frame.data(), static_cast<qsizetype>(frame.size()))});
    db.exec(
        "UPDATE sessions SET sample_rows = sample_rows + ?, imu_samples = imu_samples + ?, "
        "duration_s = ? - (SELECT t_first FROM recording_chunks WHERE session_id = ? AND "
        "seq = 0) WHERE id = ?",
        {static_cast<qint64>(samples.size()), imu, samples.back().t, sessionId, sessionId});
  });
}

}  // namespace armtrack::storage
