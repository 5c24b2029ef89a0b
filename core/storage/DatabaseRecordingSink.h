// A live session recording straight into the clinical records (docs/storage.md, "Recording into
// the database"): the session's recorder thread hands it rows; it commits them as chunks of under
// a second, so a killed process loses at most the last second.
#pragma once

#include <limits>
#include <memory>
#include <vector>

#include "core/io/Recording.h"
#include "core/storage/DatabaseUrl.h"

namespace armtrack::storage {

class Database;

/// The rows of one session begun with ClinicalStore::beginSession (which checks the user may
/// record for that patient). The sink opens its own connection on first use, in the thread that
/// uses it (a Qt Sql rule), and writes only to a session that is still "recording" and owned by
/// this process, so a second writer can never add to it.
class DatabaseRecordingSink : public RecordingSink {
 public:
  /// A chunk is committed once the rows buffered span chunkSeconds; with the session flushing
  /// every 0.2 s (kFlushInterval) a chunk covers 0.7-0.9 s.
  static constexpr double kChunkSeconds = 0.7;
  static constexpr double kFlushInterval = 0.2;

  DatabaseRecordingSink(DatabaseUrl url, qint64 sessionId, const RecordingColumns& columns,
                        double chunkSeconds = kChunkSeconds);
  ~DatabaseRecordingSink() override;  ///< commits what it can, without throwing

  void append(const ArmSample& sample) override;
  /// Commits the buffered rows as a chunk once they span chunkSeconds.
  void flush() override;
  /// Commits every buffered row.
  void sync() override;
  void close() override;
  std::uint64_t rows() const override { return m_rows; }
  std::uint64_t rowsWritten() const override { return m_rowsWritten; }
  qint64 sessionId() const { return m_sessionId; }

 private:
  void commit(bool all);
  [[noreturn]] void fail(const std::string& what) const;

  DatabaseUrl m_url;
  qint64 m_sessionId;
  RecordingColumns m_columns;
  double m_chunkSeconds;
  std::unique_ptr<Database> m_db;
  std::vector<ArmSample> m_buffer;
  double m_prevT;
  double m_firstT = std::numeric_limits<double>::quiet_NaN();  // the first row's time
  std::uint64_t m_rows = 0;
  std::uint64_t m_rowsWritten = 0;
  bool m_closed = false;
};

}  // namespace armtrack::storage
