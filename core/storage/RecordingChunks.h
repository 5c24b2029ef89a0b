// Writing a session's recording as compressed chunks, shared by ClinicalStore (imports, the
// service API) and DatabaseRecordingSink (a live session recording straight into the records).
#pragma once

#include <QString>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>

#include "core/ArmSample.h"
#include "core/storage/Database.h"

namespace armtrack::storage {

/// Stores samples (ChunkCodec::encode, codec ChunkCodec::kName) as the next chunk of session
/// sessionId in one transaction and adds them to the session's row, sample and duration counts. No
/// access check: the caller has made it. Throws StorageError(Usage) when samples are out of time
/// order or start before the previous chunk ends; StorageError(Io) when the database refuses the
/// write (nothing of the chunk is kept).
void writeChunk(Database& db, qint64 sessionId, std::span<const ArmSample> samples);

/// One stored chunk as readChunks hands it over; data is valid during the call only.
struct StoredChunk {
  int seq = 0;
  std::uint64_t rows = 0;
  std::string codec;
  std::string_view data;
};

/// Calls chunk for each of the session's chunks in seq order, without decoding them. They are
/// fetched 32 at a time, each batch by a query finished before chunk sees it, so chunk may use
/// the connection (an analysis writes its estimates as it reads). On PostgreSQL the chunks come
/// in the binary wire format through the connection's libpq handle: in text format every byte is
/// sent as two hex digits, which the server spends more time writing and the client reading than
/// decoding the chunk takes (docs/storage.md, "Speed"). Throws StorageError(Io) when a query
/// fails.
void readChunks(Database& db, qint64 sessionId,
                const std::function<void(const StoredChunk&)>& chunk);

}  // namespace armtrack::storage
