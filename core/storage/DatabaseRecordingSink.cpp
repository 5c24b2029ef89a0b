#include "core/storage/DatabaseRecordingSink.h"

#include <limits>

#include "core/storage/Database.h"
#include "core/storage/ProcessIdentity.h"
#include "core/storage/RecordingChunks.h"
#include "core/storage/Records.h"

namespace armtrack::storage {

DatabaseRecordingSink::DatabaseRecordingSink(DatabaseUrl url, qint64 sessionId,
                                             const RecordingColumns& columns, double chunkSeconds)
    : m_url(std::move(url)),
      m_sessionId(sessionId),
      m_columns(columns),
      m_chunkSeconds(chunkSeconds),
      m_prevT(-std::numeric_limits<double>::infinity()) {}

DatabaseRecordingSink::~DatabaseRecordingSink() {
  if (m_closed) return;
  try {
    commit(true);
  } catch (...) {
  }
}

void DatabaseRecordingSink::fail(const std::string& what) const {
  throw RecordingError(m_url.display().toStdString() + " session " + std::to_string(m_sessionId), 0,
                       0, what);
}

void DatabaseRecordingSink::append(const ArmSample& s) {
  if (m_closed) fail("the recording is closed");
  if (const std::optional<RowProblem> p = checkRow(s, m_columns, m_prevT, m_firstT))
    fail("row " + std::to_string(m_rows + 1) + ": " + p->message);
  m_buffer.push_back(s);
  if (m_rows == 0) m_firstT = s.t;
  m_prevT = s.t;
  ++m_rows;
}

void DatabaseRecordingSink::commit(bool all) {
  if (m_buffer.empty()) return;
  if (!all && m_buffer.back().t - m_buffer.front().t < m_chunkSeconds) return;
  try {
    if (!m_db) {
      auto db = std::make_unique<Database>(m_url, Database::Options{});
      QSqlQuery q = db->exec(
          "SELECT status, recorder_host, recorder_pid FROM sessions WHERE id = ?", {m_sessionId});
      if (!q.next()) fail("the session does not exist (was it removed?)");
      if (q.value(0).toString() != kStatusRecording ||
          q.value(1).toString() != detail::thisHost() ||
          q.value(2).toLongLong() != detail::thisProcess())
        fail("the session is not being recorded by this process; start a new session");
      q.finish();
      m_db = std::move(db);
    }
    writeChunk(*m_db, m_sessionId, m_buffer);
  } catch (const StorageError& e) {
    // The rows stay buffered: the next flush tries again (after space is freed, a server is
    // back), so a passing failure loses nothing.
    fail(std::string("cannot store the recording: ") + e.what());
  }
  m_rowsWritten += m_buffer.size();
  m_buffer.clear();
}

void DatabaseRecordingSink::flush() {
  if (m_closed) fail("the recording is closed");
  commit(false);
}

void DatabaseRecordingSink::sync() {
  if (m_closed) fail("the recording is closed");
  commit(true);
}

void DatabaseRecordingSink::close() {
  if (m_closed) fail("the recording is closed");
  commit(true);
  m_db.reset();
  m_closed = true;
}

}  // namespace armtrack::storage
