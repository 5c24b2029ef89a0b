// Sessions a home device uploads to the clinic (docs/sync.md, "Uploads"): declared by UUID with
// the recording's SHA-256, sent in numbered chunks each with its own SHA-256, and stored as a
// normal session of the device's patient once complete. Every step is idempotent and kept in the
// database, so a dropped connection resumes where it stopped, on any server.
#pragma once

#include <QByteArray>
#include <QString>
#include <functional>
#include <optional>
#include <vector>

#include "core/storage/ClinicalStore.h"

namespace armtrack::storage {

/// What a device declares of a session before sending it.
struct UploadMeta {
  QString sha256;        ///< of the whole recording (the CSV), lower-case hex
  qint64 sizeBytes = 0;  ///< of the whole recording
  int chunkCount = 0;    ///< 1 .. kMaxUploadChunks
  QString protocol;      ///< the protocol's name, or empty
  QString sidecarJson;   ///< the recording's sidecar (a JSON object), or empty
  QString metaJson;      ///< the declaration as sent, kept as it was
  /// The patient's own outcome, from metaJson's "outcome" object: {"pain_score": 0-10 or null,
  /// "comment": text, "summary": {what the home window counted}} (ClinicalStore::saveHomeOutcome).
  bool hasOutcome = false;
  std::optional<int> painScore;
  QString comment;
  QString summaryJson = "{}";
};

/// Where an upload stands.
struct UploadState {
  bool created = false;      ///< declare() made it now (it was not there before)
  std::vector<int> missing;  ///< chunk numbers not yet received
  qint64 sessionId = 0;      ///< the stored session once complete; 0 before
};

inline constexpr int kMaxUploadChunks = 100000;
inline constexpr qint64 kMaxUploadBytes = qint64{8} << 30;  // 8 GiB: hours at 1 kHz
inline constexpr qint64 kMaxChunkBytes = qint64{8} << 20;   // 8 MiB

/// The uploads of the device store is signed in as (ClinicalStore::signInWithDeviceToken or
/// enrolDevice). An upload of another patient is reported as not found, exactly as one that does
/// not exist. Throws StorageError: NotFound, Exists (a UUID declared or a chunk sent again with
/// another checksum), Corrupt (a chunk or the whole recording not matching its checksum: nothing
/// of it is kept), Usage (values out of range, a complete() with chunks missing).
class SyncUploads {
 public:
  explicit SyncUploads(ClinicalStore& store);
  /// Declares the upload uuid (a UUID in text form); again with the same checksum, size and
  /// chunk count it answers where the upload stands (created false).
  UploadState declare(const QString& uuid, const UploadMeta& meta);
  UploadState state(const QString& uuid);
  /// Stores chunk seq (0 .. chunkCount - 1) after checking data against sha256 (hex). Again with
  /// the same checksum: nothing to do.
  void putChunk(const QString& uuid, int seq, const QByteArray& data, const QString& sha256);
  /// Joins the chunks, checks the whole recording's checksum and imports it as a home session of
  /// the device's patient (ClinicalStore::importRecording, as the home account) with the
  /// declared outcome (saveHomeOutcome); then
  /// analysed(sessionId) is called (the caller analyses it; may throw, the session stays
  /// stored, pending). Again after that: the same session id, nothing imported twice.
  qint64 complete(const QString& uuid, const std::function<void(qint64)>& analyse);

 private:
  struct Row {
    qint64 patientId = 0;
    UploadMeta meta;
    qint64 sessionId = 0;
  };
  Row visible(const QString& uuid);  // NotFound unless it is this patient's
  std::vector<int> missingChunks(const QString& uuid, int count);

  ClinicalStore& m_store;
  Database& m_db;
};

/// Lower-case hex SHA-256 of data.
QString sha256Hex(const QByteArray& data);
/// Whether text is 64 lower- or upper-case hex digits.
bool isSha256Hex(const QString& text);

}  // namespace armtrack::storage
