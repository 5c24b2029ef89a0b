// Checks of the stored recordings and estimates: what `db check` runs over every session, and
// what an export runs over its session before writing anything (docs/storage.md, "Checks").
#pragma once

#include <QString>
#include <QStringList>
#include <string>
#include <vector>

#include "core/ArmSample.h"
#include "core/storage/Database.h"
#include "core/storage/RecordingChunks.h"

namespace armtrack::storage {

/// How deep a recording is checked.
enum class RecordingDepth {
  /// The chunk index (sequence without holes, known codecs, times in order, rows adding up to
  /// sessions.sample_rows) and each chunk's header and checksum (ChunkCodec::verify), without
  /// decompressing: what exports check.
  Checksums,
  /// All of that, and every chunk decoded: its rows, and its times in order and as the index
  /// says: what `db check` does.
  Decode,
};

/// What is wrong with session sessionId's stored recording, one line per problem in chunk order
/// ("chunk 3 is missing", "chunk 5: checksum mismatch: the chunk was damaged", "the chunks hold
/// 4000 rows, the session says 5000"), at most 10 and then how many more; empty when nothing is.
/// The index and sessions.sample_rows are read in one statement and only the chunks in it are
/// read after, so a session still being written is judged on what it had then. No access rule
/// (callers: ClinicalStore). Throws StorageError(NotFound) for no such session, Io.
QStringList recordingProblems(Database& db, qint64 sessionId, RecordingDepth depth);

/// What is wrong with the complete estimate versions of a session: their chunks
/// (estimate_chunks) in sequence without holes, and their rows adding up to the row count in
/// params_json ("estimates version 2: chunk 1 is missing"). A version stored whole in
/// estimates.data (before estimate_chunks) has no chunks and is not looked into. Throws
/// StorageError(Io).
QStringList estimateProblems(Database& db, qint64 sessionId);

/// A chunk decoded, as readRecordingChunks and recordingProblems(Decode) take it: a known codec,
/// ChunkCodec::decode (its checksum, its rows), times in order within it and not before
/// previousLastT (the last time of the chunk before; -infinity for the first). Throws
/// std::runtime_error saying what is wrong, without the session and chunk.
std::vector<ArmSample> decodeStoredChunk(const StoredChunk& chunk, double previousLastT);

/// "chunk 2 is missing" or "chunks 2 to 4 are missing": expected was due, found came.
QString missingChunks(qint64 expected, qint64 found);

/// The refusal for a session whose recording is damaged, one line: "session N, chunk K: what.
/// The recording of session N is damaged: restore a backup ... ('armtrack-cli db check' lists
/// every damaged session)". problem as recordingProblems gives it.
std::string damagedRecordingMessage(qint64 sessionId, const QString& problem);

/// One session db check found damaged.
struct SessionDamage {
  qint64 sessionId = 0;
  QStringList problems;  ///< recordingProblems(Decode), then estimateProblems
};

/// What ClinicalStore::checkRecords found.
struct RecordsCheckReport {
  qint64 sessionsChecked = 0;
  std::vector<qint64> beingRecorded;  ///< status "recording" (a live writer): not checked
  std::vector<SessionDamage> damaged;
};

}  // namespace armtrack::storage
