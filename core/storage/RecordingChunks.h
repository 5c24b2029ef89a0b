// Writing a session's recording as compressed chunks, shared by ClinicalStore (imports, the
// service API) and DatabaseRecordingSink (a live session recording straight into the records).
#pragma once

#include <QString>
#include <span>

#include "core/ArmSample.h"
#include "core/storage/Database.h"

namespace armtrack::storage {

/// Stores samples (ChunkCodec::encode, codec ChunkCodec::kName) as the next chunk of session sessionId in one transaction and adds them to the
/// session's row, sample and duration counts. No access check: the caller has made it. Throws
/// StorageError(Usage) when samples are out of time order or start before the previous chunk
/// ends; StorageError(Io) when the database refuses the write (nothing of the chunk is kept).
void writeChunk(Database& db, qint64 sessionId, std::span<const ArmSample> samples);

}  // namespace armtrack::storage
